"""Where each kernel flags a sample, in units of its input.

A generated kernel flags a sample (``SingularConfigurationError``, or NaN with
``on_singular="nan"``) exactly where a denominator of its generated program is 0 in floating
point, and reports a non-finite output (``NonFiniteResultError``) where an output overflows.
The denominators were read from the generated programs (``generated/numpy/<name>.py``,
``_dens``); this table says what they mean for the input.
"""

from __future__ import annotations

_SIN_HALF = ("sin(phi/2) == 0 in floating point: phi == 0 exactly (and abs(phi) < 1e-323); "
             "an output overflows (non-finite) where the result exceeds the type, about "
             "abs(phi) < 1e-300 x norm(input) in float64")
_SQ = ("{q} == 0 in floating point: {what}; a square underflows to 0 only for "
       "{x} < 1.5e-162 (float64), < 1e-19 (float32 arithmetic), which "
       "benchmarks/accuracy.py calls below the smallest useful step")

BASE = {
    "N_matrix": _SIN_HALF,
    "N_matrix_dot": _SIN_HALF,
    "N_tilde_dot": _SIN_HALF,
    "screw_axis_point": _SIN_HALF,
    "L_tilde": ("cos(phi/2) == 0 in floating point, never for a float phi (cos(fl(pi)/2) = "
                "6e-17): at phi = fl(pi) the outputs are finite, about 1e16, as exact"),
    "L_tilde_dot": ("cos(phi/2) == 0 in floating point, never for a float phi: finite at "
                    "phi = fl(pi)"),
    "instant_screw_axis": _SQ.format(q="||omega||^2", what="omega == 0", x="||omega||"),
    "natural_invariants_from_rotation": (
        "||vect(Q)||^2 == 0 with tr Q >= 0 (the main build): Q exactly symmetric in "
        "floating point, i.e. phi = 0 (Q = 1), or abs(phi) below the rounding of Q (about 1e-16)"),
    "screw_of_displacement": (
        "||Q - Q^T||^2 == 0 with tr Q >= 0 (the main build, after the rewrite of 1 - cos phi "
        "from the skew part of Q): Q exactly symmetric in floating point, phi below the "
        "rounding of Q (about 1e-16 in float64, 6e-8 in float32); before the rewrite "
        "3 - tr Q == 0 flagged up to phi ~ 1.5e-8"),
    "plucker_from_points": _SQ.format(q="||p2 - p1||^2", what="p1 == p2",
                                      x="||p2 - p1||"),
    "wrench_axis": _SQ.format(q="||f||^2", what="f == 0", x="||f||"),
}


def _euler(name: str) -> str:
    seq = name.split("_")[-2]
    if seq[0] == seq[2]:
        return ("sin(angles[1]) == 0 in floating point: the middle angle exactly 0 "
                "(sin(fl(pi)) = 1.2e-16, finite there)")
    return ("cos(angles[1]) == 0 in floating point: never for a float angle "
            "(cos(fl(pi/2)) = 6e-17): outputs about 1e16 there, as exact")


def thresholds() -> dict[str, str]:
    """``{kernel name: threshold}`` for every kernel with a singular set (Jacobian kernels
    and Euler-angle variants included)."""
    from rigidsym.kernels.runtime import state as _state

    out = {}
    for name, m in _state.meta().items():
        if not m["singular"]:
            continue
        base = name.removesuffix("_with_jacobians")
        if base.startswith("euler_angle_rates_"):
            out[name] = _euler(base)
        elif base in BASE:
            extra = ("; the Jacobians divide by a higher power of the same quantity"
                     if name != base else "")
            out[name] = BASE[base] + extra
    return out
