"""rigidsym.codegen.accuracy: the choice and measurement of accurate forms.

- ``rule``: the accuracy rule, ``err <= min(8 u (kappa + 1), max(2 e_ref, 4 u))``, and the
  textbook formula it is judged against.
- ``regimes``: the exact points a user meets where formulas cancel, overflow or lose digits.
- ``singular_sets``: the zeros of a kernel's own denominators, approached as regimes.
- ``points``: the points a form is measured on (the generator's exact ones, the float32
  plan's), built from the regimes.
- ``error``: the normwise error of a form, its worst ratio to the rule, and the meter.
- ``compensated``: compensated products and sums (Kahan's difference of products, Dot2).
- ``rewrite_rules``: the candidate rewrites of a kernel's outputs, one function a rule.
- ``tan_half``: the rewrite of fractions over ``1 + cos phi`` as polynomials in tan(phi/2).
- ``rewrites``: the choice among the candidate rewrites by measured error and the zero test.
- ``cos_form``: the choice of the form of a bare ``cos phi`` in the half-angle program.
- ``float32``: the float32 precision plan, float or double per node of the program.
- ``peers``: the peer libraries' operations and conventions, as data.
- ``peer_adapters``: the calls that bring each peer to the kernels' conventions.
- ``harness/``: the 60-digit-and-beyond reference, the judge and the worst-input search
  (``benchmarks/accuracy.py``, the accuracy tests and ``rigidsym audit`` share them).
"""
