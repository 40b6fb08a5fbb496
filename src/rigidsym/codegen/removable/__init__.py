"""rigidsym.codegen.removable.singularities."""
