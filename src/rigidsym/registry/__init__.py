"""The declarations every layer reads: the equation registry (:mod:`.declarations`: one
declaration per numbered equation of the book, or per user id), the relation types
(:mod:`.relations`: ``Rel`` and the nodes its sides may be written in) and user modules
(:mod:`.usermodules`: a reader's own declarations, checked by the book's engine).

Below the verifier and the readers, above the algebra its relations are written in."""
