"""Misuse → one line naming the cause (issue 35, "Errors"): wrong annotations, math / numpy
functions on traced variables, a missing ``noise=``, out-of-range spec parameters, floating-point
warnings of fgc's kernels, and the wording of statuses and fit verdicts in summaries."""

from __future__ import annotations

import math
import warnings
from math import atan2 as imported_atan2

import numpy as np
import pytest

import fgc
from fgc import Point2, Point3, Pose2
from fgc.app.run_report import fit_verdict, status_text
from fgc.app.specs import load_spec
from fgc.errors import DataError, DslError, FgcError
from fgc.frontend import noise

ONE = noise.isotropic(1, 0.1)


def _one_line(exc: pytest.ExceptionInfo) -> str:
    text = str(exc.value)
    assert "\n" not in text
    return text


def test_a_point2_annotated_point3_names_both_arguments_and_types():
    @fgc.factor
    def range_to_beacon(pose: Pose2, beacon: Point3, *, measured: float):
        return [pose.range(beacon) - measured]

    with pytest.raises(DslError) as exc:
        range_to_beacon("x0", "b0", measured=1.0, noise=ONE)
    text = _one_line(exc)
    assert "factor 'range_to_beacon'" in text and "ShapeError" not in text
    assert "'beacon' (Point3)" in text and "'pose' (Pose2)" in text
    assert "annotated Point3" in text


def test_a_size_mismatch_with_a_measurement_names_the_annotations():
    @fgc.factor
    def point_prior(p: Point3, *, measured: Point2):
        return p - measured

    with pytest.raises(FgcError) as exc:
        point_prior("l0", measured=Point2(1.0, 2.0), noise=noise.isotropic(3, 0.1))
    text = _one_line(exc)
    assert "factor 'point_prior' (p: Point3; measured: Point2)" in text


# every callable of the math module: the message names it and what to write instead
MATH = sorted(n for n in dir(math) if not n.startswith("_") and callable(getattr(math, n)))
REPLACED = {"atan2": "fgc.atan2(y, x)", "sqrt": "fgc.sqrt(x)", "hypot": "fgc.hypot(x, y)",
            "fabs": "abs(x)", "pow": "x**k", "cosh": "fgc.exp(x) + fgc.exp(-x)",
            "floor": "a smooth residual", "isnan": "no test on a variable"}


@pytest.mark.parametrize("name", MATH)
def test_every_math_function_on_a_variable_names_itself_and_the_fgc_replacement(name):
    g = getattr(math, name)

    @fgc.factor
    def uses_math(pose: Pose2, *, measured: float):
        return [g(pose.x()) - measured]

    with pytest.raises(DslError) as exc:
        uses_math("x0", measured=1.0, noise=ONE)
    text = _one_line(exc)
    assert f"factor 'uses_math': math.{name}() works on numbers only" in text
    assert REPLACED.get(name, "fgc.") in text or name not in REPLACED


def test_a_math_function_imported_by_name_is_named_too():
    @fgc.factor
    def bearing(pose: Pose2, *, measured: float):
        return [imported_atan2(pose.y(), pose.x()) - measured]

    with pytest.raises(DslError, match=r"math\.atan2\(\).*fgc\.atan2\(y, x\)"):
        bearing("x0", measured=1.0, noise=ONE)


@pytest.mark.parametrize("call, shown, instead", [
    (lambda p: np.arctan2(p.y(), p.x()), "np.arctan2()", "fgc.atan2(y, x)"),
    (lambda p: np.sqrt(p.x()), "np.sqrt()", "fgc.sqrt(x)"),
    (lambda p: np.hypot(p.x(), p.y()), "np.hypot()", "fgc.hypot(x, y)"),
    (lambda p: np.linalg.norm([p.x(), p.y()]), "np.linalg.norm()", "fgc.sqrt(x * x"),
    (lambda p: np.maximum(p.x(), p.y()), "np.maximum()", "a smooth residual"),
    (lambda p: np.deg2rad(p.x()), "np.deg2rad()", "x * (math.pi / 180)"),
    (lambda p: np.arcsinh(p.x()), "np.arcsinh()", "fgc.log(x + fgc.sqrt(x * x + 1))"),
])
def test_numpy_functions_on_a_variable_name_the_fgc_replacement(call, shown, instead):
    @fgc.factor
    def uses_numpy(pose: Pose2, *, measured: float):
        return [call(pose) - measured]

    with pytest.raises(DslError) as exc:
        uses_numpy("x0", measured=1.0, noise=ONE)
    text = _one_line(exc)
    assert f"factor 'uses_numpy': {shown}" in text and instead in text


def test_an_if_on_a_variable_still_says_condition():
    @fgc.factor
    def branchy(pose: Pose2, *, measured: float):
        return [pose.x() - measured] if pose.x() > 0 else [measured]

    with pytest.raises(DslError, match="condition"):
        branchy("x0", measured=1.0, noise=ONE)


def test_a_missing_noise_says_so():
    @fgc.factor
    def offset(pose: Pose2, *, measured: float):
        return [pose.x() - measured]

    with pytest.raises(DslError) as exc:
        offset("x0", measured=1.0)
    text = _one_line(exc)
    assert "factor 'offset' on ['x0']: no noise model; pass noise=" in text


def test_a_type_error_inside_build_is_not_blamed_on_the_parameters(tmp_path):
    spec = tmp_path / "broken.py"
    spec.write_text("import fgc\n\ndef build():\n    return len(3)\n")
    with pytest.raises(FgcError) as exc:
        load_spec(str(spec), {})
    text = _one_line(exc)
    assert "build() failed at line 4: TypeError" in text and "rejected" not in text
    with pytest.raises(FgcError, match=r"build\(\) has no parameter 'N'"):
        load_spec(str(spec), {"N": 3})


@pytest.mark.parametrize("spec, params, says", [
    ("examples/lio.py", {"N": -5}, "lio: N=-5: N must be at least 2 keyframes"),
    ("examples/lio.py", {"N": 5, "first": -1}, "lio: first=-1: first must be a GPS fix index"),
    ("examples/range_beacons.py", {"steps": -5}, "steps=-5: steps must be at least 1"),
])
def test_out_of_range_spec_parameters_name_the_parameter_and_bound(spec, params, says):
    with pytest.raises(DataError) as exc:
        load_spec(spec, params)
    assert says in _one_line(exc) and "exceed" not in str(exc.value)


def test_fgc_kernels_raise_no_numpy_warning_at_zero_distance():
    """A range's Jacobian at zero distance is GTSAM's convention (finite: the all-ones row of
    norm2, issue 34 item 5); a residual that is 0/0 there (a direction cosine) returns
    non-finite numbers (callers report them naming the factor), not an unworded
    RuntimeWarning."""
    from fgc.compiler.derive import derive

    @fgc.factor
    def range_to_beacon(pose: Pose2, beacon: Point2, *, measured: float):
        return [pose.range(beacon) - measured]

    @fgc.factor
    def cosine_to_beacon(pose: Pose2, beacon: Point2, *, measured: float):
        return [(beacon.v[0] - pose.x()) / pose.range(beacon) - measured]

    at = [Pose2(1.0, 2.0, 0.0), Point2(1.0, 2.0)]
    f = range_to_beacon("x0", "b0", measured=1.0, noise=ONE)
    g = cosine_to_beacon("x0", "b0", measured=1.0, noise=ONE)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r, jacobians = derive(f.type).evaluate(at, f.measured)
        r_cos, _ = derive(g.type).evaluate(at, g.measured)
    assert np.all(np.isfinite(r)) and [j.tolist() for j in jacobians] == [[[-1.0, -1.0, 0.0]],
                                                                          [[1.0, 1.0]]]
    assert not np.all(np.isfinite(r_cos))


def test_status_is_not_repeated_as_its_reason():
    assert status_text("max_iterations", "max_iterations") == "max_iterations"
    assert status_text("converged", "relative_decrease") == "converged (relative_decrease)"
    assert status_text("failed", "non_finite") == "failed (non_finite)"


def test_a_design_that_does_not_fit_says_which_resources_are_over():
    cost = {"fits": False, "device": "xc7z045",
            "utilization": {"dsp": 0.5, "bram": 14.3, "lut": 0.4, "ff": 1.2}}
    assert fit_verdict(cost) == ("does NOT fit xc7z045: BRAM36 14.3× the device's, "
                                 "FF 1.2× the device's")
    assert fit_verdict({**cost, "fits": True}) == "fits xc7z045"
