"""Deciding and its records: explicit matrices, the ball-arithmetic backing, evidence,
principal branches, the counterexample described in the book's symbols (and its exact
values) and the plain-data records. The lowest part of :mod:`rigidsym.checking`: it imports
neither the repair search nor the checker that drives both."""
