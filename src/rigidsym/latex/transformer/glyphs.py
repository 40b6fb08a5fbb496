"""The glyph rules of the LaTeX transformer (:class:`GlyphRules`, a mixin of
:class:`rigidsym.latex.transformer.chapter.LatexTransformer`): a glyph's key
(``\\mathbf{Q}``, ``\\dot{\\mathbf{p}}_{1}``, ``{}^B X_A``), its sympy symbol named by the
glyph table (:mod:`rigidsym.latex.table`) or by a reader's declarations, the sized zeros
and identities, ``t`` as time, and ranges of entries (``\\mathbf{q}_{1:3}``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

import lark
import sympy as sp

from rigidsym.latex.entries import AXES, DECLARED_PARAM, entry_index
from rigidsym.latex.kinematics import dot_key
from rigidsym.latex.shapes import LatexError, default_glyph, matrix_shape, shape_words
from rigidsym.latex.table import lookup
from rigidsym.latex.transformer.book_notations import index_key
from rigidsym.latex.transformer.meanings import alternatives
from rigidsym.latex.transformer.tilde import tilde_of

__all__: list[str] = []


TIME = sp.Symbol("t", real=True)  # the plain letter t: time, the argument of p(t)
#: the wide accents, which TeX only draws wider over several letters: the same glyph
_WIDE = {"\\widehat": "\\hat", "\\widetilde": "\\tilde"}


def wide(accent: str) -> str:
    """``\\widehat`` as ``\\hat``, ``\\widetilde`` as ``\\tilde``; any other accent as given."""
    return _WIDE.get(accent, accent)


class GlyphRules:
    """Transformer rules of the glyphs (a mixin of ``LatexTransformer``, which provides
    ``section``, ``overrides``, ``glyphs``, ``readings``, and the rules it calls:
    ``_sized`` and ``sized_zero`` of :class:`~rigidsym.latex.transformer.meanings.MeaningRules`,
    ``timed`` and ``velocity`` of
    :class:`~rigidsym.latex.transformer.book_notations.BookNotationRules`)."""

    def base(self, items):
        if len(items) == 2:
            bold, letter = items
            return ("bold", str(letter))
        return ("plain", str(items[0]))

    def zero(self, _):
        return ("zero", "0")

    def one(self, _):
        return ("one", "1")

    def subscript(self, items):
        parts = [str(i) for i in items]  # a space after a Greek letter before a letter
        return ("sub", "".join(p + " " if p.startswith("\\") and p[-1].isalpha() and
                               k + 1 < len(parts) and parts[k + 1][:1].isalpha() else p
                               for k, p in enumerate(parts)))

    def times(self, _):
        return "\\times "

    def sub_times(self, _):
        return ("sub", "\\times ")   # v_\times is v_{\times}: one name in TeX

    def slash(self, _):
        return "/"

    def boldsub(self, items):
        """A bold letter in a subscript (``R_{\\bm{n}}``: the rotation about n), part of
        the name, keyed as ``\\mathbf``."""
        return "\\mathbf{" + str(items[-1]) + "}"

    def calsub(self, items):
        return "\\mathcal{" + str(items[0]) + "}" + (str(items[1]) if len(items) > 1 else "")

    def _key(self, base, rest, accent=None, pre="") -> str:
        kind, letter = base
        core = {"bold": f"\\mathbf{{{letter}}}" if not letter.startswith("\\")
                else f"\\boldsymbol{{{letter}}}",
                "plain": letter, "zero": "\\mathbf{0}", "one": "\\mathbf{1}",
                "cal": f"\\mathcal{{{letter}}}", "font": letter}[kind]
        if accent:
            core = f"{accent}{{{core}}}"
        core = pre + core
        for r in rest:
            if isinstance(r, tuple):
                core += "_{" + r[1] + "}"
            else:
                core += str(r)
        return core

    def label_first(self, items):
        """``\\mathbf{a}^S_1``: TeX sets it as ``\\mathbf{a}_1^S``, one glyph, keyed so."""
        labels = [i for i in items if isinstance(i, lark.Token) and i.type == "SUPLABEL"]
        return self.glyph([i for i in items if i not in labels] + labels)

    def glyph(self, items):
        items = [label_key(str(i)) if isinstance(i, lark.Token) and i.type == "SUPLABEL"
                 else i for i in items]
        if isinstance(items[0], lark.Token) and items[0].type == "LEFT_INDEX":
            return self._resolve(items[1], items[2:], None, pre=index_key(str(items[0])))
        return self._resolve(items[0], items[1:], None)

    def accented(self, items):
        accent, inner = wide(str(items[0])), items[1]
        if not isinstance(inner, GlyphKey):
            raise LatexError(f"{accent} over an expression: expected a glyph", "accent")
        labels = [i for i in items[2:] if isinstance(i, lark.Token) and i.type == "SUPLABEL"]
        if labels and not inner.accent:
            # Savage's \dot{C}_B^N: TeX's accent over C_B^N (the label part of the name, as in
            # a glyph); the rate of C_B^N where that is a function of time or a model
            rest = [*inner.rest, *(i for i in items[2:] if i not in labels),
                    *(label_key(str(i)) for i in labels)]
            under = self._resolve(inner.base, rest, None)
            self._unuse(inner.key)
            if accent == "\\dot" and self.timed(under.key):
                return self.velocity(under.key, under.value)
            rate = self.model_rate(under.key) if accent == "\\dot" else None
            if rate is not None:
                return rate
            self._unuse(under.key)
            return self._resolve(inner.base, rest, accent)
        if accent == "\\dot" and not inner.accent and not inner.rest and len(items) == 3 \
                and isinstance(items[2], tuple) and ":" in items[2][1] \
                and self.timed(inner.key):
            # \dot{\mathbf{e}}_{1:1} of e(t): entries of its rate (a unit vector's tangent)
            return self._rate_slice(inner, items[2], accent)
        if not inner.accent and not inner.rest and len(items) == 3 \
                and isinstance(items[2], tuple) and ":" in items[2][1]:
            # \bar{q}_{1:3}: a range of entries of the accented vector \bar{q}, not of q
            self._unuse(inner.key)
            key = self._key(inner.base, [items[2]], accent, "")
            return self._slice(key, inner.base, [items[2]], accent, "")
        if not inner.accent and not inner.key.startswith("{}") and all(
                isinstance(r, tuple) for r in [*inner.rest, *items[2:]]) \
                and bool(inner.rest) != bool(items[2:]):
            # \dot{\Omega_1} is \dot{\Omega}_1, TeX's one glyph, keyed as the glyph table
            # writes it (\dot{\mathbf{h}}_{C}); the rate of a function of time Omega_1 either
            # way
            under = inner if inner.rest else self._resolve(inner.base, list(items[2:]), None)
            if under is not inner:
                self._unuse(inner.key)  # \dot\theta_1: theta alone is no glyph of it
            if accent == "\\dot" and self.timed(under.key):
                return self.velocity(under.key, under.value)
            rate = self.model_rate(under.key) if accent == "\\dot" else None
            if rate is not None:  # \dot{e}_R of a model e_R built on functions of time
                return rate
            self._unuse(under.key)
            return self._resolve(inner.base, list(under.rest), accent)
        base, rest = inner.base, list(inner.rest) + list(items[2:])
        if accent == "\\dot" and not items[2:] and self.timed(inner.key):  # d/dt of X(t)
            return self.velocity(inner.key, inner.value)
        if accent == "\\ddot" and not items[2:] and not inner.accent:  # d/dt twice
            rate = self.model_rate(inner.key) if not self.timed(inner.key) else \
                self.velocity(inner.key, inner.value) if dot_key(inner.key) in self.overrides \
                else None
            if rate is not None:  # \ddot of a model, or of X(t) with a --let rate
                return self.time_derivative(rate)
            if self.timed(inner.key) and not self.overrides[inner.key].meaning.startswith(
                    ("rotation", "homogeneous")):
                return self.second_rate(inner.key)  # X's shape (a 4-vector's)
            if self.timed(inner.key) and f"\\ddot{{{inner.key}}}" not in self.overrides:
                # a rotation's (a transform's) rate is X [X_w]: its second rate needs the
                # rate of the body velocity, which nothing declares (a constant one would
                # restrict the motions; a free symbol would be unrelated to X)
                raise LatexError(
                    f"\\ddot{{{inner.key}}}: the second time derivative of {inner.key}(t), "
                    f"whose angular velocity's rate nothing declares: declare the rate, e.g. "
                    f"--let '\\boldsymbol\\omega(t): vector' --let '\\dot{{{inner.key}}} = "
                    f"{inner.key}[\\boldsymbol\\omega]_\\times' (the second rate follows), or "
                    f"--let '\\ddot{{{inner.key}}}: matrix' (a symbol of its own)", "rate")
        if accent == "\\dot" and not items[2:] and (
                not inner.accent or inner.key in self.overrides):  # of a model (\tilde{R} = ...)
            rate = self.model_rate(inner.key)
            if rate is not None:
                return rate
        if accent == "\\tilde" and not items[2:]:  # a vector's tilde: its [x]_x or its own
            skew = tilde_of(self, f"\\tilde{{{inner.key}}}", inner)
            if skew is not None:
                return skew
        self._unuse(inner.key)  # only the accented glyph is a symbol here
        return self._resolve(base, rest, (inner.accent or "") + accent if inner.accent
                             else accent, inner)

    def arrow(self, items):
        key = f"\\overrightarrow{{{items[0]}}}"
        return self._symbol(key, None)

    def _resolve(self, base, rest, accent, inner=None, pre=""):
        if inner is not None:  # an accent over a glyph that has its own sub/primes
            # (or accents: \dot{\hat{R}} is keyed so, its accents recorded as \hat\dot)
            outer = accent[len(inner.accent):] if inner.accent and \
                accent.startswith(inner.accent) else accent
            key = f"{outer}{{{inner.key}}}" + "".join(
                "_{" + r[1] + "}" if isinstance(r, tuple) else str(r)
                for r in rest[len(inner.rest):])
        else:
            key = self._key(base, rest, accent, pre)
        kind = base[0]
        if rest and isinstance(rest[-1], tuple) and ":" in rest[-1][1] and inner is None:
            return self._slice(key, base, rest, accent, pre)
        sized = self._sized(key, base, rest, accent)  # I, I_3, \mathbf{1}_3 (transformer.meanings)
        if sized is not None:
            return GlyphKey(key, base, rest, accent, sized)
        if kind == "zero":
            z = None if accent else self.sized_zero(key, rest)
            return GlyphKey(key, base, rest, accent, z if z is not None
                             else sp.ZeroMatrix(3, 1))
        if kind == "one":
            n = 3
            for r in rest:
                if isinstance(r, tuple) and "times" in r[1]:
                    n = int(r[1].split("\\times")[0])
            return GlyphKey(key, base, rest, accent, sp.Identity(n))
        if kind == "bold" and base[1] == "O" and not accent:
            rows = cols = 3
            for r in rest:
                if isinstance(r, tuple) and r[1].isdigit() and len(r[1]) == 2:
                    rows, cols = int(r[1][0]), int(r[1][1])
            return GlyphKey(key, base, rest, accent, sp.ZeroMatrix(rows, cols))
        if kind == "plain" and base[1] == "t" and not rest and not accent:
            return GlyphKey(key, base, rest, accent, TIME)
        if accent in ("\\vec", "\\underline") and kind == "plain":  # vector fonts
            base = ("bold", base[1])
        entry = self._entry(key, base, rest, accent, inner, pre)
        if entry is not None:
            return entry
        return GlyphKey(key, base, rest, accent, self._symbol(key, base))

    def _entry(self, key, base, rest, accent, inner, pre):
        """``a_1``, ``\\mathbf{q}_4`` where nothing declares it but a ``--let`` declares the
        vector ``\\mathbf{a}`` (``\\mathbf{q}``): a symbol of its own or entry 1 (4) of
        the vector, a choice point (``self.choices``, a symbol of its own
        unless told). ``None`` where it is no choice: the symbol, by the rules."""
        if not getattr(self, "reader", False) or accent or inner is not None or pre \
                or len(rest) != 1 or not isinstance(rest[0], tuple) \
                or not (rest[0][1].isdigit() or rest[0][1] in AXES) \
                or key in self.overrides:
            return None
        axis = rest[0][1] in AXES
        k = AXES[rest[0][1]] if axis else int(rest[0][1])
        for vbase in dict.fromkeys([("bold", base[1]), base]):
            vkey = self._key(vbase, [], None)
            g = self.overrides.get(vkey)
            shape = getattr(g, "shape", ())
            if axis and (shape != (3, 1) or base[0] == "bold" or g.kind == "param"):
                continue  # n_x: an entry of a declared 3-vector only
            if axis:
                self.readings.append(f"{key}: read as entry {k} ({rest[0][1]}) of {vkey} "
                                     f"(--let '{key}: scalar' for a symbol of its own)")
                return GlyphKey(key, base, rest, accent, self._symbol(vkey, vbase)[k - 1, 0])
            if len(shape) == 2 and shape[1] == 1 and shape[0] > 1 and base[0] != "bold" and (
                    g.kind != "param" or g.meaning.endswith(DECLARED_PARAM)):
                try:  # a --let's vector: its entry, counted from 1 (from 0 too: a 4-vector)
                    at, note = entry_index(key, vkey, k, shape[0], self.choices,
                                           self.choice_points)
                except ValueError as exc:
                    raise LatexError(str(exc), "subscript") from None
                if at is None:
                    return None
                self.readings.append(note)
                return GlyphKey(key, base, rest, accent, self._symbol(vkey, vbase)[at, 0])
            if len(shape) == 2 and shape[1] == 1 and 1 <= k <= shape[0] > 1:
                point = f"{key} of {vkey}"
                self.choice_points.setdefault(point, alternatives(point))
                if self.choices.get(point) != "entry":
                    self.readings.append(f"{key}: a symbol of its own (a choice: or entry {k} "
                                         f"of {vkey})")
                    return None
                self.readings.append(f"{key}: read as entry {k} of {vkey} (a choice: or a "
                                     f"symbol of its own)")
                return GlyphKey(key, base, rest, accent, self._symbol(vkey, vbase)[k - 1, 0])
        return self._free_entry(key, base, rest, accent, k)

    def _free_entry(self, key, base, rest, accent, k):
        r"""``q_k`` outside a function whose parameter ``\mathbf{q}`` no ``--let`` declares,
        in the reading where the body's ``q_k`` are the parameter's entries: entry k of the
        free ``\mathbf{q}`` too, so that one notation holds for the letter throughout
        (Diebel's ``R(\mathbf{q})`` beside ``q_0^2 + ... + q_3^2``: never the body's
        entries and the statement's names, two readings of one letter at once)."""
        vbase = ("bold", base[1])
        vkey = self._key(vbase, [], None)
        if self.choices.get(f"{key} of {vkey}") != "entry" or vkey in self.overrides:
            return None
        v = self._symbol(vkey, vbase)
        shape = getattr(v, "shape", ())
        if not (len(shape) == 2 and shape[1] == 1 and 1 <= k <= shape[0] > 1):
            return None
        self.readings.append(f"{key}: read as entry {k} of {vkey} (a choice: or a symbol of "
                             f"its own)")
        return GlyphKey(key, base, rest, accent, v[k - 1, 0])

    def _rate_slice(self, inner, sub, accent):
        """``\\dot{\\mathbf{e}}_{lo:hi}`` of a vector of time: entries of its rate, as
        :meth:`velocity` reads it."""
        v = self.velocity(inner.key, inner.value)
        key = self._key(inner.base, [sub], accent, "")
        lo, hi = (int(n) for n in sub[1].replace(" ", "").split(":"))
        shape = matrix_shape(v)
        if not shape or shape[1] != 1 or not 1 <= lo <= hi <= shape[0]:
            raise LatexError(f"{key}: entries {lo} to {hi} of the rate of {inner.key}, "
                             f"{shape_words(v)}", "shapes")
        what = f"entry {lo}" if lo == hi else f"entries {lo} to {hi}"
        self.readings.append(f"{key}: {what} of the rate of {inner.key}")
        value = v[lo - 1, 0] if lo == hi else \
            sp.ImmutableMatrix([[v[i, 0]] for i in range(lo - 1, hi)])
        return GlyphKey(key, inner.base, [sub], accent, value)

    def _slice(self, key, base, rest, accent, pre):
        """``\\mathbf{q}_{1:3}``: entries 1 to 3 (counted from 1, both included) of the
        vector ``\\mathbf{q}``; of a scalar or matrix refused."""
        lo, hi = (int(n) for n in rest[-1][1].replace(" ", "").split(":"))
        vkey = self._key(base, rest[:-1], accent, pre)
        v = self._symbol(vkey, base)
        shape = getattr(v, "shape", None)
        if not shape or shape[1] != 1 or shape[0] == 1:
            raise LatexError(f"{key}: a range of entries of {vkey}, which is no vector "
                             f"({shape_words(v)}); declare it, e.g. --let '{vkey}: 4-vector'",
                             "shapes")
        if not 1 <= lo <= hi <= shape[0]:
            raise LatexError(f"{key}: entries {lo} to {hi} of {vkey}, a {shape[0]}-vector",
                             "shapes")
        if lo == hi:  # q_{4:4}: one entry, a scalar
            self.readings.append(f"{key}: entry {lo} of {vkey}")
            return GlyphKey(key, base, rest, accent, v[lo - 1, 0])
        self.readings.append(f"{key}: entries {lo} to {hi} of {vkey}")
        return GlyphKey(key, base, rest, accent,
                         sp.ImmutableMatrix([[v[i, 0]] for i in range(lo - 1, hi)]))

    def _unuse(self, key) -> None:
        """The glyph ``key`` read under an accent: no use of its own, unless the LaTeX uses
        it elsewhere too (``Q(\\mathbf{q})`` beside ``\\bar Q(\\mathbf{p})``: the bar's Q
        does not take Q's own use away, so Q is not reported as "does not occur")."""
        uses = self.__dict__.setdefault("_uses", {})
        uses[key] = uses.get(key, 1) - 1
        if uses[key] <= 0:
            self.glyphs.pop(key, None)

    def _symbol(self, key, base):
        uses = self.__dict__.setdefault("_uses", {})
        uses[key] = uses.get(key, 0) + 1
        g = self.overrides.get(key)
        if g is None and self.section is not None:  # None: no glyph table (a reader's LaTeX)
            g = lookup(key, self.section)
        if g is None:
            g = default_glyph(key, base)
            if key in getattr(self, "renamed", ()):  # \theta beside \boldsymbol\theta
                g = replace(g, name=g.name + "_")
        self.glyphs[key] = g
        if g.shape == ():
            return sp.Symbol(g.name, real=True)
        if g.kind == "row":  # a per-id note: the text's vector stands for its row
            self.readings.append(f"{key} read as the row {g.name}^T (per-id note)")
            return sp.MatrixSymbol(g.name, *g.shape).T
        return sp.MatrixSymbol(g.name, *g.shape)


def label_key(token: str) -> str:
    """A superscript label in one spelling: ``^S``, ``^{ S }``, ``^{\\mathcal{S}}`` ->
    ``^{S}``; ``^{(k)}``."""
    token = re.sub(r"\\mathcal\s*\{\s*([A-Z])\s*\}", r"\1", token)
    return "^{" + "".join(token.lstrip("^").split()).strip("{}") + "}"


@dataclass(frozen=True)
class GlyphKey:
    """A glyph as the transformer read it: its ``key`` (the LaTeX, normalised), the ``base``
    and the ``rest`` of its parts, its ``accent`` (``dot``, ``hat``...) if any, and the
    ``value`` it stands for."""

    key: str
    base: tuple
    rest: list
    accent: str | None
    value: object
