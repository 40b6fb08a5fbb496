"""Any document in, its errata out: every displayed relation of a reader's own notes,
paper or book (Markdown or LaTeX) decided by ``check_latex``, with one reading file of
declarations per document (``docs/check-documents.md``).

- ``displays``: a display and where it stands; ``macros``: the document's macros;
  ``relations``: a display split into relations; ``markdown``, ``tex``: the readers;
  ``document``: a document read;
- ``declarations``: what each relation is checked with (the reading file, the document's
  own definitions in order); ``store``: the verdict store; ``checking``: the errata;
  ``report``: text, JSON and Markdown.
"""

from rigidsym.documents.checking import DocumentResult as DocumentResult
from rigidsym.documents.checking import check_document as check_document
from rigidsym.documents.checking import exit_code as exit_code
from rigidsym.documents.document import Document as Document
from rigidsym.documents.document import read_document as read_document
from rigidsym.documents.relations import Relation as Relation

__all__ = ["Document", "DocumentResult", "Relation", "check_document", "exit_code",
           "read_document"]
