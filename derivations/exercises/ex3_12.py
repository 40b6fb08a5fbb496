"""Exercise 3.12: the hexagonal prism cut by a plane at 45 deg through a base edge."""

from __future__ import annotations

import sympy as sp

from rigidsym.checking.worked import Solution, exact_check

from ._prism import A_SIDE, HEIGHT, S, mass_properties, principal_yz, y

ID = "ex3.12"


def _part(s: Solution, name: str, zlo, zhi):
    V, c, I_C, I_O = mass_properties(zlo, zhi)
    s.step(f"{name}: volume", V, "Exact iterated integral over the part.")
    s.step(f"{name}: centroid", c, "First moments / V (x = 0 by symmetry in the plane x = 0).")
    s.step(f"{name}: I_C per unit density", I_C,
           "Integral about O moved to the centroid (Eq. 3.133a); I_xy = I_xz = 0 by symmetry.")
    pr, alpha = principal_yz(I_C)
    s.step(f"{name}: principal moments per unit density", sp.Matrix([p[0] for p in pr]),
           "x is principal; the y-z block's eigenvalues (I_yy + I_zz)/2 -+ "
           "sqrt(((I_yy - I_zz)/2)^2 + I_yz^2).")
    s.step(f"{name}: principal axes", sp.Matrix.hstack(*[p[1] for p in pr]),
           "Columns (unnormalised): e_x and [0, I_yz, lambda - I_yy] in the y-z plane.")
    return V, c, I_C, I_O, pr, alpha


def solve() -> Solution:
    """Worked solution of Exercise 3.12."""
    h = HEIGHT
    s = Solution(
        ID, "Prism cut at 45 degrees: two parts",
        "\"cutting it into two parts, which are separated by a plane that contains one of the "
        "edges of the base and makes an angle of 45 deg with the axis of the prism. Find the "
        "centroidal principal axes and moments of inertia of each of the two parts.\"",
        "Angeles, Sec. 3.9, Exercise 3.12",
        given={"cut plane": "z = y + a sqrt(3)/2 (contains the base edge y = -a sqrt(3)/2, "
                            "z = 0; normal [0, -1, 1]/sqrt(2), at 45 deg to the Z axis)",
               "a (m)": A_SIDE, "h (m)": h},
        assumptions=["Same frame as Exercise 3.11 (hexagon centred at O, 0 <= z <= h). The "
                     "plane reaches z = a sqrt(3) = 43.3 mm < h, so it cuts off a wedge "
                     "(lower part) and leaves the upper part.",
                     "Results per unit density (m^5) and per kg of the part (m^2)."])
    lower = _part(s, "wedge", 0, y + S)
    upper = _part(s, "upper part", y + S, h)
    I_full = mass_properties(0, h)[3]
    for tag, (V, c, I_C, _, pr, alpha) in (("wedge", lower), ("upper", upper)):
        s.answers[f"{tag}_volume_m3"] = V
        s.answers[f"{tag}_centroid_m"] = c
        s.answers[f"{tag}_I_C_per_rho_m5"] = I_C
        s.answers[f"{tag}_principal_moments_per_rho_m5"] = sp.Matrix([p[0] for p in pr])
        s.answers[f"{tag}_principal_moments_per_kg_m2"] = sp.Matrix([p[0] / V for p in pr])
        s.answers[f"{tag}_principal_axes"] = sp.Matrix.hstack(*[p[1] for p in pr])
        s.answers[f"{tag}_axis_angle_from_y_rad"] = alpha
    A = 3 * sp.sqrt(3) / 2 * A_SIDE**2
    s.check(exact_check("wedge volume = apothem x hexagon area (Cavalieri), volumes add to "
                        "the prism's", [lower[0] - S * A, lower[0] + upper[0] - A * h]))
    s.check(exact_check("inertia about O is additive: wedge + upper = whole prism",
                        [lower[3] + upper[3] - I_full]))
    for tag, (_, _, I_C, _, pr, _) in (("wedge", lower), ("upper", upper)):
        s.check(exact_check(f"{tag}: I_C v = lambda v for the three principal pairs",
                            [I_C * v - lam * v for lam, v in pr]))
    return s
