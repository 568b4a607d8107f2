"""GTSAM's Jacobian conventions at singular points (issue 34 item 5).

A range, a distance or a bearing between coincident points has no derivative; GTSAM gives one
anyway (norm2 / norm3: the all-ones row; Rot2::relativeBearing: the identity rotation with a zero
Jacobian), and fgc derives the same (``fgc.frontend.geometry.special``: ``VectorNorm`` and
``GuardedQuotient``). Each case here linearises fgc's factor and GTSAM's own at coincident
points and just around GTSAM's thresholds (1e-10 for the norm, 1e-5 for the bearing) and
requires the same whitened (A, b) to 1e-12 (relative to max(1, |A|, |b|)).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import fgc
from fgc.compiler.derive import derive
from fgc.frontend import noise
from fgc.frontend.factors.bearing_range import BearingRangeFactor
from fgc.frontend.geometry import Point2, Point3, Pose2, Pose3, Rot2, Rot3, special
from fgc.interop.to_gtsam import linearize_factor, singular_at

gtsam = pytest.importorskip("gtsam")

TOL = 1e-12


@fgc.factor
def point_distance(p: Point2, q: Point2, *, measured: float):
    return [(q - p).norm() - measured]


@fgc.factor
def sqrt_distance(p: Point2, q: Point2, *, measured: float):
    d = q.v - p.v
    return [fgc.sqrt(d[0] * d[0] + d[1] * d[1]) - measured]


@fgc.factor
def pose2_range(x: Pose2, q: Point2, *, measured: float):
    return [x.range(q) - measured]


@fgc.factor
def pose3_range(x: Pose3, q: Point3, *, measured: float):
    return [x.range(q) - measured]


# offsets of the second point from the first: exactly coincident, inside and outside each
# threshold
OFFSETS = [0.0, 1e-11, 1e-9, 1e-6, 1e-4]
POSE2 = Pose2(1.0, 2.0, 0.3)
POSE3 = Pose3(Rot3.Expmap(np.array([0.1, -0.2, 0.3])), np.array([1.0, 2.0, 3.0]))


def _compare(factor, fgc_values, gtsam_factor, gtsam_values) -> float:
    a, b = linearize_factor(factor, fgc_values)
    v = gtsam.Values()
    for i, value in enumerate(gtsam_values):
        v.insert(i, value)
    a_g, b_g = gtsam_factor.linearize(v).jacobian()
    assert np.all(np.isfinite(a)) and np.all(np.isfinite(b))
    scale = max(1.0, np.abs(a_g).max(), np.abs(b_g).max())
    return max(np.abs(a - a_g).max(), np.abs(b - b_g).max()) / scale


@pytest.mark.parametrize("offset", OFFSETS)
def test_bearing_range_2d_matches_gtsam_at_coincident_points(offset):
    n2 = noise.isotropic(2, 1.0)
    f = BearingRangeFactor("x", "l", Rot2.fromAngle(0.5), 2.0, n2)
    q = POSE2.t + np.array([offset, 0.0])
    g = gtsam.BearingRangeFactor2D(0, 1, gtsam.Rot2(0.5), 2.0,
                                   gtsam.noiseModel.Isotropic.Sigma(2, 1.0))
    err = _compare(f, [POSE2, Point2(*q)], g, [gtsam.Pose2(1.0, 2.0, 0.3), q])
    assert err <= TOL, (offset, err)


@pytest.mark.parametrize("offset", OFFSETS)
@pytest.mark.parametrize("factor", [point_distance, sqrt_distance])
def test_point2_distance_matches_gtsam_range_factor2(factor, offset):
    p = np.array([1.0, 2.0])
    q = p + np.array([offset, 0.0])
    f = factor("p", "q", measured=2.0, noise=noise.isotropic(1, 1.0))
    g = gtsam.RangeFactor2(0, 1, 2.0, gtsam.noiseModel.Isotropic.Sigma(1, 1.0))
    assert _compare(f, [Point2(*p), Point2(*q)], g, [p, q]) <= TOL


@pytest.mark.parametrize("offset", OFFSETS)
def test_pose2_range_matches_gtsam_range_factor_2d(offset):
    q = POSE2.t + np.array([0.0, offset])
    f = pose2_range("x", "q", measured=2.0, noise=noise.isotropic(1, 1.0))
    g = gtsam.RangeFactor2D(0, 1, 2.0, gtsam.noiseModel.Isotropic.Sigma(1, 1.0))
    assert _compare(f, [POSE2, Point2(*q)], g, [gtsam.Pose2(1.0, 2.0, 0.3), q]) <= TOL


@pytest.mark.parametrize("offset", OFFSETS)
def test_pose3_range_matches_gtsam_range_factor_3d(offset):
    """GTSAM takes Pose3's range of the world-frame difference: at coincident points its
    Jacobian is the all-ones row for the point and −(1 1 1)·R for the pose's translation."""
    q = POSE3.t + np.array([offset, 0.0, 0.0])
    f = pose3_range("x", "q", measured=2.0, noise=noise.isotropic(1, 1.0))
    g = gtsam.RangeFactor3D(0, 1, 2.0, gtsam.noiseModel.Isotropic.Sigma(1, 1.0))
    gpose = gtsam.Pose3(gtsam.Rot3(POSE3.r.R), POSE3.t)
    assert _compare(f, [POSE3, Point3(*q)], g, [gpose, q]) <= TOL


def test_singular_points_are_recognised_and_nothing_is_nan():
    f = point_distance("p", "q", measured=1.0, noise=noise.isotropic(1, 1.0))
    assert singular_at(f, [Point2(1.0, 2.0), Point2(1.0, 2.0)])
    assert not singular_at(f, [Point2(1.0, 2.0), Point2(1.0, 2.5)])
    r, (jp, jq) = derive(point_distance).evaluate([Point2(0.0, 0.0), Point2(0.0, 0.0)],
                                                  {"measured": np.array([1.0])})
    assert r.tolist() == [-1.0] and jp.tolist() == [[-1.0, -1.0]] and jq.tolist() == [[1, 1]]


def test_a_bearing_entry_constant_at_regular_points_is_computed():
    """∂bearing/∂θ is −1 at every regular point and 0 (GTSAM's) at the landmark: the probes
    that make constant entries exact must not fix it at −1."""
    sf = derive(BearingRangeFactor("x", "l", Rot2.fromAngle(0.0), 1.0,
                                   noise.isotropic(2, 1.0)).type)
    assert sf.structure[0][0][2] == "x"


def test_the_dsl_spells_norms_as_vector_norm():
    x, y = sp.symbols("x y", real=True)
    assert isinstance(fgc.hypot(x, y), special.VectorNorm)
    assert isinstance(Point2(x, y).norm(), special.VectorNorm)
    assert fgc.hypot(3.0, 4.0) == 5.0 and float(Point2(3.0, 4.0).norm()) == 5.0
    c, s = special.relative_bearing(0.0, 0.0)
    assert (c, s) == (1.0, 0.0)  # GTSAM: the identity rotation


def test_every_backend_printer_prints_the_guard_without_dividing_by_zero():
    """The simulator's NumPy (run here on a coincident and a regular instance side by side:
    finite, equal to the derivation, no NumPy warning) and the C++ printers, scalar and
    lane-wise (the C++ itself is compiled and run by tests/test_singular_start.py)."""
    import warnings

    from fgc_backends.cfamily.printer import print_kernel
    from fgc_backends.sim.printer import SimPrinter

    sf = derive(point_distance)
    printed = SimPrinter().kernel(sf.kernel, "k")
    assert any("numpy.where" in line for line in printed.lines)
    ns: dict = {"numpy": np}
    exec("def k(x):\n" + "\n".join("    " + line for line in printed.lines), ns)  # noqa: S102
    x = np.array([[1.0, 1.0], [2.0, 2.0], [1.0, 4.0], [2.0, 6.0], [1.0, 1.0]])  # p, q, measured
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = ns["k"](x)
    assert np.all(np.isfinite(out))
    for i in range(2):
        r, jacs = sf.evaluate([Point2(*x[0:2, i]), Point2(*x[2:4, i])], {"measured": x[4:, i]})
        assert np.allclose(out[:, i], np.concatenate([r, *[j.ravel() for j in jacs]]),
                           rtol=1e-15, atol=0)
    names = [f"in[{i}]" for i in range(len(sf.kernel.inputs))]
    scalar = print_kernel(sf.kernel, names, "point_distance")
    lanes = print_kernel(sf.kernel, names, "point_distance", vector=True)
    text = "\n".join(scalar.intermediates + scalar.outputs)
    assert "fgc_guarded_quotient(" in text and "v_fgc_guarded_quotient(" not in text
    assert "v_fgc_guarded_quotient(" in "\n".join(lanes.intermediates + lanes.outputs)
