/* A sin/cos pair per sample, three ways, side by side (the C back-end's trig):
 * the generated header's rigidsym_sin/rigidsym_cos (OWN), glibc's libmvec (-DMVEC, with
 * -fopenmp-simd -fno-builtin-sin -fno-builtin-cos -lmvec) and libm's scalar sin/cos (neither).
 * Prints ns per pair (thread CPU time, best of 30 rounds over 4096 samples) and the largest
 * error in ulp against long double sinl/cosl (64-bit significand: its own error is about
 * 2^-11 ulp of a double) per regime. Driven by benchmarks/trig_pair.py. */
#define _POSIX_C_SOURCE 199309L
#include "rigidsym_common.h"
#include <stdio.h>
#include <time.h>
#if defined(MVEC)
#pragma omp declare simd notinbranch
double sin(double);
#pragma omp declare simd notinbranch
double cos(double);
#endif
#define N 4096
static double xs[N], so[N], co[N];

static RIGIDSYM_NOINLINE void pairs(void)
{
#if defined(OWN)
    int64_t far = 0;
#pragma omp simd reduction(|:far)
    for (int j = 0; j < N; ++j) {
        so[j] = rigidsym_sin(xs[j]);
        co[j] = rigidsym_cos(xs[j]);
        far |= rigidsym_trig_far(xs[j]);
    }
    if (far)
        for (int j = 0; j < N; ++j)
            if (rigidsym_trig_far(xs[j])) {
                so[j] = sin(xs[j]);
                co[j] = cos(xs[j]);
            }
#else
#if defined(MVEC)
#pragma omp simd
#endif
    for (int j = 0; j < N; ++j) {
        so[j] = sin(xs[j]);
        co[j] = cos(xs[j]);
    }
#endif
}

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double ulps(double v, long double ref)
{
    if (isnan(v) || isnan((double)ref))
        return isnan(v) && isnan((double)ref) ? 0 : 1e300;
    const double r = (double)ref;
    if (r == 0)
        return v == 0 ? 0 : 1e300;
    int e;
    frexp(r, &e);
    double u = ldexp(1.0, e - 53);
    if (u < 0x1p-1074)
        u = 0x1p-1074;
    return (double)(fabsl((long double)v - ref) / u);
}

static uint64_t state = 88172645463325252ULL;
static double urand(void)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (double)(state >> 11) * 0x1p-53;
}

static const long double PIO2 = 1.5707963267948966192313216916397514L;

static double point(int regime, int i)
{
    const double u = urand(), sgn = urand() < 0.5 ? -1 : 1;
    switch (regime) {
    case 0: return (u - 0.5) * 8;                          /* |x| < 4 */
    case 1: return (u - 0.5) * 2e3;
    case 2: return (u - 0.5) * 3.2e6;                      /* up to RIGIDSYM_TRIG_MAX */
    case 3: {                                              /* doubles next to k pi/2 */
        double x = (double)(floor(u * 1e6) * PIO2);
        for (int s = (int)(urand() * 8) - 4; s != 0; s += s > 0 ? -1 : 1)
            x = nextafter(x, s > 0 ? 1e300 : -1e300);
        return sgn * x;
    }
    case 4:                                                /* phi/2 near pi/2, pi, ... */
        return sgn * ((double)((1 + floor(u * 4)) * PIO2)
                      + (urand() - 0.5) * ldexp(1.0, -(int)(urand() * 60)));
    case 5: return sgn * pow(10.0, (u - 0.5) * 600);       /* 1e-300 .. 1e300 (fallback) */
    default: {
        static const double sp[] = {0.0, -0.0, 0x1p-1074, 1e-310, 1e-20, -1e-8,
                                    0.78539816339744828, 1.5707963267948966,
                                    3.141592653589793, RIGIDSYM_TRIG_MAX,
                                    1.6470993291652857e6, 1e22, 1.5e300};
        return sgn * sp[i % 13];
    }
    }
}

int main(void)
{
    static const char *names[] = {"abs x < 4", "abs x < 1e3", "abs x < 1.6e6", "next to k pi/2",
                                  "near pi/2, pi, 3pi/2, 2pi", "1e-300 .. 1e300", "special"};
    for (int i = 0; i < N; ++i)
        xs[i] = (urand() - 0.5) * 8;
    double best = 1e9;
    for (int r = 0; r < 30; ++r) {
        const double t0 = seconds();
        for (int k = 0; k < 50; ++k)
            pairs();
        const double t = (seconds() - t0) / 50 / N * 1e9;
        best = t < best ? t : best;
    }
    printf("ns_per_pair %.3f\n", best);
    for (int g = 0; g < 7; ++g) {
        double worst = 0, wx = 0, sum = 0;
        long cnt = 0;
        for (int rep = 0; rep < 100; ++rep) {
            for (int i = 0; i < N; ++i)
                xs[i] = point(g, i);
            pairs();
            for (int i = 0; i < N; ++i) {
                const double a = ulps(so[i], sinl(xs[i])), b = ulps(co[i], cosl(xs[i]));
                const double m = a > b ? a : b;
                if (m > worst) { worst = m; wx = xs[i]; }
                if (xs[i] == 0 && signbit(so[i]) != signbit(xs[i]))
                    worst = 1e300;                         /* sin(-0) must be -0 */
                sum += a + b;
                cnt += 2;
            }
        }
        printf("regime %s;%.3f;%.3f;%.17g;%ld\n", names[g], worst, sum / cnt, wx, cnt);
    }
    return 0;
}
