"""Degenerate problems: each is refused before numerics, named when elimination finds it, or
solved and equal to GTSAM — never returned as NaN or garbage.

- structural: gauge freedom and a point seen by one range measurement are StructureErrors at
  compile time, naming the variables;
- numerical rank deficiency: an elimination pivot at most 1e-10 (float64) / 1e-5 (float32)
  times its column's norm is singular; Gauss-Newton stops with status "failed", reason
  "singular" and names the variable (GTSAM's Gauss-Newton throws on the same variable); LM's
  damping keeps the step well posed, and the float64 diagnosis at its solution names the variable
  with a RankDeficientWarning (or fails, with ``SimConfig(singular_lm_fails=True)``);
- divergence: LM out of damping and a Gauss-Newton step into NaN are "failed" with the last
  accepted cost; a zero-length IMU interval is a DataError;
- solvable corner cases (θ = π exactly, a factor added twice) match GTSAM to 1e-6 in tangent
  space (float64).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
import sympy as sp
from strategies import gtsam_optimum

import fgc
from fgc import Point2, Pose2, Pose3, Vector1, Vector2
from fgc.compile import compile_graph
from fgc.errors import DataError, StructureError
from fgc.frontend.factors import BetweenFactor, CombinedImuFactor, PriorFactor
from fgc.frontend.geometry import Rot3
from fgc.frontend.preintegration import ImuParams, PreintegratedCombinedMeasurements
from fgc.interop.to_gtsam import to_gtsam
from fgc.ir.conditioning import RankDeficientWarning
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import sim
from fgc_backends.sim import SimConfig

STATE_TOL = 1e-6


@fgc.factor(name="range2")
def range2(pose: Pose2, point: Point2, *, measured: float):
    """Distance from a Pose2 to a Point2 (one row)."""
    return [pose.range(point) - measured]


@fgc.factor(name="excited_bias")
def excited_bias(p: Vector1, b: Vector1, *, u: float, z: float):
    """z = p + u·b: the bias b is observable only with excitation u ≠ 0."""
    return [p[0] + u * b[0] - z]


def solve(graph: fgc.Graph, precision: str = "float64", config: SimConfig | None = None,
          **solver) -> sim.SimResult:
    program = compile_graph(graph, SolverConfig(**solver))
    return sim.run(program, problem_data(graph, program), precision=precision, config=config)


def assert_matches_gtsam(graph: fgc.Graph, result: sim.SimResult) -> None:
    assert result.converged, (result.status, result.reason)
    theirs, _, _ = gtsam_optimum(graph)
    keys = {str(k): k for k in graph.variables}
    for key, value in result.values.items():
        assert np.linalg.norm(theirs[keys[key]].local(value)) <= STATE_TOL, key


def gtsam_gauss_newton(graph: fgc.Graph) -> dict:
    """GTSAM's Gauss-Newton optimum with QR (LM's damping stalls on the 4e7-conditioned case)."""
    import gtsam

    from fgc.interop.to_gtsam import values_from_gtsam

    problem = to_gtsam(graph)
    params = gtsam.GaussNewtonParams()
    params.setRelativeErrorTol(1e-15)
    params.setAbsoluteErrorTol(0.0)
    params.setLinearSolverType("MULTIFRONTAL_QR")  # Cholesky squares κ: GTSAM refuses it
    result = gtsam.GaussNewtonOptimizer(problem.graph, problem.values, params).optimize()
    return values_from_gtsam(graph, problem, result)


# --------------------------------------------------------------------------------------------
# structural rank deficiency: refused at compile time, by name
# --------------------------------------------------------------------------------------------


def _pose2_pair(prior: bool) -> fgc.Graph:
    g = fgc.Graph()
    g.add_variable("x0", Pose2(0, 0, 0)).add_variable("x1", Pose2(1, 0, 0))
    g.add(BetweenFactor("x0", "x1", Pose2(1, 0, 0), fgc.noise.isotropic(3, 0.1)))
    if prior:
        g.add(PriorFactor("x0", Pose2(0, 0, 0), fgc.noise.isotropic(3, 0.1)))
    return g


def test_gauge_freedom_is_refused_before_numerics():
    with pytest.raises(StructureError, match=r"component \{x0, x1\} has no prior: gauge"):
        compile_graph(_pose2_pair(prior=False))


@pytest.mark.parametrize("ordering", ["auto", "min-degree", "nested-dissection"])
def test_point_seen_by_one_range_is_structurally_rank_deficient(ordering):
    g = _pose2_pair(prior=True)
    g.add_variable("landmark", Point2([3.0, 4.0]))
    g.add(range2("x1", "landmark", measured=4.5, noise=fgc.noise.isotropic(1, 0.1)))
    with pytest.raises(StructureError, match=r"landmark.*structurally rank-deficient"):
        compile_graph(g, SolverConfig(ordering=ordering))


def test_unconstrained_variable_is_named():
    g = _pose2_pair(prior=True).add_variable("lost", Point2([0.0, 0.0]))
    with pytest.raises(StructureError, match="'lost' is not constrained"):
        compile_graph(g)


# --------------------------------------------------------------------------------------------
# numerical rank deficiency: named during elimination
# --------------------------------------------------------------------------------------------


def _unexcited_bias(u: tuple[float, float] = (0.0, 0.0)) -> fgc.Graph:
    """A prior on p and two readings z = p + u·b; with u = 0 the bias b is unobservable."""
    g = fgc.Graph()
    g.add_variable("p", Vector1([0.1])).add_variable("gyro_bias", Vector1([0.2]))
    g.add(PriorFactor("p", Vector1([0.0]), fgc.noise.isotropic(1, 0.1)))
    for ui, z in zip(u, (1.0, 1.2), strict=True):
        g.add(excited_bias("p", "gyro_bias", u=ui, z=z, noise=fgc.noise.isotropic(1, 0.1)))
    return g


@pytest.mark.parametrize("linear", ["qr", "cholesky"])
@pytest.mark.parametrize("precision", ["float64", "float32"])
def test_gauss_newton_names_an_unobservable_bias(linear, precision):
    result = solve(_unexcited_bias(), precision, method="gn", linear=linear)
    assert (result.status, result.reason) == ("failed", "singular")
    assert result.singular_variable == "gyro_bias"
    assert "'gyro_bias'" in result.message and "not determined" in result.message
    assert all(np.all(np.isfinite(v)) for v in result.storage.values())


def test_gtsam_gauss_newton_refuses_the_same_variable():
    import gtsam

    problem = to_gtsam(_unexcited_bias())
    with pytest.raises(RuntimeError, match=r"Indeterminate linear system.*\n?.*variable\s+1"):
        gtsam.GaussNewtonOptimizer(problem.graph, problem.values).optimize()
    assert problem.keys["gyro_bias"] == 1


def test_lm_keeps_its_damped_solution_but_names_the_variable():
    with pytest.warns(RankDeficientWarning, match="'gyro_bias'"):
        result = solve(_unexcited_bias())
    assert result.converged and result.singular_variable == "gyro_bias"
    assert result.values["gyro_bias"][0] == pytest.approx(0.2)  # damping never moved it
    strict = solve(_unexcited_bias(), config=SimConfig(singular_lm_fails=True))
    assert (strict.status, strict.reason, strict.singular_variable) == (
        "failed", "singular", "gyro_bias")


def test_point_ranged_from_one_place_is_named():
    """Two range readings from the same position: the landmark's tangential direction is
    unobservable although rows ≥ unknowns."""
    g = fgc.Graph()
    for key in ("x0", "x1"):
        g.add_variable(key, Pose2(0, 0, 0))
        g.add(PriorFactor(key, Pose2(0, 0, 0), fgc.noise.isotropic(3, 0.01)))
    g.add_variable("landmark", Point2([3.0, 4.1]))
    for key, measured in (("x0", 5.0), ("x1", 5.1)):
        g.add(range2(key, "landmark", measured=measured, noise=fgc.noise.isotropic(1, 0.1)))
    result = solve(g, method="gn")
    assert (result.status, result.singular_variable) == ("failed", "landmark")


@fgc.factor(name="projection")
def projection(point: Point2, *, a: Vector2, z: float):
    """z = a·point: one linear reading of a 2-D point."""
    return [a[0] * point[0] + a[1] * point[1] - z]


def test_pivot_tolerance_depends_on_precision():
    """Readings along (1, 1) and (1, 1 + 1e-7): nearly parallel columns leave a relative pivot
    near 1e-7 — solvable in float64 (and equal to GTSAM), singular in float32, whose rounding
    is of that size."""
    g = fgc.Graph().add_variable("point", Point2([0.0, 0.0]))
    truth = np.array([2.0, -1.0])
    for a in ((1.0, 1.0), (1.0, 1.0 + 1e-7)):
        g.add(projection("point", a=Vector2(a), z=float(np.dot(a, truth)),
                         noise=fgc.noise.isotropic(1, 0.1)))
    f64 = solve(g, method="gn")
    assert f64.converged and f64.condition > 1e7  # κ ≈ 4e7: ill-conditioned, not singular
    assert np.linalg.norm(gtsam_gauss_newton(g)["point"].local(f64.values["point"])) <= 1e-6
    assert np.allclose(f64.values["point"], truth, atol=1e-6)
    f32 = solve(g, "float32", method="gn")
    assert (f32.status, f32.reason, f32.singular_variable) == ("failed", "singular", "point")


# --------------------------------------------------------------------------------------------
# divergence and bad IMU intervals
# --------------------------------------------------------------------------------------------


@fgc.factor(name="root_reading")
def root_reading(x: Vector1, *, z: float):
    return [sp.sqrt(x[0]) - z]


@fgc.factor(name="angle_reading")
def angle_reading(x: Vector1, *, z: float):
    return [sp.atan(x[0]) - z]


def _one(ftype, start: float, z: float) -> fgc.Graph:
    g = fgc.Graph().add_variable("x", Vector1([start]))
    return g.add(ftype("x", z=z, noise=fgc.noise.isotropic(1, 0.1)))


def test_lm_out_of_damping_reports_the_last_cost():
    """atan from x = 10: the Gauss-Newton step overshoots to x ≈ −138, so LM must damp; with a
    damping bound of 1e-2 it gives up at the initial point."""
    g = _one(angle_reading, 10.0, 0.0)
    result = solve(g, lambda_upper_bound=1e-2)
    assert (result.status, result.reason) == ("failed", "lambda_limit")
    assert result.final_error == pytest.approx(g.error(), rel=1e-12)
    assert result.values["x"][0] == 10.0 and "last accepted cost" in result.message
    assert solve(g).converged  # the default bound lets LM through


def test_gauss_newton_step_into_nan_is_a_clear_failure():
    """√x from x = 4 towards 0.1: the full step lands at x < 0, where √x is NaN."""
    g = _one(root_reading, 4.0, 0.1)
    result = solve(g, method="gn")
    assert (result.status, result.reason) == ("failed", "non_finite")
    assert result.final_error == pytest.approx(g.error()) and result.values["x"][0] == 4.0
    assert "non-finite" in result.message


def test_zero_length_imu_interval_is_a_data_error():
    pim = PreintegratedCombinedMeasurements(ImuParams.make_u())
    with pytest.raises(DataError, match="zero-length"):
        CombinedImuFactor("x0", "v0", "x1", "v1", "b0", "b1", pim)
    with pytest.raises(DataError, match="IMU sample 0: dt must be finite and > 0"):
        pim.integrate_measurement([0, 0, 9.81], [0, 0, 0], 0.0)


# --------------------------------------------------------------------------------------------
# corner cases that solve
# --------------------------------------------------------------------------------------------


def _theta_pi_pose2(perturb: bool) -> fgc.Graph:
    g = fgc.Graph()
    truth = [Pose2(0, 0, np.pi), Pose2(-1, 0, np.pi), Pose2(-1, 1, -np.pi / 2)]
    rng = np.random.default_rng(7)
    for i, pose in enumerate(truth):
        g.add_variable(f"x{i}", pose.retract(rng.normal(size=3) * 0.05) if perturb else pose)
    g.add(PriorFactor("x0", truth[0], fgc.noise.isotropic(3, 0.01)))
    for i, j in ((0, 1), (1, 2), (0, 2)):
        g.add(BetweenFactor(f"x{i}", f"x{j}", truth[i].between(truth[j]),
                            fgc.noise.diagonal([0.1, 0.1, 0.05])))
    g.add(BetweenFactor("x0", "x1", Pose2(1, 0, np.pi), fgc.noise.isotropic(3, 0.2)))
    return g


def _theta_pi_pose3(perturb: bool) -> fgc.Graph:
    flip = Rot3(np.diag([1.0, -1.0, -1.0]))  # a rotation by exactly π about x
    truth = [Pose3(Rot3(np.eye(3)), [0, 0, 0]), Pose3(flip, [1, 0, 0]), Pose3(flip, [2, 1, 0])]
    rng = np.random.default_rng(8)
    g = fgc.Graph()
    for i, pose in enumerate(truth):
        g.add_variable(f"x{i}", pose.retract(rng.normal(size=6) * 0.05) if perturb else pose)
    g.add(PriorFactor("x1", truth[1], fgc.noise.isotropic(6, 0.01)))
    for i, j in ((0, 1), (1, 2), (0, 2)):
        g.add(BetweenFactor(f"x{i}", f"x{j}", truth[i].between(truth[j]),
                            fgc.noise.isotropic(6, 0.1)))
    return g


@pytest.mark.parametrize("perturb", [False, True])
@pytest.mark.parametrize("build", [_theta_pi_pose2, _theta_pi_pose3])
def test_poses_at_exactly_pi_solve_and_match_gtsam(build, perturb):
    graph = build(perturb)
    for linear in ("qr", "cholesky"):
        assert_matches_gtsam(graph, solve(graph, linear=linear))


def test_a_factor_added_twice_counts_twice():
    """The same factor twice equals GTSAM with it twice, and one copy with σ/√2."""
    once, twice = _theta_pi_pose2(True), _theta_pi_pose2(True)
    twice.add(twice.factors[1])
    result = solve(twice)
    assert_matches_gtsam(twice, result)
    f = once.factors[1]
    sigmas = 1.0 / np.diag(f.noise.sqrt_information) / np.sqrt(2.0)
    once.factors[1] = BetweenFactor(*f.keys, Pose2.from_storage(f.measured["measured"]),
                                    fgc.noise.diagonal(sigmas))
    merged = solve(once)
    for key, value in result.values.items():
        assert np.linalg.norm(merged.values[key].local(value)) <= 1e-9


def test_well_posed_problems_stay_quiet():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = solve(_theta_pi_pose2(True), "float32")
    assert result.singular_variable is None and result.warnings == ()
    assert result.condition is not None and result.float32_ok
