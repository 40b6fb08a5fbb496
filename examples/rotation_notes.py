"""A reader's notes on rotations about an axis, certified against their own text.

The text is ``examples/rotation_notes.md`` (Markdown with LaTeX displays, each tagged with
its id, ``\\tag{axis:rodrigues}``), the reading of its glyphs is
``examples/rotation_notes.reading.toml`` (each glyph's kind or model, each id's class).
Each declaration gives the display as ``latex=``, character for character, and proves the
relation written in Python; certcheck holds the certificate to the text and to the reading
(docs/own-equations.md, "Certified against your own text")::

    rigidsym verify --module examples/rotation_notes.py --certificates certs \\
        --book examples/rotation_notes.md --reading examples/rotation_notes.reading.toml

One form is misremembered on purpose (``expected="does-not-hold"``): its certificate gives
a counterexample point and proves the corrected form.
"""

from __future__ import annotations

import sympy as sp

from rigidsym import (
    I3,
    Rel,
    Statement,
    angle,
    cpm,
    equation,
    mat,
    rotation_from_natural_invariants,
    trace,
    unit_vector,
    vec,
)

# constrained atoms: e . e = 1, cos^2 + sin^2 = 1 (imposed exactly by the checker)
e, phi = unit_vector("e"), angle("phi")
# the text's glyphs, given their first-principles values by the model
Q, E, e_ = mat("Q"), mat("E"), vec("e")
MODEL = {Q: rotation_from_natural_invariants(e, phi), E: cpm(e), e_: e}


@equation("axis:rodrigues", "Rodrigues' formula in E", section="rotations",
          latex=r"\mathbf{Q} = \mathbf{1} + \sin\phi\,\mathbf{E} + (1 - \cos\phi)\,\mathbf{E}^2")
def rodrigues() -> Statement:
    return Statement([Rel(Q, I3 + sp.sin(phi) * E + (1 - sp.cos(phi)) * E**2)], MODEL)


@equation("axis:rodrigues-sign", "Rodrigues' formula, sin term with the wrong sign",
          section="rotations", expected="does-not-hold",
          latex=r"\mathbf{Q} = \mathbf{1} - \sin\phi\,\mathbf{E} + (1 - \cos\phi)\,\mathbf{E}^2",
          cause="misremembered: 1 - sin(phi) E + ... is Q^T, the rotation by -phi")
def rodrigues_sign() -> Statement:
    return Statement([Rel(Q, I3 - sp.sin(phi) * E + (1 - sp.cos(phi)) * E**2)], MODEL,
                     corrected=[Rel(Q, I3 + sp.sin(phi) * E + (1 - sp.cos(phi)) * E**2)])


@equation("axis:orthogonal", "Q is proper orthogonal", section="rotations",
          latex=r"\mathbf{Q}^T\mathbf{Q} = \mathbf{1}, \quad \det\mathbf{Q} = 1")
def proper_orthogonal() -> Statement:
    return Statement([Rel(Q.T * Q, sp.eye(3), "Q^T Q"), Rel(sp.Determinant(Q), 1, "det Q")],
                     MODEL)


@equation("axis:trace", "Trace of a rotation", section="rotations",
          latex=r"\mathrm{tr}(\mathbf{Q}) = 1 + 2\cos\phi")
def trace_of_rotation() -> Statement:
    return Statement([Rel(trace(Q), 1 + 2 * sp.cos(phi))], MODEL)


@equation("axis:fixed", "The axis is fixed by the rotation", section="rotations",
          latex=r"\mathbf{Q}\mathbf{e} = \mathbf{e}")
def axis_is_fixed() -> Statement:
    return Statement([Rel(Q * e_, e_)], MODEL)
