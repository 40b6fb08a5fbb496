"""rigidsym.latex.transformer."""
