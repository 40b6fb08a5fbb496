"""The printing layer: book notation (Unicode, LaTeX) and LaTeX to MathML Core."""
