"""Removable singularities of a kernel's program, derived and certified: where a quotient
such as ``sin s / s`` or ``(1 - cos s) / s^2`` of a norm ``s = sqrt(T)`` has a finite limit,
the generated code switches to its series there.

- :mod:`.singularities`: the pass over a kernel's program (which quotients, where, the
  branch written into the kernel);
- :mod:`.terms`: a kernel output's terms in the norm, grouped by their factor free of it;
- :mod:`.series`: the series of a removable quotient and its certificate."""
