"""certcheck: an independent checker of rigidsym's certificates.

Standard library only (python-flint, when installed, only speeds up the polynomial
arithmetic); it imports neither rigidsym nor sympy nor numpy. ``python -m certcheck DIR``
checks every certificate in DIR and exits non-zero when any fails. The format:
``docs/certificates.md`` of the rigidsym repository.
"""

from certcheck.check import CheckError, check_certificate, load

__all__ = ["CheckError", "check_certificate", "load"]
__version__ = "1.0"
