"""The printing layer: book notation (Unicode, LaTeX: notation; the atoms' book names:
names; the labels and evidence declarations write: labels), plain ASCII for terminals
(ascii) and LaTeX to MathML Core (mathml)."""
