"""rigidsym.kernels.cbuild."""
