"""The public surface, pinned (in the style of NumPy's ``numpy/tests/test_public_api.py``).

Each public module's ``__all__`` is listed here in full: adding or removing a public name
fails this test until the list is updated on purpose (issues add their new names here).
Everything else is private: an underscore, or not re-exported.
"""

from __future__ import annotations

import importlib
import inspect

import pytest

DECLARE = [
    "Blocks", "Cross", "Det", "I3", "MS", "O3", "Rel", "RigidMotion", "Statement", "TIME",
    "angle", "as_vector", "block", "cancel_matrix", "cpm", "equation",
    "euler_rodrigues_parameters", "eye3",
    "linear_invariants", "mat", "matrix", "rigid_motion", "rotation",
    "rotation_from_euler_rodrigues", "rotation_from_natural_invariants",
    "rotation_from_quaternion", "scalar", "symmetric_matrix", "trace", "unit_vector",
    "unit_vector4", "vec", "vect", "vector",
    # the vocabulary of rigid motions
    "twist", "wrench", "hat", "vee", "transform", "transform_inverse", "Ad", "ad", "ad_dual",
    "expm", "logm", "diff", "acos", "atan2", "ORDERS",
    "norm3",
]
KERNELS = [
    "H_matrix", "H_matrix_dot", "H_tilde", "H_tilde_dot", "L_matrix", "L_matrix_dot",
    "L_tilde", "L_tilde_dot", "N_matrix", "N_matrix_dot", "N_tilde", "N_tilde_dot",
    "inertia_at_point", "inertia_dyad_at_point", "instant_screw_axis", "kinetic_energy",
    "moving_frame_acceleration", "natural_invariants_from_rotation", "newton_euler_wrench",
    "plucker_from_points", "plucker_transfer", "point_acceleration",
    "rotation_from_euler_rodrigues", "rotation_from_natural_invariants", "screw_axis_point",
    "screw_of_displacement", "twist_transfer", "twist_transfer_matrix", "wrench_axis",
    "wrench_transfer", "wrench_transfer_matrix",
    # the Lie-group maps (their Jacobians through kernels.jacobian(name))
    "euler_rodrigues_from_rotation", "euler_rodrigues_product",
    "exponential_coordinates_from_transform", "exponential_coordinates_left_jacobian",
    "exponential_coordinates_left_jacobian_inverse", "rotation_from_rotation_vector",
    "rotation_vector_from_rotation", "rotation_vector_left_jacobian",
    "rotation_vector_left_jacobian_inverse", "rotation_vector_right_jacobian",
    "rotation_vector_right_jacobian_inverse", "transform_from_exponential_coordinates",
]
PUBLIC = {
    "rigidsym": ["BadInput", "Result", "Results", "audit", "check", "check_latex", "load_module",
                 "verify",
                 *DECLARE],
    "rigidsym.declare": DECLARE,
    "rigidsym.kernels": [
        "BroadcastWarning", "NonFiniteResultError", "SingularConfigurationError", "accuracy",
        "backend",
        "batch_function", "build_info",
        "euler_angle_rates", "euler_angles_from_rotation", "euler_rate_matrix",
        "get_num_threads", "jacobian", "load", "release_output_pool",
        "set_num_threads", "set_output_pool", "swap_blocks", "use_backend", *KERNELS],
    # Grouped marks a group the removable-singularity pass never distributes
    "rigidsym.codegen.spec": ["Arg", "Branch", "Grouped", "Kernel", "Out", "input_symbols"],
    "rigidsym.cli": ["build_parser", "main"],
    # the exercises to run, see and vary
    "rigidsym.exercises": ["EXERCISE_IDS", "Graded", "IllPosed", "Param", "Parameters",
                           "Solution", "exam", "figure", "grade", "parameters", "solve",
                           "write_notebook"],   # exam, grade, Graded
    # the reader of the chapter's LaTeX and the transcription check
    "rigidsym.latex": ["Glyph", "LatexError", "Parsed", "Relation", "glyph_table", "lookup",
                       "parse_latex"],
    "rigidsym.latex.transcription": ["STATUSES", "check_transcription", "notes",
                                     "transcription_for", "transcription_words"],
    # LaTeX in, verdict out (rigidsym.check_latex, rigidsym check --latex)
    "rigidsym.latex.lets": ["KIND_WORDS", "Let", "kind_of", "let_items", "model_names",
                            "model_spelling", "rated_lets", "read_lets",
                            "respell_model_names", "split_lets", "without_lets"],
}


#: the differentiable back-ends, importable where their extra is installed
ARRAY_BACKENDS = ["NonFiniteResultError", "SingularConfigurationError", "euler_angle_rates",
                  "euler_angles_from_rotation", "euler_rate_matrix", "load", *KERNELS]
EXTRA_PUBLIC = {"rigidsym.kernels.torch": ("torch", ARRAY_BACKENDS),
                "rigidsym.kernels.jax": ("jax", ARRAY_BACKENDS)}


@pytest.mark.extra
@pytest.mark.parametrize("name", sorted(EXTRA_PUBLIC))
def test_extra_public_names_are_pinned(name):
    lib, names = EXTRA_PUBLIC[name]
    pytest.importorskip(lib, reason=f"{lib} is not installed (the [{lib}] extra)")
    mod = importlib.import_module(name)
    assert sorted(mod.__all__) == sorted(names), (
        f"{name}.__all__ changed: added {sorted(set(mod.__all__) - set(names))}, "
        f"removed {sorted(set(names) - set(mod.__all__))}; update EXTRA_PUBLIC on purpose")
    for attr in names:
        obj = getattr(mod, attr)
        assert callable(obj), f"{name}.{attr}"
        if inspect.isfunction(obj):  # made by _arrays' factories: the back-end's own (autodoc)
            assert (obj.__module__, obj.__qualname__) == (name, attr), f"{name}.{attr}"
            assert "Args:" in obj.__doc__ and "Returns:" in obj.__doc__, f"{name}.{attr}"


@pytest.mark.parametrize("name", sorted(PUBLIC))
def test_public_names_are_pinned(name):
    mod = importlib.import_module(name)
    assert sorted(mod.__all__) == sorted(PUBLIC[name]), (
        f"{name}.__all__ changed: added {sorted(set(mod.__all__) - set(PUBLIC[name]))}, "
        f"removed {sorted(set(PUBLIC[name]) - set(mod.__all__))}; update PUBLIC on purpose")
    assert len(mod.__all__) == len(set(mod.__all__)), f"{name}.__all__ lists a name twice"


@pytest.mark.parametrize("name", sorted(PUBLIC))
def test_every_public_name_resolves(name):
    mod = importlib.import_module(name)
    for attr in PUBLIC[name]:
        assert getattr(mod, attr) is not None, f"{name}.{attr}"


def test_old_public_import_paths_keep_working():
    from rigidsym.cli import main
    from rigidsym.codegen.spec import Arg, Kernel
    from rigidsym.kernels import N_matrix, load

    assert callable(main) and callable(load) and callable(N_matrix)
    assert Kernel.__module__ == Arg.__module__ == "rigidsym.codegen.spec"


def test_repair_keywords_and_fields_are_public():
    """the repair search's keywords and the Result fields it fills."""
    import dataclasses
    import inspect

    import rigidsym

    for f in (rigidsym.check, rigidsym.verify):
        params = inspect.signature(f).parameters
        assert params["repairs"].default is True, f.__name__
        assert params["repair_budget"].default is None, f.__name__
        assert params["repairs"].kind is inspect.Parameter.KEYWORD_ONLY
    assert inspect.signature(rigidsym.equation).parameters["repair_budget"].default is None
    fields = {f.name for f in dataclasses.fields(rigidsym.Result)}
    assert {"repairs", "repair_search", "correction"} <= fields
