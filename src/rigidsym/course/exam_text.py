"""What a handout says: each exercise's task stated once on the student's data (no book
numbers to be replaced), and each answer box named in the book's words and symbols.

The tasks paraphrase the chapter's exercises (Angeles, Sec. 3.9) without their numbers:
the numbers are the student's, in the data table under the task. A box label says what
the answer is, in the book's symbols (``[Q]_1``, ``p*``, ``[w]_2``), its shape, unit and,
for a list, its order; the answer's column name in the class's answers CSV follows it.
"""

from __future__ import annotations

__all__ = ["ANSWER_FORMAT", "task", "box_label", "TASKS", "BOXES", "ASKED", "lms_statement"]

#: exercise -> the answers a handout asks (default: every answer that is a value); 3.10's
#: table of all twelve sequences stays in the key
ASKED = {"ex3.10": ("W", "W_body", "det_W", "W_inverse")}

#: exercise -> the task, stated on "the data below" (no number of the book's)
TASKS = {
    "ex3.1": "A cube ABCDEFGH (its edges AB, AD, AE as the data give them) is displaced "
             "rigidly: its vertices A, B, D, E move to A', "
             "B', D', E' (data below). Find the rotation Q undergone by the cube, its angle "
             "phi and unit axis e, the Plücker coordinates of the line L of the points "
             "displaced least, and the intersections of L with the coordinate planes.",
    "ex3.2": "The regular tetrahedron P_1 P_2 P_3 P_4 (data below) carries the forces f_1, "
             "of unit magnitude along P_2 P_3, and f_2, of unit magnitude along P_4 P_1. Find "
             "the point P, closest to P_4, about which the moment n of the system is of "
             "minimum magnitude, that moment, and the resultant force f.",
    "ex3.4": "Two six-axis force sensors, with frames F_1 and F_2, read the same wrench "
             "(data below). Show from the invariants of the wrench that the readings are "
             "compatible, and find the orientation [Q]_1 of F_2 relative to F_1.",
    "ex3.5": "A joint axis is estimated by its normalised Plücker coordinates [e; n] in "
             "the gripper frame (data below: e is the unit vector of the axis, n its moment "
             "about the origin). Find the distance d of the axis from the origin and the "
             "point P* of the axis closest to the origin, p* = e x n.",
    "ex3.6": "A gripper G grasps the truncated unit cube [0, 1]^3 of the data below by its "
             "two cut faces (the finger planes, normal to the data's face normal) and "
             "carries its point P to the vertex C'. The gripper's frame G'' is fixed by the "
             "grasp: i'' is the unit normal of the finger planes with positive components; "
             "j'' is the unit vector normal to i'' and to the diagonal CC' with a positive Z "
             "component; k'' = i'' x j''. G'' starts parallel to F, so the rotation of the "
             "grasp is Q = [i'' j'' k''] (columns in F). Find Q, its angle phi and unit axis "
             "e, and the axis of the points of G displaced least (a point p_0 on it and its "
             "Plücker coordinates).",
    "ex3.7": "The moment of a line is measured about two points A and B (data below). Find "
             "the unit vector e of the line, the point P* of the line closest to the origin, "
             "and the Plücker coordinates of the line about the origin.",
    "ex3.10": "For the Euler-angle sequence below, find the matrix W with omega = W "
              "eta_dot (in the fixed frame) and W_body (in the body frame), det W, and the "
              "angles at which W is singular.",
    "ex3.11": "A prism with regular hexagonal bases of side a and height h (data below) is "
              "made of a homogeneous material. The frame: origin O at the centre of the "
              "lower base, Z along the axis, the base's vertices at (+-a, 0, 0) and "
              "(+-a/2, +-a sqrt(3)/2, 0) (two sides parallel to X). Find its volume, its "
              "centroid C, its centroidal inertia matrix [I_C] per unit density and per "
              "unit mass, and its principal moments.",
    "ex3.12": "The hexagonal prism of the data below (side a, height h; origin O at the "
              "centre of the lower base, Z along the axis, the base's vertices at "
              "(+-a, 0, 0) and (+-a/2, +-a sqrt(3)/2, 0)) is cut by a plane through the base "
              "edge y = -a sqrt(3)/2, z = 0 at 45 deg to its axis, rising towards +Y: "
              "z = y + a sqrt(3)/2. The wedge is the part below the plane, the upper part "
              "the rest. For each part, find the volume, the centroid, the centroidal "
              "inertia matrix, the principal moments (ascending) and the principal axes (in "
              "the order of the moments).",
    "ex3.14": "Two observers A and B report the centroidal inertia matrix of one body, each "
              "in its own frame (data below). Show that the two reports are acceptable (the "
              "invariants agree), and find the principal moments and the rotation [Q]_B "
              "taking A's frame to B's.",
    "ex3.19": "A six-axis force sensor with frame F_S reads the moment [n]_S about its "
              "origin S and the force [f]_S. The gripper point P lies at d = p - s from S, "
              "and the gripper frame F_2 has the orientation Q of the data below "
              "([x]_S = Q [x]_2). Find the wrench [w]_2 = [n_2; f_2] acting at P, in F_2.",
}

#: exercise -> answer name -> its label: the book's symbol and words, shape, unit, order
BOXES = {
    "ex3.1": {"Q": "rotation matrix Q of the cube (3 x 3, rows in order)",
              "phi": "angle of rotation phi (rad)",
              "e": "unit vector e of the axis of rotation (3)",
              "plucker": "Plücker coordinates [e; n] of the line L (6: e, then its moment "
                         "n about the origin, m)",
              "intersection_x=0": "intersection of L with the plane x = 0 (3, m)",
              "intersection_y=0": "intersection of L with the plane y = 0 (3, m)",
              "intersection_z=0": "intersection of L with the plane z = 0 (3, m)"},
    "ex3.2": {"P": "position vector p of the point P (3, m)",
              "P_barycentric": "barycentric coordinates of P in P_1 ... P_4 (4, summing "
                               "to 1)",
              "n_min": "moment n of the system about P (3, N m)",
              "f": "resultant force f = f_1 + f_2 (3, N)",
              "n_min_magnitude": "the minimum magnitude ||n|| (N m)"},
    "ex3.4": {"compatible": "are the readings compatible? (true or false)",
              "invariants": "invariants of the wrench (3, in this order: f . f in N^2, "
                            "n . n in N^2 m^2, n . f in N^2 m)",
              "Q_1_2": "orientation [Q]_1 of F_2 in F_1, [x]_1 = Q [x]_2 (3 x 3)",
              "residual": "least-squares residual of the fit (N m, N)"},
    "ex3.5": {"d": "distance d of the axis from the origin (m)",
              "p_star": "position vector p* of the point P* (3, m)"},
    "ex3.6": {"Q": "rotation matrix Q of the grasp (3 x 3)",
              "phi": "angle of rotation phi (rad)",
              "e": "unit vector e of the axis of rotation (3)",
              "axis_point_p0": "a point p_0 of the axis of least displacement (3, m)",
              "axis_plucker": "Plücker coordinates [e; n] of that axis (6: e, then n, m)"},
    "ex3.7": {"e": "unit vector e of the line (3)",
              "p_star": "position vector p* of the point P* (3, m)",
              "plucker_O": "Plücker coordinates [e; n_O] about the origin (6: e, then n_O, "
                           "m)"},
    "ex3.10": {"W": "matrix W with omega = W eta_dot, fixed frame (3 x 3)",
               "W_body": "matrix W with omega = W eta_dot, body frame (3 x 3)",
               "det_W": "det W (in the angles)",
               "W_inverse": "W^-1 where it exists (3 x 3)"},
    "ex3.11": {"volume_m3": "volume V (m^3)",
               "centroid_m": "position vector c of the centroid C; origin O at the centre "
                             "of the lower base, Z along the axis (3, m)",
               "I_C_per_rho_m5": "centroidal inertia matrix [I_C] / rho (3 x 3, m^5)",
               "I_C_per_kg_m2": "centroidal inertia matrix [I_C] / m (3 x 3, m^2)",
               "principal_moments_per_kg_m2": "principal moments / m (3, m^2, in the order "
                                              "I_xx, I_yy, I_zz)"},
    "ex3.14": {"acceptable": "are the two reports acceptable? (true or false)",
               "invariants": "invariants of [I]: tr I, the sum of its principal 2 x 2 "
                             "minors, det I (3, in this order)",
               "principal_moments": "principal moments, ascending (3, kg m^2)",
               "Q_B_A": "a rotation [Q]_B taking A's frame to B's, [I]_B = Q [I]_A Q^T "
                        "(3 x 3; a principal axis has no sense, so four rotations have "
                        "this property when the principal moments differ: give any one)",
               "residual": "least-squares residual (kg m^2)"},
    "ex3.15": {"moment_along_d": "the principal moment about P along d = p - c, d = delta "
                                 "e_1 (in I_1, I_2, I_3, m, delta: the centroidal principal "
                                 "moments, the mass, the distance)",
               "moments_normal_to_d": "the two principal moments about P normal to d (2, in "
                                      "this order: along the principal axis of I_2, then "
                                      "of I_3)"},
    "ex3.19": {"w_2": "wrench [w]_2 = [n_2; f_2] at P, in F_2 (6: N m, then N)",
               "n_2": "moment [n]_2 about P, in F_2 (3, N m)",
               "f_2": "force [f]_2, in F_2 (3, N)"},
}

#: the boxes of a true-or-false variant (any exercise)
TRUE_OR_FALSE = {"holds": "true or false, for (i), (ii), (iii) in order (3: true, false, "
                          "...)",
                 "why": "the number of the reason, for (i), (ii), (iii) in order (3: 1 to 4)"}

_PARTS = {"wedge": "the wedge (below the cut)", "upper": "the upper part"}


#: what every handout says about writing an answer (the grader's reading and tolerance)
ANSWER_FORMAT = (
    "How to write an answer: a number with a decimal point (1.25) or exact (sqrt(3)/2, "
    "2*pi/3); a vector as its entries separated by commas (1, 0, 2); a matrix row by row, "
    "rows separated by ';' (1, 0, 0; 0, 1, 0; 0, 0, 1); true or false as true or false. "
    "Units: as each box says (m, rad, kg m^2); another unit is read when written after the "
    "number ('25 mm', '30 deg'). An answer is right within 0.1 % of the largest entry of "
    "the right answer: give at least 4 significant figures. An axis and angle may be given "
    "as (e, phi) or (-e, -phi), an angle plus any whole number of turns, with the Plücker "
    "array of the same sign as e; a point of an axis may be any point of it; principal "
    "axes each with either sign; a rotation asked by a property it has (Q [I]_A Q^T = "
    "[I]_B) may be any rotation that has it.")


def task(ex_id: str, statement: str) -> str:
    """The task of ``ex_id`` on the data below; the solution's own statement where the
    exercise has no numbers to replace (a proof, a true-or-false)."""
    return TASKS.get(ex_id, statement)


def box_label(ex_id: str, name: str) -> str:
    """The label of the answer box ``name`` of ``ex_id``: the book's symbol and words."""
    got = BOXES.get(ex_id, {}).get(name) or TRUE_OR_FALSE.get(name)
    if got:
        return got
    if ex_id == "ex3.12":
        tag, _, rest = name.partition("_")
        inner = {
            "principal_moments_per_kg_m2": "principal moments / m (3, m^2, ascending)",
            "principal_moments_per_rho_m5": "principal moments / rho (3, m^5, ascending)",
            "principal_axes": "principal axes, one unit vector per column, in the order "
                              "of the moments (3 x 3)",
            "axis_angle_from_y_rad": ("angle alpha from Y towards Z of the principal axis "
                                      "[0, cos alpha, sin alpha] of the smaller moment in "
                                      "the Y-Z plane (rad)")}.get(
            rest) or BOXES["ex3.11"].get(rest)
        if inner:
            return f"{_PARTS.get(tag, tag)}: {inner}"
    if ex_id == "ex3.10":
        for stem, words in (("det_W_body_", "det W_body for the sequence "),
                            ("det_W_", "det W for the sequence "),
                            ("singular_", "singular angles for the sequence ")):
            if name.startswith(stem):
                return words + name[len(stem):]
    return name.replace("_", " ")


def lms_statement(p: dict) -> str:
    """A problem's statement as an LMS question shows it (HTML): the task the handout
    states (kept in the key record as ``task``: a proof's true-or-false statements in the
    book's notation, with its symbols defined) and the student's data, each datum named as
    the handout's table names it (no datum of a drawn statement's internal numbering)."""
    import html

    from rigidsym.course.worked import exercise_module, parameters

    mod = exercise_module(p["id"])
    text = p.get("task") or task(p["id"], getattr(mod, "STATEMENT", ""))
    names = {q.name for q in parameters(p["id"])}
    data = [f"<li>{html.escape(k)} = {html.escape(_shown(v))}</li>"
            for k, v in p["data"].items() if k in names]
    return f"<p>{html.escape(text)}</p>" + (f"<ul>{''.join(data)}</ul>" if data else "")


def _shown(v) -> str:
    """A datum as the handout shows it: ``[1, -1/20, 0]``."""
    if isinstance(v, list):
        return "[" + ", ".join(_shown(x) for x in v) + "]"
    return str(v)
