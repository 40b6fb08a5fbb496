"""rigidsym: checked computer algebra and generated kernels for rigid-body mechanics.

Chapter 3 of J. Angeles, *Fundamentals of Robotic Mechanical Systems*: every numbered
equation declared once (``rigidsym.derivations``), decided by a sound constraint-aware checker
(:mod:`rigidsym.checker`), reported, and compiled to kernels.
"""

__version__ = "0.2.0"
