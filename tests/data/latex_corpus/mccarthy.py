"""J. M. McCarthy, *An Introduction to Theoretical Kinematics*, MIT Press, 1990, ch. 2-3
. Notation: the Cayley map C(b) = (I - B)^{-1}(I + B) of the Rodrigues
vector b (B = [b]x), a function of b (his (2.33)); its properties. Truth by NumPy."""

import numpy as np
from _num import I3, E, hat


def _f(x):
    """A 1 x 1 array (or a number) as a float."""
    return np.asarray(x, float).item()

BOOK = {"key": "mccarthy", "title": "McCarthy, An Introduction to Theoretical Kinematics",
        "edition": "MIT Press, 1990"}

TABLE = r"""
\mathbf{b}: vector
"""

C = r"C(\mathbf{b}) = (I_3 - [\mathbf{b}]_\times)^{-1}(I_3 + [\mathbf{b}]_\times)"


def _c(b):
    return np.linalg.inv(I3 - hat(b)) @ (I3 + hat(b))


ENTRIES = [
    E("2.4", "(2.33)", r"C(\mathbf{b})^T C(\mathbf{b}) = I_3", True,
      lambda v: (_c(v.b).T @ _c(v.b), I3), lets=(C,)),
    E("2.4", "(2.33)", r"C(\mathbf{b})\mathbf{b} = \mathbf{b}", True,
      lambda v: (_c(v.b) @ v.b, v.b), lets=(C,)),
    E("2.4", "(2.34)", r"C(-\mathbf{b}) = C(\mathbf{b})^T", True,
      lambda v: (_c(-v.b), _c(v.b).T), lets=(C,)),
    E("2.4", "(2.34)", r"C(-\mathbf{b}) = C(\mathbf{b})", False,
      lambda v: (_c(-v.b), _c(v.b)), lets=(C,)),
    E("2.4", "(2.33)", r"C(\mathbf{b}) = (I_3 + [\mathbf{b}]_\times)(I_3 - [\mathbf{b}]_\times"
      r")^{-1}", True, lambda v: (_c(v.b), (I3 + hat(v.b)) @ np.linalg.inv(I3 - hat(v.b))),
      lets=(C,)),
    E("2.4", "(2.33)", r"C(\mathbf{b}) = (I_3 - [\mathbf{b}]_\times)(I_3 + [\mathbf{b}]_\times"
      r")^{-1}", False, lambda v: (_c(v.b), (I3 - hat(v.b)) @ np.linalg.inv(I3 + hat(v.b))),
      lets=(C,)),
]
