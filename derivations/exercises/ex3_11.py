"""Exercise 3.11: centroid, principal axes and moments of a homogeneous hexagonal prism."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check

from ._prism import A_SIDE, HEIGHT, mass_properties

ID = "ex3.11"


def solve() -> Solution:
    """Worked solution of Exercise 3.11."""
    a, h = A_SIDE, HEIGHT
    s = Solution(
        ID, "Hexagonal prism: centroid and principal inertia",
        "\"A rectangular prism with regular hexagonal bases whose sides are 25 mm long and "
        "whose height is 150 mm ... Find the centroidal principal axes and moments of "
        "inertia\"",
        "Angeles, Sec. 3.9, Exercise 3.11",
        given={"a (m)": a, "h (m)": h,
               "region": "hexagon centred at O in the x-y plane, 0 <= z <= h; two edges at "
                         "y = +-a sqrt(3)/2"},
        assumptions=["Homogeneous density rho; results per unit density (m^5) and per kg "
                     "of mass (m^2)."])
    V, c, I_C, _ = mass_properties(0, h)
    s.step("volume", V, "Exact iterated integral of 1 over the prism.")
    s.step("centroid", c, "First moments / V: on the axis, at mid-height.")
    s.step("centroidal inertia per unit density", I_C,
           "Integral of ||r||^2 1 - r r^T about O, moved to C by Steiner (Eq. 3.133a).")
    per_kg = (I_C / V).applyfunc(sp.radsimp)
    s.step("per kg", per_kg, "I_C / m with m = rho V.")
    s.answers = {"volume_m3": V, "centroid_m": c, "I_C_per_rho_m5": I_C,
                 "I_C_per_kg_m2": per_kg,
                 "principal_axes": "the prism axis Z (moment I_zz) and every axis normal to "
                                   "it through C (moment I_xx = I_yy: the hexagon is "
                                   "isotropic in its plane)",
                 "principal_moments_per_kg_m2": sp.Matrix([per_kg[0, 0], per_kg[1, 1],
                                                           per_kg[2, 2]])}
    A = 3 * sp.sqrt(3) / 2 * a**2
    s.check(exact_check("volume = hexagon area x h, area = 3 sqrt(3) a^2 / 2", [V - A * h]))
    s.check(exact_check("closed forms: I_zz/m = 5 a^2/12, I_xx/m = I_yy/m = 5 a^2/24 + h^2/12, "
                        "products zero",
                        [per_kg[2, 2] - 5 * a**2 / 12, per_kg[0, 0] - 5 * a**2 / 24 - h**2 / 12,
                         per_kg[1, 1] - per_kg[0, 0], per_kg[0, 1], per_kg[0, 2], per_kg[1, 2]]))
    s.check(exact_check("principal: I_C e_z = I_zz e_z, I_C e_x = I_xx e_x",
                        [I_C * sp.Matrix([0, 0, 1]) - I_C[2, 2] * sp.Matrix([0, 0, 1]),
                         I_C * sp.Matrix([1, 0, 0]) - I_C[0, 0] * sp.Matrix([1, 0, 0])]))
    return s
