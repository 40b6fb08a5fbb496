/* A control loop on the generated C (examples/c/README.md): per tick, the attitude of a
 * body from its axis-angle and from its quaternion, the twist of a tool point, the
 * Newton-Euler wrench and the kinetic energy of the body, and a planar arm's tip with its
 * Jacobian. Prints every output (%.17g) so that tests/test_c_target.py compares them with
 * the NumPy kernels; exits 1 when a call returns a nonzero status.
 * C99 and C++ (the headers carry extern "C"). SPDX-License-Identifier: MIT */
#include <math.h>
#include <stdio.h>

#include "rigidsym_c.h"

static void print(const char *name, int tick, const double *v, int n)
{
    int i;
    printf("%s %d", name, tick);
    for (i = 0; i < n; ++i)
        printf(" %.17g", v[i]);
    printf("\n");
}

int main(void)
{
    int tick, bad = 0;
    for (tick = 0; tick < 8; ++tick) {
        const double t = 0.01 * tick;
        /* book kernels: eq. (2.49), (3.83), (3.134)/(3.139) */
        const double e[3] = {0.0, 0.6, 0.8};
        const double phi = 0.3 + t;
        double Q[9];
        const double t_A[6] = {0.1, -0.2 + t, 0.3, 1.0, 0.5, -0.25};
        const double a[3] = {0.0, 0.0, 0.0};
        const double p[3] = {0.2, 0.1 - t, 0.4};
        double t_P[6];
        const double I_C[9] = {0.02, 0.001, 0.0, 0.001, 0.03, 0.002, 0.0, 0.002, 0.025};
        const double m = 1.5;
        const double omega[3] = {0.1, -0.2 + t, 0.3};
        const double omega_dot[3] = {0.0, 0.5, -t};
        const double c_ddot[3] = {0.0, 0.0, -9.81 + t};
        double w[6];
        /* the user module (my_kernels.py) */
        const double s = sin(0.5 * phi);
        const double q[4] = {cos(0.5 * phi), 0.0, 0.6 * s, 0.8 * s};
        double Qq[9];
        const double q1 = 0.4 + t, q2 = -0.7 + 2.0 * t, l1 = 0.35, l2 = 0.25;
        double tip[2], tip_D_q1[2], tip_D_q2[2], tip_D_l1[2], tip_D_l2[2];
        const double v[3] = {0.3, 0.0, -0.1 + t};
        double T;

        bad |= rigidsym_c_rotation_from_natural_invariants(e, phi, Q);
        bad |= rigidsym_c_twist_transfer(t_A, a, p, t_P);
        bad |= rigidsym_c_newton_euler_wrench(I_C, m, omega, omega_dot, c_ddot, w);
        bad |= rigidsym_c_quaternion_rotation(q, Qq);
        bad |= rigidsym_c_planar_arm_tip_with_jacobians(q1, q2, l1, l2, tip, tip_D_q1,
                                                        tip_D_q2, tip_D_l1, tip_D_l2);
        bad |= rigidsym_c_body_energy(m, v, I_C, omega, &T);
        print("Q", tick, Q, 9);
        print("t_P", tick, t_P, 6);
        print("w", tick, w, 6);
        print("Qq", tick, Qq, 9);
        print("tip", tick, tip, 2);
        print("tip_D_q1", tick, tip_D_q1, 2);
        print("tip_D_q2", tick, tip_D_q2, 2);
        print("T", tick, &T, 1);
    }
    if (bad)
        fprintf(stderr, "a kernel returned status %d\n", bad);
    return bad ? 1 : 0;
}
