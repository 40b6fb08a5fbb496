/* Driver of benchmarks/c_scalar_arm.py: `arm_main KERNEL gen|hand f64|f32 N` under qemu's
 * Linux user mode calls one function N times (the cases of cases.h), after checking that the
 * generated and the hand-written function agree (exit status 1 if not). Built with a C
 * library's start-up (arm-linux-gnueabihf, aarch64-linux-gnu) or, with -DBARE, for a
 * Cortex-M4F with newlib and no start-up files: then _start below takes argc and argv from
 * the stack qemu sets up and leaves by the Linux exit call. Nothing is printed: the script
 * counts the instructions qemu traces inside the called function and its callees.
 * SPDX-License-Identifier: MIT */
#include "cases.h"

static volatile double sink;
static volatile float sinkf;

static int atoi_(const char *s)
{
    int n = 0;
    while (*s >= '0' && *s <= '9')
        n = 10 * n + (*s++ - '0');
    return n;
}

static int same(const char *a, const char *b)
{
    while (*a && *a == *b)
        ++a, ++b;
    return *a == *b;
}

int start_c(int argc, char **argv);

int start_c(int argc, char **argv)
{
    int kernel, c, f32;
    long i, n;
    double out[16];
    float outf[16];
    if (argc != 5)
        return 2;
    for (kernel = 0; kernel < NKERNELS && !same(argv[1], NAMES[kernel]); ++kernel)
        ;
    if (kernel == 6)
        return 2;
    if (disagree(kernel))
        return 1;
    c = 2 * kernel + same(argv[2], "hand");
    f32 = same(argv[3], "f32");
    n = atoi_(argv[4]);
    if (f32)   /* no double operation in the loop: a Cortex-M4F would call helpers for it */
        for (i = 0; i < n; ++i)
            sinkf += run_f32(c, 1e-7f * (float)i, outf);
    else
        for (i = 0; i < n; ++i)
            sink += run(c, 1e-7 * (double)i, out);
    return 0;
}

#ifdef BARE
__attribute__((naked, noreturn)) void _start(void);

__attribute__((naked, noreturn)) void _start(void)
{   /* r0 = argc, r1 = argv; the exit status start_c returns is r0 of the exit call (r7 = 1) */
    __asm__ volatile("ldr r0, [sp]\n\tadd r1, sp, #4\n\tbl start_c\n\tmovs r7, #1\n\t"
                     "svc #0\n\tb .\n");
}
#else
int main(int argc, char **argv)
{
    return start_c(argc, argv);
}
#endif
