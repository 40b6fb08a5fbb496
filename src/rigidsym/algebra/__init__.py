"""The algebra layer: constrained atoms, chapter-2 primitives and the book's operators.

Imports nothing of rigidsym above it. Public names reach users through
:mod:`rigidsym.declare`.
"""
