// SymForce 0.12.0's generated C++ (Eigen 3.4) on the inputs of benchmarks/c_scalar/bench.c
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <Eigen/Core>
#include "rotation_from_natural_invariants.h"
#include "twist_transfer.h"
#include "planar_arm_tip_with_jacobians.h"
#include "body_energy.h"

#define NI __attribute__((noinline))
template <typename T> NI void sf_rotation(const T e[3], T phi, T Q[9]) {
  const Eigen::Matrix<T, 3, 1> ev(e[0], e[1], e[2]);
  const Eigen::Matrix<T, 3, 3> R = sym::RotationFromNaturalInvariants<T>(ev, phi);
  for (int i = 0; i < 3; ++i) for (int j = 0; j < 3; ++j) Q[3 * i + j] = R(i, j);
}
template <typename T> NI void sf_twist(const T t[6], const T a[3], const T p[3], T o[6]) {
  Eigen::Matrix<T, 6, 1> tv; for (int i = 0; i < 6; ++i) tv(i) = t[i];
  const Eigen::Matrix<T, 3, 1> av(a[0], a[1], a[2]), pv(p[0], p[1], p[2]);
  const Eigen::Matrix<T, 6, 1> r = sym::TwistTransfer<T>(tv, av, pv);
  for (int i = 0; i < 6; ++i) o[i] = r(i);
}
template <typename T> NI void sf_arm(T q1, T q2, T l1, T l2, T o[10]) {
  Eigen::Matrix<T, 2, 1> a, b, c, d;
  const Eigen::Matrix<T, 2, 1> r = sym::PlanarArmTipWithJacobians<T>(q1, q2, l1, l2, &a, &b, &c, &d);
  o[0] = r(0); o[1] = r(1); o[2] = a(0); o[3] = a(1); o[4] = b(0); o[5] = b(1);
  o[6] = c(0); o[7] = c(1); o[8] = d(0); o[9] = d(1);
}
template <typename T> NI void sf_energy(T m, const T v[3], const T I[9], const T w[3], T *E) {
  const Eigen::Matrix<T, 3, 1> vv(v[0], v[1], v[2]), wv(w[0], w[1], w[2]);
  Eigen::Matrix<T, 3, 3> Im; for (int i = 0; i < 3; ++i) for (int j = 0; j < 3; ++j) Im(i, j) = I[3 * i + j];
  *E = sym::BodyEnergy<T>(m, vv, Im, wv);
}
template <typename T> T run(int c, T x, T *out) {
  const T e[3] = {0, (T)0.6, (T)0.8}, phi = (T)0.3 + x;
  const T t[6] = {(T)0.1, (T)-0.2 + x, (T)0.3, (T)1.0, (T)0.5, (T)-0.25};
  const T a[3] = {0, 0, x}, p[3] = {(T)0.2, (T)0.1 - x, (T)0.4};
  const T I[9] = {(T)0.02, (T)0.001, 0, (T)0.001, (T)0.03, (T)0.002, 0, (T)0.002, (T)0.025};
  const T w[3] = {(T)0.1, (T)-0.2 + x, (T)0.3}, v[3] = {(T)0.3, 0, (T)-0.1 + x};
  int k;
  switch (c) {
  case 0: sf_rotation<T>(e, phi, out); k = 9; break;
  case 1: sf_twist<T>(t, a, p, out); k = 6; break;
  case 2: sf_arm<T>((T)0.4 + x, (T)-0.7, (T)0.35, (T)0.25, out); k = 10; break;
  default: sf_energy<T>((T)1.5, v, I, w, out); k = 1; break;
  }
  T s = 0; while (k--) s += out[k];
  return s;
}
int main(int argc, char **argv) {
  const int c = atoi(argv[1]), f32 = !strcmp(argv[2], "f32"), n = atoi(argv[3]);
  double sum = 0; double od[16]; float of[16];
  for (int i = 0; i < n; ++i) {
    if (f32) sum += run<float>(c, (float)(1e-4 * (i % 100)), of);
    else sum += run<double>(c, 1e-4 * (i % 100), od);
  }
  printf("%g\n", sum);
  return 0;
}
