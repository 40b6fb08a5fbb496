"""Exercise 3.3: the lines meeting three given lines sweep a quadric; when is det M != 0."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Solution, identity_check, nonidentity_check
from rigidsym.declare import scalar, vector

ID = "ex3.3"
TITLE = "Lines meeting three lines: a ruled quadric"
STATEMENT = ("\"show that the locus of all lines L intersecting three given lines {L_k} is a "
             "quadric ... Show, furthermore, that det(M) is nonzero ... and hence, the "
             "quadric is a one-sheet hyperboloid.\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.3"


def plane_normal(a, e, p) -> sp.Matrix:
    """Normal of the plane through point p and the line {a + lambda e}: ``n + e x p``,
    ``n = a x e`` (the line's moment about O)."""
    return a.cross(e) + e.cross(p)


def quadric(lines, p):
    """``f(p) = det[N_1, N_2, N_3]`` and its coefficients ``M`` (symmetric), ``g``, ``h``."""
    n1, n2, n3 = (plane_normal(a, e, p) for a, e in lines)
    f = sp.expand(n1.dot(n2.cross(n3)))
    M = sp.hessian(f, list(p)) / 2
    zero = dict.fromkeys(p, 0)
    g = sp.Matrix([sp.diff(f, v) for v in p]).subs(zero)
    h = f.subs(zero)
    return f, M.subs(zero), g, h


def _origin_check(s: Solution) -> None:
    """Three skew lines with independent directions; moving the origin by c turns h into
    f(c) and keeps M: both signs of h occur with one det M, so h > 0 does not fix it."""
    from rigidsym.course.worked import truth_check

    p = sp.Matrix(sp.symbols("x y z", real=True))
    lines = [(sp.zeros(3, 1), sp.Matrix([1, 0, 0])), (sp.Matrix([0, 0, 1]), sp.Matrix([0, 1, 0])),
             (sp.Matrix([1, 1, 0]), sp.Matrix([0, 0, 1]))]
    f, M, _, _ = quadric(lines, p)
    vals = [f.subs(dict(zip(p, c, strict=True))) for c in ([0, 0, 0], [2, 2, 2], [0, 1, 0])]
    ok = det3(M) != 0 and max(vals) > 0 > min(vals)
    s.check(truth_check("one quadric, det M != 0, and f takes both signs at origins c: h = "
                        "f(c) > 0 or < 0 for the same det M", ok,
                        f"det M = {det3(M)}, f(c) = {', '.join(map(str, vals))} (exact)"))


def det3(m: sp.Matrix) -> sp.Expr:
    """det of a 3 x 3 matrix as the triple product of its columns (sympy's default Bareiss
    elimination simplifies every product on the way: seconds a call on symbolic entries)."""
    return m[:, 0].dot(m[:, 1].cross(m[:, 2]))


def mutual_moment(l1, l2):
    """Moment of one line about another (Exercise 3.3): ``(a_1 - a_2) . (e_1 x e_2)``
    up to the norms of e_1, e_2; zero iff the lines meet (or are parallel)."""
    (a1, e1), (a2, e2) = l1, l2
    return (a1 - a2).dot(e1.cross(e2))


def solve() -> Solution:
    """Worked solution of Exercise 3.3.

    Long: a worked solution is read top to bottom as the book's steps (statement, steps,
    answers, checks); split into functions it would no longer read as one solution.
    """
    p = sp.Matrix(sp.symbols("x y z", real=True))
    lines = [(vector(f"a{k}"), vector(f"e{k}")) for k in (1, 2, 3)]
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"L_k": "{a_k + lambda e_k}, k = 1, 2, 3, pairwise skew (generic a_k, e_k)"},
        assumptions=["The three lines are pairwise skew (two meeting lines make the locus "
                     "degenerate into planes).",
                     "h > 0 is a normalisation of the sign of f (f and -f define the same "
                     "surface); it fails only when the origin is on the surface (h = 0).",
                     "The book's claim det(M) != 0 is false in general: it holds iff the "
                     "directions e_1, e_2, e_3 are linearly independent; when they are "
                     "parallel to a common plane the quadric is a hyperbolic paraboloid."])
    s.step("plane through p and L_k", plane_normal(*lines[0], p),
           "A line through p meets L_k iff it lies in the plane through p and L_k, of normal "
           "N_k = n_k + e_k x p (n_k = a_k x e_k); zero moment about L_k (the exercise's "
           "criterion).")
    s.step("locus", "f(p) = det[N_1, N_2, N_3] = 0",
           "The line through p meeting L_1 and L_2 has direction N_1 x N_2; it meets L_3 iff "
           "(N_1 x N_2) . N_3 = 0.")
    s.step("no cubic term", "det[E_1 p, E_2 p, E_3 p] = 0",
           "The three vectors e_k x p are all normal to p, hence coplanar: f is quadratic.")
    f, M, g, h = quadric(lines, p)
    n = [a.cross(e) for a, e in lines]
    e = [e for _, e in lines]
    s.step("expansion", "f(p) = det[n_1 + E_1 p, n_2 + E_2 p, n_3 + E_3 p]",
           "E_k = CPM(e_k); det[u, v, w] = u.(v x w) is linear in each column, so f is the "
           "sum of the determinants with 0, 1, 2 or 3 columns E_k p.")
    s.step("M (no components)", "M = (1/2) sum_cyc [n_k (e_i x e_j)^T + (e_i x e_j) n_k^T]",
           "(e_i x p) x (e_j x p) = ((e_i x e_j).p) p, so det[E_i p, E_j p, n_k] = "
           "(n_k.p)((e_i x e_j).p) = p^T n_k (e_i x e_j)^T p; M is its symmetric part, summed "
           "over (i, j, k) = (1, 2, 3), (2, 3, 1), (3, 1, 2).")
    s.step("g (no components)", "g = -[e_1 x (n_2 x n_3) + e_2 x (n_3 x n_1) + e_3 x (n_1 x n_2)]",
           "det[E_1 p, n_2, n_3] = (e_1 x p).(n_2 x n_3) = -p.(e_1 x (n_2 x n_3)), and "
           "cyclically.")
    s.step("h (no components)", "h = det[n_1, n_2, n_3]", "h = f(0).")
    M_book = sum((n[k] * e[i].cross(e[j]).T + e[i].cross(e[j]) * n[k].T
                  for i, j, k in ((0, 1, 2), (1, 2, 0), (2, 0, 1))), sp.zeros(3, 3)) / 2
    g_book = -(e[0].cross(n[1].cross(n[2])) + e[1].cross(n[2].cross(n[0]))
               + e[2].cross(n[0].cross(n[1])))
    h_book = det3(sp.Matrix.hstack(*n))
    # coefficient of det M: derive in the frame of the common perpendicular of L_1, L_2
    d, t_, b1, b2, b3, q1, q2, q3 = sp.symbols("d t b1 b2 b3 q1 q2 q3", real=True)
    special = [(sp.zeros(3, 1), sp.Matrix([1, 0, 0])),
               (sp.Matrix([0, 0, d]), sp.Matrix([1, t_, 0])),
               (sp.Matrix([b1, b2, b3]), sp.Matrix([q1, q2, q3]))]
    _, Ms, _, _ = quadric(special, p)
    prod_s = (mutual_moment(special[0], special[1]) * mutual_moment(special[1], special[2])
              * mutual_moment(special[2], special[0])
              * det3(sp.Matrix.hstack(*[e for _, e in special])))
    s.step("det M in adapted axes", sp.factor(det3(Ms)),
           "Axes: L_1 the X axis, L_2 through (0, 0, d) normal to Z (Z along the common "
           "perpendicular), as the hint suggests.")
    k = sp.cancel(det3(Ms) / prod_s)
    mu = [mutual_moment(lines[i], lines[j]) for i, j in ((0, 1), (1, 2), (2, 0))]
    detE = sp.expand(det3(sp.Matrix.hstack(*[e for _, e in lines])))
    law = s.step("det M", k * mu[0] * mu[1] * mu[2] * detE,
                 "det M = k mu_12 mu_23 mu_31 det[e_1, e_2, e_3] (frame-free form, decided "
                 "below for generic lines); mu_ij = (a_i - a_j).(e_i x e_j) vanishes iff "
                 "L_i, L_j meet.")
    s.step("isotropic directions", "e_k^T M e_k = 0, k = 1, 2, 3",
           "L_k lies on the quadric, so f(a_k + lambda e_k) = 0 for every lambda; its "
           "lambda^2 coefficient is e_k^T M e_k.")
    s.step("det M < 0", "M indefinite; det M != 0 => eigenvalues (+, +, -) or (-, -, +)",
           "A definite M has e^T M e != 0 for every e != 0, so M, isotropic on e_1, e_2, e_3, "
           "is indefinite; with det M != 0 two eigenvalues share a sign. f and -f give the "
           "same surface: the sign that makes two eigenvalues positive gives det M < 0. The "
           "book's h > 0 does not fix that sign: h = f(0) changes sign with the origin (a "
           "point inside or outside the surface) while M does not (checked below).")
    s.answers = {"f": "p^T M p + g^T p + h",
                 "M": "(1/2) sum_cyc [n_k (e_i x e_j)^T + (e_i x e_j) n_k^T], n_k = a_k x e_k",
                 "g": "-[e_1 x (n_2 x n_3) + e_2 x (n_3 x n_1) + e_3 x (n_1 x n_2)]",
                 "h": "det[n_1, n_2, n_3]",
                 "det_M": law, "det_M_nonzero_in_general": sp.false,
                 "det_M_nonzero_iff": "the lines are pairwise skew and e_1, e_2, e_3 are "
                                      "linearly independent (not all parallel to one plane)",
                 "det_M_negative": "when f is signed so that M has two positive eigenvalues "
                                   "(M is indefinite: e_k^T M e_k = 0); h > 0 does not fix "
                                   "the sign, since h depends on the origin"}
    s.check(identity_check("M, g, h in the book's matrix form equal the coefficients of f "
                           "(generic lines)", [M - M_book, g - g_book, h - h_book]))
    s.check(identity_check("e_k^T M e_k = 0 for k = 1, 2, 3 (generic lines)",
                           [(ek.T * M * ek)[0] for ek in e]))
    _origin_check(s)
    s.check(identity_check("f(p) = p^T M p + g^T p + h (quadratic) for generic lines",
                           [f - ((p.T * M * p)[0] + (g.T * p)[0] + h)]))
    lam = scalar("lambda")
    s.check(identity_check("each given line lies on the quadric: f(a_k + lambda e_k) = 0",
                           [f.subs(dict(zip(p, a + lam * e, strict=True)),
                                   simultaneous=True) for a, e in lines]))
    s.check(identity_check("det M = k mu_12 mu_23 mu_31 det[e_1, e_2, e_3], generic lines",
                           [det3(M) - law]))
    s.check(nonidentity_check("det M is not identically zero (hyperboloid for generic lines)",
                              [det3(M)]))
    par = [(sp.zeros(3, 1), sp.Matrix([1, 0, 0])), (sp.Matrix([0, 0, 1]), sp.Matrix([1, 1, 0])),
           (sp.Matrix([0, 0, 2]), sp.Matrix([0, 1, 0]))]
    _, Mp, _, _ = quadric(par, p)
    s.check(identity_check("counterexample: three skew lines parallel to the X-Y plane give "
                           "det M = 0 (hyperbolic paraboloid)", [det3(Mp)]))
    return s
