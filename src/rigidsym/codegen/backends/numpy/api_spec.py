"""The Python face of the generated kernels: common keywords and the ``api.py`` module.

``rigidsym generate`` writes ``api.py`` beside ``kernels.json``: one real function per
public kernel, whose parameters are the kernel's arguments followed by the common keywords
(:data:`COMMON_KEYWORDS`, defined here once), with type hints (``ArrayLike`` in,
``NDArray[np.floating]`` out) and the docstring built from the metadata. Static tools and
``help()`` therefore see the true signatures; :func:`rigidsym.kernels.load` binds each
module to the checked evaluation of its own generated directory.
"""

from __future__ import annotations

from dataclasses import dataclass

from rigidsym.core import kinds as _kinds

__all__ = ["Keyword", "COMMON_KEYWORDS", "render_api", "docstring", "accuracy_line"]


@dataclass(frozen=True)
class Keyword:
    """A keyword-only parameter shared by every kernel.

    Attributes:
        name: parameter name.
        annotation: type hint (source text, resolved in the generated module).
        default: default value (source text).
        doc: one line for the docstrings.
    """

    name: str
    annotation: str
    default: str
    doc: str


#: the keywords every kernel accepts after its arguments (the one definition)
COMMON_KEYWORDS = (
    Keyword("out", "OutArrays", "None",
            "preallocated float64 output array (a tuple of them for several outputs), "
            "shape batch + output shape; returned filled"),
    Keyword("check", "bool", "True",
            "validate the inputs (finite, unit e/eta, orthogonal Q); False skips only that: "
            "on valid input the same result, and a NaN or inf input gives NaN in the "
            "outputs that depend on it"),
    Keyword("on_singular", "OnSingular | None", "None",
            '"raise" (SingularConfigurationError naming the argument and the batch indices) '
            'or "nan" (NaN in exactly those rows); None: "raise", or "nan" for Dask inputs'),
    Keyword("threads", "int | None", "None",
            "threads of the C batch loop; None: kernels.set_num_threads, else "
            "RIGIDSYM_NUM_THREADS, else 1 (outputs identical for every count)"),
)


def _shape(s: list) -> str:
    return "(...)" if not s else f"(..., {', '.join(map(str, s))})"


def docstring(meta: dict) -> str:
    """Google-style docstring of a kernel from its ``kernels.json`` entry."""
    lines = [meta["summary"], "", f"    {meta['formula']}", "",
             f"Book: Eq. {', '.join('(' + i + ')' for i in meta['ids'])}; composed of "
             f"{', '.join(meta['sources'])}.", "", "Args:"]
    for a in meta["args"]:
        k = _kinds.for_spec(a["kind"], a["shape"])
        kind = k.arg_words if k is not None else ""
        doc = f"; {a['doc']}" if a["doc"] else ""
        lines.append(f"    {a['name']}: array-like {_shape(a['shape'])}{kind}{doc}")
    for k in COMMON_KEYWORDS:
        lines.append(f"    {k.name}: {k.doc}.")
    lines += ["", "Returns:"]
    outs = [f"{o['name']}: ndarray {_shape(o['shape'])}" + (f"; {o['doc']}" if o["doc"] else "")
            for o in meta["outputs"]]
    if len(outs) == 1:  # Google style: "type: description" (the type says the shape)
        o = meta["outputs"][0]
        lines.append(f"    ndarray {_shape(o['shape'])}: {o['name']}"
                     + (f"; {o['doc']}" if o["doc"] else ""))
    else:
        names = ", ".join(o["name"] for o in meta["outputs"])
        lines += [f"    tuple of ndarray: ({names}), with", ""]
        lines += [f"        - {x}" for x in outs]
    lines += ["", "Raises:",
              "    TypeError: an argument that is not an array of real numbers (str, object, "
              "complex, bool).",
              "    ValueError: bad shape, batch shapes that do not broadcast, ragged or "
              "non-finite input, non-unit or non-orthogonal argument (naming it).",
              "    NonFiniteResultError: the result of finite inputs overflows the dtype "
              "(inputs of extreme magnitude are computed in a wider type first), unless "
              "on_singular='nan'."]
    if meta["singular"]:
        lines += ["    SingularConfigurationError: on the singular set "
                  f"({meta['singular']}), unless on_singular='nan'."]
    lines += ["", "Notes:"]
    if meta["singular"]:
        lines += [f"    Singular set: {meta['singular']}.", ""]
    if meta["notes"]:
        lines += [f"    {meta['notes']}", ""]
    if meta.get("accuracy"):
        lines += [f"    {accuracy_line(meta)}", ""]
    lines += [f"    Generated; {meta['ops']} operations; math hash {meta['hash']}."]
    return "\n".join(lines)


def accuracy_line(meta: dict) -> str:
    """The docstring's accuracy line from the measured row (``kernels.accuracy``)."""
    a = meta["accuracy"]
    f64, f32 = a.get("float64", {}), a.get("float32", {})
    line = (f"Accuracy: error <= {max(f64.get('bound', 0), 1):.3g} u (kappa + 1) in float64, "
            f"<= {max(f32.get('bound', 0), 1):.3g} u (kappa + 1) in float32 (u the unit "
            f"roundoff, kappa the condition number; worst {f64.get('ulps', 0):.3g} ulp in "
            f"float64) over {len(a.get('regimes', []))} regimes (docs/accuracy.md, "
            "kernels.accuracy)")
    if meta["singular"]:
        line += f"; singular when {meta['singular']}"
        if a.get("threshold"):
            line += f", flagged where {a['threshold']}"
    return line + "."


def render_api(env, metas: list[dict], versions: dict) -> str:
    """Text of the generated ``api.py`` for the public kernels among ``metas``."""
    public = [m for m in metas if m["public"]]
    return env.get_template("api.py.j2").render(
        kernels=public, keywords=COMMON_KEYWORDS, docstring=docstring,
        template="api.py.j2", **versions)
