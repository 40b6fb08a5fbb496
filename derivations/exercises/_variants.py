"""Variants of the exercises that draw no random data of their own.

Exercise 3.6 gets numeric variants (the gripper point P drawn at random). The proofs
(3.3, 3.8, 3.9, 3.13, 3.15-3.18, 3.20, 3.21) become "true or false, and why": three
statements drawn from the exercise's identity, equivalent forms of it, and one-edit slips
of it (a sign, a factor or exponent, the order of a product or a transpose), as the repair
search edits a printed equation. Every statement is decided here by the sound zero test
(:func:`rigidsym.course.worked.identity_check`, and a refutation by an exact
counterexample, :func:`~rigidsym.course.worked.nonidentity_check`), never assumed: a
statement neither proved nor refuted is never drawn.

The answers: ``holds``, one truth per statement (1 true, 0 false; "true"/"false" typed),
and ``why``, one reason per statement, by the number the handout gives it: the reasons (it
holds, the identity or an equivalent form; it fails by a sign; by a factor, term or
exponent; by the order of a product or a transpose, :data:`WHY`) are listed in an order
drawn with the statements (the datum ``reasons``: the :data:`WHY` key of each number), so
that neighbours' reason numbers differ.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from rigidsym.course.worked import (
    Solution,
    exercise_module,
    identity_check,
    nonidentity_check,
)
from rigidsym.declare import (
    TIME,
    block,
    cpm,
    rotation_from_natural_invariants,
    scalar,
    symmetric_matrix,
    unit_vector,
    vect,
    vector,
)

__all__ = ["drawn", "draw", "statements", "decided", "WHY", "SYMBOLS", "symbols"]

#: the reasons a student picks from, by number
WHY = {1: "it holds (the identity, or an equivalent form of it)",
       2: "it fails: a sign is changed",
       3: "it fails: a factor, a term or an exponent is changed",
       4: "it fails: the order of a product, or a transpose, is changed"}
_PER_VARIANT = 3

#: the notation every true-or-false handout defines (the book's, Sec. 2.2 and 3.8)
_NOTATION = ("CPM(a): the cross-product matrix of a 3-vector a, CPM(a) b = a x b for every b; "
             "a x b: the cross product; a . b: the dot product; ||a||: the Euclidean norm; "
             "^T: the transpose; tr: the trace; 1: the 3 x 3 identity matrix; O: the 3 x 3 "
             "zero matrix; [[A, B], [C, D]]: a matrix of 3 x 3 blocks, row by row")
#: exercise -> what its statements' symbols are (every symbol a statement uses, defined
#: on the handout: a symbol's meaning is part of the problem, never only of the key)
SYMBOLS = {
    "ex3.3": "p, e, x: any 3-vectors; lambda: any real number",
    "ex3.8": "omega, p: any 3-vectors",
    "ex3.9": "phi(t): an angle, a function of the time t; e(t): a unit vector, a function "
             "of t; Q: the "
             "rotation through phi about e (Eq. 2.49); omega = vect(Q_dot Q^T): its angular "
             "velocity; phi_dot, e_dot, d/dt: derivatives with respect to t; to first order "
             "in phi: for a small rotation, terms in phi^2, phi phi_dot and higher dropped; "
             "a, b: any 3-vectors (CPM(a), CPM(b): two small rotations' cross-product "
             "matrices)",
    "ex3.13": "p_1, p_2: any 3-vectors (the positions of two particles); m: any real number "
              "(the mass of each); P = [p_1 p_2]: the 3 x 2 matrix of columns p_1, p_2",
    "ex3.15": "d: any 3-vector (d = p - c, from the mass centre C to the point P); m: any "
              "real number (the mass); I_C: any symmetric 3 x 3 matrix (the inertia matrix "
              "about C); I_P = I_C - m CPM(d)^2: the inertia matrix about P",
    "ex3.16": "d: any 3-vector (d = a - c, from the mass centre C to the point A); x: any "
              "3-vector; m: any real number (the mass); I_C: any symmetric 3 x 3 matrix (the "
              "inertia matrix about C); I_A = I_C - m CPM(d)^2: the inertia matrix about A",
    "ex3.17": "omega: any 3-vector (the angular velocity); Omega = CPM(omega); I: any "
              "symmetric 3 x 3 matrix (an inertia matrix)",
    "ex3.18": "omega: any 3-vector (the angular velocity); Omega = CPM(omega); I: any "
              "symmetric 3 x 3 matrix (an inertia matrix)",
    "ex3.20": "b: any 3-vector; m: any real number (the mass); I_C: any symmetric 3 x 3 "
              "matrix (the inertia matrix about the mass centre C); M_C = [[I_C, O], "
              "[O, m 1]]: the 6 x 6 mass matrix about C; B = CPM(b); N = [[1, O], [-B, 1]]",
    "ex3.21": "omega, omega_dot: any two 3-vectors (the angular velocity and acceleration, "
              "independent of each other)",
}


def symbols(ex_id: str) -> str:
    """The sentence a true-or-false handout of ``ex_id`` defines its symbols with."""
    return f"Symbols: {SYMBOLS[ex_id]}; {_NOTATION}."


def _dot(u, v):
    return (u.T * v)[0]


def _s33():
    e, p, x, lam = vector("e"), vector("p"), vector("x"), scalar("lambda")
    m = (p + lam * e).cross(e)
    return [("(p + lambda e) x e = p x e", m - p.cross(e), 1),
            ("(p + lambda e) x e = -(p x e)", m + p.cross(e), 2),
            ("(p + lambda e) x e = (1 + lambda) p x e", m - (1 + lam) * p.cross(e), 3),
            ("(p + lambda e) x e = e x p", m - e.cross(p), 4),
            ("(x - p) x e = x x e + e x p", (x - p).cross(e) - x.cross(e) - e.cross(p), 1)]


def _s38():
    w, p = vector("omega"), vector("p")
    W, n = cpm(w), _dot(w, w)
    return [("CPM(omega)^2 = omega omega^T - ||omega||^2 1", W**2 - (w * w.T - n * sp.eye(3)), 1),
            ("CPM(omega)^2 = omega omega^T + ||omega||^2 1", W**2 - (w * w.T + n * sp.eye(3)), 2),
            ("CPM(omega)^3 = -||omega||^2 CPM(omega)", W**3 + n * W, 1),
            ("CPM(omega)^3 = -||omega||^4 CPM(omega)", W**3 + n**2 * W, 3),
            ("CPM(omega)^5 p = -||omega||^4 omega x p", W**5 * p + n**2 * w.cross(p), 2),
            ("CPM(omega)^4 = ||omega||^2 (||omega||^2 1 - omega omega^T)",
             W**4 - n * (n * sp.eye(3) - w * w.T), 1)]


def _small_rotation_rate():
    """The first-order coefficient of omega = vect(Q_dot Q^T) for Q the rotation through
    epsilon phi(t) about the unit e(t) (Eq. 2.49), as 3.9's worked solution expands it;
    and phi, e."""
    e = unit_vector("ex39_e", t=TIME)
    phi = scalar("phi", t=TIME)
    eps = sp.Symbol("epsilon", real=True)
    Q = rotation_from_natural_invariants(e, eps * phi)
    omega = vect(Q.diff(TIME) * Q.T)
    return omega.diff(eps).subs(eps, 0), phi, e


def _s39():
    a, b = vector("a"), vector("b")
    A, B = cpm(a), cpm(b)
    w1, phi, e = _small_rotation_rate()
    rate = (phi * e).diff(TIME)
    return [("omega = d(phi e)/dt, to first order in phi", w1 - rate, 1),
            ("omega = -d(phi e)/dt, to first order in phi", w1 + rate, 2),
            ("omega = phi_dot e, to first order in phi", w1 - phi.diff(TIME) * e, 3),
            ("CPM(a) CPM(b) - CPM(b) CPM(a) = CPM(a x b)", A * B - B * A - cpm(a.cross(b)), 1),
            ("CPM(a) CPM(b) - CPM(b) CPM(a) = CPM(b x a)", A * B - B * A - cpm(b.cross(a)), 4),
            ("CPM(a) CPM(b) = CPM(b) CPM(a) (two small rotations commute exactly)",
             A * B - B * A, 4),
            ("CPM(a) b = -CPM(b) a", A * b + B * a, 1),
            ("CPM(a) CPM(b) = b a^T - (a . b) 1", A * B - (b * a.T - _dot(a, b) * sp.eye(3)), 1),
            ("CPM(a) CPM(b) = a b^T - (a . b) 1", A * B - (a * b.T - _dot(a, b) * sp.eye(3)), 4)]


def _s313():
    p1, p2, m = vector("p_1"), vector("p_2"), scalar("m")
    P = sp.Matrix.hstack(p1, p2)
    L = m * ((P * P.T).trace() * sp.eye(3) - P * P.T)
    S = cpm(p1)**2 + cpm(p2)**2
    return [("m[tr(P P^T) 1 - P P^T] = -m (CPM(p_1)^2 + CPM(p_2)^2), P = [p_1 p_2]",
             L + m * S, 1),
            ("m[tr(P P^T) 1 - P P^T] = m (CPM(p_1)^2 + CPM(p_2)^2), P = [p_1 p_2]", L - m * S, 2),
            ("m[tr(P P^T) 1 - P P^T] = -2 m (CPM(p_1)^2 + CPM(p_2)^2), P = [p_1 p_2]",
             L + 2 * m * S, 3),
            ("-CPM(p_1)^2 = ||p_1||^2 1 - p_1 p_1^T",
             -cpm(p1)**2 - (_dot(p1, p1) * sp.eye(3) - p1 * p1.T), 1),
            ("-CPM(p_1)^2 = ||p_1||^2 1 + p_1 p_1^T",
             -cpm(p1)**2 - (_dot(p1, p1) * sp.eye(3) + p1 * p1.T), 2)]


def _steiner():
    d, m, I_C = vector("d"), scalar("m"), symmetric_matrix("I_C")
    return d, m, I_C, I_C - m * cpm(d)**2


def _s315():
    d, m, I_C, I_P = _steiner()
    n = _dot(d, d)
    return [("I_P = I_C - m CPM(d)^2 equals I_C + m (||d||^2 1 - d d^T)",
             I_P - (I_C + m * (n * sp.eye(3) - d * d.T)), 1),
            ("I_P = I_C - m CPM(d)^2 equals I_C - m (||d||^2 1 - d d^T)",
             I_P - (I_C - m * (n * sp.eye(3) - d * d.T)), 2),
            ("I_P = I_C - m CPM(d)^2 equals I_C + m d d^T", I_P - (I_C + m * d * d.T), 3),
            ("(I_C - m CPM(d)^2) d = I_C d", I_P * d - I_C * d, 1),
            ("(I_C - m CPM(d)^2) d = I_C d + m ||d||^2 d", I_P * d - I_C * d - m * n * d, 3)]


def _s316():
    d, m, I_C, I_A = _steiner()
    x = vector("x")
    q = (x.T * (I_A - I_C) * x)[0]
    dx = d.cross(x)
    return [("x^T (I_A - I_C) x = m ||d x x||^2", q - m * _dot(dx, dx), 1),
            ("x^T (I_A - I_C) x = -m ||d x x||^2", q + m * _dot(dx, dx), 2),
            ("x^T (I_A - I_C) x = m (d . x)^2", q - m * _dot(d, x)**2, 3),
            ("x^T (I_A - I_C) x = m (||d||^2 ||x||^2 - (d . x)^2)",
             q - m * (_dot(d, d) * _dot(x, x) - _dot(d, x)**2), 1),
            ("x^T (I_A - I_C) x = m ||d||^2 ||x||^2", q - m * _dot(d, d) * _dot(x, x), 3)]


def _omega_inertia():
    w, I = vector("omega"), symmetric_matrix("I")
    return w, cpm(w), I


def _s317():
    w, O, I = _omega_inertia()
    C = O * I - I * O
    return [("(Omega I - I Omega)^T = Omega I - I Omega", C.T - C, 1),
            ("(Omega I + I Omega)^T = Omega I + I Omega", (O * I + I * O).T - (O * I + I * O), 2),
            ("(Omega I)^T = -I Omega", (O * I).T + I * O, 1),
            ("(Omega I)^T = -Omega I", (O * I).T + O * I, 4),
            ("Omega omega = 0", O * w, 1)]


def _s318():
    w, O, I = _omega_inertia()
    S = O * I + I * O
    D = (O * I - I * O) - 2 * O * I
    return [("(Omega I + I Omega)^T = -(Omega I + I Omega)", S.T + S, 1),
            ("(Omega I - I Omega)^T = -(Omega I - I Omega)",
             (O * I - I * O).T + (O * I - I * O), 2),
            ("(Omega I - I Omega) - 2 Omega I = -(Omega I + I Omega)", D + S, 1),
            ("(Omega I - I Omega) - 2 Omega I = -(Omega I + 2 I Omega)", D + O * I + 2 * I * O, 3),
            ("(Omega I - I Omega) - 2 Omega I = Omega I - I Omega", D - (O * I - I * O), 2)]


def _s320():
    b, m, I = vector("b"), scalar("m"), symmetric_matrix("I_C")
    B, one, O = cpm(b), sp.eye(3), sp.zeros(3)
    N = block([[one, O], [-B, one]])
    M = block([[I, O], [O, m * one]])

    def right(k):
        return block([[I - k * m * B**2, m * B], [-m * B, m * one]])
    NMN = N.T * M * N
    return [("N^T M_C N = [[I_C - m B^2, m B], [-m B, m 1]], N = [[1, O], [-B, 1]], "
             "B = CPM(b)", NMN - right(1), 1),
            ("N^T M_C N = [[I_C + m B^2, m B], [-m B, m 1]], N = [[1, O], [-B, 1]], "
             "B = CPM(b)", NMN - right(-1), 2),
            ("N^T M_C N = [[I_C - 2 m B^2, m B], [-m B, m 1]], N = [[1, O], [-B, 1]], "
             "B = CPM(b)", NMN - right(2), 3),
            ("N M_C N^T = [[I_C - m B^2, m B], [-m B, m 1]], N = [[1, O], [-B, 1]], "
             "B = CPM(b)", N * M * N.T - right(1), 4),
            ("(N^T M_C N)^T = N^T M_C N (it is symmetric)", NMN.T - NMN, 1)]


def _s321():
    a, b = vector("omega"), vector("omega_dot")
    A, B = cpm(a), cpm(b)
    return [("tr(CPM(omega_dot) (CPM(omega)^2)^T) = 0", sp.Matrix([(B * (A**2).T).trace()]), 1),
            ("tr(CPM(omega_dot)^2 (CPM(omega)^2)^T) = 0",
             sp.Matrix([(B**2 * (A**2).T).trace()]), 3),
            ("tr(CPM(omega) CPM(omega_dot)) = -2 omega . omega_dot",
             sp.Matrix([(A * B).trace() + 2 * _dot(a, b)]), 1),
            ("tr(CPM(omega) CPM(omega_dot)) = -omega . omega_dot",
             sp.Matrix([(A * B).trace() + _dot(a, b)]), 3),
            ("tr(CPM(omega) CPM(omega_dot)) = 2 omega . omega_dot",
             sp.Matrix([(A * B).trace() - 2 * _dot(a, b)]), 2),
            ("(CPM(omega)^2)^T = CPM(omega)^2", (A**2).T - A**2, 1)]


_STATEMENTS = {"ex3.3": _s33, "ex3.8": _s38, "ex3.9": _s39, "ex3.13": _s313,
               "ex3.15": _s315, "ex3.16": _s316, "ex3.17": _s317, "ex3.18": _s318,
               "ex3.20": _s320, "ex3.21": _s321}
_NUMERIC = ("ex3.6",)
#: exercise -> its statements of the exercise's own point, one of which every variant asks
#: (3.9: the angular velocity of a small rotation is d(phi e)/dt)
_POINT = {"ex3.9": (0, 1, 2)}


#: the finger planes' normals a draw of 3.6 takes: the book's cube diagonal, and unit
#: normals with positive components from Pythagorean quadruples (a corner cut obliquely)
_NORMALS = ((1, 1, 1), (1, 2, 2), (2, 1, 2), (2, 2, 1), (2, 3, 6), (3, 6, 2), (6, 2, 3),
            (1, 4, 8), (8, 1, 4), (4, 8, 1), (4, 4, 7), (7, 4, 4), (4, 7, 4))


def _grasp_data(rng) -> dict:
    """3.6 on drawn data: the finger planes' normal (:data:`_NORMALS`), the diagonal CC'
    of the unit cube (one of the three not along [1, 1, 1], either sense, so C and C' are
    vertices of the cube) and the gripper point P in quarters of a metre: the rotation,
    its axis and angle change with the normal and the diagonal."""
    n = list(rng.choice(_NORMALS))
    d = [rng.choice((1, -1)) * x for x in rng.choice(((-1, 1, 1), (1, -1, 1), (1, 1, -1)))]
    return {"face_normal": n, "CC_prime": d,
            "C_prime": [sp.Rational(x + 1, 2) for x in d],
            "p": [sp.Rational(rng.randint(-8, 8), 4) for _ in range(3)]}


def drawn() -> tuple[str, ...]:
    """The exercises this module draws variants of."""
    return _NUMERIC + tuple(_STATEMENTS)


@cache
def statements(ex_id: str) -> tuple:
    """``((text, zero expression, reason number), ...)`` of a proof exercise."""
    return tuple(_STATEMENTS[ex_id]())


@cache
def decided(ex_id: str, k: int):
    """Statement ``k`` of ``ex_id`` decided: ``(holds, check)``; ``holds`` is None when
    the zero test neither proved nor refuted it."""
    text, expr, _ = statements(ex_id)[k]
    proved = identity_check(f"({text}) decided: holds for every value", [expr])
    if proved.passed:
        return True, proved
    refuted = nonidentity_check(f"({text}) decided: fails (an exact counterexample)", [expr])
    return (False, refuted) if refuted.passed else (None, proved)


def draw(ex_id: str, rng) -> tuple[str, dict] | Solution:
    """A variant of ``ex_id``: ``("data", {...})`` for the exercise's solver (3.6), or the
    true-or-false problem itself, a solved and checked :class:`Solution`.

    Raises:
        KeyError: ``ex_id`` has no variant here (see :func:`drawn`).
    """
    if ex_id == "ex3.6":
        return "data", _grasp_data(rng)
    pool = [k for k in range(len(statements(ex_id))) if decided(ex_id, k)[0] is not None]
    picks = rng.sample(pool, _PER_VARIANT)
    point = [k for k in _POINT.get(ex_id, ()) if k in pool]
    if point and not set(picks) & set(point):      # the exercise's own point is asked
        picks[rng.randrange(_PER_VARIANT)] = rng.choice(point)
    # the reasons listed in a drawn order, as a quiz shuffles its choices: neighbours'
    # reason numbers differ though their statements' verdicts agree
    order = list(WHY)
    rng.shuffle(order)
    mod = exercise_module(ex_id)
    lines = [f"({'i' * (n + 1) if n < 3 else n + 1}) {statements(ex_id)[k][0]}"
             for n, k in enumerate(picks)]
    s = Solution(ex_id, mod.TITLE,
                 "True or false, and why? For every value of the symbols: "
                 + "; ".join(lines) + ". " + symbols(ex_id) + " Reasons: "
                 + "; ".join(f"{n} {WHY[r]}" for n, r in enumerate(order, 1)) + ".",
                 mod.CITATION + " (a true-or-false variant)")
    truths = [decided(ex_id, k)[0] for k in picks]
    s.steps = [_step(ex_id, k) for k in picks]
    label = {reason: n for n, reason in enumerate(order, 1)}
    s.answers = {"holds": sp.Matrix([int(t) for t in truths]),
                 "why": sp.Matrix([label[1 if t else statements(ex_id)[k][2]]
                                   for t, k in zip(truths, picks, strict=True)])}
    s.checks = [decided(ex_id, k)[1] for k in picks]
    s.data = {"statements": sp.Matrix(picks), "reasons": sp.Matrix(order)}
    return s


def _step(ex_id: str, k: int):
    from rigidsym.course.worked import Step

    text, expr, why = statements(ex_id)[k]
    holds = decided(ex_id, k)[0]
    return Step(text, expr, "holds: " + WHY[1] if holds else f"fails: {WHY[why]}")
