"""Sec. 3.7: Static analysis of rigid bodies, Eqs. (3.106)-(3.122), Theorems 3.7.1-3.7.2.

Book: J. Angeles, *Fundamentals of Robotic Mechanical Systems*, 4th ed., Sec. 3.7.

First principles used by the models (nothing of the book's closed forms is assumed):

- a *system of forces* is a set of forces ``f_i`` applied at points ``r_i`` plus a couple
  ``c``; its resultant is ``f = sum f_i`` and its moment about a point X is
  ``n_X = sum (r_i - x) x f_i + c``;
- where ``||f||`` appears, the resultant is written ``f = W e`` with ``e`` a constrained unit
  vector and ``W`` a free scalar, so that ``||f|| = W`` is rational (``W > 0``; an identity
  polynomial in ``W`` that holds for ``W > 0`` holds for every ``W``);
- the wrench axis is *characterised*, not copied: the point of it nearest the origin solves
  ``f x n_X = 0`` (moment parallel to the force) with ``f . x = 0``, solved by ``sympy.solve``;
  "any point of the line" is the generic point ``p0 + lambda f`` with ``lambda`` free;
- the power of a system of forces on a moving rigid body is ``sum f_i . v(r_i) + c . omega``
  with the body points moving rigidly (``x(t) = a(t) + Q(t) s``, Q exactly orthogonal);
- a twist/wrench screw is (3.71): ``s = [e; r x e + h e]`` for an axis through ``r`` of
  direction ``e`` and pitch ``h``; the pitch is the ratio of the (parallel) moment on the
  axis to the force, or of the sliding velocity on the axis to the angular velocity.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.declare import (
    Rel,
    Statement,
    as_vector,
    block,
    cpm,
    equation,
    scalar,
    unit_vector,
    vector,
)

from .common import MS, mat, vec

__all__ = ["wrench_axis_point", "wrench_pitch", "wrench_transfer_matrix", "wrench_transfer"]

im = sp.ImmutableMatrix

# Book symbols.
n_P, n_A, f, a, p = vec("n_P"), vec("n_A"), vec("f"), vec("a"), vec("p")
norm_f = sp.Symbol("norm_f", positive=True)  # ||f||
n0_vec, n0 = vec("n_0"), sp.Symbol("n_0", real=True)
pitch_w, pitch_w_turn = sp.Symbol("p_wrench", real=True), sp.Symbol("p_wrench_turn", real=True)
p_L, e_w, n_w = MS("p_L2", 6, 1), vec("e_2prime"), vec("n_2prime")
p0_w = vec("p_0_2prime")
Gamma, U, V = MS("Gamma", 6, 6), MS("U", 6, 6), MS("V", 6, 6)
A_cpm, P_cpm = mat("A"), mat("P")
w, t, s_w, s_t = MS("w", 6, 1), MS("t", 6, 1), MS("s_w", 6, 1), MS("s_t", 6, 1)
w_A, w_P, t_A, t_P = MS("w_A", 6, 1), MS("w_P", 6, 1), MS("t_A", 6, 1), MS("t_P", 6, 1)
n_vec, Pi = vec("n"), sp.Symbol("Pi", real=True)
W_amp, T_amp = sp.Symbol("W", real=True), sp.Symbol("T", real=True)


def _x(u, v) -> sp.Matrix:
    """Cross product of two book 3-vectors (symbols or explicit)."""
    return sp.Matrix(u).cross(sp.Matrix(v))


# --------------------------------------------------------------------------- kernels
def wrench_axis_point(n_A, f, a) -> sp.Matrix:
    """Point of the wrench axis nearest the origin.

    ``p0'' = f x (n_A - f x a) / ||f||^2``.

    Book: Sec. 3.7, Eq. (3.111).

    Args:
        n_A: 3x1, resultant moment about A (N m).
        f: 3x1, resultant force (N).
        a: 3x1, position of A (m).

    Returns:
        3x1 ``sympy.Matrix`` (m). Singular set: ``f = 0`` (a pure couple has no axis).
    """
    n_A, f, a = as_vector(n_A), as_vector(f), as_vector(a)
    return f.cross(n_A - f.cross(a)) / f.dot(f)


def wrench_pitch(n_A, f):
    """Pitch of a wrench: ``p'' = n_A . f / ||f||^2`` (same for every point A).

    Book: Sec. 3.7, Eq. (3.109) (m/rad; multiply by 2 pi for m/turn).

    Args:
        n_A: 3x1, resultant moment about any point A (N m).
        f: 3x1, resultant force (N).

    Returns:
        scalar (m). Singular set: ``f = 0``.
    """
    n_A, f = as_vector(n_A), as_vector(f)
    return n_A.dot(f) / f.dot(f)


def wrench_transfer_matrix(a, p) -> sp.Matrix:
    """Wrench-transfer matrix ``V = [[1, A - P], [O, 1]]``, ``A = cpm(a)``, ``P = cpm(p)``.

    Book: Sec. 3.7, Eq. (3.119b). Wrenches in axis coordinates ``[n; f]``.

    Args:
        a, p: 3x1 positions of A and P (m).

    Returns:
        6x6 ``sympy.Matrix`` (upper block unit-triangular; ``V^-1 = U^T``). No singular set.
    """
    return block([[sp.eye(3), cpm(a) - cpm(p)], [sp.zeros(3), sp.eye(3)]])


def wrench_transfer(w_A, a, p) -> sp.Matrix:
    """Wrench at P from the wrench at A: ``w_P = V w_A = [n_A + (a - p) x f; f]``.

    Book: Sec. 3.7, Eq. (3.119a).

    Args:
        w_A: 6x1, ``[n_A; f]`` (N m; N).
        a, p: 3x1 positions of A and P (m).

    Returns:
        6x1 ``sympy.Matrix`` ``[n_P; f]``. No singular set.
    """
    w_A = sp.Matrix(w_A)
    if w_A.shape != (6, 1):
        raise ValueError(f"w_A: expected a 6-vector, got shape {w_A.shape}")
    return wrench_transfer_matrix(a, p) * w_A


# --------------------------------------------------------------------------- models
def _gamma() -> sp.Matrix:
    return block([[sp.zeros(3), sp.eye(3)], [sp.eye(3), sp.zeros(3)]])


def _force_system(unit: bool = True):
    """Resultant force and moment function of a generic system of forces.

    ``unit=True``: one force ``W e`` at ``r1`` plus a couple ``c`` (``e`` unit, so that
    ``||f|| = W``); otherwise two forces at two points plus a couple. Either reaches every
    (f, n) pair.
    """
    c = vector("s37_c")
    if unit:
        e, W = unit_vector("s37_e"), scalar("s37_W")
        forces = [(vector("s37_r1"), W * e)]
    else:
        e, W = None, None
        forces = [(vector("s37_r1"), vector("s37_f1")), (vector("s37_r2"), vector("s37_f2"))]
    res = sum((fi for _, fi in forces), sp.zeros(3, 1))

    def moment(x):
        return sum(((ri - x).cross(fi) for ri, fi in forces), sp.zeros(3, 1)) + c

    return res, moment, e, W


def _axis_point_by_solving(moment, d) -> sp.Matrix:
    """The point x with ``d x moment(x) = 0`` (moment parallel to d) and ``d . x = 0``."""
    x = sp.Matrix(sp.symbols("x1:4", cls=sp.Dummy, real=True))
    eqs = list(d.cross(moment(x))) + [d.dot(x)]
    sol = sp.solve(eqs, list(x), dict=True)
    if len(sol) != 1:
        raise RuntimeError("axis point: expected one generic solution")
    return x.xreplace(sol[0])


def _wrench_model():
    """Model with ||f|| rational: f = W e; n_A, n_P at free points A, P; the axis point.

    Fresh copies of dicts derived once per process (six declarations share them; the axis
    point's ``solve`` took a third of the section's build, once per declaration)."""
    model, ex = _wrench_model_once()
    return dict(model), dict(ex)


@cache
def _wrench_model_once():
    fv, moment, e, W = _force_system(unit=True)
    av, pv = vector("s37_a"), vector("s37_p")
    p0 = _axis_point_by_solving(moment, fv)
    model = {f: im(fv), norm_f: W, a: im(av), p: im(pv), n_A: im(moment(av)),
             n_P: im(moment(pv))}
    return model, {"moment": moment, "e": e, "W": W, "p0": p0, "lam": scalar("s37_lam")}


# --------------------------------------------------------------------------- 3.106-3.111
@equation("3.106", "Moment about P of a force f at A plus a moment n_A", section="3.7",
          latex=r"\mathbf{n}_P = \mathbf{n}_A + (\mathbf{a} - \mathbf{p}) \times \mathbf{f}")
def moment_transfer() -> Statement:
    """``n_P = n_A + (a - p) x f``. Book: Sec. 3.7, Eq. (3.106). 3x1, N m."""
    fv, moment, _, _ = _force_system(unit=False)
    av, pv = vector("s37_a"), vector("s37_p")
    model = {f: im(fv), a: im(av), p: im(pv), n_A: im(moment(av)), n_P: im(moment(pv))}
    return Statement([Rel(n_P, n_A + _x(a - p, f))], model)


@equation("3.107", "Moment transfer, velocity-like form", section="3.7",
          latex=r"\mathbf{n}_P = \mathbf{n}_A + \mathbf{f} \times (\mathbf{p} - \mathbf{a})")
def moment_transfer_velocity_form() -> Statement:
    """``n_P = n_A + f x (p - a)`` (cf. (3.50)). Book: Sec. 3.7, Eq. (3.107). 3x1, N m."""
    st = moment_transfer()
    return Statement([Rel(n_P, n_A + _x(f, p - a))], st.model)


@equation("thm3.7.1", "Minimum-moment line: the wrench axis", section="3.7", kind="claim",
          latex=r"if the resultant force is applied at any point of a particular line")
def minimum_moment_line() -> Statement:
    """Theorem 3.7.1, checked at the generic point ``p_L = p0 + lambda f`` of the line.

    ``p0`` solves ``f x n_X = 0``, ``f . x = 0``. Claims: (i) the moment at p_L is parallel
    to f; (ii) for an arbitrary point Q, ``||n_Q||^2 = ||n_L||^2 + ||f x (q - p_L)||^2``
    (a sum of squares: the moment at p_L has minimum magnitude); (iii)
    ``f x n_Q = -||f||^2 (q - p0) + f f^T (q - p0)``, which vanishes iff q - p0 is parallel
    to f: the points of minimum moment form exactly the line through p0 along f.
    Same structure as Theorem 3.4.2 (ISA) with (omega, v) -> (f, n). Q is the page's
    arbitrary point A (its atoms ``s37_a``: the table's ``a``, ``n_A``); (ii) and (i) are
    the relations the theorem's words state, in that order (``certcheck.words``), (iii)
    the proof's own.

    Book: Sec. 3.7, Theorem 3.7.1.
    """
    model, ex = _wrench_model()
    mom, fv, p0 = ex["moment"], model[f], ex["p0"]
    pl, qv = p0 + ex["lam"] * fv, vector("s37_a")  # Q arbitrary: the page's A (n_A)
    n_L, n_Q, q, pL = vec("n_L"), vec("n_Q"), vec("q"), vec("p_L")
    model.update({n_L: im(mom(pl)), n_Q: im(mom(qv)), q: im(qv), pL: im(pl),
                  p0_w: im(p0)})
    d = _x(f, q - pL)
    return Statement([], model, claims=[
        Rel(_x(f, n_L), sp.zeros(3, 1), "moment on the line is parallel to f", page=2),
        Rel(n_Q.T * n_Q, n_L.T * n_L + d.T * d, "moment magnitude is minimum on the line",
            page=1),
        Rel(_x(f, n_Q), -norm_f**2 * (q - p0_w) + f * (f.T * (q - p0_w)),
            "moment parallel to f only on the line"),
    ])


@equation("3.108", "Minimum-magnitude moment", section="3.7", kind="definition",
          latex=r"\mathbf{n}_0 = n_0 \frac{\mathbf{f}}{\|\mathbf{f}\|}, \quad n_0 \equiv "
                r"\frac{\mathbf{n}_P \cdot \mathbf{f}}{\|\mathbf{f}\|}")
def minimum_moment() -> Statement:
    """``n_0 = n_0 f / ||f||`` with ``n_0 = n_P . f / ||f||`` (defined).

    The scalar ``n_0`` is defined; the first member is checked as a claim with the vector
    ``n_0`` modelled as the moment at a point of the wrench axis (Theorem 3.7.1), P generic.

    Book: Sec. 3.7, Eq. (3.108). Shapes: 3x1 and scalar, N m.
    """
    model, ex = _wrench_model()
    n0_def = (n_P.T * f) / norm_f
    model.update({n0_vec: im(ex["moment"](ex["p0"] + ex["lam"] * model[f])),
                  n0: sp.Matrix(n0_def.xreplace(model).as_explicit())[0]})
    return Statement([Rel(n0, n0_def)], model, defines=("n_0",),
                     claims=[Rel(n0_vec, n0 * f / norm_f, "minimum moment n_0", page=1)])


@equation("3.109", "Pitch of the wrench (m/rad and m/turn)", section="3.7",
          kind="definition",
          latex=r"p'' \equiv \frac{n_0}{\|\mathbf{f}\|} = \frac{\mathbf{n}_P \cdot \mathbf{f}}"
                r"{\|\mathbf{f}\|^2} \quad \text{or} \quad p'' = \frac{2\pi \mathbf{n}_P \cdot "
                r"\mathbf{f}}{\|\mathbf{f}\|^2}")
def wrench_pitch_definition() -> Statement:
    """``p'' = n_0 / ||f|| = n_P . f / ||f||^2`` (m/rad), ``2 pi n_P . f / ||f||^2`` (m/turn).

    Claims: the middle member (P generic), the kernel :func:`wrench_pitch` at a generic A,
    and the defining property of a pitch: the moment on the axis is ``p'' f``.

    Book: Sec. 3.7, Eq. (3.109). Scalars, m/rad and m/turn.
    """
    model, ex = _wrench_model()
    pw_val = ((n_P.T * f)[0, 0] / norm_f**2).xreplace(model).doit()
    model.update({n0: ((n_P.T * f)[0, 0] / norm_f).xreplace(model).doit(), pitch_w: pw_val,
                  pitch_w_turn: 2 * sp.pi * pw_val,  # a turn is 2 pi rad (the words: m/turn)
                  n0_vec: im(ex["moment"](ex["p0"] + ex["lam"] * model[f]))})
    kernel = wrench_pitch(model[n_A], model[f])
    return Statement(
        [Rel(pitch_w, n0 / norm_f, "p'' in m/rad"),
         Rel(pitch_w_turn, 2 * sp.pi * (n_P.T * f) / norm_f**2, "p'' in m/turn")],
        model, defines=("p_wrench", "p_wrench_turn"),
        claims=[Rel(pitch_w, (n_P.T * f) / norm_f**2, "second member", page=2),
                Rel(pitch_w, kernel, "kernel wrench_pitch"),
                Rel(n0_vec, pitch_w * f, "moment on the axis = pitch x force")])


@equation("3.110", "Plücker array of the wrench axis", section="3.7", kind="definition",
          latex=r"\mathbf{p}_{\mathcal{L}''} \equiv \begin{bmatrix} \mathbf{e}'' \\ "
                r"\mathbf{n}'' \end{bmatrix}, \quad \mathbf{e}'' = \frac{\mathbf{f}}"
                r"{\|\mathbf{f}\|}, \quad \mathbf{n}'' = \mathbf{p} \times \mathbf{e}''")
def wrench_axis_pluecker() -> Statement:
    """``p_L'' = [e''; n'']``, ``e'' = f / ||f||``, ``n'' = p x e''`` (p any point of L'').

    Claims, at the generic point ``p = p0 + lambda f`` of the axis: ``e''`` is a unit
    vector, ``e'' . n'' = 0`` (Pluecker condition), ``n'' = p0 x e''`` (independent of the
    point chosen).

    Book: Sec. 3.7, Eq. (3.110). Shapes: 6x1; 3x1 (1) and 3x1 (m).
    """
    model, ex = _wrench_model()
    pl = ex["p0"] + ex["lam"] * model[f]
    model.update({p: im(pl), e_w: im(ex["e"]), n_w: im(pl.cross(ex["e"])), p0_w: im(ex["p0"])})
    return Statement(
        [Rel(p_L, sp.BlockMatrix([[e_w], [n_w]])), Rel(e_w, f / norm_f), Rel(n_w, _x(p, e_w))],
        model, defines=("p_L2", "e_2prime", "n_2prime"),
        claims=[Rel(e_w.T * e_w, sp.Identity(1), "unit direction"),
                Rel(e_w.T * n_w, sp.ZeroMatrix(1, 1), "Plücker condition"),
                Rel(n_w, _x(p0_w, e_w), "same moment for every point of the axis")])


@equation("3.111", "Point of the wrench axis nearest the origin", section="3.7",
          latex=r"\mathbf{p}_0'' = \frac{1}{\|\mathbf{f}\|^2} \mathbf{f} \times "
                r"(\mathbf{n}_A - \mathbf{f} \times \mathbf{a})", singular="f = 0")
def wrench_axis_nearest_point() -> Statement:
    """``p0'' = f x (n_A - f x a) / ||f||^2``; ``p0''`` modelled by solving its defining
    conditions (moment parallel to f, ``f . p0'' = 0``). Claim: kernel
    :func:`wrench_axis_point`. Same structure as (3.70) with (omega, a_dot) -> (f, n_A).

    Book: Sec. 3.7, Eq. (3.111). 3x1, m.
    """
    model, ex = _wrench_model()
    model[p0_w] = im(ex["p0"])
    kernel = wrench_axis_point(model[n_A], model[f], model[a])
    return Statement([Rel(p0_w, _x(f, sp.Matrix(n_A) - _x(f, a)) / norm_f**2)], model,
                     claims=[Rel(p0_w, kernel, "kernel wrench_axis_point")])


@equation("thm3.7.2", "Axial moment is the same at every point", section="3.7", kind="claim",
          latex=r"The projection of the resultant moment onto the wrench axis is identical "
                r"for all points")
def axial_moment_invariant() -> Statement:
    """Theorem 3.7.2: ``e'' . n_P = e'' . n_A`` for generic points A and P, the relation
    the theorem's words state (certcheck's table of them, ``certcheck.words``): the claim
    is the page's relation 1.

    Book: Sec. 3.7, Theorem 3.7.2 (cf. Theorem 3.4.1 / (3.51)).
    """
    model, ex = _wrench_model()
    model[e_w] = im(ex["e"])
    return Statement([], model, claims=[Rel(e_w.T * n_P, e_w.T * n_A, page=1)])  # the words
