"""rigidsym.kernels.runtime."""
