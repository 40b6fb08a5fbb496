"""The glossary covers every word the output uses.

The words come from the source where it names them: the verdicts (``VERDICTS``), the
does-not-hold's origins as the summaries and the certificates name them (``CAUSE_KEYS``,
``CAUSE_CLASSES``), certcheck's line words (``CHECKED``, ``NOT READ``, ``FAILED``, ``NOTE``), the
reader's ``tangent order`` declaration; and the field's words the output prints (symbol
tables of certificates, ``--let`` kinds, ``check --latex``'s notes), each checked to be in a
string of the package's code. A word is covered when docs/glossary.md has an entry headed by
it or prints it in bold inside an entry.
"""

from __future__ import annotations

import ast
import re
from functools import cache
from pathlib import Path

import pytest

from rigidsym.checking.certifying.certificates import CAUSE_CLASSES
from rigidsym.latex import tangent
from rigidsym.registry.declarations import VERDICTS
from rigidsym.report.record import CAUSE_KEYS

ROOT = Path(__file__).resolve().parents[1]
GLOSSARY = ROOT / "docs" / "glossary.md"
SRC = ROOT / "src" / "rigidsym"
CERTCHECK_MAIN = ROOT / "certcheck" / "src" / "certcheck" / "__main__.py"

# the package's strings (code_strings, every source parsed) are read once, on one worker:
# each worker that ran a field word's test read them again
pytestmark = pytest.mark.xdist_group("glossary")

#: words of the field the output prints (certificates' symbol tables, ``--let`` kinds and
#: readings, ``check --latex``'s notes); each must occur in a string of the package's code
FIELD_WORDS = ("counterexample", "numeric cross-check", "natural invariants", "pitch",
               "twist", "wrench", "Plücker array", "Plücker coordinates", "inertia dyad",
               "cross-product matrix", "certificate")


def certcheck_words() -> list[str]:
    """The upper-case words a line of certcheck's output starts with (``NOT READ x.json:``)."""
    text = CERTCHECK_MAIN.read_text(encoding="utf-8")
    return sorted(set(re.findall(r'f?"([A-Z]{3,}(?: [A-Z]{3,})*) ', text)))


def output_words() -> list[str]:
    causes = [CAUSE_CLASSES.get(key, key) for key, _ in CAUSE_KEYS]
    return [*VERDICTS, *causes, *certcheck_words(), tangent.NAME, *FIELD_WORDS]


@cache
def covered() -> set[str]:
    text = GLOSSARY.read_text(encoding="utf-8")
    heads = re.findall(r"^## (.+?)\s*$", text, flags=re.M)
    bold = re.findall(r"\*\*(.+?)\*\*", text, flags=re.S)
    return {" ".join(w.split()).lower() for w in heads + bold}


@cache
def code_strings() -> str:
    """Every string constant of the package's code (docstrings left out) and the strings of
    the chapter's reading (its model lines' words go into every certificate), joined."""
    import tomllib

    reading = tomllib.loads((ROOT / "derivations" / "angeles-chapter3.reading.toml")
                            .read_text(encoding="utf-8"))
    found = [x.get("where", "") for x in reading.get("let", [])]
    for path in SRC.rglob("*.py"):
        docs, strings = set(), []       # one walk of the tree: its docstrings, its strings
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef,
                                  ast.AsyncFunctionDef))
                    and node.body and isinstance(node.body[0], ast.Expr)
                    and isinstance(node.body[0].value, ast.Constant)):
                docs.add(id(node.body[0].value))
            elif isinstance(node, ast.Constant) and isinstance(node.value, str):
                strings.append(node)
        found += [node.value for node in strings if id(node) not in docs]
    return "\n".join(found)


def test_the_words_come_from_the_source():
    words = output_words()
    assert {"verified", "definition", "does-not-hold", "undecided"} <= set(words)
    assert {"book erratum", "conversion slip", "unattributed"} <= set(words)
    assert {"CHECKED", "NOT READ", "FAILED", "NOTE"} <= set(words)
    assert "tangent order" in words


@pytest.mark.parametrize("word", FIELD_WORDS)
def test_a_field_word_is_printed_by_the_package(word):
    assert word in code_strings(), f"{word!r} is in no string of src/rigidsym: drop it here"


@pytest.mark.parametrize("word", output_words())
def test_every_output_word_has_a_glossary_entry(word):
    assert " ".join(word.split()).lower() in covered(), (
        f"{word!r} is printed but docs/glossary.md has no entry for it (a '## {word}' "
        "heading or the word in bold; then copy the file to src/rigidsym/report/glossary.md)")
