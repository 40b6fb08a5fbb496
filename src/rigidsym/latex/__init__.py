"""A reader of the chapter's LaTeX (lark grammar + glyph table) and the transcription
check of every declaration against its LaTeX."""

from rigidsym.latex.lexing import Parsed, Relation
from rigidsym.latex.reader import parse_latex
from rigidsym.latex.shapes import LatexError
from rigidsym.latex.table import Glyph, glyph_table, lookup

__all__ = ["LatexError", "Parsed", "Relation", "parse_latex", "Glyph", "glyph_table",
           "lookup"]
