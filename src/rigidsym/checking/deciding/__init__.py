"""Deciding and its records: the registry of declarations and user modules, explicit
matrices, the ball-arithmetic backing, evidence, the counterexample described in the book's
symbols and the plain-data records. The lowest part of :mod:`rigidsym.checking`: it imports
neither the repair search nor the checker that drives both."""
