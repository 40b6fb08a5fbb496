"""The repair search: the search itself (repair), its edits (mutate, edit_words), candidates,
the structural tree operations (shapes, marks, treeops), the fast modular evaluator
(fasteval), its time limit (deadline), its records (records), and the corrected form of a
failing member (correction). It rests on :mod:`rigidsym.checking.deciding` (registry,
explicit matrices, records) and is driven by :mod:`rigidsym.checking.checker`."""
