"""The checking layer: declarations and registry, evidence, records, the checker, the
parallel runner, user modules and the worked-exercise framework."""
