"""The DSL boundary: every malformed factor, graph or measurement raises an ``FgcError`` subclass
whose message names the user's factor, variable or argument."""

import contextlib
import math

import numpy as np
import pytest

import fgc
from fgc import DataError, DslError, FgcError, Point3, Pose2, Pose3
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor


@fgc.factor
def landmark_offset(point: Point3, *, offset_x: float):
    return [point.x() - offset_x, point.y()]


@fgc.factor
def point_pair(first: Point3, second: Point3):
    return (first - second).v


@fgc.factor
def pose_near(pose: Pose3, *, target: Pose3):
    return target.local(pose)


def _graph() -> fgc.Graph:
    return (fgc.Graph()
            .add_variable("l1", Point3(1.0, 2.0, 3.0))
            .add_variable("l2", Point3(0.0, 1.0, 0.0))
            .add_variable("x1", Pose3()))


@contextlib.contextmanager
def _raises(error: type[FgcError], *names: str):
    """pytest.raises for ``error`` whose message contains every one of ``names``."""
    assert issubclass(error, FgcError)
    with pytest.raises(error) as info:
        yield info
    message = str(info.value)
    for name in names:
        assert name in message, f"{name!r} not named in: {message}"


def test_residual_dimension_differs_from_noise_model():
    with _raises(DslError, "landmark_offset", "3", "2"):
        landmark_offset("l1", offset_x=1.0, noise=noise.isotropic(3, 0.1))


def test_noise_model_of_wrong_size_for_builtin():
    with _raises(DslError, "BetweenFactorPose3", "6"):
        BetweenFactor("x1", "x2", Pose3(), noise.diagonal([0.1, 0.1, 0.1]))


def test_unknown_variable_key():
    graph = _graph()
    with _raises(DslError, "landmark_offset", "'l9'", "point"):
        graph.add(landmark_offset("l9", offset_x=1.0, noise=noise.isotropic(2, 0.1)))


def test_variable_of_wrong_type():
    graph = _graph()
    with _raises(DslError, "landmark_offset", "'x1'", "Pose3", "point", "Point3"):
        graph.add(landmark_offset("x1", offset_x=1.0, noise=noise.isotropic(2, 0.1)))


def test_wrong_number_of_keys():
    with _raises(DslError, "point_pair", "first", "second"):
        point_pair("l1", noise=noise.isotropic(3, 0.1))


@pytest.mark.parametrize("bad", [math.nan, math.inf, -np.inf])
def test_non_finite_scalar_measurement(bad):
    with _raises(DataError, "landmark_offset", "offset_x"):
        landmark_offset("l1", offset_x=bad, noise=noise.isotropic(2, 0.1))


def test_non_finite_geometry_measurement():
    target = Pose3(fgc.Rot3.identity(), [0.0, np.nan, 0.0])
    with _raises(DataError, "pose_near", "target"):
        pose_near("x1", target=target, noise=noise.isotropic(6, 0.1))


def test_non_finite_initial_value():
    with _raises(DataError, "'l3'"):
        _graph().add_variable("l3", Point3(np.inf, 0.0, 0.0))


def test_non_finite_noise_sigma():
    with _raises(DataError, "sigma"):
        noise.diagonal([0.1, np.nan, 0.1])


def test_measurement_of_wrong_type():
    with _raises(DataError, "pose_near", "target", "Pose3", "Pose2"):
        pose_near("x1", target=Pose2(0.0, 0.0, 0.0), noise=noise.isotropic(6, 0.1))


def test_python_if_on_a_symbolic_value():
    @fgc.factor
    def one_sided(point: Point3, *, limit: float):
        if point.x() > limit:
            return [point.x() - limit]
        return [limit - point.x()]

    with _raises(DslError, "one_sided", "condition"):
        one_sided("l1", limit=0.0, noise=noise.isotropic(1, 0.1))


def test_plain_truth_test_on_a_symbolic_value():
    """``if x:`` would silently take one branch (sympy makes every expression truthy)."""

    @fgc.factor
    def nonzero_only(point: Point3, *, measured: float):
        if point.x():
            return [point.x() - measured]
        return [measured]

    with _raises(DslError, "nonzero_only", "condition"):
        nonzero_only("l1", measured=1.0, noise=noise.isotropic(1, 0.1))


def test_math_sqrt_on_a_symbol():
    @fgc.factor
    def radius(point: Point3, *, measured: float):
        return [math.sqrt(point.x() ** 2 + point.y() ** 2) - measured]

    with _raises(DslError, "radius", "math"):
        radius("l1", measured=1.0, noise=noise.isotropic(1, 0.1))


def test_other_failure_inside_the_residual_function():
    @fgc.factor
    def typo(point: Point3, *, measured: float):
        return [point.norm2() - measured]

    with _raises(DslError, "typo", "norm2"):
        typo("l1", measured=1.0, noise=noise.isotropic(1, 0.1))


def test_geometry_error_inside_the_residual_function_names_the_factor():
    @fgc.factor
    def short_vector(point: Point3):
        return (point - [1.0, 2.0]).v

    with _raises(DataError, "short_vector", "length 3"):
        short_vector("l1", noise=noise.isotropic(3, 0.1))


def test_residual_that_is_a_group_element():
    @fgc.factor
    def returns_pose(pose: Pose3):
        return pose

    with _raises(DslError, "returns_pose", "Pose3"):
        returns_pose("x1", noise=noise.isotropic(6, 0.1))


def test_duplicate_variable_key():
    with _raises(DslError, "'l1'"):
        _graph().add_variable("l1", Point3(0.0, 0.0, 0.0))


def test_duplicate_key_within_one_factor():
    graph = _graph()
    with _raises(DslError, "point_pair", "'l1'"):
        graph.add(point_pair("l1", "l1", noise=noise.isotropic(3, 0.1)))


def test_missing_measurement():
    with _raises(DslError, "landmark_offset", "offset_x"):
        landmark_offset("l1", noise=noise.isotropic(2, 0.1))


def test_unknown_measurement():
    with _raises(DslError, "landmark_offset", "offset_y", "offset_x"):
        landmark_offset("l1", offset_x=1.0, offset_y=2.0, noise=noise.isotropic(2, 0.1))


def test_missing_annotation_on_a_measurement():
    def untyped(point: Point3, *, measured):
        return [point.x() - measured]

    with _raises(DslError, "untyped", "measured", "annotation"):
        fgc.factor(untyped)


def test_missing_annotation_on_a_variable():
    def untyped_variable(point, *, measured: float):
        return [point.x() - measured]

    with _raises(DslError, "untyped_variable", "point", "annotation"):
        fgc.factor(untyped_variable)


def test_variable_annotated_with_a_non_geometry_type():
    def float_variable(value: float):
        return [value]

    with _raises(DslError, "float_variable", "value", "geometry"):
        fgc.factor(float_variable)


def test_noise_that_is_not_a_noise_model():
    with _raises(DslError, "landmark_offset", "noise"):
        landmark_offset("l1", offset_x=1.0, noise=0.1)


def test_prior_value_that_is_not_geometry():
    with _raises(DslError, "PriorFactor"):
        PriorFactor("l1", [1.0, 2.0, 3.0], noise.isotropic(3, 0.1))


def test_well_formed_graph_is_accepted():
    graph = _graph()
    graph.add(landmark_offset("l1", offset_x=0.5, noise=noise.isotropic(2, 0.1)))
    graph.add(point_pair("l1", "l2", noise=noise.diagonal([0.1, 0.2, 0.3])))
    graph.add(pose_near("x1", target=Pose3(), noise=noise.isotropic(6, 1.0)))
    assert len(graph.factors) == 3
    # Σ ½‖R r‖² at the initial values: (0.5/0.1)² + (2/0.1)², (1/0.1)² + (1/0.2)² + (3/0.3)²
    expected = 0.5 * (25.0 + 400.0) + 0.5 * (100.0 + 25.0 + 100.0)
    assert graph.error() == pytest.approx(expected, rel=1e-12)
