"""The extension target: the C of the Python package's extension module (``generated/c/``):
per kernel a header and a source (``c_kernel.h.j2``, ``c_kernel.c.j2``: the batch loops in
double and float32), the shared declarations (``c_common.h.j2``), the index of the kernels
(``c_kernels_index.h.j2``), the module (``c_module.c.j2``), the per-path table of batch
functions (``c_table.c.j2``), the CPU dispatcher (``c_dispatch.h.j2``) and the per-call entry
points (``c_fast.h.j2``).
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import sympy as sp

from rigidsym.codegen.backends import RenderContext, Target, kernel_files, shared_environment
from rigidsym.codegen.backends.extension.printer import KernelCPrinter, KernelCVectorPrinter
from rigidsym.codegen.backends.extension.program import f32_code, finite_check, trig_plan
from rigidsym.codegen.backends.printing import program_lines
from rigidsym.codegen.optimise import Program, trig_split
from rigidsym.codegen.spec import Kernel
from rigidsym.core import kinds as _kinds

__all__ = ["TARGET", "TEMPLATES", "SOA_F32", "SOA_F64", "VEC_F64", "render", "render_kernel",
           "render_module", "vector_text", "vectorisable", "VEC_CALLS"]

#: the target's templates
TEMPLATES = Path(__file__).parent / "templates"
#: the ``kind`` of an entry point's argument whose constraint only the Python path checks
#: (``RIGIDSYM_PYTHON`` in ``c_fast.h.j2``)
_C_PYTHON_CHECK = 3
#: kernels whose checked calls take the Python path for a check the C entry lacks: the
#: rigid-body checks of rigidsym.kernels.runtime.inputs.check_inertia (BODY_KERNELS there)
_PYTHON_CHECKED = frozenset({"inertia_at_point", "inertia_dyad_at_point"})
#: kernels whose float32 lanes function reads its samples through local columns (structure
#: of arrays): where that measured faster than the row-major loop, which gcc
#: leaves scalar for them (``benchmarks/soa_check.py``, ``benchmarks/RESULTS.md``); slower
#: for kernels whose row-major loop vectorises (K4, K6), so not the default
SOA_F32 = frozenset({"rotation_from_euler_rodrigues"})
#: the same in float64: K1's row-major loop (4 strided loads, 9 strided stores a sample) is
#: scalar, with a division; through local columns it vectorises (callgrind 88 -> 47
#: instructions a sample; the peer benchmark, N = 1e6, 1.22 -> 0.95 of the fastest peer,
#: benchmarks/RESULTS.md)
SOA_F64 = frozenset({"rotation_from_euler_rodrigues"})
#: kernels whose float64 lanes function runs across samples on x86-64-v3 (``RIGIDSYM_VEC_F64``
#: in ``c_common.h.j2``): inputs transposed to columns of 4 with AVX2 shuffles, the range
#: filter fed from those columns in the same pass instead of a second one, the arithmetic on
#: GCC vector types (for a kernel with sin/cos, the per-sample loop after the sin/cos loop).
#: Chosen by measurement on an AVX2 CPU (``benchmarks/vec_lanes_select.py``): of the 131
#: kernels whose vector text is :func:`vectorisable`, those faster than their row-major loop
#: in cache (N = 4096) and at N = 2e5 in two runs; slower were mostly Jacobians with large
#: outputs (up to 1.8x: their columns spill). K6 13.6 -> 11.2, K4 5.9 -> 5.0, K2 17.1 -> 9.7 ns
#: a sample at N = 1e6 in a C driver (benchmarks/RESULTS.md).
VEC_F64 = frozenset({"H_matrix", "H_matrix_dot", "H_tilde", "H_tilde_dot", "L_matrix",
    "L_matrix_dot", "L_tilde", "L_tilde_dot", "N_matrix", "N_matrix_dot", "N_tilde",
    "N_tilde_dot", "euler_angle_rates_xyx_fixed", "euler_angle_rates_xyz_body",
    "euler_angle_rates_xyz_fixed", "euler_angle_rates_xzx_fixed",
    "euler_angle_rates_xzy_body", "euler_angle_rates_xzy_fixed",
    "euler_angle_rates_yxy_fixed", "euler_angle_rates_yxz_body",
    "euler_angle_rates_yxz_fixed", "euler_angle_rates_yzx_body",
    "euler_angle_rates_zxy_body", "euler_angle_rates_zxz_fixed",
    "euler_angle_rates_zyx_body", "euler_angle_rates_zyx_fixed",
    "euler_angle_rates_zyz_fixed", "euler_rate_matrix_xyx_body",
    "euler_rate_matrix_xyx_fixed", "euler_rate_matrix_xyz_body",
    "euler_rate_matrix_xyz_fixed", "euler_rate_matrix_xzx_body",
    "euler_rate_matrix_xzx_fixed", "euler_rate_matrix_xzy_body",
    "euler_rate_matrix_xzy_fixed", "euler_rate_matrix_yxy_body",
    "euler_rate_matrix_yxy_fixed", "euler_rate_matrix_yxz_body",
    "euler_rate_matrix_yxz_fixed", "euler_rate_matrix_yzx_body",
    "euler_rate_matrix_yzx_fixed", "euler_rate_matrix_yzy_body",
    "euler_rate_matrix_yzy_fixed", "euler_rate_matrix_zxy_body",
    "euler_rate_matrix_zxy_fixed", "euler_rate_matrix_zxz_body",
    "euler_rate_matrix_zxz_fixed", "euler_rate_matrix_zyx_body",
    "euler_rate_matrix_zyx_fixed", "euler_rate_matrix_zyz_body",
    "euler_rate_matrix_zyz_fixed", "euler_rodrigues_product",
    "euler_rodrigues_product_with_jacobians", "inertia_at_point", "instant_screw_axis",
    "instant_screw_point_pitch", "kinetic_energy", "kinetic_energy_with_jacobians",
    "moving_frame_acceleration", "moving_frame_acceleration_with_jacobians",
    "newton_euler_residual", "newton_euler_wrench", "plucker_from_points",
    "plucker_from_points_with_jacobians", "plucker_transfer", "point_acceleration",
    "point_acceleration_with_jacobians", "rotation_from_natural_invariants",
    "screw_axis_point", "screw_axis_point_with_jacobians", "twist_transfer", "wrench_axis",
    "wrench_transfer"})
#: the kernels of ``VEC_F64`` whose lanes run on x86-64-v4 (an AVX-512 CPU) as well, where
#: the others keep the compiler's own vectorisation of the row-major loop and the AVX-512
#: range test as a second pass: the kernel's C defines ``RIGIDSYM_VEC_F64_ON_V4`` before
#: including ``rigidsym_common.h``. Chosen by measurement on an AVX-512 CPU
#: (``benchmarks/vec_lanes_select.py --kernels`` over the 73, record
#: ``vec_lanes_v4.json``): those faster than the v4 loop in cache and at N = 2e5 in two runs,
#: the same bits; K6 (``newton_euler_residual``) 0.71 and 0.80-0.83, K4 level (not listed).
VEC_F64_V4 = frozenset({
    "H_matrix", "H_matrix_dot", "H_tilde_dot", "L_matrix", "L_matrix_dot", "L_tilde",
    "L_tilde_dot", "N_matrix", "N_matrix_dot", "N_tilde", "N_tilde_dot",
    "euler_rate_matrix_xyx_body", "euler_rate_matrix_xyx_fixed",
    "euler_rate_matrix_xyz_body", "euler_rate_matrix_xyz_fixed",
    "euler_rate_matrix_xzx_body", "euler_rate_matrix_xzx_fixed",
    "euler_rate_matrix_xzy_body", "euler_rate_matrix_xzy_fixed",
    "euler_rate_matrix_yxy_body", "euler_rate_matrix_yxy_fixed",
    "euler_rate_matrix_yxz_body", "euler_rate_matrix_yxz_fixed",
    "euler_rate_matrix_yzx_body", "euler_rate_matrix_yzy_body",
    "euler_rate_matrix_yzy_fixed", "euler_rate_matrix_zxy_body",
    "euler_rate_matrix_zxy_fixed", "euler_rate_matrix_zxz_body",
    "euler_rate_matrix_zxz_fixed", "euler_rate_matrix_zyx_body",
    "euler_rate_matrix_zyx_fixed", "euler_rate_matrix_zyz_body",
    "euler_rate_matrix_zyz_fixed", "newton_euler_residual",
    "rotation_from_natural_invariants", "screw_axis_point_with_jacobians"})

#: the functions the vector text may call: each is defined in ``c_common.h.j2`` and does the
#: scalar form's IEEE operations lane by lane (fma as ``_mm256_fmadd_pd``, one rounding)
VEC_CALLS = frozenset({"rigidsym_diffprod_v4", "rigidsym_sumprod2_v4", "rigidsym_sumprod3_v4",
                       "rigidsym_sumprod4_v4", "rigidsym_select_v4", "rigidsym_sqrt_v4"})
#: a call in printed C (``name(``)
_CALL = re.compile(r"\b([A-Za-z_][A-Za-z0-9_]*)\s*\(")
#: C's ternary and logical operators (defined for scalars, not GCC's vector types in C)
_SCALAR_OP = re.compile(r"\?|&&|\|\||!(?!=)")


def vector_text(program: Program, kernel: Kernel) -> dict:
    """``program`` printed on columns of 4 samples (:class:`KernelCVectorPrinter`):
    ``{"temps", "outputs", "dens", "finite"}`` as the templates read them."""
    vp = KernelCVectorPrinter()
    return {"temps": [(str(s), vp.column(v)) for s, v in program.temps],
            "outputs": [vp.column(v) for v in program.outputs],
            "dens": [vp.doprint(v) for v in program.dens],
            "finite": finite_check(program, kernel, vp) or None}


def vectorisable(text: dict) -> bool:
    """Whether a vector text (:func:`vector_text`) runs as printed on GCC vector types: no
    call but those of :data:`VEC_CALLS`, and no ternary or logical operator (which C defines
    for scalars only); ``+``, ``-``, ``*``, ``/``, comparisons and literals act lane by lane."""
    texts = [e for _, e in text["temps"]] + list(text["outputs"]) + list(text["dens"])
    texts += [text["finite"]] if text["finite"] else []
    return all(name in VEC_CALLS for t in texts for name in _CALL.findall(t)) and not any(
        _SCALAR_OP.search(t) for t in texts)


def render_kernel(ctx: RenderContext, kc) -> dict[str, str]:
    """``c/<kernel>.h`` and ``c/<kernel>.c`` of the compiled kernel ``kc``."""
    env = shared_environment(TEMPLATES)
    k = kc.kernel
    cp = KernelCPrinter()
    divides = any(v.program.dens for v in kc.variants)
    used = set()
    for v in kc.variants:
        for e in [*(x for _, x in v.program.temps), *v.program.outputs, *v.program.dens,
                  *([v.cond] if v.cond is not None else [])]:
            used |= {str(s) for s in sp.sympify(e).free_symbols}
    cvars = [{"name": v.name, "cond": None if v.cond is None else cp.doprint(v.cond),
              "finite": finite_check(v.program, k), **program_lines(v.program, cp)}
             for v in kc.variants]
    # nothing a sample could flag (no division, no finiteness test, no branch): the batch
    # loop needs no count
    never_singular = len(cvars) == 1 and not divides and not cvars[0]["finite"]
    common = {"k": k, "meta": ctx.meta(kc), "inputs": kc.inputs, "divides": divides}
    trig = trig_plan(kc, cp)
    vec = k.name in VEC_F64
    vtext = None
    if vec:
        split = trig_split(kc) if trig else None
        if (split is None and len(kc.variants) != 1) or k.name in SOA_F64:
            raise ValueError(f"VEC_F64 lists {k.name!r}, which has several variants (a "
                             "branch per sample) or which SOA_F64 lists too")
        vtext = vector_text(split["program"] if split else kc.variants[0].program, k)
        if not vectorisable(vtext):
            raise ValueError(f"VEC_F64 lists {k.name!r}, whose sample calls a function "
                             "without a _v4 form or has a ternary or logical operator: "
                             f"{vtext}")
    files = {}
    for t, path in (("c_kernel.h.j2", f"c/{k.name}.h"), ("c_kernel.c.j2", f"c/{k.name}.c")):
        files[path] = env.get_template(t).render(header=ctx.header(kc, t), variants=cvars,
                                                 used=used, trig=trig,
                                                 never_singular=never_singular,
                                                 soa_f32=k.name in SOA_F32,
                                                 soa_f64=k.name in SOA_F64,
                                                 vec_f64=vec,
                                                 vec_v4=k.name in VEC_F64_V4,
                                                 vec_text=vtext,
                                                 f32=f32_code(kc), **common)
    return files


def render_module(env, metas: list[dict], ver: dict) -> dict[str, str]:
    """The extension module's own C: the module (``c_module.c.j2``), the per-path table of
    batch functions (``c_table.c.j2``), the CPU dispatcher (``c_dispatch.h.j2``) and the
    per-call entry points (``c_fast.h.j2``)."""
    def size(shape) -> int:
        return int(math.prod(shape))
    def c_check(a: dict) -> int:  # the kind table's C validation routine (0 for outputs)
        k = _kinds.for_spec(a["kind"], a["shape"]) if "kind" in a else None
        if k is None:
            return 0
        # a checked kind with no C routine of its own: checked calls take the Python path
        return k.c_check if k.c_check or k.check is None else _C_PYTHON_CHECK

    def slot(a: dict, body: bool = False) -> dict:
        return {"nd": len(a["shape"]), "dims": list(a["shape"]), "size": size(a["shape"]),
                "kind": _C_PYTHON_CHECK if body and a["name"] == "I_C" else c_check(a)}
    ck = [{"name": m["name"], "ins": [size(a["shape"]) for a in m["args"]],
           "outs": [size(o["shape"]) for o in m["outputs"]],
           "narrays": len(m["args"]) + len(m["outputs"]),
           "nin": len(m["args"]), "nout": len(m["outputs"]),
           "args": [slot(a, m["name"] in _PYTHON_CHECKED) for a in m["args"]],
           "outs_meta": [slot(o) for o in m["outputs"]]} for m in metas]
    files = {}
    for t, path in (("c_module.c.j2", "c/rigidsym_module.c"),
                    ("c_table.c.j2", "c/rigidsym_table.c"),
                    ("c_dispatch.h.j2", "c/rigidsym_dispatch.h"),
                    ("c_fast.h.j2", "c/rigidsym_fast.h")):
        files[path] = env.get_template(t).render(kernels=ck, template=t, **ver)
    return files


def render(ctx: RenderContext) -> dict[str, str]:
    """The extension target's files of a generation (``{relative path: text}``)."""
    env = shared_environment(TEMPLATES)
    files: dict[str, str] = {}
    for kc in ctx.kernels:
        files.update(kernel_files(ctx, TARGET, kc))
    for t, path in (("c_common.h.j2", "c/rigidsym_common.h"),
                    ("c_kernels_index.h.j2", "c/rigidsym_kernels.h")):
        files[path] = env.get_template(t).render(kernels=ctx.metas, template=t,
                                                 **ctx.versions)
    files.update(render_module(env, ctx.metas, ctx.versions))
    return files


TARGET = Target("extension", TEMPLATES, KernelCPrinter, render, render_kernel=render_kernel)
