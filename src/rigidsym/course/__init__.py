"""rigidsym.course."""
