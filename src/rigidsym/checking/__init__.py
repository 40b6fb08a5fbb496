"""The checking layer, in three parts and the modules that drive them:

- :mod:`.deciding`: declarations and registry, user modules, explicit matrices, the
  numeric backing (balls), evidence, the counterexample's description and the records;
- :mod:`.repairing`: the repair search (edits, candidates, the fast evaluator) and the
  corrected form of a failing member (:mod:`.repairing.correction`);
- :mod:`.worked`: the worked-exercise framework (its data and renderers);
- here, above deciding and repairing: the checker (:mod:`.checker`), the verdict cache
  (:mod:`.verdict_cache`) and the parallel runner (:mod:`.runner`).

Layered (import-linter contract in ``pyproject.toml``): runner > verdict_cache > checker >
repairing > deciding; worked imports nothing else of checking and nothing else imports it."""
