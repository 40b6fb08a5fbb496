"""What every layer shares, importing none of them: the error of bad user input
(:mod:`.errors`), the constraint-kind table (:mod:`.kinds`), where the book and the
generated kernels are (:mod:`.config`), files written atomically and modules loaded from a
file (:mod:`.files`), the user cache (:mod:`.cache`), the digests of sources (:mod:`.sources`),
progress on stderr (:mod:`.progress`), counts of real work (:mod:`.work`), valid float
draws of a kernel argument (:mod:`.draws`) and the engine's tuning constants in one settings
dataclass (:mod:`.settings`).

No imports here: the kernels runtime and ``setup.py``'s build read single modules of this
package without loading sympy or the rest."""
