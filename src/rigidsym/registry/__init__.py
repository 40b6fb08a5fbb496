"""rigidsym.registry."""
