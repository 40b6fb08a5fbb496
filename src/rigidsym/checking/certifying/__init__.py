"""Certificates of verdicts, for the independent checker ``certcheck/`` (docs/certificates.md).

- :mod:`.certificates`: each decided id written as a statement and its evidence;
- :mod:`.statement`: the statement in the certificates' grammar;
- :mod:`.cofactors`: cofactor evidence ``D (lhs - rhs) = sum mu_i h_i``, found by a linear
  ansatz (:mod:`.cofactor_ansatz`) or by the rotation's triangular set
  (:mod:`.rotation_triangular_set`);
- :mod:`.coq`, :mod:`.coq_normal_form`: Coq proofs of the identities, by ``ring`` on the
  cofactors or by normal forms."""
