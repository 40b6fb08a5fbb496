/* The control loop of main.c on the float-only functions (_f32), for an MCU whose FPU has
 * no double (Cortex-M4F): float data, float literals, no double operation anywhere, so that
 * the linked program references no __aeabi_d* helper and no double libm function
 * (tests/test_c_target.py checks both with arm-none-eabi-gcc). Built with
 * -DRIGIDSYM_EXAMPLE_PRINT on a host it prints the outputs (as doubles, for the test).
 * C99 and C++. SPDX-License-Identifier: MIT */
#include <math.h>

#include "rigidsym_c.h"

#if defined(RIGIDSYM_EXAMPLE_PRINT)
#include <stdio.h>
static void print(const char *name, int tick, const float *v, int n)
{
    int i;
    printf("%s %d", name, tick);
    for (i = 0; i < n; ++i)
        printf(" %.9g", (double)v[i]);
    printf("\n");
}
#else
/* on the MCU the outputs go to the actuators; here, to a volatile sink */
static volatile float sink;
static void print(const char *name, int tick, const float *v, int n)
{
    int i;
    (void)name;
    (void)tick;
    for (i = 0; i < n; ++i)
        sink = v[i];
}
#endif

int main(void)
{
    int tick, bad = 0;
    for (tick = 0; tick < 8; ++tick) {
        const float t = 0.01f * (float)tick;
        const float e[3] = {0.0f, 0.6f, 0.8f};
        const float phi = 0.3f + t;
        float Q[9];
        const float t_A[6] = {0.1f, -0.2f + t, 0.3f, 1.0f, 0.5f, -0.25f};
        const float a[3] = {0.0f, 0.0f, 0.0f};
        const float p[3] = {0.2f, 0.1f - t, 0.4f};
        float t_P[6];
        const float I_C[9] = {0.02f, 0.001f, 0.0f, 0.001f, 0.03f, 0.002f, 0.0f, 0.002f, 0.025f};
        const float m = 1.5f;
        const float omega[3] = {0.1f, -0.2f + t, 0.3f};
        const float omega_dot[3] = {0.0f, 0.5f, -t};
        const float c_ddot[3] = {0.0f, 0.0f, -9.81f + t};
        float w[6];
        const float s = sinf(0.5f * phi);
        const float q[4] = {cosf(0.5f * phi), 0.0f, 0.6f * s, 0.8f * s};
        float Qq[9];
        const float q1 = 0.4f + t, q2 = -0.7f + 2.0f * t, l1 = 0.35f, l2 = 0.25f;
        float tip[2], tip_D_q1[2], tip_D_q2[2], tip_D_l1[2], tip_D_l2[2];
        const float v[3] = {0.3f, 0.0f, -0.1f + t};
        float T;

        bad |= rigidsym_c_rotation_from_natural_invariants_f32(e, phi, Q);
        bad |= rigidsym_c_twist_transfer_f32(t_A, a, p, t_P);
        bad |= rigidsym_c_newton_euler_wrench_f32(I_C, m, omega, omega_dot, c_ddot, w);
        bad |= rigidsym_c_quaternion_rotation_f32(q, Qq);
        bad |= rigidsym_c_planar_arm_tip_with_jacobians_f32(q1, q2, l1, l2, tip, tip_D_q1,
                                                            tip_D_q2, tip_D_l1, tip_D_l2);
        bad |= rigidsym_c_body_energy_f32(m, v, I_C, omega, &T);
        print("Q", tick, Q, 9);
        print("t_P", tick, t_P, 6);
        print("w", tick, w, 6);
        print("Qq", tick, Qq, 9);
        print("tip", tick, tip, 2);
        print("tip_D_q1", tick, tip_D_q1, 2);
        print("tip_D_q2", tick, tip_D_q2, 2);
        print("T", tick, &T, 1);
    }
    return bad ? 1 : 0;
}
