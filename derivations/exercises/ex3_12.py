"""Exercise 3.12: the hexagonal prism cut by a plane at 45 deg through a base edge."""

from __future__ import annotations

import sympy as sp

from rigidsym.course.worked import Param, Solution, exact_check, settled, values_only

from ._prism import (
    A_SIDE,
    HEIGHT,
    mass_properties,
    part_properties,
    positive_sizes,
    principal_check,
    principal_yz,
    y,
)

ID = "ex3.12"
TITLE = "Prism cut at 45 degrees: two parts"
STATEMENT = ("\"cutting it into two parts, which are separated by a plane that contains one of "
             "the edges of the base and makes an angle of 45 deg with the axis of the prism. "
             "Find the centroidal principal axes and moments of inertia of each of the two "
             "parts.\"")
CITATION = "Angeles, Sec. 3.9, Exercise 3.12"
FIGURE_NAME = "cut"
#: the solver runs on floating data for a slip's replay (rigidsym.course.worked.solve_values):
#: where the cut leaves the prism, and how each part splits at y = 0, are decided on values
#: clear of 0 (settled), the principal axes' case on is_zero
VALUES_REPLAY = True
#: what the answers are: principal axes are lines (each column up to its sign), so the
#: angle of the first one from Y is defined modulo pi
ANSWER_CLASSES = tuple(
    d for tag in ("wedge", "upper") for d in (
        {"kind": "columns up to sign", "name": f"{tag}_principal_axes"},
        {"kind": "angle", "name": f"{tag}_axis_angle_from_y_rad", "period": "pi"}))
PARAMETERS = (Param("a", A_SIDE, (), "side of the regular hexagonal bases", "m"),
              Param("h", HEIGHT, (), "height of the prism (below a sqrt(3) the cut leaves "
                    "through the top face)", "m"))
VARIANTS = (
    ("a wider prism", {"a": "0.05", "h": "0.15"}),
    ("a prism so short that the cut leaves through the top face", {"h": "0.025"}),
)


def _pieces(a, h, tag: str, through_top: bool) -> list:
    """The part ``tag`` ("wedge" below the cut plane z = y + a sqrt(3)/2, "upper" above it)
    as pieces ``(ylo, yhi, zlo(y), zhi(y))``; ``through_top``: the plane leaves through the
    top face, at y = h - a sqrt(3)/2, and the wedge is the full height beyond."""
    S = a * sp.sqrt(3) / 2
    if not through_top:
        return [(-S, S, 0, y + S)] if tag == "wedge" else [(-S, S, y + S, h)]
    y0 = h - S
    return ([(-S, y0, 0, y + S), (y0, S, 0, h)] if tag == "wedge" else [(-S, y0, y + S, h)])


def _part(s: Solution, name: str, a, h, tag: str, through_top: bool):
    V, c, I_C, I_O = part_properties(_pieces, a, h, tag, through_top)
    s.step(f"{name}: volume", V, "Exact iterated integral over the part (once in a symbolic "
           "a and h for this shape of the cut, then at the data).")
    s.step(f"{name}: centroid", c, "First moments / V (x = 0 by symmetry in the plane x = 0).")
    s.step(f"{name}: I_C per unit density", I_C,
           "Integral about O moved to the centroid (Eq. 3.133a); I_xy = I_xz = 0 by symmetry.")
    pr, alpha = principal_yz(I_C)
    s.step(f"{name}: principal moments per unit density", sp.Matrix([p[0] for p in pr]),
           "x is principal; the y-z block's eigenvalues (I_yy + I_zz)/2 -+ "
           "sqrt(((I_yy - I_zz)/2)^2 + I_yz^2); sorted, smallest first.")
    s.step(f"{name}: principal axes", sp.Matrix.hstack(*[p[1] for p in pr]),
           "Unit columns, in the order of the moments: e_x, and [0, I_yz, lambda - I_yy] "
           "normalised in the y-z plane.")
    return V, c, I_C, I_O, pr, alpha


def solve(a=A_SIDE, h=HEIGHT) -> Solution:
    """Worked solution of Exercise 3.12 (side ``a`` and height ``h`` in metres)."""
    S = a * sp.sqrt(3) / 2
    s = Solution(
        ID, TITLE, STATEMENT, CITATION,
        given={"cut plane": "z = y + a sqrt(3)/2 (contains the base edge y = -a sqrt(3)/2, "
                            "z = 0; normal [0, -1, 1]/sqrt(2), at 45 deg to the Z axis)",
               "a (m)": a, "h (m)": h},
        assumptions=["Same frame as Exercise 3.11 (hexagon centred at O, 0 <= z <= h). The "
                     "plane rises to z = a sqrt(3) (43.3 mm for the book's a) at the far edge: "
                     "at or below h it cuts off a wedge (lower part); above h it leaves "
                     "through the top face, and the lower part is the rest below the plane.",
                     "Results per unit density (m^5) and per kg of the part (m^2)."])
    positive_sizes(s, a, h)
    y0 = sp.radsimp(h - S)  # where the cut plane z = y + S meets the top face z = h
    through_top = not settled(sp.radsimp(y0 - S)) >= 0
    if through_top:
        s.step("the cut leaves through the top face", y0,
               "a sqrt(3) > h: the plane meets the top face z = h along y = h - a sqrt(3)/2; "
               "beyond it the lower part is the full height.")
    lower = _part(s, "wedge", a, h, "wedge", through_top)
    upper = _part(s, "upper part", a, h, "upper", through_top)
    I_full = mass_properties(0, h, a)[3]
    for tag, (V, c, I_C, _, pr, alpha) in (("wedge", lower), ("upper", upper)):
        s.answers[f"{tag}_volume_m3"] = V
        s.answers[f"{tag}_centroid_m"] = c
        s.answers[f"{tag}_I_C_per_rho_m5"] = I_C
        s.answers[f"{tag}_principal_moments_per_rho_m5"] = sp.Matrix([p[0] for p in pr])
        s.answers[f"{tag}_principal_moments_per_kg_m2"] = sp.Matrix([p[0] / V for p in pr])
        s.answers[f"{tag}_principal_axes"] = sp.Matrix.hstack(*[p[1] for p in pr])
        s.answers[f"{tag}_axis_angle_from_y_rad"] = alpha
    if values_only():
        return s                # a replay for its values: no check (its exact solve checks)
    s.extra = _in_mm(s)
    A = 3 * sp.sqrt(3) / 2 * a**2
    s.check(exact_check("volumes add to the prism's, and the wedge is half the prism below "
                        "z = 2 S for a tall prism (Cavalieri)",
                        [lower[0] + upper[0] - A * h]
                        + ([] if through_top else [lower[0] - S * A])))
    s.check(exact_check("inertia about O is additive: wedge + upper = whole prism",
                        [lower[3] + upper[3] - I_full]))
    for tag, (_, _, I_C, _, pr, _) in (("wedge", lower), ("upper", upper)):
        s.check(principal_check(f"{tag}: I_C v = lambda v for the three principal pairs, and "
                                "the axes are orthonormal (R^T R = 1)", I_C, pr))
    return s


def _in_mm(s: Solution) -> str:
    """The answers in the book's units (mm), to 4 digits: volume, centroid, the principal
    moments per kg (sorted) and their unit axes."""
    out = ["In the book's units (mm), to 4 digits:"]
    for tag, name in (("wedge", "lower part"), ("upper", "upper part")):
        V = float(s.answers[f"{tag}_volume_m3"]) * 1e9
        c = [float(x) * 1e3 for x in s.answers[f"{tag}_centroid_m"]]
        m = [float(x) * 1e6 for x in s.answers[f"{tag}_principal_moments_per_kg_m2"]]
        R = s.answers[f"{tag}_principal_axes"]
        out.append(f"  {name}: V = {V:.4g} mm^3, C = [{', '.join(f'{x:.4g}' for x in c)}] mm")
        for k in range(3):
            axis = ", ".join(f"{float(x):.4f}" for x in R[:, k])
            out.append(f"    I_{k + 1}/m = {m[k]:.4g} mm^2 about [{axis}]")
    return "\n".join(out)


def figure(s: Solution):
    """The prism, the 45-degree cut plane, and each part's centroid with its principal
    axes (drawn from the answers)."""
    from ._draw import arrow, axes3d, new_figure, point
    from ._prism import draw_prism

    a, h = s.given["a (m)"], s.given["h (m)"]
    S = a * sp.sqrt(3) / 2
    fig, ax = new_figure("Exercise 3.12: the prism cut at 45 degrees, two parts")
    pts = draw_prism(ax, a, h)
    _draw_cut(ax, a, S)
    for tag, colour in (("wedge", "tab:red"), ("upper", "tab:blue")):
        c, axes = s.answers[f"{tag}_centroid_m"], s.answers[f"{tag}_principal_axes"]
        per_kg = s.answers[f"{tag}_principal_moments_per_kg_m2"]
        point(ax, c, colour, f"{tag}: centroid; principal axes, length = radius of "
                             f"gyration")
        for k in range(3):
            # scaled: each axis is drawn as long as its radius of gyration sqrt(I_k / m)
            r = float(sp.sqrt(sp.N(per_kg[k], 15)))
            v = [float(x) for x in axes[:, k]]
            arrow(ax, c, sp.Matrix(v), colour, scale=r)
            tip = [float(ci) + r * vi for ci, vi in zip(c, v, strict=True)]
            ax.text(*tip, f" {k + 1}: {1000 * r:.3g} mm", color=colour, fontsize=7)
    axes3d(ax, pts)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    return fig


def given_figure(s: Solution):
    """The given data only (the students' handout): the prism of side a and height h and
    the 45-degree cut through a base edge; no centroid, no axes, no moments."""
    from ._draw import axes3d, new_figure
    from ._prism import draw_prism

    a, h = sp.sympify(s.data["a"]), sp.sympify(s.data["h"])
    S = a * sp.sqrt(3) / 2
    fig, ax = new_figure(f"Hexagonal prism (side a = {a} m, height h = {h} m) and the cut")
    pts = draw_prism(ax, a, h)
    _draw_cut(ax, a, S)
    axes3d(ax, pts, legend=False)
    return fig


def _draw_cut(ax, a, S) -> None:
    """The 45-degree cut, z = y + S, on the side faces of the prism of side a."""
    from ._draw import segment
    from ._prism import hexagon

    hx = hexagon(a)
    for k, (px, py) in enumerate(hx):
        qx, qy = hx[(k + 1) % 6]
        segment(ax, (px, py, py + S), (qx, qy, qy + S), color="tab:orange",
                label="cut plane" if k == 0 else None)


def random_data(rng) -> dict:
    """A variant with readable sizes in metres (an exam's draw): the side a (1 to 10 cm)
    and a height h of 2 to 6 sides, so that h >= a sqrt(3) and the cut leaves through a
    side face; 50 variants."""
    from decimal import Decimal

    a = rng.choice([f"0.{k:02d}" for k in range(1, 10)] + ["0.1"])
    k = rng.choice(["2", "3", "4", "5", "6"])
    return {"a": a, "h": format((Decimal(a) * Decimal(k)).normalize(), "f")}
