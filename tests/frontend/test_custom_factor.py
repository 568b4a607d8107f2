"""Factors written by the user in the DSL (not built-ins) against independent GTSAM factors.

fgc's side is ``fgc.interop.to_gtsam.linearize_factor`` (derived Jacobians, whitened); GTSAM's side
is
``factor.linearize(values).jacobian()`` of a native GTSAM factor or of a ``gtsam.CustomFactor``
with Jacobians written here, so nothing of fgc's derivation is on the GTSAM side.

Tolerances (relative to max(1, |A|max, |b|max), float64):
- 3-D range vs ``gtsam.RangeFactor3D`` (Pose3 → Point3), point-to-plane and linear factors vs
  CustomFactors with hand-written Jacobians: whitened A and b ≤ 1e-9;
- Pose2 odometry with scale vs a CustomFactor with central-difference Jacobians (step 1e-5 along
  GTSAM's own retract): b ≤ 1e-9, A ≤ 1e-6 (the finite differences' own error is ~1e-10).
"""

import gtsam
import numpy as np
import pytest

import fgc
from fgc import Point3, Pose2, Pose3, Vector1, Vector2
from fgc.frontend import noise
from fgc.frontend.geometry import Rot3
from fgc.interop.to_gtsam import linearize_factor, noise_to_gtsam, value_to_gtsam

TOL = 1e-9
NUMERICAL_TOL = 1e-6
N_POINTS = 100
SPECIAL_ANGLES = (0.0, 1e-8, 1e-4, np.pi - 1e-6)


@fgc.factor(name="range")
def range_factor(pose: Pose3, point: Point3, *, measured: float):
    """Distance from the pose's origin to the point (GTSAM ``RangeFactor<Pose3, Point3>``)."""
    return [pose.range(point) - measured]


@fgc.factor
def point_to_plane(pose: Pose3, *, point: Point3, normal: Point3, offset: float):
    """LiDAR point-to-plane: signed distance of the body-frame ``point``, mapped to the world by
    ``pose``, from the plane n·x + d = 0."""
    return [normal.dot(pose.transformFrom(point)) + offset]


@fgc.factor
def linear_measurement(point: Point3, *, H: fgc.Matrix(2, 3), z: Vector2):  # noqa: N803
    """z = H·p for a 2×3 measurement matrix H."""
    return H * point.v - z.v


@fgc.factor
def scaled_odometry(x1: Pose2, x2: Pose2, scale: Vector1, *, measured: Pose2):
    """Odometry whose translation is known up to a scale (a monocular visual odometry)."""
    predicted = Pose2(measured.t * scale[0], r=measured.r)
    return predicted.local(x1.between(x2))


def _pose3(rng, i: int) -> Pose3:
    if i < len(SPECIAL_ANGLES):
        axis = rng.normal(size=3)
        rot = Rot3.Expmap(axis / np.linalg.norm(axis) * SPECIAL_ANGLES[i])
        return Pose3(rot, rng.normal(size=3) * 3)
    return Pose3.random(rng, 3.0)


def _compare(f: fgc.Factor, fgc_values: list, gtsam_factor, gtsam_values,
             a_tol: float = TOL, b_tol: float = TOL) -> None:
    a_fgc, b_fgc = linearize_factor(f, fgc_values)
    a_g, b_g = gtsam_factor.linearize(gtsam_values).jacobian()
    scale = max(1.0, np.abs(a_g).max(), np.abs(b_g).max())
    err_a, err_b = np.abs(a_fgc - a_g).max() / scale, np.abs(b_fgc - b_g).max() / scale
    assert err_a <= a_tol, f"{f.name}: whitened A differs by {err_a:.2e} (> {a_tol})"
    assert err_b <= b_tol, f"{f.name}: whitened b differs by {err_b:.2e} (> {b_tol})"


def _values(*pairs) -> gtsam.Values:
    values = gtsam.Values()
    for key, value in pairs:
        values.insert(key, value)
    return values


# --------------------------------------------------------------------------------------------
# 3-D range against GTSAM's own RangeFactor3D
# --------------------------------------------------------------------------------------------


def _range_noise(kind: str):
    base = noise.isotropic(1, 0.05)
    return {"isotropic": base, "huber": noise.huber(1.345, base),
            "cauchy": noise.cauchy(0.5, base)}[kind]


@pytest.mark.parametrize("kind", ["isotropic", "huber", "cauchy"])
def test_range_3d_matches_gtsam_range_factor(kind):
    assert range_factor.name == "range"
    rng = np.random.default_rng(100)
    model = _range_noise(kind)
    for i in range(N_POINTS):
        pose, point = _pose3(rng, i), Point3(rng.normal(size=3) * 5)
        measured = pose.range(point) + rng.normal() * 0.3
        f = range_factor("x", "l", measured=measured, noise=model)
        g = gtsam.RangeFactor3D(0, 1, measured, noise_to_gtsam(model))
        _compare(f, [pose, point], g, _values((0, value_to_gtsam(pose)), (1, point.v)))


def test_range_3d_in_a_graph():
    """The factor type composes with the rest of the DSL: graph error equals GTSAM's."""
    rng = np.random.default_rng(101)
    graph, gtsam_graph = fgc.Graph(), gtsam.NonlinearFactorGraph()
    values = gtsam.Values()
    for k in range(3):
        pose = Pose3.random(rng, 3.0)
        graph.add_variable(f"x{k}", pose)
        values.insert(k, value_to_gtsam(pose))
    for j in range(4):
        point = Point3(rng.normal(size=3) * 5)
        graph.add_variable(f"l{j}", point)
        values.insert(10 + j, point.v)
    model = noise.isotropic(1, 0.1)
    for k in range(3):
        for j in range(4):
            measured = float(rng.uniform(1.0, 8.0))
            graph.add(range_factor(f"x{k}", f"l{j}", measured=measured, noise=model))
            gtsam_graph.add(gtsam.RangeFactor3D(k, 10 + j, measured, noise_to_gtsam(model)))
    assert graph.error() == pytest.approx(gtsam_graph.error(values), rel=1e-12)


# --------------------------------------------------------------------------------------------
# point-to-plane and a linear factor against CustomFactors with hand-written Jacobians
# --------------------------------------------------------------------------------------------


def _gtsam_point_to_plane(point, normal, offset, model):
    def error(this, values, jacobians):
        pose = values.atPose3(this.keys()[0])
        r = pose.rotation().matrix()
        world = pose.transformFrom(point)
        if jacobians is not None:
            # right perturbation: R·Exp(ω)·p + t + R·v → ∂/∂ω = −nᵀR[p]×, ∂/∂v = nᵀR
            px = np.array([[0, -point[2], point[1]], [point[2], 0, -point[0]],
                           [-point[1], point[0], 0]])
            jacobians[0] = np.hstack([-normal @ r @ px, normal @ r]).reshape(1, 6)
        return np.array([normal @ world + offset])

    return gtsam.CustomFactor(noise_to_gtsam(model), [0], error)


def test_point_to_plane_matches_hand_written_jacobian():
    rng = np.random.default_rng(102)
    model = noise.isotropic(1, 0.02)
    for i in range(N_POINTS):
        pose = _pose3(rng, i)
        point = rng.normal(size=3) * 10
        normal = rng.normal(size=3)
        normal /= np.linalg.norm(normal)
        offset = float(rng.normal() * 3)
        f = point_to_plane("x", point=point, normal=normal, offset=offset, noise=model)
        g = _gtsam_point_to_plane(point, normal, offset, model)
        _compare(f, [pose], g, _values((0, value_to_gtsam(pose))))


def test_linear_measurement_with_matrix_argument():
    rng = np.random.default_rng(103)
    for _ in range(N_POINTS):
        h, z, p = rng.normal(size=(2, 3)), rng.normal(size=2), rng.normal(size=3) * 4
        m = rng.normal(size=(2, 2))
        model = noise.covariance(m @ m.T + 2 * np.eye(2))

        def error(this, values, jacobians, h=h, z=z):
            if jacobians is not None:
                jacobians[0] = h
            return h @ values.atPoint3(this.keys()[0]) - z

        g = gtsam.CustomFactor(noise_to_gtsam(model), [0], error)
        f = linear_measurement("l", H=h, z=z, noise=model)
        _compare(f, [Point3(p)], g, _values((0, p)))


# --------------------------------------------------------------------------------------------
# Pose2 odometry with scale against a CustomFactor with numerical Jacobians
# --------------------------------------------------------------------------------------------

STEP = 1e-5


def _scaled_odometry_error(x1, x2, scale: float, measured) -> np.ndarray:
    predicted = gtsam.Pose2(scale * measured.x(), scale * measured.y(), measured.theta())
    return predicted.localCoordinates(x1.between(x2))


def _central_difference(fun, x, dim: int, retract) -> np.ndarray:
    cols = []
    for i in range(dim):
        d = np.zeros(dim)
        d[i] = STEP
        cols.append((fun(retract(x, d)) - fun(retract(x, -d))) / (2 * STEP))
    return np.column_stack(cols)


def _gtsam_scaled_odometry(measured, model):
    def error(this, values, jacobians):
        k1, k2, k3 = this.keys()
        x1, x2, s = values.atPose2(k1), values.atPose2(k2), values.atVector(k3)

        def pose_retract(x, d):
            return x.retract(d)

        if jacobians is not None:
            jacobians[0] = _central_difference(
                lambda y: _scaled_odometry_error(y, x2, s[0], measured), x1, 3, pose_retract)
            jacobians[1] = _central_difference(
                lambda y: _scaled_odometry_error(x1, y, s[0], measured), x2, 3, pose_retract)
            jacobians[2] = _central_difference(
                lambda y: _scaled_odometry_error(x1, x2, y[0], measured), s, 1,
                lambda v, d: v + d)
        return _scaled_odometry_error(x1, x2, s[0], measured)

    return gtsam.CustomFactor(noise_to_gtsam(model), [0, 1, 2], error)


def test_scaled_odometry_matches_numerical_jacobians():
    rng = np.random.default_rng(104)
    for _ in range(N_POINTS):
        x1, x2 = Pose2.random(rng, 3.0), Pose2.random(rng, 3.0)
        scale = Vector1([rng.uniform(0.3, 3.0)])
        measured = Pose2.random(rng, 2.0)
        model = noise.diagonal(rng.uniform(0.05, 0.5, size=3))
        f = scaled_odometry("x1", "x2", "s", measured=measured, noise=model)
        g = _gtsam_scaled_odometry(value_to_gtsam(measured), model)
        gvalues = _values((0, value_to_gtsam(x1)), (1, value_to_gtsam(x2)), (2, scale.v))
        _compare(f, [x1, x2, scale], g, gvalues, a_tol=NUMERICAL_TOL)


def test_scaled_odometry_at_true_scale_is_between_factor():
    """With scale 1 the factor is GTSAM's BetweenFactorPose2 (exact Jacobians, 1e-9)."""
    rng = np.random.default_rng(105)
    for _ in range(20):
        x1, x2, measured = (Pose2.random(rng, 3.0) for _ in range(3))
        model = noise.isotropic(3, 0.1)
        f = scaled_odometry("x1", "x2", "s", measured=measured, noise=model)
        a, b = linearize_factor(f, [x1, x2, Vector1([1.0])])
        g = gtsam.BetweenFactorPose2(0, 1, value_to_gtsam(measured), noise_to_gtsam(model))
        a_g, b_g = g.linearize(_values((0, value_to_gtsam(x1)),
                                       (1, value_to_gtsam(x2)))).jacobian()
        scale = max(1.0, np.abs(a_g).max(), np.abs(b_g).max())
        assert np.abs(a[:, :6] - a_g).max() / scale <= TOL
        assert np.abs(b - b_g).max() / scale <= TOL
