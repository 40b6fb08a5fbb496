"""Derivatives of a kernel's program: the Jacobian twins of the kernels
(:mod:`.jacobians`: ``<name>_with_jacobians``, their names and layout) and forward- and
reverse-mode differentiation over the optimised straight-line program (:mod:`.vjp`)."""
