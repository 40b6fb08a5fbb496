"""rigidsym.checking.certifying."""
