"""Exercise 3.11: centroid, principal axes and moments of a homogeneous hexagonal prism."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check

from ._prism import A_SIDE, HEIGHT, mass_properties, positive_sizes

ID = "ex3.11"
TITLE = "Hexagonal prism: centroid and principal inertia"
STATEMENT = ("\"A rectangular prism with regular hexagonal bases whose sides are 25 mm long "
             "and whose height is 150 mm ... Find the centroidal principal axes and moments "
             "of inertia\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.11"
FIGURE_NAME = "prism"
PARAMETERS = (Param("a", A_SIDE, (), "side of the regular hexagonal bases", "m"),
              Param("h", HEIGHT, (), "height of the prism", "m"))
VARIANTS = (
    ("a flat hexagonal plate", {"a": "0.05", "h": "0.01"}),
)


def solve(a=A_SIDE, h=HEIGHT) -> Solution:
    """Worked solution of Exercise 3.11 (side ``a`` and height ``h`` in metres)."""
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"a (m)": a, "h (m)": h,
               "region": "hexagon centred at O in the x-y plane, 0 <= z <= h; two edges at "
                         "y = +-a sqrt(3)/2"},
        assumptions=["Homogeneous density rho; results per unit density (m^5) and per kg "
                     "of mass (m^2)."])
    positive_sizes(s, a, h)
    V, c, I_C, _ = mass_properties(0, h, a)
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


def slips(s: Solution) -> dict:
    """The exercise's own slip, for the grader: the inertia about the centre O of the base
    (the axis through the base) instead of the centroid C, by Steiner (Eq. 3.133a)."""
    V, c = s.answers["volume_m3"], s.answers["centroid_m"]
    shift = c.dot(c) * sp.eye(3) - c * c.T
    I_O = s.answers["I_C_per_rho_m5"] + V * shift
    per_kg = s.answers["I_C_per_kg_m2"] + shift
    return {"I_C_per_rho_m5": [("reference point", "the inertia about the base's centre O, "
                                "not the centroid C", I_O)],
            "I_C_per_kg_m2": [("reference point", "the inertia about the base's centre O, "
                               "not the centroid C", per_kg)],
            "principal_moments_per_kg_m2": [("reference point", "moments about the base's "
                                             "centre O, not the centroid C",
                                             sp.Matrix([per_kg[0, 0], per_kg[1, 1],
                                                        per_kg[2, 2]]))]}


def figure(s: Solution):
    """The prism, its centroid and its centroidal principal axes (labelled with the
    principal moments per kg)."""
    from ._draw import arrow, axes3d, new_figure, point
    from ._prism import draw_prism

    a, h = s.given["a (m)"], s.given["h (m)"]
    c, mom = s.answers["centroid_m"], s.answers["principal_moments_per_kg_m2"]
    fig, ax = new_figure("Exercise 3.11: hexagonal prism, centroid and principal axes")
    pts = draw_prism(ax, a, h)
    size = max(a, h) / 3
    colours = ("tab:red", "tab:green", "tab:blue")
    for k, name in enumerate("xyz"):
        axis = sp.zeros(3, 1)
        axis[k] = size
        arrow(ax, c, axis, colours[k], f"principal axis {name}: I/m = "
              f"{float(sp.N(mom[k])):.3g} m^2")
    point(ax, c, "k", "centroid C", "C")
    axes3d(ax, pts)
    return fig


def given_figure(s: Solution):
    """The prism of the given data only (side a, height h): no centroid, no axes, no
    moments (the students' handout)."""
    from ._draw import axes3d, new_figure
    from ._prism import draw_prism

    a, h = s.data["a"], s.data["h"]
    fig, ax = new_figure(f"Hexagonal prism: side a = {a} m, height h = {h} m")
    axes3d(ax, draw_prism(ax, a, h), legend=False)
    return fig


def random_data(rng) -> dict:
    """A variant with readable sizes in metres (an exam's draw): a side of 1 to 10 cm
    (or 2.5, 7.5 cm) and a height of 5 to 30 cm, whole centimetres; 312 variants, so a
    class of 30 gets 30 different prisms."""
    sides = [f"0.{k:02d}" for k in range(1, 10)] + ["0.1", "0.025", "0.075"]
    return {"a": rng.choice(sides),
            "h": rng.choice([f"{k / 100:g}" for k in range(5, 31)])}
