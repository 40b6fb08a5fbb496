"""The arrays of certcheck's second reader: matrices whose entries are texts of the
certificate's grammar (``(a)*(b) + ...``), and the operations the chapter's notation prints
on them (sum, product, transpose, cross product, cross-product matrix, inverse, determinant).
Each entry is built as text, never simplified: :func:`certcheck.check.check_identity`
compares it.
"""

from __future__ import annotations

__all__ = ["NotRead", "M", "scalar", "add", "mul", "vec3", "cross", "cpm", "det", "inverse"]


class NotRead(Exception):
    """The reader cannot read this text (the message says what)."""


class M:
    """A matrix of grammar texts (rows of strings); ``loose``: its shape rests on the size 3
    the reader gave a bare 1, O or 0, no operand confirming it (``1 - e e^T`` is firm)."""

    def __init__(self, rows, loose: bool = False):
        self.rows = [list(r) for r in rows]
        self.loose = loose

    @property
    def shape(self):
        return len(self.rows), len(self.rows[0])

    def t(self):
        return M(list(zip(*self.rows, strict=True)), self.loose)


def scalar(x: str) -> M:
    return M([[x]])


def add(a: M, b: M, sign: str) -> M:
    if a.shape != b.shape:
        raise NotRead(f"a sum of shapes {a.shape} and {b.shape}")
    return M([[f"({x}) {sign} ({y})" for x, y in zip(ra, rb, strict=True)]
              for ra, rb in zip(a.rows, b.rows, strict=True)], a.loose and b.loose)


def mul(a: M, b: M) -> M:
    if a.shape == (1, 1):
        return M([[f"({a.rows[0][0]})*({y})" for y in r] for r in b.rows], b.loose)
    if b.shape == (1, 1):
        return M([[f"({x})*({b.rows[0][0]})" for x in r] for r in a.rows], a.loose)
    if a.shape[1] != b.shape[0]:
        raise NotRead(f"a product of shapes {a.shape} and {b.shape}")
    cols = b.t().rows  # rows from a, columns from b: a loose square factor takes the other's
    rows_firm = not a.loose or a.shape[0] == a.shape[1] and not b.loose
    cols_firm = not b.loose or b.shape[0] == b.shape[1] and not a.loose
    return M([[" + ".join(f"({x})*({y})" for x, y in zip(r, c, strict=True)) for c in cols]
              for r in a.rows], not (rows_firm and cols_firm))


def vec3(v: M) -> list[str]:
    if v.shape in ((3, 1), (1, 3)):  # a column or a row: its three entries in order
        return [x for r in v.rows for x in r]
    raise NotRead(f"a 3-vector expected, shape {v.shape}")


def cross(a: M, b: M) -> M:
    x, y = vec3(a), vec3(b)
    return M([[f"({x[(i + 1) % 3]})*({y[(i + 2) % 3]}) - ({x[(i + 2) % 3]})*({y[(i + 1) % 3]})"]
              for i in range(3)])


def cpm(v: M) -> M:
    x = vec3(v)
    return M([["0", f"-({x[2]})", f"{x[1]}"], [f"{x[2]}", "0", f"-({x[0]})"],
              [f"-({x[1]})", f"{x[0]}", "0"]])


def det(v: M) -> M:
    """A square array's determinant, expanded by its first row (as written)."""
    n, a = v.shape[0], v.rows
    if v.shape != (n, n):
        raise NotRead(f"the determinant of a {v.shape} array")
    return v if n == 1 else scalar(" + ".join(
        f"({(-1) ** j})*({a[0][j]})*({det(_minor(v, 0, j)).rows[0][0]})" for j in range(n)))


def _minor(v: M, i: int, j: int) -> M:
    return M([r[:j] + r[j + 1:] for k, r in enumerate(v.rows) if k != i])


def inverse(v: M) -> M:
    """A scalar's reciprocal or a 3 x 3 matrix's inverse (adjugate over determinant)."""
    if v.shape == (1, 1):
        return scalar(f"1/({v.rows[0][0]})")
    if v.shape != (3, 3):
        raise NotRead(f"the inverse of a {v.shape} array")
    d = det(v).rows[0][0]
    return M([[f"({(-1) ** (i + j)})*({det(_minor(v, j, i)).rows[0][0]})/({d})" for j in
               range(3)] for i in range(3)], v.loose)
