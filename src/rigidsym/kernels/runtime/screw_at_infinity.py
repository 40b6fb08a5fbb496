"""Screws at infinity: a pure translation (a pure couple) where a generated kernel cannot say it.

A rigid-body motion without rotation (Q = 1 in a finite displacement, omega = 0 in a twist)
is a screw of infinite pitch (Angeles, Sec. 3.2 and 3.4.1), and so is its dual, a pure couple
(f = 0 in a wrench, Sec. 3.7): its axis direction is the translation's (the couple's),
``e = t / ||t||``; its pitch is ``+inf`` (an IEEE 754 value: an answer, not an error); its
axis is any line parallel to ``e`` (as the axis of Q = 1 is any unit vector), and the answer
takes the one through the origin, ``p0 = 0`` (pytransform3d's ``q = 0`` of a translation
screw); its Plücker array is the normalised screw at infinity ``[0; e]`` (the limit of the
screw array ``[e; p0 x e + p e] / p`` of Eq. (3.71) as ``p -> inf``; Modern Robotics' screw
axis ``S = [0; v]`` of a translation, in the same ``[omega; v]`` order), not ``[e; p0 x e]``.
No motion (Q = 1 and a' = a; omega = 0 and a_dot = 0) and no load (w_A = 0) have no screw:
every output but ``phi = 0`` is undetermined, a
:class:`~rigidsym.kernels.runtime.errors.SingularConfigurationError` naming the argument under
``on_singular="raise"`` and NaN under ``"nan"``.

The generated kernels hold their branch's value at those rows (``screw_of_displacement``'s
``identity`` branch: phi = 0 exactly and finite placeholders; ``instant_screw_axis`` and
``wrench_axis``: the singular flag of their division by ``||omega||^2``, ``||f||^2``).
:func:`complete` replaces them after the batch runs, on the NumPy and C back-ends and through
Dask (each block's call), from the inputs of those rows alone; :func:`wrap_entry` does it
after the compiled entries of the C extension, which answer those rows themselves. The
PyTorch and JAX kernels answer them alike, in their own array operations
(:mod:`rigidsym.kernels.arrays.infinity`, traceable); the C target (``rigidsym generate
--target c``) keeps the generated values and says so in its status. The slide of a pure
translation, ``||a' - a||``, is not among ``screw_of_displacement``'s outputs (``pitch *
phi`` is ``inf * 0``, NaN): it is the caller's ``e . (a' - a)``.
"""

from __future__ import annotations

import numpy as np

from rigidsym.kernels.runtime.errors import SingularConfigurationError, at_batch_indices

__all__ = ["COMPLETED", "NO_MOTION", "complete", "wrap_entry", "document", "note", "no_motion"]

#: the kernels whose pure-translation rows :func:`complete` answers
COMPLETED = ("screw_of_displacement", "instant_screw_axis", "wrench_axis")
#: each kernel's argument named where it has no screw at all, and why
NO_MOTION = {"screw_of_displacement": ("a_prime", "Q = 1 and a' = a: no motion"),
             "instant_screw_axis": ("a_dot", "omega = 0 and a_dot = 0: no motion"),
             "wrench_axis": ("w_A", "f = 0 and n_A = 0: no load")}
#: sample flag of the generated batch functions for a singular row (numpy_kernel.py.j2)
_SINGULAR = 1

#: the docstring paragraph's label
_LABEL = {"screw_of_displacement": "Pure translation", "instant_screw_axis": "Pure translation",
          "wrench_axis": "Pure couple"}
#: the docstring paragraph of each kernel of COMPLETED
_DOC = {
    "screw_of_displacement": (
        "at Q = 1 with a' != a (a pure translation by t = a' - a; vect(Q) = 0 exactly, "
        "cos phi > 0) the displacement is a screw of infinite pitch: e = t / ||t||, phi = 0, "
        "p0 = 0 (the axis is any line parallel to e; the answer is the one through the "
        "origin, pytransform3d's convention), pitch = +inf, plucker = [0; e] (the "
        "normalised screw at infinity, Modern Robotics' S = [0; v]; not [e; p0 x e]). The "
        "slide ||t|| = e . (a' - a) is not among the outputs (pitch * phi is NaN there). At "
        "Q = 1 with a' = a (no motion) every output but phi = 0 is undetermined: "
        "SingularConfigurationError naming 'a_prime' (on_singular='nan': NaN in e, p0, "
        "pitch and plucker, phi = 0). The C target (docs/c-api.md) keeps "
        "the finite placeholders there, e = [1, 0, 0], p0 = 0, pitch = 0, plucker = [1, 0, "
        "0, 0, 0, 0], and says so with RIGIDSYM_C_DEFAULT_OUTPUT in the status."),
    "instant_screw_axis": (
        "at omega = 0 with a_dot != 0 (a pure translation at velocity v = a_dot) the instant "
        "screw is a screw of infinite pitch: p0 = 0 (the axis is any line parallel to v; the "
        "answer is the one through the origin), pitch = +inf, plucker = [0; v / ||v||] (the "
        "normalised screw at infinity, Modern Robotics' S = [0; v/||v||]). At omega = 0 and "
        "a_dot = 0 (no motion) every output is undetermined: SingularConfigurationError "
        "naming 'a_dot' (on_singular='nan': NaN). The C target keeps its singular status "
        "there."),
    "wrench_axis": (
        "at f = 0 with n_A != 0 (a pure couple: the moment n = n_A about every point) the "
        "wrench is a screw of infinite pitch: p0 = 0 (the axis is any line parallel to n; "
        "the answer is the one through the origin), pitch = +inf, plucker = [0; n / ||n||] "
        "(the normalised screw at infinity, as for a translational twist). At w_A = 0 (no "
        "load) every output is undetermined: SingularConfigurationError naming 'w_A' "
        "(on_singular='nan': NaN). The C target keeps its singular status there."),
}


def _unit_rows(t: np.ndarray) -> np.ndarray:
    """``t / ||t||`` row by row (``t != 0``), computed in float64 after scaling by the
    largest component (no overflow or underflow of the squares), in ``t``'s dtype."""
    t64 = t.astype(np.float64)
    s = np.abs(t64).max(axis=1, keepdims=True)
    u = t64 / s
    return (u / np.linalg.norm(u, axis=1, keepdims=True)).astype(t.dtype)


def _difference(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``b - a`` row by row in float64, both scaled by the same power of two first (exact),
    so that the direction of a difference that overflows the type is kept: only its
    direction is used."""
    a64, b64 = a.astype(np.float64), b.astype(np.float64)
    big = np.maximum(np.abs(a64).max(axis=1), np.abs(b64).max(axis=1))
    k = np.frexp(np.where(np.isfinite(big) & (big > 0), big, 1.0))[1][:, None]
    return np.ldexp(b64, -k) - np.ldexp(a64, -k)


def note(name: str) -> str | None:
    """The docstring paragraph of kernel ``name`` on its screw at infinity (None: not one
    of :data:`COMPLETED`)."""
    return f"{_LABEL[name]}: {_DOC[name]}" if name in _DOC else None


def no_motion(name: str, rows: np.ndarray, batch: tuple) -> None:
    """Raise the error of kernel ``name``'s rows without motion (or load).

    Args:
        name: the kernel (one of :data:`COMPLETED`).
        rows: the flat indices of those rows in the batch (at least one).
        batch: the batch shape.

    Raises:
        SingularConfigurationError: always, naming the argument of :data:`NO_MOTION` and
            the first 20 batch indices.
    """
    arg, what = NO_MOTION[name]
    w = [tuple(int(j) for j in np.unravel_index(i, batch)) for i in rows[:20]]
    raise SingularConfigurationError(
        f"{name}: singular configuration ({what}, so no screw) in argument "
        f"{arg!r}{at_batch_indices(w, rows.size > 20)}", arg, w)


def complete(name: str, flat: list, bufs: list, flags, batch: tuple,
             on_singular: str):
    """Answer the pure-translation rows of kernel ``name`` in place.

    Args:
        name: the kernel (one of :data:`COMPLETED`; any other is left as it is).
        flat: its inputs, flattened to ``(n, ...)`` and broadcast.
        bufs: its output buffers ``(n, ...)``, as the batch function wrote them.
        flags: the ``(n,)`` uint8 sample flags (1 singular, 2 non-finite), or None when no
            row is flagged.
        batch: the batch shape (for the indices of an error).
        on_singular: ``"raise"`` or ``"nan"``.

    Returns:
        The flags, with the rows answered here cleared (None stays None).

    Raises:
        SingularConfigurationError: a row without motion under ``on_singular="raise"``.
    """
    if name == "screw_of_displacement":
        _a, a, a_prime = flat
        e, phi, p0, pitch, kappa = bufs
        mask = phi == 0
        if flags is not None:
            mask &= flags == 0
        rows = np.flatnonzero(mask)
        if rows.size:
            t = _difference(a[rows], a_prime[rows])
            _answer(name, rows, t, p0, pitch, kappa, e, batch, on_singular)
        return flags
    if name in ("instant_screw_axis", "wrench_axis") and flags is not None:
        if name == "instant_screw_axis":    # omega = 0: every point moves at a_dot
            zero, a, a_dot = flat
        else:                               # f = 0: the moment is n_A about every point
            w_A, a = flat
            zero, a_dot = w_A[:, 3:], w_A[:, :3]
        p0, pitch, kappa = bufs
        rows = np.flatnonzero((flags == _SINGULAR) & (zero == 0).all(axis=1)
                              & np.isfinite(a).all(axis=1))
        if rows.size:
            _answer(name, rows, a_dot[rows], p0, pitch, kappa, None, batch, on_singular)
            flags = flags.copy()
            flags[rows] = 0
    return flags


def wrap_entry(name: str, entry, shapes: tuple):
    """The compiled entry of kernel ``name`` (``entry(*inputs, out, check, on_singular,
    threads)``), followed by :func:`complete` on the rows it answered with the generated
    program's values: ``screw_of_displacement``'s rows of phi == 0 exactly, and
    ``instant_screw_axis``'s NaN rows under ``on_singular="nan"`` (under ``"raise"`` the
    entry hands its flagged calls to the Python path, which completes them). A call without
    such a row costs one comparison of an output; a lazy (Dask) result is returned as it is.

    Args:
        name: the kernel (one of :data:`COMPLETED`).
        entry: its compiled entry.
        shapes: its inputs' core shapes (``(3, 3)``, ``(3,)``, ...).

    Returns:
        The wrapped entry, with the same calling convention.
    """
    nin, sod = len(shapes), name == "screw_of_displacement"

    def f(*args):
        res = entry(*args)
        mark = res[1]                   # phi; the pitch of instant_screw_axis
        if type(mark) is not np.ndarray:
            return res
        if mark.ndim == 0:                  # one sample: a Python comparison, no ufunc
            v = mark.item()
            if (v != 0) if sod else (v == v):
                return res
        rows = mark == 0 if sod else np.isnan(mark)
        if not rows.any():
            return res
        on_singular = "raise" if args[nin + 2] is None else args[nin + 2]
        batch, dtype = mark.shape, mark.dtype
        n = mark.size
        ins = [np.broadcast_to(np.asarray(x, dtype=dtype), batch + sh).reshape((n,) + sh)
               for x, sh in zip(args[:nin], shapes, strict=True)]
        bufs = [np.array(r, copy=True).reshape((n,) + r.shape[len(batch):]) for r in res]
        flags = None if sod else \
            np.where(rows.reshape(n), _SINGULAR, 0).astype(np.uint8)
        complete(name, ins, bufs, flags, batch, on_singular)
        for r, b in zip(res, bufs, strict=True):
            r[...] = b.reshape(r.shape)
        return res
    f.__name__ = f.__qualname__ = name
    return f


def _answer(name, rows, t, p0, pitch, kappa, e, batch, on_singular) -> None:
    """Write the screw at infinity of translations ``t`` into ``rows``; the rows with
    ``t = 0`` raise or get NaN, those of a non-finite ``t`` (an unchecked NaN or inf input)
    NaN."""
    finite = np.isfinite(t).all(axis=1)
    moving = finite & (t != 0).any(axis=1)
    still = rows[finite & ~moving]
    if still.size and on_singular == "raise":
        no_motion(name, still, batch)
    go = rows[moving]
    if go.size:
        u = _unit_rows(t[moving]).astype(pitch.dtype)
        if e is not None:
            e[go] = u
        p0[go] = 0
        pitch[go] = np.inf
        kappa[go, :3] = 0
        kappa[go, 3:] = u
    for buf in (e, p0, pitch, kappa):
        if buf is not None:
            buf[rows[~moving]] = np.nan


#: the generated docstrings' sentences that the answer changes: (old, new) per kernel
_REPLACE = {
    "screw_of_displacement": (
        ("At Q = 1 (vect(Q) = 0 exactly, cos phi > 0: a pure translation by a' - a, or "
         "none) phi = 0 exactly and the outputs it leaves undetermined hold documented "
         "defaults: e = [1, 0, 0], p0 = 0, pitch = 0 (the pitch of a pure translation is "
         "infinite), plucker = [1, 0, 0, 0, 0, 0]; phi == 0 exactly says they are the "
         "defaults (the C target's status has RIGIDSYM_C_DEFAULT_OUTPUT). ", ""),
        ("the axis is lost in the type), unless on_singular='nan'.",
         "the axis is lost in the type), and at Q = 1 with a' = a (no motion, naming "
         "'a_prime'), unless on_singular='nan'."),
        ("\n        Singular set: Q != 1", "\n        Singular set: Q = 1 with a' = a (no "
         "motion); Q != 1")),
    "instant_screw_axis": (
        ("on the singular set (omega = 0 (pure translation))",
         "on the singular set (omega = 0 and a_dot = 0: no motion, naming 'a_dot')"),
        ("Singular set: omega = 0 (pure translation).",
         "Singular set: omega = 0 and a_dot = 0 (no motion); omega = 0 alone is a pure "
         "translation, answered above.")),
    "wrench_axis": (
        ("on the singular set (f = 0 (pure moment))",
         "on the singular set (w_A = 0: no load, naming 'w_A')"),
        ("Singular set: f = 0 (pure moment).",
         "Singular set: w_A = 0 (no load); f = 0 alone is a pure couple, answered above.")),
}


def document(mod) -> None:
    """Say in the docstrings of :data:`COMPLETED`'s kernels of the generated ``api`` module
    ``mod`` what they return at a pure translation: the paragraph first in ``Notes``, and
    the generated sentences on the finite placeholders and the singular set rewritten (the
    generated text describes the generated program, which the C target keeps)."""
    for name, text in _DOC.items():
        f = getattr(mod, name, None)
        if f is None or f.__doc__ is None or text in f.__doc__:
            continue
        doc = f.__doc__
        for old, new in _REPLACE[name]:
            doc = doc.replace(old, new)
        marker = "\n    Notes:\n"
        if marker in doc:
            doc = doc.replace(marker, f"{marker}        {_LABEL[name]}: {text}\n\n", 1)
        else:
            doc = doc.rstrip() + f"\n\n    Notes:\n        {_LABEL[name]}: {text}\n"
        f.__doc__ = doc
