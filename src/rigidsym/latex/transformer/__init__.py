"""The LaTeX transformer: lark's parse tree of ``grammar.lark`` made into sympy objects of the
declaration vocabulary, one class, :class:`rigidsym.latex.transformer.chapter.LatexTransformer`
(what :func:`rigidsym.latex.reader.parse_latex` runs), made of a mixin per rule family:

- :mod:`~rigidsym.latex.transformer.chapter`: the class itself and the chapter's rules
  (numbers, groups, sums and products, transposes, inverses and powers, block matrices,
  ``Cross``, ``Det``, ``Cpm``, ``Vect``, relations and chains);
- :mod:`~rigidsym.latex.transformer.glyphs`: the glyphs (``GlyphRules``): a glyph's key and
  its symbol by the glyph table or a reader's declarations, sized zeros and identities, ``t``
  as time, ranges of entries;
- :mod:`~rigidsym.latex.transformer.meanings`: the choices between meanings in a reader's
  LaTeX (``MeaningRules``): a symbol applied to an argument or a product, ``[x]`` as a
  cross-product matrix, a sized identity or zero;
- :mod:`~rigidsym.latex.transformer.rigid_motions`: the vocabulary of rigid motions as
  Modern Robotics and Murray-Li-Sastry write it (``RigidMotionRules``: ``e^X``, ``\\log``,
  ``[x]``, ``\\mathrm{Ad}``, ``\\frac{dX}{d\\theta}`` ...);
- :mod:`~rigidsym.latex.transformer.book_notations`: the other books' notations
  (``BookNotationRules``: ``^\\wedge``, ``^\\vee``, Featherstone's ``\\times^*``, frame indices,
  norms, ``\\operatorname{diag}``, trailing declarations);
- :mod:`~rigidsym.latex.transformer.products`: products written without parentheses,
  read by their shapes (functions ``BookNotationRules`` calls).
"""
