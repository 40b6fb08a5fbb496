"""The algebra layer: constrained atoms (symbols), chapter-2 primitives (primitives), the
book's operators (operators) and the vocabulary of rigid motions (rigid_motions).

Imports nothing of rigidsym above it. Public names reach users through
:mod:`rigidsym.declare`.
"""
