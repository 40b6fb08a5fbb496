"""The kernels' compiler flags (:mod:`rigidsym.kernels.cbuild.driver`'s), and the refusal of flags
that would make the kernels silently wrong.

Standard library only: ``setup.py`` loads :mod:`rigidsym.kernels.cbuild.driver` by path, and it
loads this module by path too (its ``_sibling``). The reasons for each flag are beside it;
:mod:`rigidsym.kernels.cbuild.driver`'s docstring tells the whole build.
"""

from __future__ import annotations

import os
import shlex

__all__ = ["KERNEL_FLAGS", "COMMON_FLAGS", "MVEC_FLAGS", "OMP_FLAGS", "UNSAFE_FLAGS",
           "unsafe_flag", "kernel_flags"]

#: optimisation flags of the kernels (``RIGIDSYM_CFLAGS`` replaces them). -fno-math-errno:
#: sqrt then never calls libm to set errno, a branch that kept every lanes loop with a root
#: scalar (gcc -fopt-info-vec-missed: "control flow in loop"); results are the same bits.
#: -fno-tree-slp-vectorize: GCC's SLP vectorizer (12.2, x86-64-v3 and -v4) forms fused
#: multiply-add-subtract instructions (vfmaddsub, vfmsubadd) from alternating `a b - c` and `a
#: b + c` lanes even under -ffp-contract=off (the bug class box2d's tracker records at
#: github.com/erincatto/box2d/issues/1086, on RISC-V): 18 functions of the module have
#: them, and 9 float64 kernels give other bits on C than on NumPy
#: (moving_frame_acceleration at 18 % of random points,
#: wrench_axis_with_jacobians 1024 ulps of a small component), and float32 lanes loops leave
#: their measured plans. Without it: the
#: same bits as the scalar program; measured at the geometric mean 0.99 of the time over
#: the 158 kernels (one thread, N = 1e5), up to 1.2 on two Jacobian kernels. Clang takes the
#: flag as its -fno-slp-vectorize (and honours -ffp-contract=off there anyway).
KERNEL_FLAGS = ("-O3", "-std=c99", "-ffp-contract=off", "-fno-math-errno",
                "-fno-tree-slp-vectorize")
#: every object: position-independent, only PyInit__ckernels exported
COMMON_FLAGS = ("-fPIC", "-fvisibility=hidden", "-DNDEBUG")
#: flags of the libmvec build (sin/cos not fused into a scalar sincos call)
MVEC_FLAGS = ("-fopenmp-simd", "-fno-builtin-sin", "-fno-builtin-cos", "-DRIGIDSYM_LIBMVEC")
#: flags of the OpenMP build (compile and link)
OMP_FLAGS = ("-fopenmp",)


#: flags that let the compiler assume no NaN or inf, or reorder sums: the
#: kernels' NaN/singular tests (x - x, x != x) fold away and rigidsym_sincos' reduction is
#: reassociated (the book's rotation came back as the identity). Each with the flag that
#: undoes it when it comes later on the line.
UNSAFE_FLAGS = {
    "-ffast-math": "-fno-fast-math", "-Ofast": "-fno-fast-math",
    "-ffinite-math-only": "-fno-finite-math-only",
    "-fassociative-math": "-fno-associative-math",
    "-funsafe-math-optimizations": "-fno-unsafe-math-optimizations",
    "-freciprocal-math": "-fno-reciprocal-math",
}


def unsafe_flag(flags) -> str | None:
    """The first flag of ``flags`` that would make the kernels silently wrong and that no
    later flag undoes (:data:`UNSAFE_FLAGS`; ``-fno-fast-math`` undoes them all), or None."""
    flags = list(flags)
    for i, f in enumerate(flags):
        if f in UNSAFE_FLAGS:
            later = flags[i + 1:]
            if UNSAFE_FLAGS[f] not in later and "-fno-fast-math" not in later and \
                    "-fno-unsafe-math-optimizations" not in later:
                return f
    return None


def kernel_flags() -> tuple[str, ...]:
    """``RIGIDSYM_CFLAGS`` (split) or :data:`KERNEL_FLAGS`.

    Raises:
        ValueError: the flags contain one of :data:`UNSAFE_FLAGS` (``-ffast-math``,
            ``-Ofast``, ``-ffinite-math-only``, ``-fassociative-math``, ...) not undone
            later on the line: it breaks the NaN/singular logic and the sin/cos reduction.
    """
    env = os.environ.get("RIGIDSYM_CFLAGS")
    flags = tuple(shlex.split(env)) if env else KERNEL_FLAGS
    bad = unsafe_flag(flags)
    if bad is not None:
        raise ValueError(f"RIGIDSYM_CFLAGS: {bad} breaks the kernels' NaN/singular logic and "
                         f"their sin/cos reduction; remove it (or add "
                         f"{UNSAFE_FLAGS[bad]} after it)")
    return flags
