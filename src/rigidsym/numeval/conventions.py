"""The second semantics' own table of the contested constructs: the readings it evaluates
for each construct that two books read two ways, written here from the books (not taken
from the symbolic reader's table, :mod:`rigidsym.latex.contested`), so that a reading the
two semantics shared by accident could not decide a statement alone.

- ``bracket cross``: ``[A\\mathbf{x}\\wedge]`` is the cross-product matrix of the content,
  ``(A x)^∧`` (Groves (2013) (2.50)), or ``A x^∧``, the operator bound to the factor before it
  (Featherstone (2008) (2.31)).
- ``quaternion product``: Hamilton's units ``ij = k`` with the scalar first (Hamilton 1843,
  Solà (2017) (8)), JPL's ``ij = -k`` with the scalar last (Trawny & Roumeliotis (2005) (2)),
  or Hamilton's units with the scalar last (Szeliski (2022) (2.42), Eigen's storage):
  :func:`rigidsym.numeval.values.quaternion_product` and
  :func:`rigidsym.numeval.values.quaternion_storage`.
- ``tangent order``: a twist ``[ω; v]`` (Lynch & Park) or ``[v; ω]`` (Barfoot),
  :func:`rigidsym.numeval.values.tangent_order`.
- ``star``: ``X^*`` of a 6x6 matrix is its transpose, the adjoint of Jain's rigid-body
  transformation operator (Jain (2011) ch. 1: ``V(y) = φ^*(x, y) V(x)``), or the inverse of
  the transpose, the dual of a motion transform (Featherstone (2008) (2.25): a force
  transforms by ``X^* = X^{-T}``).
- ``argument extent``: ``\\sin\\omega t`` (a function's argument without parentheses, then
  more scalar factors) is sin(ω) t, the operator taking one factor as in Rodrigues' formula
  written ``\\sin\\theta\\,\\hat\\omega`` (Murray, Li & Sastry (1994) (2.14)), or sin(ω t),
  the argument running over the whole product as in the vibration books' ``\\sin\\omega t``
  (Thomson & Dahleh (1998) ch. 1, Taylor (2005) (5.62)).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

__all__ = ["READINGS", "BRACKET_CROSS", "QUATERNION", "TANGENT", "STAR", "ARGUMENT_EXTENT",
           "choice_key", "settled", "declared_readings"]

#: [A x\wedge]: the content's hat, or A times x's hat
BRACKET_CROSS = ("content", "bind")
#: p \otimes q: Hamilton's (scalar first, ij = k), JPL's (scalar last, ij = -k), or
#: Hamilton's units stored scalar last
QUATERNION = ("Hamilton", "JPL", "Hamilton, scalar last")
#: a 6-vector's order: angular part first or translation first
TANGENT = ("angular first", "translation first")
#: X^* of a 6x6 matrix: its transpose (Jain's adjoint) or its inverse's transpose (the dual)
STAR = ("transpose", "dual")
#: \sin\omega t: the function of the next factor only, or of the whole scalar product after it
ARGUMENT_EXTENT = ("factor", "product")
#: every contested construct this semantics evaluates, by name, its readings
READINGS = {"bracket cross": BRACKET_CROSS, "quaternion product": QUATERNION,
            "tangent order": TANGENT, "star": STAR, "argument extent": ARGUMENT_EXTENT}


def choice_key(construct: str, text: str) -> str:
    """The choice point of ``construct`` (a key of :data:`READINGS`) written ``text``."""
    return f"{construct} {text}"


_SETTLED: ContextVar[dict | None] = ContextVar("numeval_settled", default=None)


def settled(construct: str) -> str | None:
    """The reading of ``construct`` the user declared for this evaluation, or ``None``
    (every reading of :data:`READINGS` is then evaluated)."""
    return (_SETTLED.get() or {}).get(construct)


@contextmanager
def declared_readings(readings: dict) -> Iterator[None]:
    """Within the block each construct of ``readings`` (name -> reading, one of
    :data:`READINGS`) is read so, as the user's ``--let 'CONSTRUCT: READING'`` says.

    Raises:
        ValueError: a construct or reading this semantics does not have.
    """
    for k, v in readings.items():
        if v not in READINGS.get(k, ()):
            raise ValueError(f"readings: {k!r}: {v!r} is no reading of this semantics")
    token = _SETTLED.set(dict(readings))
    try:
        yield
    finally:
        _SETTLED.reset(token)
