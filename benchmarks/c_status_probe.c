/* The status of the float rotation vector (rigidsym_c_rotation_vector_from_rotation_f32) and
 * screw (rigidsym_c_screw_of_displacement_f32) on small ordinary inputs, with what made it:
 * how many samples the range test sends to the cold path (a nonzero input component of
 * magnitude outside [2^-30, 2^31)), how many come back flagged, the x86-64 exception flags
 * each flagged call raised (the functions give the caller its flags back with those raised
 * since), the worst relative error of the log against the exact phi e and the logs of status
 * 0 off by more than 16 u (silent wrongs). One JSON object
 * a line; benchmarks/c_status_probe.py builds it with gcc and clang at -O2 and -Ofast.
 * $SET_MXCSR (hex) sets the caller's MXCSR first (0x1fc0: DAZ alone). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "rigidsym_c_rotation_vector_from_rotation.h"
#include "rigidsym_c_screw_of_displacement.h"

static uint64_t st = 88172645463325252ULL;
static double urand(void)
{
    st ^= st << 13; st ^= st >> 7; st ^= st << 17;
    return (double)(st >> 11) * (1.0 / 9007199254740992.0);
}
static double nrand(void) { return sqrt(-2 * log(urand() + 1e-300)) * cos(6.283185307179586 * urand()); }
static void unit(double e[3])
{
    double n;
    do {
        e[0] = nrand(); e[1] = nrand(); e[2] = nrand();
        n = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    } while (n == 0);
    e[0] /= n; e[1] /= n; e[2] /= n;
}
/* (2.49) in double (1 - cos phi as 2 sin^2(phi/2)), rounded to float */
static void rotation(const double e[3], double phi, float Q[9])
{
    const double c = cos(phi), s = sin(phi), v = 2 * sin(phi / 2) * sin(phi / 2);
    const double M[9] = {c + e[0] * e[0] * v, e[0] * e[1] * v - e[2] * s, e[0] * e[2] * v + e[1] * s,
                         e[1] * e[0] * v + e[2] * s, c + e[1] * e[1] * v, e[1] * e[2] * v - e[0] * s,
                         e[2] * e[0] * v - e[1] * s, e[2] * e[1] * v + e[0] * s, c + e[2] * e[2] * v};
    for (int i = 0; i < 9; ++i) Q[i] = (float)M[i];
}
static int fires(const float *p, int n, float *which)
{
    int f = 0;
    for (int j = 0; j < n; ++j)
        if (p[j] != 0 && (fabsf(p[j]) < 0x1p-30f || fabsf(p[j]) >= 0x1p31f)) { f = 1; *which = p[j]; }
    return f;
}
static unsigned mxcsr_get(void) { unsigned m; __asm__ volatile("stmxcsr %0" : "=m"(m)); return m; }
static void mxcsr_put(unsigned m) { __asm__ volatile("ldmxcsr %0" : : "m"(m)); }

struct tally { int n, flagged, fired, fired_flagged, extreme, ie, ze, oe, ue, wrong; float input; double maxrel; };
static void count(struct tally *t, int s, int f, float which, unsigned raised)
{
    t->n++; t->fired += f; t->flagged += s != 0; t->fired_flagged += f && s != 0;
    t->extreme += (s & RIGIDSYM_C_EXTREME_INPUT) != 0;
    if (s) {
        t->ie += raised & 1; t->ze += (raised >> 2) & 1; t->oe += (raised >> 3) & 1; t->ue += (raised >> 4) & 1;
        if (t->input == 0) t->input = which;
    }
}
static void print(const char *name, const struct tally *t)
{
    printf("{\"case\": \"%s\", \"n\": %d, \"flagged\": %d, \"extreme_input\": %d, \"range_test_fires\": %d, "
           "\"fired_and_flagged\": %d, \"flagged_raised\": {\"invalid\": %d, \"divide_by_zero\": %d, "
           "\"overflow\": %d, \"underflow\": %d}, \"a_flagged_input\": %.3g, ",
           name, t->n, t->flagged, t->extreme, t->fired, t->fired_flagged, t->ie, t->ze, t->oe, t->ue,
           (double)t->input);
    if (t->maxrel < 0) printf("\"silent_wrong_16u\": null, \"max_rel_err\": null}\n");
    else printf("\"silent_wrong_16u\": %d, \"max_rel_err\": %.3g}\n", t->wrong, t->maxrel);
}
static void logs(const char *name, double lo, double hi, int n)
{
    struct tally t = {0};
    for (int i = 0; i < n; ++i) {
        double e[3], err = 0;
        float Q[9], w[3], which = 0;
        unit(e);
        const double phi = lo == hi ? lo : exp(log(lo) + (log(hi) - log(lo)) * urand());
        rotation(e, phi, Q);
        mxcsr_put(mxcsr_get() & ~0x3fU);
        const int s = rigidsym_c_rotation_vector_from_rotation_f32(Q, w);
        const unsigned raised = mxcsr_get() & 0x3fU;
        count(&t, s, fires(Q, 9, &which), which, raised);
        for (int k = 0; k < 3; ++k) err += (w[k] - phi * e[k]) * (w[k] - phi * e[k]);
        if (s == 0 && !(sqrt(err) / phi <= 16 * 0x1p-24)) t.wrong++;  /* status 0, off by 16 u */
        if (sqrt(err) / phi > t.maxrel) t.maxrel = sqrt(err) / phi;
    }
    print(name, &t);
}
static void screws(const char *name, double r, int n)
{
    struct tally t = {0};
    t.maxrel = -1;   /* not measured */
    for (int i = 0; i < n; ++i) {
        double e[3], u[3], d[3];
        float Q[9], a[3], ap[3], oe[3], phi, p0[3], pitch, pl[6], which = 0;
        unit(e); unit(u); unit(d);
        rotation(e, 3.14159 * urand(), Q);
        for (int k = 0; k < 3; ++k) a[k] = (float)(r * u[k]);
        for (int k = 0; k < 3; ++k)
            ap[k] = (float)((double)Q[3 * k] * a[0] + (double)Q[3 * k + 1] * a[1] + (double)Q[3 * k + 2] * a[2] + r * d[k]);
        mxcsr_put(mxcsr_get() & ~0x3fU);
        const int s = rigidsym_c_screw_of_displacement_f32(Q, a, ap, oe, &phi, p0, &pitch, pl);
        const unsigned raised = mxcsr_get() & 0x3fU;
        const int f = fires(Q, 9, &which) | fires(a, 3, &which) | fires(ap, 3, &which);
        count(&t, s, f, which, raised);
    }
    print(name, &t);
}
int main(int argc, char **argv)
{
    const int n = argc > 1 ? atoi(argv[1]) : 20000;
    if (getenv("SET_MXCSR")) mxcsr_put((unsigned)strtoul(getenv("SET_MXCSR"), 0, 16));
    printf("{\"mxcsr_at_main\": \"0x%04x\"}\n", mxcsr_get());
    logs("log, phi = 1e-6", 1e-6, 1e-6, n);
    logs("log, phi log-uniform in [1e-12, 1e-3]", 1e-12, 1e-3, n);
    logs("log, phi log-uniform in [1e-30, 1e-3]", 1e-30, 1e-3, n);
    for (double phi = 1e-15; phi > 1e-20; phi /= 10) {
        char name[64];
        snprintf(name, sizeof name, "log, phi = %.0e", phi);
        logs(name, phi, phi, n / 4);
    }
    screws("screw, |a| = 1 nm", 1e-9, n);
    screws("screw, |a| = 1 m", 1.0, n);
    return 0;
}
