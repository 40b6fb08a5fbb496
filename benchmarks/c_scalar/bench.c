/* Driver of benchmarks/c_scalar.py: `bench CASE N MODE` calls one function N times on
 * inputs that move each call (so nothing is hoisted); MODE "count" runs once (for
 * callgrind), "time" prints the best of 7 runs in ns per call. Checks first that the
 * generated and the hand-written function agree (to 1e-12 double, 1e-5 float).
 * SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cases.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    int kernel, hand, f32, c, r;
    long n, i;
    double best = 1e300, sum = 0.0;
    if (argc != 5) {
        fprintf(stderr, "usage: bench KERNEL gen|hand f64|f32 N\n");
        return 2;
    }
    for (kernel = 0; kernel < NKERNELS && strcmp(argv[1], NAMES[kernel]) != 0; ++kernel)
        ;
    hand = strcmp(argv[2], "hand") == 0;
    f32 = strcmp(argv[3], "f32") == 0;
    n = atol(argv[4]);
    c = 2 * kernel + hand;
    {   /* the two functions agree */
        const int j = disagree(kernel);
        if (j) {
            fprintf(stderr, "%s: output %d differs\n", NAMES[kernel], j - 1);
            return 1;
        }
    }
    for (r = 0; r < (strcmp(argv[4], "0") == 0 ? 0 : 7); ++r) {
        double t0 = now();
        double out[16];
        float outf[16];
        for (i = 0; i < n; ++i)
            sum += f32 ? (double)run_f32(c, 1e-7f * (float)i, outf) : run(c, 1e-7 * (double)i, out);
        t0 = now() - t0;
        if (t0 < best)
            best = t0;
    }
    printf("%.3f %g\n", 1e9 * best / (double)n, sum);
    return 0;
}
