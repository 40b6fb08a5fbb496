/* The cases of the scalar benchmarks (benchmarks/c_scalar.py on x86-64, c_scalar_arm.py on
 * Arm under qemu): the declarations of the hand-written functions (hand.c) and run(), one
 * call of case c (0..13: seven kernels x generated/hand) on inputs that move with x.
 * SPDX-License-Identifier: MIT */
#ifndef C_SCALAR_CASES_H
#define C_SCALAR_CASES_H
#include <math.h>

#include "rigidsym_c.h"

#define DECL(T, S)                                                                           \
void hand_rotation##S(const T e[3], T phi, T Q[9]);                                          \
void hand_twist##S(const T t[6], const T a[3], const T p[3], T out[6]);                      \
void hand_wrench_transfer##S(const T w[6], const T a[3], const T p[3], T out[6]);            \
void hand_wrench##S(const T I[9], T m, const T w[3], const T wd[3], const T cdd[3], T out[6]); \
void hand_quat##S(const T q[4], T Q[9]);                                                     \
void hand_arm##S(T q1, T q2, T l1, T l2, T p[2], T a[2], T b[2], T c[2], T d[2]);            \
void hand_energy##S(T m, const T v[3], const T I[9], const T w[3], T *E);
DECL(double, )
DECL(float, _f32)

/* one call of case c (0..13: seven kernels x generated/hand) at input offset x; returns a
 * checksum of its outputs */
#define CASES(T, S)                                                                          \
static T run##S(int c, T x, T *out)                                                          \
{                                                                                            \
    const T e[3] = {(T)0.0, (T)0.6, (T)0.8}, phi = (T)0.3 + x;                               \
    const T t[6] = {(T)0.1, (T)-0.2 + x, (T)0.3, (T)1.0, (T)0.5, (T)-0.25};                  \
    const T a[3] = {(T)0.0, (T)0.0, x}, p[3] = {(T)0.2, (T)0.1 - x, (T)0.4};                 \
    const T I[9] = {(T)0.02, (T)0.001, 0, (T)0.001, (T)0.03, (T)0.002, 0, (T)0.002, (T)0.025}; \
    const T w[3] = {(T)0.1, (T)-0.2 + x, (T)0.3}, wd[3] = {0, (T)0.5, -x};                   \
    const T cdd[3] = {0, 0, (T)-9.81 + x}, v[3] = {(T)0.3, 0, (T)-0.1 + x};                  \
    const T q[4] = {(T)0.8, (T)0.0 + x, (T)0.36, (T)0.48};                                   \
    T sum = 0;                                                                               \
    int k;                                                                                   \
    switch (c) {                                                                             \
    case 0: rigidsym_c_rotation_from_natural_invariants##S(e, phi, out); k = 9; break;       \
    case 1: hand_rotation##S(e, phi, out); k = 9; break;                                     \
    case 2: rigidsym_c_twist_transfer##S(t, a, p, out); k = 6; break;                        \
    case 3: hand_twist##S(t, a, p, out); k = 6; break;                                       \
    case 4: rigidsym_c_newton_euler_wrench##S(I, (T)1.5, w, wd, cdd, out); k = 6; break;     \
    case 5: hand_wrench##S(I, (T)1.5, w, wd, cdd, out); k = 6; break;                        \
    case 6: rigidsym_c_quaternion_rotation##S(q, out); k = 9; break;                         \
    case 7: hand_quat##S(q, out); k = 9; break;                                              \
    case 8: rigidsym_c_planar_arm_tip_with_jacobians##S((T)0.4 + x, (T)-0.7, (T)0.35,        \
            (T)0.25, out, out + 2, out + 4, out + 6, out + 8); k = 10; break;                \
    case 9: hand_arm##S((T)0.4 + x, (T)-0.7, (T)0.35, (T)0.25, out, out + 2, out + 4,        \
            out + 6, out + 8); k = 10; break;                                                \
    case 10: rigidsym_c_body_energy##S((T)1.5, v, I, w, out); k = 1; break;                  \
    case 11: hand_energy##S((T)1.5, v, I, w, out); k = 1; break;                             \
    case 12: rigidsym_c_wrench_transfer##S(t, a, p, out); k = 6; break;                      \
    default: hand_wrench_transfer##S(t, a, p, out); k = 6; break;                            \
    }                                                                                        \
    while (k--)                                                                              \
        sum += out[k];                                                                       \
    return sum;                                                                              \
}
CASES(double, )
CASES(float, _f32)

static const char *NAMES[] = {"rotation_from_natural_invariants", "twist_transfer",
    "newton_euler_wrench", "quaternion_rotation", "planar_arm_tip_with_jacobians",
    "body_energy", "wrench_transfer"};
/* the number of kernels, and each one's outputs */
#define NKERNELS 7
static const int NOUT[NKERNELS] = {9, 6, 6, 9, 10, 1, 6};


/* 0 where the generated and the hand-written function of a kernel agree (to 1e-12 in
 * double, 1e-5 in float) at one input, else 1 + the first output that differs */
static int disagree(int kernel)
{
    double gd[16], hd[16];
    float gf[16], hf[16];
    int j;
    run(2 * kernel, 0.01, gd);
    run(2 * kernel + 1, 0.01, hd);
    run_f32(2 * kernel, 0.01f, gf);
    run_f32(2 * kernel + 1, 0.01f, hf);
    for (j = 0; j < NOUT[kernel]; ++j)
        if (fabs(gd[j] - hd[j]) > 1e-12 || fabsf(gf[j] - hf[j]) > 1e-5f)
            return j + 1;
    return 0;
}

#endif
