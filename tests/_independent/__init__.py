"""Independent solutions of the chapter's exercises, in plain NumPy (and SciPy's convex
hull): written from the book's statements, never importing rigidsym, so the property tests
compare the solver with a second solution by another method."""
