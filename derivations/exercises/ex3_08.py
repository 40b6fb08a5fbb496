"""Exercise 3.8: repeated cross products, ``CPM(omega)^n p``, proved for every k by induction."""

from __future__ import annotations

import random

import sympy as sp

from rigidsym.course.worked import Solution, identity_check, truth_check
from rigidsym.declare import cpm, scalar, vector

ID = "ex3.8"
TITLE = "Even and odd powers of the cross-product matrix"
STATEMENT = ("\"Prove that for any three-dimensional vectors omega and p, [2k factors] = (-1)^k "
             "(||omega||^(2k) 1 - ||omega||^(2(k-1)) omega omega^T) p, [2k+1 factors] = (-1)^k "
             "(||omega||^(2k) omega) x p\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.8"


def solve() -> Solution:
    """Worked solution of Exercise 3.8."""
    w = vector("omega")
    p = vector("p")
    sigma, P = scalar("sigma"), scalar("P")  # (-1)^k and ||w||^(2(k-1))
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"omega": w, "p": p},
        assumptions=["k >= 1 (for k = 0 the even formula has ||omega||^(-2) omega omega^T "
                     "and fails unless omega omega^T p = 0; the odd one holds for k = 0)."])
    Om = cpm(w)
    n2 = (w.T * w)[0]
    A1 = s.step("k-fold product as a power", Om**2,
                "omega x (omega x ... p) with n factors is CPM(omega)^n p, so it suffices "
                "to find CPM(omega)^(2k).")
    base = s.step("base case k = 1", A1 - (-(n2 * sp.eye(3) - w * w.T)),
                  "Eq. (2.40): CPM(omega)^2 = omega omega^T - ||omega||^2 1, the claim for "
                  "k = 1 (this difference is zero).")
    Ak = sigma * (P * n2 * sp.eye(3) - P * w * w.T)
    s.step("induction hypothesis", Ak,
           "CPM^(2k) = (-1)^k(||w||^(2k) 1 - ||w||^(2(k-1)) w w^T), written with the free "
           "symbols sigma = (-1)^k, P = ||w||^(2(k-1)) so that k is arbitrary.")
    step_even = s.step("induction step, even", Om**2 * Ak - (-sigma) * (P * n2**2 * sp.eye(3)
                                                                     - P * n2 * w * w.T),
                       "CPM^(2k+2) = CPM^2 CPM^(2k) must equal the claim at k + 1, with "
                       "(-1)^(k+1) = -sigma and ||w||^(2k+2) = P ||w||^4.")
    step_odd = s.step("odd powers", Om * Ak * p - sigma * P * n2 * w.cross(p),
                      "CPM^(2k+1) p = CPM(w) CPM^(2k) p and CPM(w) w = 0, leaving "
                      "(-1)^k ||w||^(2k) w x p.")
    s.answers = {"even": "CPM(omega)^(2k) = (-1)^k (||omega||^(2k) 1 - ||omega||^(2(k-1)) "
                         "omega omega^T), k >= 1",
                 "odd": "CPM(omega)^(2k+1) p = (-1)^k ||omega||^(2k) omega x p, k >= 0",
                 "holds_for_every_k": sp.true}
    s.check(identity_check("base case k = 1 (sound zero test)", [base]))
    s.check(identity_check("induction step for symbolic sigma = (-1)^k, P = ||w||^(2(k-1))",
                           [step_even]))
    s.check(identity_check("odd case for every k", [step_odd]))
    # independent: literal repeated cross products at random rational vectors, k = 1..6
    rng = random.Random(38)
    ok = True
    for k in range(1, 7):
        wv = sp.Matrix([sp.Rational(rng.randint(-9, 9), rng.randint(1, 5)) for _ in range(3)])
        pv = sp.Matrix([sp.Rational(rng.randint(-9, 9), rng.randint(1, 5)) for _ in range(3)])
        nn = (wv.T * wv)[0]
        x = pv
        for n in range(1, 2 * k + 2):
            x = wv.cross(x)
            if n == 2 * k:
                ok &= x == (-1)**k * (nn**k * pv - nn**(k - 1) * wv * (wv.T * pv)[0])
        ok &= x == (-1)**k * nn**k * wv.cross(pv)
    s.check(truth_check("literal nested cross products, k = 1..6, exact rationals", ok,
                        "compared entrywise in Q"))
    return s
