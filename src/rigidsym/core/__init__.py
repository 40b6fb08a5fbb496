"""rigidsym.core."""
