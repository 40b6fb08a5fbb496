"""Drawing helpers for the exercises' figures (matplotlib, 3-D axes).

Figures are built from a solution's own data and answers (exact sympy values converted to
floats only here, for drawing), so new data redraw them. They are plain
:class:`matplotlib.figure.Figure` objects, not registered with pyplot (a notebook shows a
returned figure once, and nothing leaks between calls); the view, size and colours are
fixed so the SVG is deterministic.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

__all__ = ["new_figure", "frame", "arrow", "segment", "point", "line", "line_in_box", "box",
           "edges", "axes3d", "as_array"]

#: one view for every 3-D figure (elevation, azimuth in degrees)
VIEW = (22, -58)


def as_array(v) -> np.ndarray:
    """A sympy vector (or list) as a float array of shape (3,)."""
    return np.array([float(sp.N(x)) for x in list(v)])


def new_figure(title: str, size=(6.4, 5.2)):
    """A figure with one 3-D axes (labels x, y, z; fixed view)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=size)
    ax = fig.add_subplot(projection="3d")
    ax.set_title(title, fontsize=11)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.tick_params(labelsize=7)   # metre-scale ticks (0.025, ...) would overlap at 10 pt
    ax.view_init(*VIEW)
    return fig, ax


def arrow(ax, start, vec, color: str, label: str | None = None, dashed: bool = False,
          scale: float = 1.0) -> None:
    """An arrow from ``start`` along ``vec`` (times ``scale``)."""
    p, d = as_array(start), as_array(vec) * scale
    ax.quiver(*p, *d, color=color, linestyle="--" if dashed else "-", linewidth=1.6,
              arrow_length_ratio=0.12, label=label)


def frame(ax, origin, R, name: str, color: str, scale: float = 1.0) -> None:
    """Coordinate axes at ``origin`` along the columns of ``R``, labelled ``name``."""
    o = as_array(origin)
    for k, axis in enumerate("xyz"):
        d = as_array(sp.Matrix(R)[:, k]) * scale
        ax.quiver(*o, *d, color=color, linewidth=1.2, arrow_length_ratio=0.1)
        ax.text(*(o + 1.08 * d), f"${axis}_{{{name}}}$" if name else f"${axis}$",
                color=color, fontsize=10)


def segment(ax, a, b, color: str = "0.3", label: str | None = None, **kw) -> None:
    """A straight segment from ``a`` to ``b``."""
    a, b = as_array(a), as_array(b)
    ax.plot([a[0], b[0]], [a[1], b[1]], [a[2], b[2]], color=color, label=label, **kw)


def point(ax, p, color: str, label: str | None = None, text: str | None = None) -> None:
    """A marked point, with an optional legend label and an optional text beside it."""
    q = as_array(p)
    ax.scatter(*q, color=color, s=28, label=label, depthshade=False)
    if text:
        ax.text(*q, f"  {text}", color=color, fontsize=9)


def line(ax, p, e, extent: float, color: str, label: str | None = None) -> None:
    """The line ``{p + lambda e, |lambda| <= extent}`` (``e`` need not be unit)."""
    p, e = as_array(p), as_array(e)
    e = e / np.linalg.norm(e)
    segment(ax, p - extent * e, p + extent * e, color=color, label=label, linewidth=2.0)


def box(points, pad: float = 0.15) -> tuple[np.ndarray, float]:
    """Centre and half-size of the cube drawn around ``points`` (see :func:`axes3d`)."""
    P = np.array([as_array(p) for p in points])
    lo, hi = P.min(axis=0), P.max(axis=0)
    return (lo + hi) / 2, max(float((hi - lo).max()) / 2, 1e-9) * (1 + pad)


def line_in_box(ax, p, e, points, color: str, label: str | None = None) -> None:
    """The part of the line ``{p + lambda e}`` inside the drawing box of ``points``."""
    mid, half = box(points)
    p, e = as_array(p), as_array(e)
    e = e / np.linalg.norm(e)
    lo, hi = -np.inf, np.inf
    for k in range(3):           # slab clipping, one coordinate at a time
        if abs(e[k]) < 1e-12:
            if abs(p[k] - mid[k]) > half:
                return
            continue
        t1, t2 = sorted(((mid[k] - half - p[k]) / e[k], (mid[k] + half - p[k]) / e[k]))
        lo, hi = max(lo, t1), min(hi, t2)
    if lo < hi:
        segment(ax, p + lo * e, p + hi * e, color=color, label=label, linewidth=2.0)


def edges(ax, vertices: dict, pairs, color: str, label: str | None = None, **kw) -> None:
    """The edges ``pairs`` (names) of a polyhedron with ``vertices`` (name -> point)."""
    for i, (a, b) in enumerate(pairs):
        segment(ax, vertices[a], vertices[b], color=color, label=label if i == 0 else None,
                **kw)


def axes3d(ax, points, legend: bool = True, pad: float = 0.15) -> None:
    """Equal scales on a box covering ``points``; legend (fixed place) when asked."""
    mid, half = box(points, pad)
    ax.set_xlim(mid[0] - half, mid[0] + half)
    ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(mid[2] - half, mid[2] + half)
    ax.set_box_aspect((1, 1, 1))
    if legend:
        ax.legend(loc="upper left", fontsize=8, frameon=False)
