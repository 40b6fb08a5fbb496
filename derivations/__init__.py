"""The mathematics of Angeles' chapter 3, one module per book section, in book order.

Importing this package registers every declaration in
:data:`rigidsym.registry.declarations.REGISTRY`: each ``sec3_*`` module (found by name,
so that adding a section touches no other file).
"""

import importlib
import pkgutil
from pathlib import Path

#: the reading of the page these declarations transcribe: each glyph's kind or model and
#: each id's class, the file certcheck binds every certificate to (``--reading``)
READING = Path(__file__).with_name("angeles-chapter3.reading.toml")
#: how the transcription check reads some ids' LaTeX (a letter for several quantities, a
#: lost column separator, relations a definition is stated through), by id
TRANSCRIPTION_NOTES = Path(__file__).with_name("angeles-chapter3.transcription-notes.json")
#: the chapter's sections that hold no numbered equation or claim, each with why (said when
#: ``rigidsym verify --section`` is given one)
SECTIONS_WITHOUT_IDS = {"3.1": "the introduction holds no equations",
                        "3.9": "the exercises are run by `rigidsym exercise`"}

for _m in sorted(m.name for m in pkgutil.iter_modules(__path__) if m.name.startswith("sec3_")):
    importlib.import_module(f"{__name__}.{_m}")
