"""Cost of the checked kernel API: one sample (N = 1), call overhead at N = 1e3, batch cost
at N = 1e6, and float32 against float64.

Two measurements of the C backend, comparable across commits (it uses only
``kernels.use_backend``, ``kernels.batch_function``, the public kernels and ``kernels.json``):

* ``overhead``: one public call (validation, broadcasting, output allocation, the C batch,
  the singular/non-finite bookkeeping) at N = 1e3, in microseconds per call;
* ``batch``: the C batch function alone with caller-provided outputs at N = 1e6, in ns per
  sample (what the per-block finiteness test of the outputs costs).

Usage::

    python benchmarks/kernel_api.py --save new.json           # this checkout
    PYTHONPATH=/tmp/old/src python benchmarks/kernel_api.py --save old.json
    python benchmarks/kernel_api.py --ab /tmp/old/generated --ab-json ab.json   # C A/B
    python benchmarks/kernel_api.py --compare old.json new.json --ab-json ab.json   # RESULTS.md

``--fast`` (one run, side by side): N = 1 per call (checked, ``check=False``,
``check=False`` with a reused ``out=``) of K1, K2, K3, ``instant_screw_axis``, K5 and
``newton_euler_wrench`` from Python lists and floats, beside ``np.asarray`` of a 3-list,
``np.vecdot`` of two and, when Pinocchio is installed, ``pin.exp3`` and ``SE3.act``; N = 1e3
with caller outputs against the bare batch call; float32 against float64 at N = 1e6 (caller
outputs) with the float32 error in ulp; ``--ab OLD --threads 1,2``: the C batch at N = 1e6
against another build, geometric mean over the public kernels.

Timing: thread CPU time, median over rounds of repeated calls for >= 20 ms, rounds
interleaved over kernels so that a load change on the shared machine hits all of them;
``--save`` to an existing file keeps the minimum per entry, so runs alternating between
the two commits can be pooled.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

import numpy as np

OVERHEAD = ["rotation_from_natural_invariants", "twist_transfer", "screw_of_displacement",
            "kinetic_energy", "N_matrix", "plucker_from_points"]
MARK = ("<!-- kernel-api -->", "<!-- /kernel-api -->")


def _inputs(meta: dict, n: int, rng) -> list[np.ndarray]:
    from rigidsym.core.draws import draw

    out = []
    for a in meta["args"]:
        shape = (n,) + tuple(a["shape"])
        v = draw(a["kind"], shape, rng, phi=(0.2, 3.0), angle=(0.2, np.pi - 0.05),
                 free=lambda s: rng.uniform(0.5, 2.0, s))
        out.append(np.ascontiguousarray(v))
    return out


def _time(f, budget: float = 0.02) -> float:
    """Seconds per call of ``f``: repeated for >= ``budget`` of thread CPU time."""
    reps, t = 1, 0.0
    while True:
        t0 = time.thread_time()
        for _ in range(reps):
            f()
        t = time.thread_time() - t0
        if t >= budget:
            return t / reps
        reps *= 2


def measure(rounds: int, batch: bool = True) -> dict:
    from rigidsym import kernels as K
    from rigidsym.kernels.runtime import state as _state

    assert K.use_backend("c") == "c", "C backend unavailable"
    meta = {k: m for k, m in _state.meta().items() if m["public"]}
    rng = np.random.default_rng(7)
    calls, batches = {}, {}

    def bind(f, args):
        return lambda: f(*args)
    for name in OVERHEAD:
        calls[name] = bind(getattr(K, name), _inputs(meta[name], 1000, rng))
    for name, m in sorted(meta.items()) if batch else ():
        n = 1_000_000
        outs = [np.empty((n,) + tuple(o["shape"])) for o in m["outputs"]]
        batches[name] = bind(K.batch_function(name, "c"), _inputs(m, n, rng) + outs)
    res = {"overhead_us": {k: [] for k in calls}, "batch_ns": {k: [] for k in batches}}
    for _ in range(rounds):
        for k, f in calls.items():
            res["overhead_us"][k].append(_time(f) * 1e6)
        for k, f in batches.items():
            res["batch_ns"][k].append(_time(f, 0.05) * 1e9 / 1_000_000)
    return {sec: {k: statistics.median(v) for k, v in d.items()} for sec, d in res.items()}


def measure_ab(old_dir: Path, rounds: int, threads: int = 1) -> dict:
    """C batch at N = 1e6, old and new generated C loaded in this one process (both built
    by this checkout's driver, rigidsym.kernels.cbuild.driver, same flags; the old folder needs the
    extension's own C, c/rigidsym_module.c, of this version's generator) and timed
    alternately: fair on a loaded machine."""
    from rigidsym.kernels.cbuild import extension as _ext
    from rigidsym.kernels.runtime import state as _state

    mods = {"old": _ext.load(old_dir).module, "new": _state.builtin().c_lib().module}
    meta = {k: m for k, m in _state.meta().items() if m["public"]}
    rng = np.random.default_rng(7)
    n = 1_000_000
    res: dict = {"old": {}, "new": {}}
    for name, m in sorted(meta.items()):
        arrays = _inputs(m, n, rng) + [np.empty((n,) + tuple(o["shape"]))
                                       for o in m["outputs"]]
        calls = {}
        for tag, mod in mods.items():
            k = mod.kernels.index(name)
            calls[tag] = (lambda b=mod.batch, k=k, a=arrays: b(k, False, n, threads, *a))
        times: dict = {"old": [], "new": []}
        for _ in range(rounds):
            for tag in ("old", "new"):
                times[tag].append(_time(calls[tag], 0.05) * 1e9 / n)
        for tag in times:
            res[tag][name] = min(times[tag])
    return res


#: the kernels with N = 1 bounds (K1, K2, K3, instant_screw_axis, K5, wrench)
FAST = ["rotation_from_euler_rodrigues", "rotation_from_natural_invariants", "screw_axis_point",
        "instant_screw_axis", "N_matrix", "newton_euler_wrench"]
#: memory-bound (float32 target 1.6x) and trigonometric (1.3x) kernels
F32_TARGET = {"rotation_from_euler_rodrigues": 1.6, "instant_screw_axis": 1.6,
              "newton_euler_wrench": 1.6, "rotation_from_natural_invariants": 1.3,
              "screw_axis_point": 1.3, "N_matrix": 1.3}
FAST_MARK = ("<!-- kernel-fast -->", "<!-- /kernel-fast -->")


def _sample_lists(meta: dict) -> list:
    """One sample of each argument as Python floats and lists (the N = 1 case)."""
    rng = np.random.default_rng(5)
    return [a.reshape(a.shape[1:]).tolist() if a.ndim > 1 else float(a[0])
            for a in _inputs(meta, 1, rng)]


def _median_us(f, rounds: int, budget: float = 0.05) -> float:
    return statistics.median(_time(f, budget) * 1e6 for _ in range(rounds))


def _caller(f, args: list, **kw):
    """``lambda: f(a0, a1, ..., k=v, ...)``: the inputs spelled out, as a user writes the call
    (``f(*args, check=False)`` would time CPython's dict-building call path instead)."""
    names = [f"a{i}" for i in range(len(args))]
    params = ", ".join(["f", *names, *kw])
    call = ", ".join([*names, *(f"{k}={k}" for k in kw)])
    ns: dict = {}
    exec(f"def make({params}):\n    return lambda: f({call})", ns)   # noqa: S102 - fixed text
    return ns["make"](f, *args, *kw.values())


def _n1_calls(calls: dict, tag: str, space, meta: dict) -> None:
    """The N = 1 calls of :data:`FAST` from the kernel namespace ``space`` under ``tag``."""
    for name in FAST:
        f, args = getattr(space, name), _sample_lists(meta[name])
        out = f(*args)
        out = tuple(o.copy() for o in out) if isinstance(out, tuple) else out.copy()
        calls[(tag, name, "checked")] = _caller(f, args)
        calls[(tag, name, "unchecked")] = _caller(f, args, check=False)
        calls[(tag, name, "out")] = _caller(f, args, check=False, out=out)


def measure_fast(rounds: int, old_dir: Path | None = None, n1_old: Path | None = None) -> dict:
    """N = 1, N = 1e3 and float32 of :data:`FAST`, one process, interleaved rounds.
    ``n1_old``: another generated directory (a previous commit's), whose kernels
    (``kernels.load``, its own compiled module) are timed at N = 1 in the same rounds."""
    from rigidsym import kernels as K
    from rigidsym.kernels.runtime import state as _state

    assert K.use_backend("c") == "c", "C backend unavailable"
    meta = _state.meta()
    rng = np.random.default_rng(7)
    calls: dict = {}
    _n1_calls(calls, "n1", K, meta)
    if n1_old is not None:
        _n1_calls(calls, "n1old", K.load(n1_old), meta)
    for name in FAST:
        f = getattr(K, name)
        ins = _inputs(meta[name], 1000, rng)
        outs = [np.empty((1000,) + tuple(o["shape"])) for o in meta[name]["outputs"]]
        o = outs[0] if len(outs) == 1 else tuple(outs)
        bare = K.batch_function(name, "c")
        calls[("n1e3", name, "bare")] = lambda b=bare, a=ins + outs: b(*a)
        calls[("n1e3", name, "unchecked")] = lambda f=f, a=ins, o=o: f(*a, check=False, out=o)
        calls[("n1e3", name, "checked")] = lambda f=f, a=ins, o=o: f(*a, out=o)
    _reference_calls(calls)
    data = _run_rounds(calls, rounds)
    data.update(measure_f32(rounds, old_dir=old_dir))
    return data


def _reference_calls(calls: dict) -> None:
    lst = [0.1, 0.2, 0.3]
    calls[("ref", "np.asarray(3-list)", "")] = lambda: np.asarray(lst)
    calls[("ref", "np.vecdot(3-list, 3-list)", "")] = lambda: np.vecdot(lst, lst)
    try:
        import pinocchio as pin

        w, M, v = np.array(lst), pin.SE3.Random(), pin.Motion.Random()
        calls[("ref", f"pin.exp3 (Pinocchio {pin.__version__})", "")] = lambda: pin.exp3(w)
        calls[("ref", "pin.SE3.act(Motion)", "")] = lambda: M.act(v)
    except ImportError:
        pass


def _run_rounds(calls: dict, rounds: int) -> dict:
    """Median us per call of each of ``calls``, rounds interleaved over all of them."""
    res: dict = {k: [] for k in calls}
    for _ in range(rounds):
        for k, f in calls.items():
            res[k].append(_time(f, 0.02) * 1e6)
    return {"|".join(k): statistics.median(v) for k, v in res.items()}


def measure_f32(rounds: int, n: int = 1_000_000, old_dir: Path | None = None) -> dict:
    """float64 and float32 batch at N = 1e6 (caller outputs, one thread), and the float32
    error in ulp against the float64 kernel at the same float32 inputs (whose own error is
    ~1e-15, tests/test_kernels.py)."""
    from rigidsym import kernels as K
    from rigidsym.kernels.runtime import state as _state

    meta = _state.meta()
    rng = np.random.default_rng(9)
    out: dict = {}
    for name in F32_TARGET:
        m = meta[name]
        ins = [a.astype(np.float32) for a in _inputs(m, n, rng)]
        ins64 = [a.astype(np.float64) for a in ins]
        o32 = [np.empty((n,) + tuple(o["shape"]), np.float32) for o in m["outputs"]]
        o64 = [np.empty((n,) + tuple(o["shape"])) for o in m["outputs"]]
        b32 = K.batch_function(name, "c", threads=1, dtype=np.float32)
        b64 = K.batch_function(name, "c", threads=1)
        old = None
        if old_dir is not None:    # the other build's float32 (float64 arithmetic inside)
            from rigidsym.kernels.cbuild import extension as _ext

            mod = _ext.load(old_dir).module
            k = mod.kernels.index(name)
            arrays = ins + [np.empty_like(o) for o in o32]
            old = (lambda b=mod.batch, k=k, a=arrays: b(k, True, n, 1, *a))
        t32, t64, told = [], [], []
        for _ in range(rounds):
            t64.append(_time(lambda b=b64, a=ins64 + o64: b(*a), 0.1) * 1e9 / n)
            t32.append(_time(lambda b=b32, a=ins + o32: b(*a), 0.1) * 1e9 / n)
            if old is not None:
                told.append(_time(old, 0.1) * 1e9 / n)
        if told:
            out[f"f32|{name}|old_f32_ns"] = min(told)
        got = np.concatenate([o.reshape(n, -1) for o in o32], axis=1).astype(np.float64)
        ref = np.concatenate([o.reshape(n, -1) for o in o64], axis=1)
        scale = np.abs(ref).max(axis=1)
        err = np.abs(got - ref).max(axis=1) / np.where(scale == 0, 1, scale)
        out[f"f32|{name}|f64_ns"] = min(t64)
        out[f"f32|{name}|f32_ns"] = min(t32)
        out[f"f32|{name}|ulp"] = float(np.nanmax(err) / np.finfo(np.float32).eps)
    return out


N1_HEAD = "### N = 1 (us per call, median"


def n1_lines(d: dict, old_label: str = "") -> list[str]:
    """The N = 1 table of :func:`fast_section` (with the previous commit's columns when
    ``d`` has its ``n1old`` rows) and the reference rows of the same run."""
    has_old = any(k.startswith("n1old|") for k in d)
    lines = [f"{N1_HEAD}; Python lists and floats in, spelled out as in `f(e, phi, "
             "check=False)`; C backend)", ""]
    cols = [("checked", "checked"), ("unchecked", "check=False"),
            ("out", "check=False, reused out=")]
    if has_old:
        lines += [f"`old`: {old_label}, loaded with `kernels.load` (its own compiled module) "
                  "and timed in the same interleaved rounds as `new`.", "",
                  "| kernel | " + " | ".join(f"{h}: old | new" for _, h in cols) + " |",
                  "|---|" + "---:|" * 6]
    else:
        lines += ["| kernel | " + " | ".join(h for _, h in cols) + " |", "|---|---:|---:|---:|"]
    for name in FAST:
        row = []
        for w, _ in cols:
            if has_old:
                row.append(f"{d[f'n1old|{name}|{w}']:.2f}")
            row.append(f"{d[f'n1|{name}|{w}']:.2f}")
        lines.append(f"| `{name}` | " + " | ".join(row) + " |")
    lines += ["", "| reference, same run | us per call |", "|---|---:|"]
    lines += [f"| `{k.split('|')[1]}` | {v:.2f} |" for k, v in d.items()
              if k.startswith("ref|")]
    if not any("pin." in k for k in d):
        lines.append("| Pinocchio | not installed |")
    return lines


def measure_n1(rounds: int, n1_old: Path | None) -> dict:
    """The N = 1 rows of :func:`measure_fast` alone (and the reference rows)."""
    from rigidsym import kernels as K
    from rigidsym.kernels.runtime import state as _state

    assert K.use_backend("c") == "c", "C backend unavailable"
    calls: dict = {}
    _n1_calls(calls, "n1", K, _state.meta())
    if n1_old is not None:
        _n1_calls(calls, "n1old", K.load(n1_old), _state.meta())
    _reference_calls(calls)
    return _run_rounds(calls, rounds)


def fast_section(d: dict, note: str, ab: dict | None) -> str:
    """The RESULTS.md section of the N = 1 bounds from :func:`measure_fast` (and ``--ab``)."""
    lines = [FAST_MARK[0], "## Kernels cheap at every size", "", note, "",
             *n1_lines(d), "",
             "### N = 1e3 (us per call, caller-provided out=, contiguous inputs)", "",
             "| kernel | bare batch call | check=False | - bare | checked | / bare |",
             "|---|---:|---:|---:|---:|---:|"]
    for name in FAST:
        b, u, c = (d[f"n1e3|{name}|{w}"] for w in ("bare", "unchecked", "checked"))
        lines.append(f"| `{name}` | {b:.2f} | {u:.2f} | {u - b:+.2f} | {c:.2f} | "
                     f"{c / b:.2f} |")
    lines += ["", "### float32 at N = 1e6 (ns/sample, caller outputs, one thread)", "",
              "| kernel | float64 | float32 | float64 / float32 | target | float32 before "
              "(float64 arithmetic) | error (ulp of float32) |",
              "|---|---:|---:|---:|---:|---:|---:|"]
    for name, target in F32_TARGET.items():
        a, b, e = (d[f"f32|{name}|{w}"] for w in ("f64_ns", "f32_ns", "ulp"))
        o = d.get(f"f32|{name}|old_f32_ns")
        lines.append(f"| `{name}` | {a:.2f} | {b:.2f} | {a / b:.2f} | {target} | "
                     f"{'' if o is None else f'{o:.2f}'} | {e:.2f} |")
    if ab:
        lines += ["", "### C batch at N = 1e6, A/B in one process (ns/sample; geometric mean "
                  "over the public kernels)", "", "| threads | old | new | new / old |",
                  "|---:|---:|---:|---:|"]
        for t, r in sorted(ab.items()):
            ratios = [r["new"][k] / r["old"][k] for k in r["new"]]
            g = float(np.exp(np.mean(np.log(ratios))))
            go = float(np.exp(np.mean(np.log(list(r["old"].values())))))
            gn = float(np.exp(np.mean(np.log(list(r["new"].values())))))
            lines.append(f"| {t} | {go:.2f} | {gn:.2f} | {g:.3f} |")
    return "\n".join(lines + [FAST_MARK[1]]) + "\n"


def section(old: dict, new: dict, old_label: str, note: str, ab: dict | None = None) -> str:
    lines = [MARK[0], "## Kernel API cost", "",
             f"C backend, one thread; {note}. `old` is commit {old_label} "
             "(wrappers taking `*args`, finiteness tested only after divisions and roots); "
             "`new` has true signatures, argument-naming validation, the per-block finiteness "
             "test of the outputs and the overflow classification. Regenerate: "
             "`python benchmarks/kernel_api.py --overhead-only --save new.json` here and "
             "(with PYTHONPATH at its src/) in a checkout of the old commit, alternately; "
             "`--ab OLD/generated --ab-json ab.json`; then "
             "`--compare old.json new.json --ab-json ab.json`.", "",
             "### Call overhead, N = 1e3 (us per public call, allocated outputs)", "",
             "| kernel | old | new | new / old |", "|---|---:|---:|---:|"]
    ratios = []
    for k in old["overhead_us"]:
        o, n = old["overhead_us"][k], new["overhead_us"][k]
        ratios.append(n / o)
        lines.append(f"| `{k}` | {o:.1f} | {n:.1f} | {n / o:.3f} |")
    batch_old, batch_new = (ab["old"], ab["new"]) if ab else (old["batch_ns"], new["batch_ns"])
    how = ("both C builds loaded in one process and timed alternately, minimum over rounds"
           if ab else "separate processes")
    lines += [f"| geometric mean | | | {np.exp(np.mean(np.log(ratios))):.3f} |", "",
              f"### C batch alone, N = 1e6 (ns/sample, caller-provided outputs; {how})", "",
              "| kernel | old | new | new / old |", "|---|---:|---:|---:|"]
    ratios = []
    for k in batch_old:
        if k not in batch_new:
            continue
        o, n = batch_old[k], batch_new[k]
        ratios.append(n / o)
        lines.append(f"| `{k}` | {o:.2f} | {n:.2f} | {n / o:.3f} |")
    lines += [f"| geometric mean | | | {np.exp(np.mean(np.log(ratios))):.3f} |", MARK[1]]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--save", help="measure this checkout and write JSON here")
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--overhead-only", action="store_true", help="skip the N = 1e6 batches")
    p.add_argument("--compare", nargs=2, metavar=("OLD", "NEW"))
    p.add_argument("--ab", metavar="OLD_GENERATED_DIR",
                   help="time the old commit's generated C against this one in-process")
    p.add_argument("--ab-json", default="ab.json", help="where --ab writes / --compare reads")
    p.add_argument("--old-label", default="f6c9ea0")
    p.add_argument("--note", default="measured on the shared 2-core machine under load")
    p.add_argument("--results", default=str(Path(__file__).with_name("RESULTS.md")))
    p.add_argument("--fast", action="store_true",
                   help="N = 1, N = 1e3, float32 (and --ab with --threads) into "
                        "RESULTS.md")
    p.add_argument("--threads", default="1", help="--ab thread counts, e.g. 1,2")
    p.add_argument("--n1-old", metavar="OLD_GENERATED_DIR",
                   help="with --fast or --n1-only: time another commit's kernels at N = 1 in "
                        "the same rounds (kernels.load of its generated folder)")
    p.add_argument("--n1-label", default="the previous commit", help="what --n1-old is")
    p.add_argument("--n1-only", action="store_true",
                   help="only the N = 1 table (and its reference rows), replaced in "
                        "the section 'Kernels cheap at every size' of RESULTS.md")
    args = p.parse_args(argv)
    n1_old = Path(args.n1_old) if args.n1_old else None
    if args.n1_only:
        data = measure_n1(args.rounds, n1_old)
        if args.save:
            Path(args.save).write_text(json.dumps({"n1": data}, indent=1))
        _replace_n1(Path(args.results), n1_lines(data, args.n1_label), args.note)
        return 0
    if args.fast:
        data = measure_fast(args.rounds, Path(args.ab) if args.ab else None, n1_old)
        ab = None
        if args.ab:
            ab = {int(t): measure_ab(Path(args.ab), args.rounds, int(t))
                  for t in args.threads.split(",")}
        if args.save:
            Path(args.save).write_text(json.dumps({"fast": data, "ab": ab}, indent=1))
        _write_section(Path(args.results), fast_section(data, args.note, ab), FAST_MARK)
        return 0
    if args.save:
        data = measure(args.rounds, batch=not args.overhead_only)
        path = Path(args.save)
        if path.exists():       # repeated runs (alternating commits): keep the minimum
            prev = json.loads(path.read_text())
            data = {sec: {k: min(v, d.get(k, v)) for k, v in prev.get(sec, {}).items()}
                    | {k: min(v, prev.get(sec, {}).get(k, v)) for k, v in d.items()}
                    for sec, d in (prev | data).items()}
        path.write_text(json.dumps(data, indent=1))
        json.dump(data, sys.stdout, indent=1)
        print()
    if args.ab:
        data = measure_ab(Path(args.ab), args.rounds)
        Path(args.ab_json).write_text(json.dumps(data, indent=1))
    if args.compare:
        old, new = (json.loads(Path(f).read_text()) for f in args.compare)
        abp = Path(args.ab_json)
        ab = json.loads(abp.read_text()) if abp.exists() else None
        _write_section(Path(args.results), section(old, new, args.old_label, args.note, ab),
                       MARK)
    return 0


def _replace_n1(path: Path, lines: list[str], note: str) -> None:
    """Replace the N = 1 table of the section 'Kernels cheap at every size' of ``path`` (up
    to the next table heading) by ``lines``, headed by ``note``; print it."""
    from rigidsym.core.files import write_atomic

    body = path.read_text(encoding="utf-8")
    a = body.index(N1_HEAD, body.index(FAST_MARK[0]))
    b = body.index("\n### ", a) + 1
    text = "\n".join(lines[:2] + [note, ""] + lines[2:]) + "\n\n"
    write_atomic(path, body[:a] + text + body[b:])
    print(text)


def _write_section(path: Path, text: str, mark: tuple) -> None:
    """Replace the section between ``mark`` in ``path`` (or append it); print it."""
    from _results import write_section

    write_section(path, text.rstrip("\n"), *mark)
    print(text)

if __name__ == "__main__":
    raise SystemExit(main())
