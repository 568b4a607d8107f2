"""fgc.interop.from_gtsam.from_gtsam: GTSAM graphs imported into fgc, checked against GTSAM itself.

Tolerances: solutions ≤ 1e-6 in tangent distance and final errors ≤ 1e-6 relative against GTSAM's
LevenbergMarquardtOptimizer (issue 6); per-factor linearisations (whitened A, b) ≤ 1e-9 relative;
reconstructed IMU measurements against fgc's own preintegration ≤ 1e-9.
"""

from __future__ import annotations

import gtsam
import numpy as np
import pytest

from fgc.app.solve import optimize
from fgc.app.specs import example
from fgc.errors import FgcError
from fgc.frontend import noise as fn
from fgc.interop.from_gtsam import default_key_name, from_gtsam, noise_from_gtsam
from fgc.interop.to_gtsam import linearize_factor, noise_to_gtsam, to_gtsam, value_from_gtsam

lio = example("lio")

X, L = gtsam.symbol_shorthand.X, gtsam.symbol_shorthand.L
_nm = gtsam.noiseModel


def _gtsam_lm(graph, values):
    params = gtsam.LevenbergMarquardtParams()
    params.setRelativeErrorTol(1e-12)
    params.setAbsoluteErrorTol(1e-14)
    params.setMaxIterations(100)
    return gtsam.LevenbergMarquardtOptimizer(graph, values, params).optimize()


def _assert_same_solution(graph, gvalues, fgc_graph, key_of) -> None:
    """fgc's LM on the imported graph against GTSAM's LM on the original."""
    sol = optimize(fgc_graph)
    result = _gtsam_lm(graph, gvalues)
    worst = 0.0
    for k, var in fgc_graph.variables.items():
        reader = getattr(result, {"Pose3": "atPose3", "Pose2": "atPose2",
                                  "ImuBias": "atConstantBias"}.get(var.type.__name__, "atVector"))
        ref = value_from_gtsam(var.type, reader(key_of(k)))
        worst = max(worst, float(np.abs(ref.local(sol.values[k])).max()))
    assert worst <= 1e-6
    assert sol.error == pytest.approx(graph.error(result), rel=1e-6)


def test_lio_round_trip_matches_gtsam():
    graph = lio.build(N=10)
    problem = to_gtsam(graph)
    names = {i: k for k, i in problem.keys.items()}
    imported = from_gtsam(problem.graph, problem.values, key_names=names)
    assert list(imported.variables) == list(graph.variables)
    kinds = [f.type.name for f in imported.factors]
    assert kinds.count("CombinedImuFactor") == 9 and kinds.count("GPSFactor") == 10
    assert imported.error() == pytest.approx(problem.graph.error(problem.values), rel=1e-12)
    _assert_same_solution(problem.graph, problem.values, imported, problem.keys.__getitem__)


def test_imu_measurements_reconstructed_exactly():
    """Bias Jacobians, gravity and ζ read back through pim.predict equal fgc's preintegration."""
    graph = lio.build(N=3, error_mode="componentwise")
    problem = to_gtsam(graph)
    imported = from_gtsam(problem.graph, problem.values)
    pairs = [(a, b) for a, b in zip(graph.factors, imported.factors, strict=True)
             if a.type.name.startswith("CombinedImuFactor")]
    assert pairs and all(b.type.name == "CombinedImuFactorComponentWise" for _, b in pairs)
    for a, b in pairs:
        for name, want in a.measured.items():
            np.testing.assert_allclose(b.measured[name], want, rtol=1e-9, atol=1e-12,
                                       err_msg=name)
        np.testing.assert_allclose(b.noise.sqrt_information, a.noise.sqrt_information,
                                   rtol=1e-9, atol=1e-9)


def test_imu_with_coriolis_is_refused():
    params = gtsam.PreintegrationCombinedParams.MakeSharedU(9.81)
    params.setOmegaCoriolis(np.array([0.0, 0.0, 7.29e-5 * 1e3]))
    pim = gtsam.PreintegratedCombinedMeasurements(params, gtsam.imuBias.ConstantBias())
    for _ in range(20):
        pim.integrateMeasurement(np.array([0.1, 0.0, 9.9]), np.array([0.0, 0.1, 0.2]), 0.01)
    graph = gtsam.NonlinearFactorGraph()
    graph.add(gtsam.CombinedImuFactor(X(0), 1, X(1), 2, 3, 4, pim))
    values = gtsam.Values()
    values.insert(X(0), gtsam.Pose3())
    values.insert(X(1), gtsam.Pose3(gtsam.Rot3(), np.array([0.0, 0.0, 0.1])))
    for k in (1, 2):
        values.insert(k, np.array([1.0, 0.0, 0.0]))
    for k in (3, 4):
        values.insert(k, gtsam.imuBias.ConstantBias())
    with pytest.raises(FgcError, match=r"factor 0 \(CombinedImuFactor\) could not be recon"):
        from_gtsam(graph, values)


@pytest.mark.parametrize("name", ["w100.graph", "pose3example.txt"])
def test_pose_graph_round_trip_matches_gtsam(name):
    path = gtsam.findExampleDataFile(name)
    if name.endswith(".graph"):
        graph, initial = gtsam.load2D(path)
        k0 = initial.keys()[0]
        graph.add(gtsam.PriorFactorPose2(k0, initial.atPose2(k0), _nm.Diagonal.Sigmas(
            np.array([0.1, 0.1, 0.05]))))
    else:
        graph, initial = gtsam.readG2o(path, True)
        k0 = initial.keys()[0]
        graph.add(gtsam.PriorFactorPose3(k0, initial.atPose3(k0), _nm.Isotropic.Sigma(6, 0.01)))
    imported = from_gtsam(graph, initial)
    assert len(imported.factors) == graph.size()
    assert list(imported.variables) == list(initial.keys())  # plain int keys stay ints
    _assert_same_solution(graph, initial, imported, lambda k: k)


def _small_graph() -> tuple[gtsam.NonlinearFactorGraph, gtsam.Values]:
    """One of each supported non-IMU factor, some with robust or full noise models."""
    g, v = gtsam.NonlinearFactorGraph(), gtsam.Values()
    rng = np.random.default_rng(3)
    iso, full = _nm.Isotropic.Sigma, _nm.Gaussian.Covariance
    cov6 = np.cov(rng.normal(size=(6, 40))) * 0.01
    huber = _nm.Robust.Create(_nm.mEstimator.Huber.Create(0.5), iso(3, 0.1))
    cauchy = _nm.Robust.Create(_nm.mEstimator.Cauchy.Create(0.2), _nm.Diagonal.Sigmas(
        np.array([0.1, 0.2])))
    p3 = [gtsam.Pose3(gtsam.Rot3.Expmap(rng.normal(size=3)), rng.normal(size=3)) for _ in "ab"]
    p2 = [gtsam.Pose2(*rng.normal(size=3)) for _ in "ab"]
    v.insert(X(0), p3[0]), v.insert(X(1), p3[1]), v.insert(X(2), p2[0]), v.insert(X(3), p2[1])
    v.insert(L(0), rng.normal(size=3)), v.insert(L(1), rng.normal(size=2) + 3.0)
    v.insert(L(2), rng.normal(size=3)), v.insert(L(3), rng.normal(size=2))
    v.insert(5, gtsam.Rot3.Expmap(rng.normal(size=3))), v.insert(6, gtsam.Rot2(0.4))
    v.insert(7, gtsam.imuBias.ConstantBias(rng.normal(size=3), rng.normal(size=3)))
    v.insert(8, rng.normal(size=4)), v.insert(9, gtsam.Rot3()), v.insert(10, gtsam.Rot2(-1.0))
    v.insert(11, rng.normal(size=4))
    g.add(gtsam.PriorFactorPose3(X(0), p3[1], full(cov6)))
    g.add(gtsam.BetweenFactorPose3(X(0), X(1), p3[0], iso(6, 0.1)))
    g.add(gtsam.PriorFactorPose2(X(2), p2[1], iso(3, 0.3)))
    g.add(gtsam.BetweenFactorPose2(X(2), X(3), p2[0], _nm.Unit.Create(3)))
    g.add(gtsam.PriorFactorPoint3(L(0), np.ones(3), huber))
    g.add(gtsam.BetweenFactorPoint3(L(0), L(2), np.ones(3), iso(3, 0.2)))
    g.add(gtsam.PriorFactorPoint2(L(1), np.ones(2), cauchy))
    g.add(gtsam.BetweenFactorPoint2(L(1), L(3), np.ones(2), iso(2, 0.2)))
    g.add(gtsam.PriorFactorRot3(5, gtsam.Rot3(), iso(3, 0.1)))
    g.add(gtsam.BetweenFactorRot3(5, 9, gtsam.Rot3.Expmap(np.array([0.1, 0.2, 0.3])),
                                  iso(3, 0.1)))
    g.add(gtsam.PriorFactorRot2(6, gtsam.Rot2(0.1), iso(1, 0.1)))
    g.add(gtsam.BetweenFactorRot2(6, 10, gtsam.Rot2(0.2), iso(1, 0.1)))
    g.add(gtsam.PriorFactorConstantBias(7, gtsam.imuBias.ConstantBias(), iso(6, 0.1)))
    g.add(gtsam.PriorFactorVector(8, np.arange(4.0), iso(4, 0.5)))
    g.add(gtsam.BetweenFactorVector(8, 11, np.ones(4), iso(4, 0.5)))
    g.add(gtsam.GPSFactor(X(1), np.ones(3), iso(3, 2.0)))
    g.add(gtsam.BearingRangeFactor2D(X(2), L(1), gtsam.Rot2(0.3), 2.0, _nm.Diagonal.Sigmas(
        np.array([0.05, 0.1]))))
    g.add(gtsam.RangeFactor2D(X(2), L(3), 1.5, iso(1, 0.1)))
    g.add(gtsam.RangeFactor3D(X(0), L(2), 1.5, iso(1, 0.1)))
    g.add(gtsam.RangeFactorPose2(X(2), X(3), 1.5, iso(1, 0.1)))
    g.add(gtsam.RangeFactorPose3(X(0), X(1), 1.5, iso(1, 0.1)))
    return g, v


def test_each_factor_linearises_like_gtsam():
    graph, values = _small_graph()
    imported = from_gtsam(graph, values)
    assert "x0" in imported.variables and "l1" in imported.variables and 5 in imported.variables
    for i, f in enumerate(imported.factors):
        a, b = linearize_factor(f, [imported.variables[k].initial for k in f.keys])
        a_g, b_g = graph.at(i).linearize(values).jacobian()
        scale = max(1.0, np.abs(a_g).max(), np.abs(b_g).max())
        assert np.abs(a - a_g).max() <= 1e-9 * scale, f.name
        assert np.abs(b - b_g).max() <= 1e-9 * scale, f.name
    assert imported.error() == pytest.approx(graph.error(values), rel=1e-12)


@pytest.mark.parametrize("noise", [
    fn.isotropic(3, 0.2), fn.diagonal([0.1, 0.2, 0.3]),
    fn.covariance([[2.0, 0.3, 0.1], [0.3, 1.0, 0.2], [0.1, 0.2, 0.5]]),
    fn.huber(1.345, fn.diagonal([0.1, 0.2, 0.3])), fn.cauchy(0.1, fn.isotropic(3, 3.0)),
    fn.cauchy(250.0, fn.isotropic(3, 1.0))])
def test_noise_round_trip(noise):
    back = noise_from_gtsam(noise_to_gtsam(noise))
    assert back.kind == noise.kind
    np.testing.assert_allclose(back.sqrt_information, noise.sqrt_information, rtol=1e-14)
    assert (back.robust is None) == (noise.robust is None)
    if noise.robust is not None:
        assert back.robust.kind == noise.robust.kind
        assert back.robust.k == pytest.approx(noise.robust.k, rel=1e-13)


@pytest.mark.parametrize(("model", "match"), [
    (_nm.Constrained.All(3), "constrained"),
    (_nm.Robust.Create(_nm.mEstimator.Tukey.Create(4.0), _nm.Unit.Create(3)), "Tukey"),
    (_nm.Robust.Create(_nm.mEstimator.Huber.Create(
        1.0, _nm.mEstimator.Huber.ReweightScheme.Scalar), _nm.Unit.Create(3)), "Block")])
def test_unsupported_noise_models(model, match):
    with pytest.raises(FgcError, match=match):
        noise_from_gtsam(model)


def test_key_names():
    assert default_key_name(X(1)) == "x1"
    assert default_key_name(gtsam.symbol("L", 12)) == "L12"
    assert default_key_name(7) == 7
    graph = gtsam.NonlinearFactorGraph()
    graph.add(gtsam.BetweenFactorPose2(X(1), 7, gtsam.Pose2(), _nm.Unit.Create(3)))
    values = gtsam.Values()
    values.insert(X(1), gtsam.Pose2()), values.insert(7, gtsam.Pose2(1.0, 0.0, 0.0))
    assert list(from_gtsam(graph, values).variables) == [7, "x1"]  # values' key order
    assert list(from_gtsam(graph, values, {7: "y7"}).variables) == ["y7", "x1"]
    with pytest.raises(FgcError, match="both map to the fgc key 'x1'"):
        from_gtsam(graph, values, {7: "x1"})


def test_errors_name_the_factor():
    graph = gtsam.NonlinearFactorGraph()
    graph.add(gtsam.PriorFactorPose3(X(0), gtsam.Pose3(), _nm.Unit.Create(6)))
    graph.add(gtsam.BearingRangeFactor3D(X(0), L(0), gtsam.Unit3(), 1.0, _nm.Unit.Create(3)))
    values = gtsam.Values()
    values.insert(X(0), gtsam.Pose3()), values.insert(L(0), np.zeros(3))
    with pytest.raises(FgcError, match=r"factor 1 \(BearingRangeFactor3D\): .*no fgc built-in"):
        from_gtsam(graph, values)
    graph = gtsam.NonlinearFactorGraph()
    graph.add(gtsam.PriorFactorPose3(X(0), gtsam.Pose3(), _nm.Unit.Create(6)))
    graph.add(gtsam.PriorFactorPose2(X(0), gtsam.Pose2(), _nm.Unit.Create(3)))
    with pytest.raises(FgcError, match=r"factor 1 \(PriorFactorPose2\) uses key 'x0' as a Pose2"):
        from_gtsam(graph, values)
    graph = gtsam.NonlinearFactorGraph()
    graph.add(gtsam.PriorFactorPose3(X(9), gtsam.Pose3(), _nm.Unit.Create(6)))
    with pytest.raises(FgcError, match=r"no value for key\(s\) 'x9' used"):
        from_gtsam(graph, values)
    graph = gtsam.NonlinearFactorGraph()
    graph.add(gtsam.PriorFactorPose2(X(0), gtsam.Pose2(), _nm.Unit.Create(3)))
    with pytest.raises(FgcError, match="variable 'x0'.*not a Pose2"):
        from_gtsam(graph, values)


def test_one_twin_table_for_both_directions():
    """Every built-in with a GTSAM twin in fgc.interop.twins is exported as that class (not as
    a numeric CustomFactor) and imported back to the same fgc factor: a Vector between, a range
    to a point and to a pose (the exporter and importer disagreed on both before)."""
    import fgc
    from fgc.frontend.factors import BetweenFactor, PriorFactor
    from fgc.frontend.geometry import Point2, Pose2, vector_type
    from fgc.interop.from_gtsam import from_gtsam, range_factor_type
    from fgc.interop.to_gtsam import to_gtsam

    v3 = vector_type(3)
    g = fgc.Graph()
    g.add_variable("a", v3(np.array([1.0, 2.0, 3.0]))).add_variable("b", v3(np.zeros(3)))
    g.add_variable("p", Pose2(0.1, 0.2, 0.3)).add_variable("q", Pose2(1.0, -1.0, 0.5))
    g.add_variable("l", Point2(2.0, 1.0))
    g.add(PriorFactor("a", v3(np.array([1.0, 2.0, 3.0])), fgc.noise.isotropic(3, 0.1)))
    g.add(BetweenFactor("a", "b", v3(np.array([0.5, 0.5, 0.5])), fgc.noise.isotropic(3, 0.2)))
    g.add(PriorFactor("p", Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    g.add(range_factor_type(Pose2, Point2)("p", "l", measured=2.5,
                                             noise=fgc.noise.isotropic(1, 0.1)))
    g.add(range_factor_type(Pose2, Pose2)("p", "q", measured=1.2,
                                            noise=fgc.noise.isotropic(1, 0.1)))
    problem = to_gtsam(g)
    classes = [type(problem.graph.at(i)).__name__ for i in range(problem.graph.size())]
    assert classes == ["PriorFactorVector", "BetweenFactorVector", "PriorFactorPose2",
                       "RangeFactor2D", "RangeFactorPose2"]
    assert problem.graph.error(problem.values) == pytest.approx(g.error(), rel=1e-12)
    back = from_gtsam(problem.graph, problem.values)
    assert [f.type.name for f in back.factors] == [f.type.name for f in g.factors]
    assert back.error() == pytest.approx(g.error(), rel=1e-12)
