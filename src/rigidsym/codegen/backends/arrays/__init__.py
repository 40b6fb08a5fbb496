"""What the PyTorch and JAX targets share (no target of its own): the rendering of a
kernel's programs (:mod:`.programs`) and its template (``templates/array_kernel.py.j2``)."""
