"""Exercise 3.10: angular velocity from Euler-angle rates, ``omega = W eta_dot``.

All twelve intrinsic sequences (six proper-Euler, six Tait-Bryan), with omega in the fixed
frame and in the body frame; det W, its singular set (solved by sympy) and W^-1.
"""

from __future__ import annotations

import functools

import sympy as sp

from rigidsym.course.worked import Param, Solution, identity_check, truth_check
from rigidsym.declare import TIME, angle, cpm, rotation_from_natural_invariants, vect

ID = "ex3.10"
TITLE = "Euler-angle rates and the angular velocity"
STATEMENT = ("\"find the matrix W such that omega = W eta_dot ... Find under which conditions "
             "W becomes singular.\"")
CITATION = "Angeles, Fundamentals of Robotic Mechanical Systems, Sec. 3.9, Exercise 3.10"
#: the documented unit of each answer with one (graded answers may be written in any
#: compatible unit); the others are pure numbers or mixed
ANSWER_UNITS = {"eta_dot": "rad/s"}
FIGURE_NAME = "condition"
PROPER_EULER = ["ZXZ", "XYX", "YZY", "ZYZ", "XZX", "YXY"]
TAIT_BRYAN = ["XYZ", "YZX", "ZXY", "XZY", "ZYX", "YXZ"]
SEQUENCES = PROPER_EULER + TAIT_BRYAN
#: the sequence taken for the book's Exercise 2.19 (see ``solve``'s assumptions).
BOOK_SEQUENCE = "ZXZ"
PARAMETERS = (Param("sequence", BOOK_SEQUENCE, None, "the intrinsic Euler-angle sequence "
                    "whose W is derived step by step (all twelve are tabulated)",
                    choices=tuple(SEQUENCES)),
              Param("theta", None, (), "first Euler angle, to evaluate W at (not given: "
                    "symbolic)", "rad"),
              Param("phi", None, (), "middle Euler angle (not given: symbolic)", "rad"),
              Param("psi", None, (), "third Euler angle (not given: symbolic)", "rad"),
              Param("omega", None, (3,), "angular velocity, fixed frame, to solve "
                    "eta_dot = W^-1 omega (not given: none)", "rad/s"))
VARIANTS = (
    ("a Tait-Bryan sequence (roll, pitch, yaw)", {"sequence": "XYZ"}),
    ("W, det W and the Euler-angle rates at given angles",
     {"theta": "pi/6", "phi": "pi/4", "psi": "0", "omega": [0, 0, 1]}),
)
DATA_NOTE = ("the Euler-angle convention; the angles stay symbolic (theta, phi, psi) unless "
             "given, and then W, det W and eta_dot = W^-1 omega are evaluated there")

theta, phi, psi = sp.symbols("theta phi psi", real=True)
ETA = sp.Matrix([theta, phi, psi])
_AXES = {"X": sp.Matrix([1, 0, 0]), "Y": sp.Matrix([0, 1, 0]), "Z": sp.Matrix([0, 0, 1])}


def axis_rotation(axis: str, a) -> sp.Matrix:
    """Rotation through ``a`` about the coordinate axis ``axis`` (Eq. 2.49 with e = axis)."""
    return rotation_from_natural_invariants(_AXES[axis], a)


def euler_rotation(seq: str, eta=ETA) -> sp.Matrix:
    """Intrinsic sequence: ``Q = R_a(theta) R_b(phi) R_c(psi)`` (each about the moved axis)."""
    a, b, c = seq
    return axis_rotation(a, eta[0]) * axis_rotation(b, eta[1]) * axis_rotation(c, eta[2])


def euler_rate_matrix(seq: str, frame: str = "fixed") -> sp.Matrix:
    """``W`` with ``omega = W eta_dot`` for the intrinsic sequence ``seq``.

    Fixed frame: ``W = [u_a, R_a u_b, R_a R_b u_c]`` (each rate contributes the current
    direction of its axis). Body frame: ``W_B = Q^T W = [R_c^T R_b^T u_a, R_c^T u_b, u_c]``.
    """
    a, b, c = seq
    Ra, Rb, Rc = (axis_rotation(x, v) for x, v in zip(seq, ETA, strict=True))
    if frame == "fixed":
        cols = [_AXES[a], Ra * _AXES[b], Ra * Rb * _AXES[c]]
    else:
        cols = [Rc.T * Rb.T * _AXES[a], Rc.T * _AXES[b], _AXES[c]]
    return sp.Matrix.hstack(*cols).applyfunc(sp.trigsimp)


def singular_set(det) -> sp.Set:
    """Real solutions of ``det W = 0`` for the middle angle, by ``sympy.solveset``."""
    return sp.solveset(det, phi, domain=sp.Interval.Ropen(-sp.pi, sp.pi))


def condition_number(seq: str, phi_value: float) -> float:
    """2-norm condition number of W at middle angle ``phi_value`` (independent of the others)."""
    import numpy as np
    f = sp.lambdify((theta, phi, psi), euler_rate_matrix(seq), "numpy")
    return float(np.linalg.cond(np.array(f(0.3, phi_value, -0.7), dtype=float)))


@functools.cache
def table() -> list[tuple]:
    """Rows (sequence, class, det W (fixed), det W (body), singular set of phi); computed
    once (the angles given by a student do not change it)."""
    rows = []
    for seq in SEQUENCES:
        Wf, Wb = euler_rate_matrix(seq), euler_rate_matrix(seq, "body")
        df, db = sp.trigsimp(Wf.det()), sp.trigsimp(Wb.det())
        rows.append((seq, "proper Euler" if seq in PROPER_EULER else "Tait-Bryan", df, db,
                     singular_set(df)))
    return rows


def condition_curve(seq: str, xs) -> list[float]:
    """cond_2(W) of ``seq`` at the middle angles ``xs`` (capped at 1e4 near the singular set)."""
    import numpy as np
    f = sp.lambdify((theta, phi, psi), euler_rate_matrix(seq), "numpy")
    out = []
    for x in xs:
        try:
            out.append(min(float(np.linalg.cond(np.array(f(0.3, float(x), -0.7),
                                                          dtype=float))), 1e4))
        except np.linalg.LinAlgError:
            out.append(1e4)
    return out


def figure(s: Solution):
    """cond_2(W) against the middle angle: the solution's sequence and a sequence of the
    other class (the conditioning is the same within each class)."""
    import numpy as np
    from matplotlib.figure import Figure

    seq = s.given["sequence"]
    other = "XYZ" if seq in PROPER_EULER else "ZXZ"
    xs = np.linspace(-np.pi, np.pi, 721)
    fig = Figure(figsize=(7, 4))
    ax = fig.add_subplot()
    for q in (seq, other):
        cls = "proper Euler" if q in PROPER_EULER else "Tait-Bryan"
        label = (f"{q} ({cls}, this solution)" if q == seq
                 else f"{q} ({cls}: all six alike)")
        ax.semilogy(xs, condition_curve(q, xs), label=label)
    ax.set_xlabel("middle angle phi [rad]")
    ax.set_ylabel("cond_2(W)")
    ax.set_title("Exercise 3.10: conditioning of the Euler-angle rate matrix W")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    return fig


def solve(sequence: str = BOOK_SEQUENCE, theta=None, phi=None, psi=None,
          omega=None) -> Solution:
    """Worked solution of Exercise 3.10, step by step for ``sequence`` (e.g. ``"ZXZ"``).

    Long: a worked solution is read top to bottom as the book's steps (statement, steps,
    answers, checks); split into functions it would no longer read as one solution.
    """
    seq = sequence
    at = {k: v for k, v in (("theta", theta), ("phi", phi), ("psi", psi)) if v is not None}
    return _solve(seq, at, None if omega is None else sp.Matrix(omega))


def _solve(seq: str, at: dict, omega) -> Solution:
    """:func:`solve` with the angles given (by name) and omega (or None)."""
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"eta": ETA, "sequence": seq, "sequences": ", ".join(SEQUENCES)},
        assumptions=[
            "Exercise 2.19 of the book (chapter 2) fixes the Euler angles; they are taken as the "
            "intrinsic Z-X-Z sequence Q = R_Z(theta) R_X(phi) R_Z(psi), the classical "
            "(Goldstein) convention and the one whose singularity the book's remark about "
            "non-invertible W describes; all twelve sequences are solved as well.",
            "Intrinsic rotations: each about an axis of the frame moved by the previous ones.",
            "omega in fixed-frame components unless labelled body frame (omega_B = Q^T omega).",
        ])
    a, b, c = seq
    Ra = s.step("first rotation", axis_rotation(a, theta), f"theta about {a}.")
    s.step(f"Q for {a}-{b}-{c}", euler_rotation(seq),
           f"Intrinsic rotations compose by post-multiplication: Q = R_{a}(theta) R_{b}(phi) "
           f"R_{c}(psi).")
    s.step("rate contributions", sp.Matrix.hstack(_AXES[a], Ra * _AXES[b],
                                                  Ra * axis_rotation(b, phi) * _AXES[c]),
           f"Angular velocities add: theta_dot about {a}, phi_dot about the once-moved {b}, "
           f"psi_dot about the twice-moved {c}; these directions are the columns of W.")
    W0, Wb0, d0, sing0, Winv0 = _symbolic(seq)
    W = s.step("W (fixed frame)", W0, "omega = W eta_dot with the columns above.")
    Wb = s.step("W_B (body frame)", Wb0, "omega_B = Q^T omega, so W_B = Q^T W.")
    d = s.step("det W", d0, "Expanded and simplified by sympy.")
    sing = s.step("singular set", sing0,
                  "sympy solveset of det W = 0 for phi in [-pi, pi): the first and third "
                  "axes become parallel (gimbal lock), theta and psi rotate about one line.")
    Winv = s.step("W^-1 (where det W != 0)", Winv0,
                  "adj(W)/det W, so eta_dot = W^-1 omega off the singular set.")
    rows = table()
    s.answers = {"W": W, "W_body": Wb, "det_W": d, "singular_phi": sing,
                 "W_inverse": Winv}
    for q, _cls, df, db, ss in rows:
        s.answers[f"det_W_{q}"] = df
        s.answers[f"det_W_body_{q}"] = db
        s.answers[f"singular_{q}"] = ss
    lines = ["| sequence | class | det W (fixed) | det W (body) | singular phi in [-pi, pi) |",
             "|---|---|---|---|---|"]
    lines += [f"| {q} | {c} | `{df}` | `{db}` | `{ss}` |" for q, c, df, db, ss in rows]
    s.extra = "\n".join(lines)
    s.checks.extend(_symbolic_checks(seq))
    if at or omega is not None:
        _evaluated(s, W, d, at, omega)
    return s


@functools.cache
def _symbolic(seq: str) -> tuple:
    """W, W_B, det W, its singular set and W^-1 of ``seq`` in the angles, derived once (they
    do not depend on the angles a student evaluates them at)."""
    W = euler_rate_matrix(seq)
    d = sp.trigsimp(W.det())
    return (sp.ImmutableMatrix(W), sp.ImmutableMatrix(euler_rate_matrix(seq, "body")), d,
            singular_set(d), sp.ImmutableMatrix((W.adjugate() / d).applyfunc(sp.trigsimp)))


def _algebraic(x) -> bool:
    """Whether a closed number is algebraic (its minimal polynomial exists)."""
    try:
        sp.minimal_polynomial(x, sp.Symbol("x_minpoly"))
    except (sp.polys.polyerrors.NotAlgebraic, NotImplementedError):
        return False
    return True


def _evaluated(s: Solution, W, d, at: dict, omega) -> None:
    """W, det W and, with omega, eta_dot = W^-1 omega at the given angles (exact)."""
    from rigidsym.course.worked import exact_check, is_zero

    sub = {ETA[k]: at[n] for k, n in enumerate(("theta", "phi", "psi")) if n in at}
    free = [n for n in ("theta", "phi", "psi") if n not in at]
    shown = ", ".join(f"{n} = {at[n]}" for n in at) or "symbolic angles"
    Wv = s.step(f"W at {shown}", W.subs(sub).applyfunc(sp.radsimp),
                "The angles given, put into W (fixed frame).")
    dv = s.step(f"det W at {shown}", sp.radsimp(sp.trigsimp(d.subs(sub))),
                "det W there (its singular set is above).")
    s.answers.update({"W_at": Wv, "det_W_at": dv})
    if omega is None:
        return
    if free:   # incomplete data: bad input, naming what is missing
        raise ValueError(f"omega: eta_dot = W^-1 omega needs all three angles; "
                         f"{', '.join(free)} {'is' if len(free) == 1 else 'are'} not given "
                         f"(--set {free[0]}=...)")
    if not _algebraic(dv):
        # an angle that is not a rational multiple of pi (0.5 rad): sin and cos of it are
        # transcendental, so W is evaluated to 30 digits and the check is numeric
        Wn, on = Wv.evalf(30), omega.evalf(30)
        if abs(Wn.det()) < sp.Float("1e-25"):
            s.fail("W is singular at these angles (det W = 0 to 30 digits, gimbal lock), so "
                   "omega does not fix the Euler-angle rates.")
        rate = s.step("eta_dot = W^-1 omega (30 digits)", Wn.LUsolve(on),
                      "W is invertible here; sin and cos of these angles are transcendental, "
                      "so W and the rates are evaluated to 30 digits.")
        s.answers["eta_dot"] = rate
        res = max(abs(x) for x in Wn * rate - on)
        s.check(truth_check("W eta_dot = omega at the given angles, to 25 digits",
                            res < sp.Float("1e-25"), f"largest residual {float(res):.2g}"))
        return
    if is_zero(dv):
        in_range = sp.Matrix.hstack(Wv, omega).rank(simplify=True) == Wv.rank(simplify=True)
        s.fail("W is singular at these angles (det W = 0, gimbal lock), so omega does not "
               "fix the Euler-angle rates: " + (
                   "infinitely many eta_dot give it (the first and third rates add along one "
                   "axis)." if in_range else "no eta_dot gives it (omega is not in the range "
                   "of W)."))
    rate = s.step("eta_dot = W^-1 omega", (Wv.inv() * omega).applyfunc(sp.radsimp),
                  "W is invertible here (det W != 0), so the rates are unique.")
    s.answers["eta_dot"] = rate
    s.check(exact_check("W eta_dot = omega at the given angles", [Wv * rate - omega]))


@functools.cache
def _symbolic_checks(seq: str) -> tuple:
    """The checks of the symbolic solution of ``seq`` (:func:`_checks`), decided once: they
    do not depend on the angles a student evaluates W at."""
    W, _, _, _, Winv = _symbolic(seq)
    s = Solution(ID, TITLE, STATEMENT, CITATION)
    _checks(s, seq, W, Winv, table())
    return tuple(s.checks)


@functools.cache
def _rate_checks(q: str) -> tuple:
    """Differentiate Q(t) of sequence ``q`` directly: omega = vect(Q_dot Q^T) = W eta_dot
    and Q^T Q_dot = cpm(W_B eta_dot), as identities (decided once per sequence)."""
    at = [angle(f"ex310_{n}", t=TIME) for n in ("theta", "phi", "psi")]
    rate = sp.Matrix([sp.diff(x, TIME) for x in at])
    Q = euler_rotation(q, at)
    Qd = Q.diff(TIME)
    Omega = Qd * Q.T
    sub = dict(zip((theta, phi, psi), at, strict=True))
    wf = euler_rate_matrix(q).subs(sub) * rate
    wb = euler_rate_matrix(q, "body").subs(sub) * rate
    return (identity_check(f"{q}: vect(Q_dot Q^T) = W eta_dot, Omega = cpm(omega)",
                           [vect(Omega) - wf, Omega - cpm(wf)]),
            identity_check(f"{q}: Q^T Q_dot = cpm(W_B eta_dot)", [Q.T * Qd - cpm(wb)]))


def _checks(s: Solution, seq: str, W, Winv, rows) -> None:
    """Machine checks: differentiate Q(t) directly, omega = vect(Q_dot Q^T), for every
    sequence; W W^-1 = 1; the singular set zeroes det W and drops the rank."""
    a, b, c = seq
    at = [angle(f"ex310_{n}", t=TIME) for n in ("theta", "phi", "psi")]
    for q in SEQUENCES:
        s.checks.extend(_rate_checks(q))
    s.check(identity_check(f"{a}-{b}-{c}: W W^-1 = 1 (off the singular set)",
                           [(W * Winv - sp.eye(3)).subs(
                               {theta: at[0], phi: at[1], psi: at[2]})]))
    s.check(_singular_check(tuple(rows)))


@functools.cache
def _singular_check(rows: tuple):
    """The singular sets of the table's ``rows``: det W vanishes at each reported point, and
    the rank of W drops to 2 there (the same for every sequence solved: decided once)."""
    ok = True
    for q, _c, df, _db, ss in rows:
        for p in ss:
            ok &= df.subs(phi, p) == 0 and euler_rate_matrix(q).subs(phi, p).rank() == 2
        ok &= len(ss) == 2
    return truth_check("every singular point found zeroes det W and drops rank W to 2",
                       ok, "two points per sequence in [-pi, pi)")


def random_data(rng) -> dict:
    """A variant (an exam's draw): one of the twelve intrinsic Euler-angle sequences."""
    return {"sequence": rng.choice(sorted(SEQUENCES))}
