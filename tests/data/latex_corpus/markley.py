"""F. L. Markley and J. L. Crassidis, *Fundamentals of Spacecraft Attitude Determination and
Control*, Springer, 2014, sec. 2.9. Notation: the quaternion q with its
vector part q_{1:3} and scalar part q_4 (scalar last), Xi(q) and Psi(q) the 4x3 matrices of
(2.88)-(2.89), functions of q; A(q) the attitude matrix (2.125). Truth by NumPy."""

import numpy as np
from _num import I3, E, hat


def _f(x):
    """A 1 x 1 array (or a number) as a float."""
    return np.asarray(x, float).item()

BOOK = {"key": "markley", "title": "Markley & Crassidis, Fundamentals of Spacecraft "
        "Attitude Determination and Control", "edition": "Springer, 2014"}

TABLE = r"""
\mathbf{q}: unit 4-vector
\mathbf{p}: 4-vector
"""

XI = (r"\Xi(\mathbf{q}) = \begin{bmatrix}\mathbf{q}_{4:4} I_3 + [\mathbf{q}_{1:3}]_\times\\ "
      r"-\mathbf{q}_{1:3}^T\end{bmatrix}")
PSI = (r"\Psi(\mathbf{q}) = \begin{bmatrix}\mathbf{q}_{4:4} I_3 - [\mathbf{q}_{1:3}]_\times\\ "
       r"-\mathbf{q}_{1:3}^T\end{bmatrix}")
A = (r"A(\mathbf{q}) = (\mathbf{q}_{4:4}^2 - \mathbf{q}_{1:3}^T\mathbf{q}_{1:3})I_3 + "
     r"2\mathbf{q}_{1:3}\mathbf{q}_{1:3}^T - 2\mathbf{q}_{4:4}[\mathbf{q}_{1:3}]_\times")


def _xi(q, s=1):
    v, q4 = q[:3], _f(q[3, 0])
    return np.vstack([q4 * I3 + s * hat(v), -v.T])


def _a(q):
    v, q4 = q[:3], _f(q[3, 0])
    return (q4 ** 2 - _f(v.T @ v)) * I3 + 2 * v @ v.T - 2 * q4 * hat(v)


ENTRIES = [
    E("2.9.3", "(2.90)", r"\Xi(\mathbf{q})^T\Xi(\mathbf{q}) = I_3", True,
      lambda v: (_xi(v.q).T @ _xi(v.q), I3), lets=(XI,)),
    E("2.9.3", "(2.90)", r"\Xi(\mathbf{p})^T\Xi(\mathbf{p}) = (\mathbf{p}^T\mathbf{p})I_3",
      True, lambda v: (_xi(v.p).T @ _xi(v.p), _f(v.p.T @ v.p) * I3), lets=(XI,)),
    E("2.9.3", "(2.91)", r"\Xi(\mathbf{p})^T\mathbf{p} = \mathbf{0}", True,
      lambda v: (_xi(v.p).T @ v.p, np.zeros((3, 1))), lets=(XI,)),
    E("2.9.3", "(2.91)", r"\Psi(\mathbf{p})^T\mathbf{p} = \mathbf{0}", True,
      lambda v: (_xi(v.p, -1).T @ v.p, np.zeros((3, 1))), lets=(PSI,)),
    E("2.9.3", "(2.125)", r"A(\mathbf{q}) = \Xi(\mathbf{q})^T\Psi(\mathbf{q})", True,
      lambda v: (_a(v.q), _xi(v.q).T @ _xi(v.q, -1)), lets=(XI, PSI, A)),
    E("2.9.3", "(2.125)", r"A(\mathbf{q}) = \Psi(\mathbf{q})^T\Xi(\mathbf{q})", False,
      lambda v: (_a(v.q), _xi(v.q, -1).T @ _xi(v.q)), lets=(XI, PSI, A)),
    E("2.9.3", "(2.129)", r"A(\mathbf{q})^T A(\mathbf{q}) = I_3", True,
      lambda v: (_a(v.q).T @ _a(v.q), I3), lets=(A,)),
    E("2.9.3", "(2.129)", r"A(\mathbf{q})\mathbf{q}_{1:3} = \mathbf{q}_{1:3}", True,
      lambda v: (_a(v.q) @ v.q[:3], v.q[:3]), lets=(A,)),
    E("2.9.3", "(2.129)", r"A(\mathbf{p})\mathbf{p}_{1:3} = \mathbf{p}_{1:3}", False,
      lambda v: (_a(v.p) @ v.p[:3], v.p[:3]), lets=(A,), note="a unit quaternion only"),
    E("2.9", "(2.84)", r"\mathbf{q}_{1:3}^T\mathbf{q}_{1:3} + \mathbf{q}_{4:4}^2 = 1", True,
      lambda v: (_f(v.q[:3].T @ v.q[:3]) + _f(v.q[3, 0]) ** 2, 1.0)),
]
