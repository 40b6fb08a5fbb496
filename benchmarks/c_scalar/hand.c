/* Hand-written C of the benchmarked kernels (benchmarks/c_scalar.py): what a firmware
 * engineer writes from the formula, in double and in float. SPDX-License-Identifier: MIT */
#include <math.h>

#define HAND(T, S, SIN, COS)                                                                 \
void hand_rotation##S(const T e[3], T phi, T Q[9])                                           \
{                                                                                            \
    const T c = COS(phi), s = SIN(phi), v = (T)1 - c;                                        \
    Q[0] = c + e[0] * e[0] * v; Q[1] = e[0] * e[1] * v - e[2] * s;                           \
    Q[2] = e[0] * e[2] * v + e[1] * s;                                                       \
    Q[3] = e[0] * e[1] * v + e[2] * s; Q[4] = c + e[1] * e[1] * v;                           \
    Q[5] = e[1] * e[2] * v - e[0] * s;                                                       \
    Q[6] = e[0] * e[2] * v - e[1] * s; Q[7] = e[1] * e[2] * v + e[0] * s;                    \
    Q[8] = c + e[2] * e[2] * v;                                                              \
}                                                                                            \
void hand_twist##S(const T t[6], const T a[3], const T p[3], T out[6])                       \
{   /* v_P = v_A + (a - p) x omega */                                                        \
    const T d0 = a[0] - p[0], d1 = a[1] - p[1], d2 = a[2] - p[2];                            \
    out[0] = t[0]; out[1] = t[1]; out[2] = t[2];                                             \
    out[3] = t[3] + d1 * t[2] - d2 * t[1];                                                   \
    out[4] = t[4] + d2 * t[0] - d0 * t[2];                                                   \
    out[5] = t[5] + d0 * t[1] - d1 * t[0];                                                   \
}                                                                                            \
void hand_wrench_transfer##S(const T w[6], const T a[3], const T p[3], T out[6])              \
{   /* n_P = n_A + (a - p) x f, f_P = f_A */                                                 \
    const T d0 = a[0] - p[0], d1 = a[1] - p[1], d2 = a[2] - p[2];                            \
    out[0] = w[0] + d1 * w[5] - d2 * w[4];                                                   \
    out[1] = w[1] + d2 * w[3] - d0 * w[5];                                                   \
    out[2] = w[2] + d0 * w[4] - d1 * w[3];                                                   \
    out[3] = w[3]; out[4] = w[4]; out[5] = w[5];                                             \
}                                                                                            \
void hand_wrench##S(const T I[9], T m, const T w[3], const T wd[3], const T cdd[3], T out[6]) \
{   /* n = I wd + w x I w, f = m cdd */                                                      \
    const T h0 = I[0] * w[0] + I[1] * w[1] + I[2] * w[2];                                    \
    const T h1 = I[3] * w[0] + I[4] * w[1] + I[5] * w[2];                                    \
    const T h2 = I[6] * w[0] + I[7] * w[1] + I[8] * w[2];                                    \
    out[0] = I[0] * wd[0] + I[1] * wd[1] + I[2] * wd[2] + w[1] * h2 - w[2] * h1;             \
    out[1] = I[3] * wd[0] + I[4] * wd[1] + I[5] * wd[2] + w[2] * h0 - w[0] * h2;             \
    out[2] = I[6] * wd[0] + I[7] * wd[1] + I[8] * wd[2] + w[0] * h1 - w[1] * h0;             \
    out[3] = m * cdd[0]; out[4] = m * cdd[1]; out[5] = m * cdd[2];                           \
}                                                                                            \
void hand_quat##S(const T q[4], T Q[9])                                                      \
{                                                                                            \
    const T w = q[0], x = q[1], y = q[2], z = q[3];                                          \
    Q[0] = 1 - 2 * (y * y + z * z); Q[1] = 2 * (x * y - w * z); Q[2] = 2 * (x * z + w * y);  \
    Q[3] = 2 * (x * y + w * z); Q[4] = 1 - 2 * (x * x + z * z); Q[5] = 2 * (y * z - w * x);  \
    Q[6] = 2 * (x * z - w * y); Q[7] = 2 * (y * z + w * x); Q[8] = 1 - 2 * (x * x + y * y);  \
}                                                                                            \
void hand_arm##S(T q1, T q2, T l1, T l2, T p[2], T p_q1[2], T p_q2[2], T p_l1[2],         \
                 T p_l2[2])                                                                  \
{   /* tip and its derivatives by q1, q2, l1, l2 (as the generated twin) */                  \
    const T c1 = COS(q1), s1 = SIN(q1), c12 = COS(q1 + q2), s12 = SIN(q1 + q2);              \
    p[0] = l1 * c1 + l2 * c12; p[1] = l1 * s1 + l2 * s12;                                    \
    p_q1[0] = -l1 * s1 - l2 * s12; p_q1[1] = l1 * c1 + l2 * c12;                             \
    p_q2[0] = -l2 * s12; p_q2[1] = l2 * c12;                                                 \
    p_l1[0] = c1; p_l1[1] = s1; p_l2[0] = c12; p_l2[1] = s12;                                \
}                                                                                            \
void hand_energy##S(T m, const T v[3], const T I[9], const T w[3], T *E)                    \
{                                                                                            \
    const T h0 = I[0] * w[0] + I[1] * w[1] + I[2] * w[2];                                    \
    const T h1 = I[3] * w[0] + I[4] * w[1] + I[5] * w[2];                                    \
    const T h2 = I[6] * w[0] + I[7] * w[1] + I[8] * w[2];                                    \
    *E = (T)0.5 * (m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2])                             \
                   + w[0] * h0 + w[1] * h1 + w[2] * h2);                                     \
}

HAND(double, , sin, cos)
HAND(float, _f32, sinf, cosf)
