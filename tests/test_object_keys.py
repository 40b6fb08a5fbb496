"""Which headers key a compiled object (rigidsym.kernels.cbuild.objects.headers_digest): those
its source includes, directly or through another header, so that adding or changing one
kernel leaves every other kernel's objects in the object cache."""

from __future__ import annotations

from pathlib import Path

from rigidsym.kernels.cbuild.objects import headers_digest


def _folder(tmp_path: Path) -> Path:
    c = tmp_path / "c"
    c.mkdir()
    (c / "common.h").write_text("#define ONE 1\n")
    (c / "a.h").write_text('#include "common.h"\n#include <math.h>\nint a(void);\n')
    (c / "a.c").write_text('#include "a.h"\nint a(void) { return ONE; }\n')
    (c / "b.h").write_text('#include "common.h"\nint b(void);\n')
    (c / "index.h").write_text('#ifdef X\n#include "a.h"\n#endif\n#include "b.h"\n')
    (c / "table.c").write_text('#include "index.h"\n')
    return c


def test_a_source_is_keyed_by_the_headers_it_reads_and_no_other(tmp_path):
    c = _folder(tmp_path)
    a, table = headers_digest(c, c / "a.c"), headers_digest(c, c / "table.c")
    (c / "new_kernel.h").write_text("int new_kernel(void);\n")       # a kernel added
    (c / "b.h").write_text('#include "common.h"\nint b(int);\n')      # another one changed
    assert headers_digest(c, c / "a.c") == a
    assert headers_digest(c, c / "table.c") != table                  # it includes b.h
    (c / "common.h").write_text("#define ONE 2\n")                     # read through a.h
    assert headers_digest(c, c / "a.c") != a


def test_an_include_under_a_conditional_counts_and_one_of_a_macro_counts_every_header(
        tmp_path):
    c = _folder(tmp_path)
    table = headers_digest(c, c / "table.c")
    (c / "a.h").write_text('#include "common.h"\nint a(int);\n')       # under #ifdef X
    assert headers_digest(c, c / "table.c") != table
    (c / "m.c").write_text("#define H \"b.h\"\n#include H\n")
    assert headers_digest(c, c / "m.c") == headers_digest(c)
