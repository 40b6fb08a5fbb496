// Driver of benchmarks/log_ranges.py: the rotation log, float64, per call, on three ranges of
// angle: rigidsym's C++ layer (rigidsym::eigen::rotation_vector_from_rotation), gtsam's
// SO3::Logmap (compiled from gtsam/geometry/SO3.cpp, an out-of-line call) and the hand-written
// Eigen log of benchmarks/cpp_eigen/bench.cpp (hand_log), the last behind a call it cannot be
// inlined through and inline; rigidsym's C function itself on a row-major copy of the table
// (no C++ layer), and the layer on that copy as a row-major Eigen matrix (which it passes to
// the C function without copying): what the layer's copy of a column-major Q costs. Each range is a table of kTable rotations Q = exp(phi e): e
// uniform on the sphere, phi uniform on the range; the timed loops walk the table in order.
// `bench N ROUNDS` first checks, on every sample, that rigidsym's status is 0 and that rigidsym
// and hand agree within 1e-9 per component, and rigidsym and gtsam too where gtsam takes its
// general branches (trace + 1 >= 1e-3); where it takes its branch near pi (trace + 1 < 1e-3)
// gtsam sources from before its PR #2723 are first-order accurate there, so that difference
// is reported apart and only bounded by 1e-3 (exit 1 otherwise). Then it times N calls of each
// in ROUNDS interleaved rounds (thread CPU time, the least round kept) and prints one line a
// range: "range ns_rigidsym ns_gtsam ns_hand ns_hand_inline ns_c ns_rigidsym_rowmajor
// maxdiff_gtsam maxdiff_gtsam_nearpi maxdiff_hand n_nearpi_branch".
// SPDX-License-Identifier: MIT
#include <time.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <gtsam/geometry/SO3.h>

#include "rigidsym_c.hpp"

namespace {

constexpr int kTable = 20000;  // 20k rotations, as gtsam's SO3::Logmap timings use
constexpr double kTol = 1e-9;
constexpr double kTolNearPi = 1e-3;  // gtsam's branch near pi before its PR #2723

double now() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Range {
    const char* name;
    double lo, hi;
};
const Range kRanges[] = {{"small", 1e-4, 0.1}, {"uniform", 0.0, M_PI}, {"near_pi", M_PI - 0.1, M_PI}};

struct Table {
    std::vector<Eigen::Matrix3d> Q;
    std::vector<gtsam::SO3> R;
    std::vector<std::array<double, 9>> rm;  // Q row-major, the C function's layout
    std::vector<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> Qr;  // the same, as Eigen
    Table(const Range& r, unsigned seed) : Q(kTable), R(kTable), rm(kTable), Qr(kTable) {
        std::mt19937_64 g(seed);
        std::normal_distribution<double> nd;
        std::uniform_real_distribution<double> ang(r.lo, r.hi);
        for (int i = 0; i < kTable; ++i) {
            Eigen::Vector3d e(nd(g), nd(g), nd(g));
            e.normalize();
            Q[i] = Eigen::AngleAxisd(ang(g), e).toRotationMatrix();
            R[i] = gtsam::SO3(Q[i]);
            for (int k = 0; k < 9; ++k) rm[i][k] = Q[i](k / 3, k % 3);
            Qr[i] = Q[i];
        }
    }
};

// the hand-written log of benchmarks/cpp_eigen/bench.cpp: Eigen's AngleAxis of Q
Eigen::Vector3d hand_log(const Eigen::Matrix3d& Q) {
    const Eigen::AngleAxisd aa(Q);
    return aa.angle() * aa.axis();
}
__attribute__((noinline)) Eigen::Vector3d hand_call(const Eigen::Matrix3d& Q) { return hand_log(Q); }

template <class M> Eigen::Vector3d layer(const M& Q, int* status) {
    const auto r = rigidsym::eigen::rotation_vector_from_rotation(Q);
    *status |= static_cast<int>(r.status);
    return r.w;
}

Eigen::Vector3d c_direct(const std::array<double, 9>& q, int* status) {
    Eigen::Vector3d w;
    *status |= rigidsym_c_rotation_vector_from_rotation(q.data(), w.data());
    return w;
}

// one timed loop per variant: 0 rigidsym, 1 gtsam, 2 hand behind a call, 3 hand inline,
// 4 rigidsym's C function, 5 rigidsym on the row-major matrix
template <int V> __attribute__((noinline)) double loop(const Table& t, long n, int* st) {
    double acc = 0;
    int i = 0;
    for (long j = 0; j < n; ++j) {
        const Eigen::Vector3d w = V == 5   ? layer(t.Qr[i], st)
                                  : V == 4 ? c_direct(t.rm[i], st)
                                  : V == 0 ? layer(t.Q[i], st)
                                  : V == 1 ? gtsam::SO3::Logmap(t.R[i])
                                  : V == 2 ? hand_call(t.Q[i])
                                           : hand_log(t.Q[i]);
        acc += w.sum();
        if (++i == kTable) i = 0;
    }
    return acc;
}

bool run(const Range& r, unsigned seed, long n, int rounds) {
    const Table t(r, seed);
    double dg = 0, dgp = 0, dh = 0;
    int npi = 0;
    for (int i = 0; i < kTable; ++i) {
        int s = 0;
        const Eigen::Vector3d a = layer(t.Q[i], &s), b = gtsam::SO3::Logmap(t.R[i]), c = hand_log(t.Q[i]);
        const double eg = (a - b).cwiseAbs().maxCoeff(), eh = (a - c).cwiseAbs().maxCoeff();
        if (c_direct(t.rm[i], &s) != a || layer(t.Qr[i], &s) != a) s |= 256;  // the same function
        const bool near_pi = t.Q[i].trace() + 1.0 < 1e-3;
        npi += near_pi;
        (near_pi ? dgp : dg) = std::max(near_pi ? dgp : dg, eg);
        dh = std::max(dh, eh);
        if (s != 0 || !(eg <= (near_pi ? kTolNearPi : kTol)) || !(eh <= kTol)) {
            std::fprintf(stderr, "%s sample %d: status %d, |rigidsym - gtsam| %.3g, |rigidsym - hand| %.3g\n",
                         r.name, i, s, eg, eh);
            return false;
        }
    }
    constexpr int kV = 6;
    double best[kV] = {1e300, 1e300, 1e300, 1e300, 1e300, 1e300};
    volatile double sink = 0;
    int st = 0;
    for (int k = 0; k < rounds; ++k) {
        for (int v = 0; v < kV; ++v) {
            const int which = (v + k) % kV;  // rotate which goes first
            const double t0 = now();
            sink = sink + (which == 0   ? loop<0>(t, n, &st)
                           : which == 1 ? loop<1>(t, n, &st)
                           : which == 2 ? loop<2>(t, n, &st)
                           : which == 3 ? loop<3>(t, n, &st)
                           : which == 4 ? loop<4>(t, n, &st)
                                        : loop<5>(t, n, &st));
            const double dt = now() - t0;
            if (dt < best[which]) best[which] = dt;
        }
    }
    const double per = 1e9 / static_cast<double>(n);
    std::printf("%s %.3f %.3f %.3f %.3f %.3f %.3f %.3g %.3g %.3g %d\n", r.name, best[0] * per,
                best[1] * per, best[2] * per, best[3] * per, best[4] * per, best[5] * per, dg, dgp, dh,
                npi);
    return st == 0;
}

}  // namespace

int main(int argc, char** argv) {
    const long n = argc > 1 ? std::atol(argv[1]) : 200000;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 9;
    bool ok = true;
    for (unsigned k = 0; k < 3; ++k) ok = run(kRanges[k], 12345u + k, n, rounds) && ok;
    return ok ? 0 : 1;
}
