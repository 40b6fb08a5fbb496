"""rigidsym.kernels.arrays."""
