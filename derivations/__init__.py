"""The mathematics of Angeles' chapter 3, one module per book section, in book order.

Importing this package registers every declaration in
:data:`rigidsym.registry.declarations.REGISTRY`: each ``sec3_*`` module (found by name,
so that adding a section touches no other file).
"""

import importlib
import pkgutil

for _m in sorted(m.name for m in pkgutil.iter_modules(__path__) if m.name.startswith("sec3_")):
    importlib.import_module(f"{__name__}.{_m}")
