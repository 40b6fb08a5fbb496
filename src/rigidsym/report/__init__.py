"""The report layer: schema-2 records (record), the public API's results (results),
Markdown (markdown), HTML (html, with LaTeX to MathML in mathtext), ``show`` (show), user
reports (user), and what each output prints alike: the counterexample in the book's symbols
(counterexample), the repairs (repairs), the numeric backing's sentence (numeric) and the
glossary (glossary)."""
