"""M. D. Shuster, "A survey of attitude representations", *J. Astronautical Sciences* 41(4),
1993, pp. 439-517. Notation: [[u]] the *negative* of the cross-product
matrix (his (57)), written here as the --let function N(u) = -[u]x, since the reader refuses
[[u]] by name; A(n, theta) the attitude matrix of the axis n and angle theta, a function of
two parameters; Gibbs vector g = tan(theta/2) n; quaternion (q, q4). The attitude matrix is
as the --let defines it; truth by NumPy."""

import numpy as np
from _num import I3, E, hat


def _f(x):
    """A 1 x 1 array (or a number) as a float."""
    return np.asarray(x, float).item()

BOOK = {"key": "shuster", "title": "Shuster, A survey of attitude representations",
        "edition": "J. Astronaut. Sci. 41(4), 1993"}

TABLE = r"""
\mathbf{n}: unit vector
\theta: angle
\theta_1: angle
\theta_2: angle
\mathbf{u}: vector
\mathbf{v}: vector
"""

N = r"N(\mathbf{u}) = -[\mathbf{u}]_\times"
A = (r"A(\mathbf{n},\theta) = \cos\theta\,I_3 + (1-\cos\theta)\mathbf{n}\mathbf{n}^T"
     r" - \sin\theta\,N(\mathbf{n})")
G = r"\mathbf{g} = \tan\frac{\theta}{2}\mathbf{n}"
GIBBS = (r"\frac{(1-\mathbf{g}\cdot\mathbf{g})I_3 + 2\mathbf{g}\mathbf{g}^T {s} 2N(\mathbf{g})}"
         r"{1+\mathbf{g}\cdot\mathbf{g}}")
QUAT = [r"\mathbf{q} = \sin\frac{\theta}{2}\mathbf{n}", r"q_4 = \cos\frac{\theta}{2}"]


def _N(u):
    return -hat(u)


def _A(n, t):
    return np.cos(t) * I3 + (1 - np.cos(t)) * n @ n.T - np.sin(t) * _N(n)


def _gibbs(v, s):
    g = np.tan(v.theta / 2) * v.n
    gg = _f(g.T @ g)
    return ((1 - gg) * I3 + 2 * g @ g.T + s * 2 * _N(g)) / (1 + gg)


ENTRIES = [
    E("4", "(79)", r"A(\mathbf{n},\theta)^T A(\mathbf{n},\theta) = I_3", True,
      lambda v: (_A(v.n, v.theta).T @ _A(v.n, v.theta), I3), lets=(N, A)),
    E("4", "(80)", r"A(\mathbf{n},\theta)\mathbf{n} = \mathbf{n}", True,
      lambda v: (_A(v.n, v.theta) @ v.n, v.n), lets=(N, A)),
    E("4", "(81)", r"A(\mathbf{n},-\theta) = A(\mathbf{n},\theta)^T", True,
      lambda v: (_A(v.n, -v.theta), _A(v.n, v.theta).T), lets=(N, A)),
    E("4", "(82)", r"A(\mathbf{n},\theta_1)A(\mathbf{n},\theta_2) = A(\mathbf{n},\theta_1 + "
      r"\theta_2)", True, lambda v: (_A(v.n, v.theta_1) @ _A(v.n, v.theta_2),
                                     _A(v.n, v.theta_1 + v.theta_2)), lets=(N, A)),
    E("4", "(82)", r"A(\mathbf{n},\theta_1)A(\mathbf{n},\theta_2) = A(\mathbf{n},\theta_1 - "
      r"\theta_2)", False, lambda v: (_A(v.n, v.theta_1) @ _A(v.n, v.theta_2),
                                      _A(v.n, v.theta_1 - v.theta_2)), lets=(N, A)),
    E("3", "(58)", r"N(\mathbf{u})\mathbf{v} = \mathbf{v}\times\mathbf{u}", True,
      lambda v: (_N(v.u) @ v.v, np.cross(v.v.ravel(), v.u.ravel()).reshape(3, 1)),
      lets=(N,)),
    E("3", "(58)", r"N(\mathbf{u})\mathbf{v} = \mathbf{u}\times\mathbf{v}", False,
      lambda v: (_N(v.u) @ v.v, np.cross(v.u.ravel(), v.v.ravel()).reshape(3, 1)),
      lets=(N,)),
    E("3", "(60)", r"N(\mathbf{u})^2 = \mathbf{u}\mathbf{u}^T - (\mathbf{u}^T\mathbf{u})I_3",
      True, lambda v: (_N(v.u) @ _N(v.u), v.u @ v.u.T - _f(v.u.T @ v.u) * I3), lets=(N,)),
    E("3", "(60)", r"N(\mathbf{u})^2 = \mathbf{u}\mathbf{u}^T + (\mathbf{u}^T\mathbf{u})I_3",
      False, lambda v: (_N(v.u) @ _N(v.u), v.u @ v.u.T + _f(v.u.T @ v.u) * I3), lets=(N,)),
    E("6", "(195)", r"A(\mathbf{n},\theta) = " + GIBBS.replace("{s}", "-"), True,
      lambda v: (_A(v.n, v.theta), _gibbs(v, -1)), lets=(N, A, G)),
    E("6", "(195)", r"A(\mathbf{n},\theta) = " + GIBBS.replace("{s}", "+"), False,
      lambda v: (_A(v.n, v.theta), _gibbs(v, 1)), lets=(N, A, G)),
    E("5", "(161)", r"A(\mathbf{n},\theta) = (q_4^2 - \mathbf{q}^T\mathbf{q})I_3 + 2\mathbf{q}"
      r"\mathbf{q}^T - 2q_4N(\mathbf{q})", True,
      lambda v: (_A(v.n, v.theta), _quat(v, -1)), lets=(N, A, *QUAT)),
    E("5", "(161)", r"A(\mathbf{n},\theta) = (q_4^2 - \mathbf{q}^T\mathbf{q})I_3 + 2\mathbf{q}"
      r"\mathbf{q}^T + 2q_4N(\mathbf{q})", False,
      lambda v: (_A(v.n, v.theta), _quat(v, 1)), lets=(N, A, *QUAT)),
]


def _quat(v, s):
    q, q4 = np.sin(v.theta / 2) * v.n, np.cos(v.theta / 2)
    return (q4 ** 2 - _f(q.T @ q)) * I3 + 2 * q @ q.T + s * 2 * q4 * _N(q)
