// The C++ example on generated kernels (examples/cpp/README.md): the layer rigidsym_c.hpp
// over the C kernels, with Eigen's default column-major matrices and with std::array.
// SPDX-License-Identifier: MIT
#include <array>
#include <cstdio>

#include <Eigen/Core>

#include "rigidsym_c.hpp"

int main() {
    // A rotation from its natural invariants (axis e, angle phi): an Eigen Matrix3d,
    // column-major as Eigen's default; the layer fills it element by element.
    const Eigen::Vector3d e(0.0, 0.6, 0.8);
    const auto rot = rigidsym::eigen::rotation_from_natural_invariants(e, 0.3);
    if (!rigidsym::ok(rot.status)) return 1;
    const Eigen::Matrix3d Q = rot.Q;

    // ... and back: Q passed as it is (column-major) is read as Q, not as Q^T.
    const auto inv = rigidsym::eigen::natural_invariants_from_rotation(Q);
    std::printf("e %.15g %.15g %.15g phi %.15g\n", inv.e(0), inv.e(1), inv.e(2), inv.phi);

    // A row-major matrix, or a transpose expression, gives the answer of its own values.
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> Qr = Q;
    const auto inv_r = rigidsym::eigen::natural_invariants_from_rotation(Qr);
    const auto inv_t = rigidsym::eigen::natural_invariants_from_rotation(Q.transpose());
    std::printf("row-major e %.15g %.15g %.15g phi %.15g\n", inv_r.e(0), inv_r.e(1),
                inv_r.e(2), inv_r.phi);
    std::printf("transpose e %.15g %.15g %.15g phi %.15g\n", inv_t.e(0), inv_t.e(1),
                inv_t.e(2), inv_t.phi);

    // The twist of a body transferred from A to P (Eigen vectors of sizes 6 and 3).
    Eigen::Matrix<double, 6, 1> t_A;
    t_A << 0.1, -0.2, 0.3, 1.0, 0.5, -0.25;
    const auto tw = rigidsym::eigen::twist_transfer(t_A, Eigen::Vector3d::Zero(),
                                                    Eigen::Vector3d(0.2, 0.1, 0.4));
    std::printf("t_P");
    for (int i = 0; i < 6; ++i) std::printf(" %.15g", tw.t_P(i));
    std::printf("\n");

    // The same kernel in float on std::array (no Eigen needed for these).
    const std::array<float, 3> ef = {0.0f, 0.6f, 0.8f};
    const auto rf = rigidsym::arrays::rotation_from_natural_invariants(ef, 0.3f);
    std::printf("status %d Q01 %.7g\n", static_cast<int>(rf.status),
                static_cast<double>(rf.Q[0][1]));
    return rigidsym::ok(rf.status) ? 0 : 1;
}
