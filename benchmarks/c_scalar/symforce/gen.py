"""SymForce's generated C++ for four kernels of examples/c (the peer of benchmarks/c_scalar.py).

Run in a virtual environment of its own (SymForce pins its own sympy):

    python3 -m venv /tmp/sf && /tmp/sf/bin/pip install symforce==0.12.0
    /tmp/sf/bin/python benchmarks/c_scalar/symforce/gen.py OUT
    g++ -std=c++14 -O2 -I /usr/include/eigen3 -I OUT benchmarks/c_scalar/symforce/bench.cpp \
        -o sfbench
    valgrind --tool=callgrind ./sfbench CASE f64|f32 1000     # CASE 0..3, see bench.cpp

The formulas are the ones of benchmarks/c_scalar/hand.c, written as SymForce symbolic
functions; ``Codegen.function(...).generate_function`` prints them as C++14 templates on
Eigen (the planar arm with the Jacobians of all four arguments, ``with_jacobians``).
"""

import sys

import symforce

symforce.set_epsilon_to_symbol()

import symforce.symbolic as sf  # noqa: E402
from symforce import typing as T  # noqa: E402
from symforce.codegen import Codegen, CppConfig  # noqa: E402


def planar_arm_tip(q1: T.Scalar, q2: T.Scalar, l1: T.Scalar, l2: T.Scalar) -> sf.V2:
    return sf.V2(l1 * sf.cos(q1) + l2 * sf.cos(q1 + q2),
                 l1 * sf.sin(q1) + l2 * sf.sin(q1 + q2))


def twist_transfer(t_A: sf.V6, a: sf.V3, p: sf.V3) -> sf.V6:
    w = sf.V3(t_A[0], t_A[1], t_A[2])
    v = sf.V3(t_A[3], t_A[4], t_A[5])
    vp = v + (a - p).cross(w)
    return sf.V6(w[0], w[1], w[2], vp[0], vp[1], vp[2])


def body_energy(m: T.Scalar, v: sf.V3, inertia: sf.M33, omega: sf.V3) -> T.Scalar:
    return (m * v.dot(v) + omega.dot(inertia * omega)) / 2


def rotation_from_natural_invariants(e: sf.V3, phi: T.Scalar) -> sf.M33:
    c, s = sf.cos(phi), sf.sin(phi)
    E = sf.M33([[0, -e[2], e[1]], [e[2], 0, -e[0]], [-e[1], e[0], 0]])
    return e * e.T + c * (sf.M33.eye() - e * e.T) + s * E


def main(out: str) -> None:
    for f in (planar_arm_tip, twist_transfer, body_energy, rotation_from_natural_invariants):
        Codegen.function(func=f, config=CppConfig()).generate_function(
            output_dir=out, skip_directory_nesting=True)
    Codegen.function(func=planar_arm_tip, config=CppConfig()).with_jacobians(
        which_args=["q1", "q2", "l1", "l2"], include_results=True).generate_function(
        output_dir=out, skip_directory_nesting=True)


if __name__ == "__main__":
    main(sys.argv[1])
