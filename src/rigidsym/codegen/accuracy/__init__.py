"""rigidsym.codegen.accuracy."""
