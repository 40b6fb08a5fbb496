// Driver of benchmarks/cpp_eigen.py: the C++ layer (rigidsym_c.hpp, rigidsym::eigen::K) of
// six kernels against a hand-written Eigen formula of the same quantity, float and double.
// Every call reads sample i % 256 of a table of inputs drawn once (so nothing is hoisted)
// and adds its outputs into a checksum; the variants are timed in interleaved rounds (thread
// CPU time), the least round kept: `bench N ROUNDS` prints one line per kernel and type:
// "kernel type ns_layer ns_hand ns_hand_behind_a_call". First it checks that the two agree on
// every table sample (relative 1e-9 double, 1e-4 float) and that the layer's status is 0 there.
// SPDX-License-Identifier: MIT
#include <time.h>

#include <cfenv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigidsym_c.hpp"

namespace {

constexpr int kTable = 256;

double now() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

template <class S> struct Inputs {
    using V3 = Eigen::Matrix<S, 3, 1>;
    using M3 = Eigen::Matrix<S, 3, 3>;
    using V6 = Eigen::Matrix<S, 6, 1>;
    V3 e[kTable], a[kTable], b[kTable], w[kTable], wd[kTable], cdd[kTable];
    S phi[kTable], m[kTable];
    M3 Q[kTable], I[kTable];
    V6 t[kTable];
    explicit Inputs(unsigned seed) {
        std::mt19937_64 g(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0), ang(0.05, 3.0);
        for (int i = 0; i < kTable; ++i) {
            Eigen::Vector3d ed(u(g), u(g), u(g));
            ed.normalize();
            const double ph = ang(g);
            e[i] = ed.cast<S>();
            phi[i] = static_cast<S>(ph);
            Q[i] = Eigen::AngleAxisd(ph, ed).toRotationMatrix().cast<S>();
            for (int k = 0; k < 3; ++k) {
                a[i](k) = static_cast<S>(u(g));
                b[i](k) = static_cast<S>(u(g));
                w[i](k) = static_cast<S>(u(g));
                wd[i](k) = static_cast<S>(u(g));
                cdd[i](k) = static_cast<S>(u(g));
            }
            for (int k = 0; k < 6; ++k) t[i](k) = static_cast<S>(u(g));
            Eigen::Matrix3d R = Eigen::Matrix3d::Random();
            I[i] = (R * R.transpose() + Eigen::Matrix3d::Identity()).cast<S>();
            m[i] = static_cast<S>(1.5 + u(g));
        }
    }
};

// ---- the hand-written Eigen formulas ------------------------------------------------------
template <class S> Eigen::Matrix<S, 3, 3> hand_rotation(const Eigen::Matrix<S, 3, 1>& e, S phi) {
    return Eigen::AngleAxis<S>(phi, e).toRotationMatrix();
}
template <class S> struct Invariants { Eigen::Matrix<S, 3, 1> e; S phi; };
template <class S> Invariants<S> hand_invariants(const Eigen::Matrix<S, 3, 3>& Q) {
    const Eigen::AngleAxis<S> aa(Q);
    return {aa.axis(), aa.angle()};
}
template <class S> Eigen::Matrix<S, 3, 1> hand_log(const Eigen::Matrix<S, 3, 3>& Q) {
    const Eigen::AngleAxis<S> aa(Q);
    return aa.angle() * aa.axis();
}
template <class S>
Eigen::Matrix<S, 6, 1> hand_twist(const Eigen::Matrix<S, 6, 1>& t, const Eigen::Matrix<S, 3, 1>& a,
                                  const Eigen::Matrix<S, 3, 1>& p) {
    Eigen::Matrix<S, 6, 1> r;
    const Eigen::Matrix<S, 3, 1> om = t.template head<3>();
    r.template head<3>() = om;
    r.template tail<3>() = t.template tail<3>() + (a - p).cross(om);
    return r;
}
template <class S>
Eigen::Matrix<S, 6, 1> hand_wrench(const Eigen::Matrix<S, 3, 3>& I, S m, const Eigen::Matrix<S, 3, 1>& w,
                                   const Eigen::Matrix<S, 3, 1>& wd, const Eigen::Matrix<S, 3, 1>& cdd) {
    Eigen::Matrix<S, 6, 1> r;
    r.template head<3>() = I * wd + w.cross(I * w);
    r.template tail<3>() = m * cdd;
    return r;
}
template <class S> struct Screw {
    Eigen::Matrix<S, 3, 1> e;
    S phi;
    Eigen::Matrix<S, 3, 1> p0;
    S pitch;
    Eigen::Matrix<S, 6, 1> plucker;
};
template <class S>
Screw<S> hand_screw(const Eigen::Matrix<S, 3, 3>& Q, const Eigen::Matrix<S, 3, 1>& a,
                    const Eigen::Matrix<S, 3, 1>& ap) {
    const Eigen::AngleAxis<S> aa(Q);
    Screw<S> r;
    r.e = aa.axis();
    r.phi = aa.angle();
    const Eigen::Matrix<S, 3, 1> d = ap - a;
    r.pitch = r.e.dot(d) / r.phi;
    // p0 = (Q - 1)^T (Q a - a') / (2 (1 - cos phi))
    r.p0 = (Q - Eigen::Matrix<S, 3, 3>::Identity()).transpose() * (Q * a - ap) /
           (S(2) * (S(1) - std::cos(r.phi)));
    r.plucker.template head<3>() = r.e;
    r.plucker.template tail<3>() = r.p0.cross(r.e);
    return r;
}

// ---- the variants: each returns a value folded into the checksum -------------------------
template <class S, class Out> S fold(const Out& o) { return o.sum(); }

enum Kernel { ROT, INV, LOG, TWIST, WRENCH, SCREW, NK };
const char* const kNames[NK] = {"rotation_from_natural_invariants", "natural_invariants_from_rotation",
                                "rotation_vector_from_rotation", "twist_transfer",
                                "newton_euler_wrench", "screw_of_displacement"};

template <class S> S layer(int k, const Inputs<S>& in, int i, int* status) {
    namespace rs = rigidsym::eigen;
    switch (k) {
    case ROT: { const auto r = rs::rotation_from_natural_invariants(in.e[i], in.phi[i]);
                *status |= static_cast<int>(r.status); return r.Q.sum(); }
    case INV: { const auto r = rs::natural_invariants_from_rotation(in.Q[i]);
                *status |= static_cast<int>(r.status); return r.e.sum() + r.phi; }
    case LOG: { const auto r = rs::rotation_vector_from_rotation(in.Q[i]);
                *status |= static_cast<int>(r.status); return r.w.sum(); }
    case TWIST: { const auto r = rs::twist_transfer(in.t[i], in.a[i], in.b[i]);
                  *status |= static_cast<int>(r.status); return r.t_P.sum(); }
    case WRENCH: { const auto r = rs::newton_euler_wrench(in.I[i], in.m[i], in.w[i], in.wd[i], in.cdd[i]);
                   *status |= static_cast<int>(r.status); return r.w.sum(); }
    default: { const auto r = rs::screw_of_displacement(in.Q[i], in.a[i], in.b[i]);
               *status |= static_cast<int>(r.status);
               return r.e.sum() + r.phi + r.p0.sum() + r.pitch + r.plucker.sum(); }
    }
}

template <class S> S hand(int k, const Inputs<S>& in, int i) {
    switch (k) {
    case ROT: return hand_rotation<S>(in.e[i], in.phi[i]).sum();
    case INV: { const auto r = hand_invariants<S>(in.Q[i]); return r.e.sum() + r.phi; }
    case LOG: return hand_log<S>(in.Q[i]).sum();
    case TWIST: return hand_twist<S>(in.t[i], in.a[i], in.b[i]).sum();
    case WRENCH: return hand_wrench<S>(in.I[i], in.m[i], in.w[i], in.wd[i], in.cdd[i]).sum();
    default: { const auto r = hand_screw<S>(in.Q[i], in.a[i], in.b[i]);
               return r.e.sum() + r.phi + r.p0.sum() + r.pitch + r.plucker.sum(); }
    }
}

// the hand-written formula behind a call it cannot be inlined through, as the layer's C
// function is (a separate object): what the call itself costs, apart from the formula
template <class S, int K> __attribute__((noinline)) S hand_call(const Inputs<S>& in, int i) {
    return hand<S>(K, in, i);
}

// one timed loop per (kernel, variant: 0 the layer, 1 the formula inline, 2 the formula
// behind a call), each its own instantiation so the switch folds away
template <class S, int K, int V> __attribute__((noinline)) S loop(const Inputs<S>& in, long n, int* st) {
    S acc = 0;
    for (long j = 0; j < n; ++j) {
        const int i = static_cast<int>(j & (kTable - 1));
        acc += V == 1 ? hand<S>(K, in, i) : V == 2 ? hand_call<S, K>(in, i) : layer<S>(K, in, i, st);
    }
    return acc;
}

template <class S, int K> bool run(const char* type, const Inputs<S>& in, long n, int rounds, double tol) {
    int st = 0;
    for (int i = 0; i < kTable; ++i) {   // the two agree, and the layer says ok
        int s = 0;
        const S x = layer<S>(K, in, i, &s), y = hand<S>(K, in, i);
        if (s != 0 || !(std::fabs(static_cast<double>(x - y)) <= tol * (1.0 + std::fabs(static_cast<double>(y))))) {
            std::fprintf(stderr, "%s %s sample %d: status %d, layer %.17g hand %.17g\n", kNames[K], type, i,
                         s, static_cast<double>(x), static_cast<double>(y));
            return false;
        }
    }
    double best[3] = {1e300, 1e300, 1e300};
    volatile S sink = 0;
    for (int r = 0; r < rounds; ++r) {
        for (int v = 0; v < 3; ++v) {
            const int which = (v + r) % 3;   // rotate which goes first
            const double t0 = now();
            sink = sink + (which == 1 ? loop<S, K, 1>(in, n, &st)
                           : which == 2 ? loop<S, K, 2>(in, n, &st) : loop<S, K, 0>(in, n, &st));
            const double dt = now() - t0;
            if (dt < best[which]) best[which] = dt;
        }
    }
    std::printf("%s %s %.3f %.3f %.3f\n", kNames[K], type, 1e9 * best[0] / static_cast<double>(n),
                1e9 * best[1] / static_cast<double>(n), 1e9 * best[2] / static_cast<double>(n));
    return st == 0;
}

template <class S> bool all(const char* type, long n, int rounds, double tol) {
    const Inputs<S> in(12345u);
    return run<S, ROT>(type, in, n, rounds, tol) && run<S, INV>(type, in, n, rounds, tol) &&
           run<S, LOG>(type, in, n, rounds, tol) && run<S, TWIST>(type, in, n, rounds, tol) &&
           run<S, WRENCH>(type, in, n, rounds, tol) && run<S, SCREW>(type, in, n, rounds, tol);
}

}  // namespace

int main(int argc, char** argv) {
    const long n = argc > 1 ? std::atol(argv[1]) : 200000;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 11;
    // a third argument "sticky": an underflow flag raised before every call, as a program
    // that never clears its flags has after its first underflow
    // (a product that underflows, in SSE: feraiseexcept may set the x87 word only)
    if (argc > 3 && std::string(argv[3]) == "sticky") {
        volatile double tiny = 1e-300;
        volatile double product = tiny * tiny;
        (void)product;
        if (!std::fetestexcept(FE_UNDERFLOW)) return 2;
    }
    const bool ok = all<double>("double", n, rounds, 1e-9) && all<float>("float", n, rounds, 2e-4);
    return ok ? 0 : 1;
}
