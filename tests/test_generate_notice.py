"""``rigidsym generate --target c|cpp --notice TEXT``: the user's generated code
carries the user's notice, or none, instead of the rigidsym project's MIT notice."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="module")
def codes():
    from rigidsym.codegen.generator import compile_many
    from rigidsym.codegen.spec import Arg, Kernel, Out

    def f(a, s):
        return a * s

    k = Kernel(name="scaled", summary="A vector times a scalar.", formula="b = s a",
               ids=("t:1",), sources=(f,),
               args=(Arg("a", (3,), "any", "a vector"), Arg("s", (), "any", "a scalar")),
               outputs=(Out("b", (3,), "the product"),), build=lambda a, s: {"b": a * s})
    return compile_many([k], plan32=False)


def _files(codes, notice):
    from rigidsym.codegen.backends.c.target import generate_c
    from rigidsym.codegen.backends.cpp.target import generate_cpp

    files = generate_c(codes, "acme_kernels", single_header=True, notice=notice)
    files.update(generate_cpp(codes, "acme_kernels", notice=notice))
    return files


def test_default_is_the_projects_mit_notice(codes):
    files = _files(codes, None)
    assert "Copyright (c) 2026 The rigidsym developers" in files["LICENSE"]
    assert all("SPDX-License-Identifier: MIT" in t for n, t in files.items() if n != "LICENSE")


def test_a_users_notice_replaces_the_projects_in_every_file(codes):
    notice = "Copyright (c) 2026 Acme Robotics GmbH\nSPDX-License-Identifier: Apache-2.0"
    files = _files(codes, notice)
    assert "LICENSE" not in files
    for name, text in files.items():
        assert "rigidsym developers" not in text and "MIT" not in text, name
        assert "Acme Robotics GmbH" in text and "Apache-2.0" in text, name
    # a header's comment holds both lines, each as a comment line, still a valid comment
    head = files["rigidsym_c_scaled.h"]
    assert " * Copyright (c) 2026 Acme Robotics GmbH\n * SPDX-License-Identifier: Apache-2.0\n" \
        " */\n" in head
    assert "# Copyright (c) 2026 Acme Robotics GmbH\n# SPDX" in files["CMakeLists.txt"]


def test_an_empty_notice_is_none(codes):
    files = _files(codes, "")
    assert "LICENSE" not in files
    for name, text in files.items():
        assert "SPDX" not in text and "rigidsym developers" not in text, name
    assert "`rigidsym generate --target c`.\n */\n" in files["rigidsym_c_scaled.c"]


def test_notice_only_with_the_c_targets(capsys):
    from rigidsym.cli import main

    assert main(["generate", "--notice", "", "--check"]) == 2
    assert "--notice: only with --target c or cpp" in capsys.readouterr().err


@pytest.mark.parametrize("bad", ["a */ b", "x --> y"])
def test_a_notice_that_would_end_a_comment_is_refused(tmp_path, capsys, bad):
    from rigidsym.cli import main

    out = tmp_path / "k"
    assert main(["generate", "--target", "c", "--kernel", "twist_transfer", "--notice", bad,
                 "--out", str(out)]) != 0
    assert "--notice" in capsys.readouterr().err and not out.exists()
