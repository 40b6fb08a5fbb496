"""Answer files matched to a class's roster: by student id first, then by name as people
and file systems write it (Unicode-normalised, case-folded, accents stripped).

``Zoe Muller.json`` for "Zoë Müller", ``li wei.json`` for "Li Wei", a macOS file name in
NFD (``José`` as ``Jose`` + a combining accent) and ``Amy_Ames.json`` all match; two
roster names that fold alike (``Zoë Müller`` and ``Zoe Muller``) are reported, never
guessed, and a name the roster holds twice matches by id only; an id a spreadsheet wrote
without its leading zeros (``42`` for ``00042``) matches the one roster id it reads as.
Each file that matches no student is a line of the report, and the rest of the class is
graded.
"""

from __future__ import annotations

import re
import unicodedata

__all__ = ["fold", "match_answers"]


def fold(name: str) -> str:
    """A name as matching compares it: NFKD, combining marks dropped, case-folded, runs of
    spaces, ``_``, ``-`` and ``.`` one space (``"Zoë_Müller"`` -> ``"zoe muller"``)."""
    decomposed = unicodedata.normalize("NFKD", name)
    bare = "".join(c for c in decomposed if not unicodedata.combining(c))
    return re.sub(r"[\s_.\-]+", " ", bare.casefold()).strip()


def match_answers(labelled: list[tuple[str, dict]], students: list[dict],
                  places: list[str] | None = None
                  ) -> tuple[dict[int, tuple[str, dict]], list[str]]:
    """Each answer set matched to one student of the roster.

    Two answer sets that match one student (two CSV rows of one name without ids, one
    file named by the name and one by the id) are both refused, with a line naming both:
    which of them is the student's is not guessed, and the student is then not graded.

    Args:
        labelled: ``[(label, answers)]``: a file's stem or a CSV row's student; an
            ``"id"`` entry of ``answers`` is the student id it declares (taken out).
        students: the key's records (``student``, ``id``, ``handout``), in roster order.
        places: where each answer set was read, naming it in a refusal of two sets
            (``"María García (row 3 of answers.csv)"``), one per entry of ``labelled``;
            default: the labels.

    Returns:
        ``({roster index: (label, answers)}, problems)``: a line per answer set not
        graded (matched to no student, or one of two sets for one student).

    Raises:
        ValueError: ``places`` not one per answer set.
    """
    if places is None:
        places = [label for label, _ in labelled]
    if len(places) != len(labelled):
        raise ValueError(f"places: expected one per answer set ({len(labelled)}), got "
                         f"{len(places)}")
    by_id: dict[str, int] = {}
    by_name: dict[str, list[int]] = {}
    by_fold: dict[str, list[int]] = {}
    by_stem: dict[str, int] = {}
    for i, r in enumerate(students):
        if r.get("id"):
            by_id[str(r["id"]).strip()] = i
        by_name.setdefault(unicodedata.normalize("NFC", r["student"]), []).append(i)
        by_fold.setdefault(fold(r["student"]), []).append(i)
        stem = str(r.get("handout", "")).rsplit("/", 1)[-1].removesuffix(".html")
        if stem:
            by_stem[stem] = i
    out: dict[int, tuple[str, dict]] = {}
    claims: dict[int, list[int]] = {}
    problems = []
    for k, (label, answers) in enumerate(labelled):
        answers = dict(answers)
        declared = str(answers.pop("id", "") or "").strip()
        i, why = _one(label, declared, by_id, by_name, by_fold, by_stem, students)
        if i is None:
            problems.append(f"{label}: not graded: {why}")
            continue
        claims.setdefault(i, []).append(k)
        out.setdefault(i, (label, answers))
    for i, ks in claims.items():
        if len(ks) > 1:
            del out[i]
            who = students[i]["student"] + (f" (id {students[i]['id']})"
                                             if students[i].get("id") else "")
            problems.append(f"{' and '.join(places[k] for k in ks)}: not graded: "
                            f"{len(ks)} answer sets match {who} (give each row its student "
                            f"id, or keep one): neither is guessed")
    return out, problems


def _one(label, declared, by_id, by_name, by_fold, by_stem, students):
    """The roster index of one answer set, or ``(None, why)``."""
    if declared:
        if declared in by_id:
            return by_id[declared], ""
        # a spreadsheet drops an id's leading zeros (00042 -> 42): matched when one
        # roster id alone reads so
        bare = [i for k, i in by_id.items() if k.lstrip("0") == declared.lstrip("0")]
        if len(bare) == 1 and declared.isdigit():
            return bare[0], ""
        return None, f"its student id {declared!r} is not on the roster"
    if label.strip() in by_id:
        return by_id[label.strip()], ""
    exact = by_name.get(unicodedata.normalize("NFC", label.strip()), [])
    if len(exact) > 1:
        return None, (f"{len(exact)} students are named {label!r} (ids "
                      f"{', '.join(str(students[i]['id']) for i in exact)}): name the file "
                      f"by the student id")
    if exact:
        return exact[0], ""
    if label in by_stem:
        return by_stem[label], ""
    folded = by_fold.get(fold(label), [])
    names = sorted({students[i]["student"] for i in folded})
    if len(folded) > 1:
        return None, ("its name matches " + " and ".join(repr(n) for n in names) +
                      " once accents and case are set aside: not guessed; name the file by "
                      "the student id")
    if folded:
        return folded[0], ""
    return None, "no student id or name on the roster matches it"
