"""The verifier: each declaration's verdict decided soundly, backed numerically, repaired and
certified.

- :mod:`.deciding`: explicit matrices, the numeric backing (balls), evidence, principal
  branches, the counterexample described in the statement's symbols, and the records;
- :mod:`.repairing`: the repair search (edits, candidates, the fast evaluator) and the
  corrected form of a failing member (:mod:`.repairing.correction`);
- :mod:`.certifying`: certificates of verdicts for the independent checker ``certcheck/``
  (the statement's grammar, cofactor evidence, Coq proofs);
- here, above those parts: the checker (:mod:`.checker`, its outcome :mod:`.outcome`), the
  verdict cache (:mod:`.verdict_cache`) and the parallel runner (:mod:`.runner`).

The declarations themselves (the registry, relations, user modules) are
:mod:`rigidsym.registry`'s, below this layer. Layered (import-linter contract in
``pyproject.toml``): runner > verdict_cache > checker | certifying > repairing > deciding."""
