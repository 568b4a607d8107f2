"""The simulator's optimum against GTSAM's Levenberg-Marquardt on the shipped examples.

Tolerances: float64 — largest tangent-space distance to GTSAM's optimum ≤ 1e-6 and final errors
equal to 1e-6 relative (absolute 1e-12 for zero-residual problems); float32 — within 1 cm and
1 mrad of the float64 result (rotation part ≤ 1e-3 rad, translation part and vector variables
≤ 1e-2). GTSAM runs with relativeErrorTol 1e-12, absoluteErrorTol 1e-14, 100 iterations.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Point3, Pose2, Rot3
from fgc.interop import oracles
from fgc.interop.to_gtsam import to_gtsam, value_to_gtsam, values_from_gtsam
from fgc.ir.conditioning import IllConditionedWarning
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc.ir.stream import Incremental
from fgc_backends import sim

ROOT = Path(__file__).resolve().parents[2]

from fgc.app.specs import example  # noqa: E402

imu_window = example("imu_window")
lio = example("lio")
pose_graph = example("pose_graph")

STATE_TOL, ERROR_RTOL, ERROR_ATOL = 1e-6, 1e-6, 1e-12
ROT_TOL_F32, POS_TOL_F32 = 1e-3, 1e-2


def gtsam_lm(problem):
    """GTSAM's LM on a translated graph with the tolerances of the module docstring."""
    import gtsam

    params = gtsam.LevenbergMarquardtParams()
    params.setRelativeErrorTol(1e-12)
    params.setAbsoluteErrorTol(1e-14)
    params.setMaxIterations(100)
    optimizer = gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params)
    return optimizer.optimize(), optimizer.iterations()


class Reference:
    """A graph, GTSAM's optimum of it, and a cache of simulator runs by configuration."""

    def __init__(self, graph: fgc.Graph):
        self.graph = graph
        self.keys = {str(k): k for k in graph.variables}
        self.problem = to_gtsam(graph)
        result, _ = gtsam_lm(self.problem)
        self.values = values_from_gtsam(graph, self.problem, result)
        self.error = float(self.problem.graph.error(result))
        self._runs: dict = {}

    def run(self, precision: str = "float64", **solver) -> sim.SimResult:
        key = (precision, tuple(sorted(solver.items())))
        if key not in self._runs:
            program = compile_graph(self.graph, SolverConfig(**solver))
            self._runs[key] = sim.run(program, problem_data(self.graph, program),
                                      precision=precision)
        return self._runs[key]

    def by_graph_key(self, result: sim.SimResult) -> dict:
        return {self.keys[k]: v for k, v in result.values.items()}

    def check_float64(self, result: sim.SimResult) -> tuple[float, float]:
        """Assert the float64 tolerances; return (state distance, relative error difference)."""
        assert result.converged, (result.status, result.reason)
        values = self.by_graph_key(result)
        dist = max(float(np.linalg.norm(self.values[k].local(v))) for k, v in values.items())
        error = float(self.problem.graph.error(to_gtsam(self.graph, values).values))
        assert dist <= STATE_TOL
        assert abs(error - self.error) <= ERROR_RTOL * self.error + ERROR_ATOL
        assert result.final_error == pytest.approx(error, rel=1e-9, abs=ERROR_ATOL)
        return dist, abs(error - self.error) / max(self.error, ERROR_ATOL)


def assert_float32_close(f32: sim.SimResult, f64: sim.SimResult,
                         require_converged: bool = True) -> None:
    assert f32.precision == "float32", f32.precision
    assert f32.converged or not require_converged, (f32.status, f32.reason)
    for key, v64 in f64.values.items():
        d = v64.local(f32.values[key])
        if len(d) == 6:  # Pose3: [ω, v]
            rot, pos = np.linalg.norm(d[:3]), np.linalg.norm(d[3:])
        elif type(v64).__name__ == "Pose2":  # [vx, vy, ω]
            rot, pos = abs(d[2]), np.linalg.norm(d[:2])
        elif type(v64).__name__ in ("Rot3", "Rot2"):
            rot, pos = np.linalg.norm(d), 0.0
        else:
            rot, pos = 0.0, np.linalg.norm(d)
        assert rot <= ROT_TOL_F32 and pos <= POS_TOL_F32, (key, rot, pos)


@pytest.fixture(scope="module")
def pose3example():
    return Reference(pose_graph.build("pose3example.txt"))


@pytest.fixture(scope="module")
def w100():
    return Reference(pose_graph.build("w100.graph"))


@pytest.fixture(scope="module")
def imu20():
    return Reference(imu_window.build(N=20))


@pytest.fixture(scope="module")
def lio30():
    return Reference(lio.build(N=30))


# --------------------------------------------------------------------------------------------
# float64 against GTSAM, float32 against float64
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("linear", ["qr", "cholesky"])
def test_pose_graphs_match_gtsam(pose3example, w100, linear):
    for ref in (pose3example, w100):
        ref.check_float64(ref.run(linear=linear))


def test_pose_graphs_float32(pose3example, w100):
    for ref in (pose3example, w100):
        assert_float32_close(ref.run("float32"), ref.run())


@pytest.mark.parametrize("solver", [{"linear": "qr"}, {"linear": "cholesky"},
                                    {"linear": "qr", "ordering": "serial"}])
@pytest.mark.parametrize("example", ["imu20", "lio30"])
def test_chains_match_gtsam(request, example, solver):
    ref = request.getfixturevalue(example)
    ref.check_float64(ref.run(**solver))


def test_imu_window_float32(imu20):
    assert_float32_close(imu20.run("float32", linear="qr"), imu20.run(linear="qr"))


def test_imu_window_float32_cholesky_is_never_falsely_converged(imu20):
    """κ = 554 is below the float32 Cholesky warning (2.9e3), yet float32 Cholesky at N = 20
    sits on the edge: from iteration 4 the cost (~3e-3) is far below its rounding noise (~2.4),
    every step is accepted by the noise rule, and the weakly determined direction creeps ~0.6 mm
    an iteration. Whether a stopping rule then fires depends on the last bits of the host's BLAS
    (numpy 2.4.6: 100 iterations, max_iterations, on one AVX2 host; 42 iterations, converged by
    the step rule, on an AVX-512 AMD EPYC). Either outcome is honest only if its answer is within
    the float32 bounds of the float64 result, and "converged" must come from a stopping rule."""
    f32, f64 = imu20.run("float32", linear="cholesky"), imu20.run(linear="cholesky")
    if f32.converged:
        assert f32.status == "converged" and f32.iterations < 100
        assert_float32_close(f32, f64)
    else:
        assert f32.status == "max_iterations"
        assert_float32_close(f32, f64, require_converged=False)


def test_imu_window_float32_cholesky_needs_a_wide_linear_solver():
    """At N = 50 the normal equations square κ ≈ 5e3 past float32: pure float32 Cholesky warns
    (and misses 1 cm); the mixed design (float32 factor blocks, float64 linear solver) is back
    within the float32 bounds, without a warning, as QR is."""
    graph = imu_window.build(N=50)
    f64 = compile_graph(graph, SolverConfig(linear="cholesky"))
    data = problem_data(graph, f64)
    mixed = compile_graph(graph, SolverConfig(linear="cholesky", precision="float32",
                                              linear_precision="float64"))
    reference = sim.run(f64, data)
    with pytest.warns(IllConditionedWarning, match="--linear-precision float64"):
        sim.run(f64, data, precision="float32")
    result = sim.run(mixed, data)
    assert not result.warnings and result.float32_ok and result.linear_precision == "float64"
    assert_float32_close(result, reference)


@pytest.mark.heavy
def test_float32_cholesky_past_its_limit_still_settles():
    """N = 80 (κ ≈ 2.5e4): pure float32 Cholesky cannot meet 1 cm and says so, but it must still
    settle near the optimum. A step whose predicted decrease is below the cost's rounding noise is
    judged by that prediction, so the noise estimate has to be tight: a Cauchy-Schwarz bound on
    its ½·m_r² term (m_r summed per row) let LM wander 16 m and run out of iterations."""
    graph = imu_window.build(N=80)
    f64 = compile_graph(graph, SolverConfig(linear="cholesky"))
    data = problem_data(graph, f64)
    reference = sim.run(f64, data)
    with pytest.warns(IllConditionedWarning):
        result = sim.run(f64, data, precision="float32")
    assert result.status == "converged"
    worst = max(float(np.linalg.norm(reference.values[k].local(v)))
                for k, v in result.values.items())
    # "near" is float32's first-order error at this conditioning: κ · eps32 · the largest state
    # entry (2.5e4 · 1.2e-7 · 98 m = 0.29 m), against the 16 m the loose noise bound allowed.
    # Measured 5.2 cm when written, 18.7 cm after so3_log took θ / sin θ from atan2 (d0a36ea,
    # float32 rounding of a different formula; the fixed 0.1 m bound failed from then on,
    # unnoticed: heavy), 11.6 cm now.
    scale = max(float(np.max(np.abs(np.asarray(s)))) for s in reference.storage.values())
    bound = reference.condition * float(np.finfo(np.float32).eps) * scale
    assert 0.05 < bound < 1.0 and worst < bound, (worst, bound)


def test_lio_float32(lio30):
    assert_float32_close(lio30.run("float32"), lio30.run())


def test_serial_two_ended_qr_cholesky_agree(lio30):
    runs = [lio30.run(**s) for s in ({"linear": "qr"}, {"linear": "cholesky"},
                                     {"linear": "qr", "ordering": "serial"})]
    for r in runs[1:]:
        dist = max(float(np.linalg.norm(runs[0].values[k].local(v))) for k, v in r.values.items())
        assert dist < 1e-8


# --------------------------------------------------------------------------------------------
# robust noise and the remaining variable types
# --------------------------------------------------------------------------------------------


def _robust_pose2_graph() -> fgc.Graph:
    """A Pose2 loop with Huber/Cauchy loop closures, one of them an outlier."""
    rng = np.random.default_rng(3)
    g = fgc.Graph()
    truth = [Pose2(np.cos(a) * 5, np.sin(a) * 5, a + np.pi / 2)
             for a in np.linspace(0, 2 * np.pi, 12, endpoint=False)]
    for i, p in enumerate(truth):
        g.add_variable(f"p{i}", p.retract(rng.normal(size=3) * 0.2))
    odo = fgc.noise.diagonal([0.1, 0.1, 0.05])
    for i in range(len(truth)):
        j = (i + 1) % len(truth)
        meas = truth[i].inverse().compose(truth[j]).retract(rng.normal(size=3) * 0.05)
        g.add(BetweenFactor(f"p{i}", f"p{j}", meas, odo))
    closures = [(0, 6, fgc.noise.huber(1.0, odo)), (3, 9, fgc.noise.cauchy(0.5, odo)),
                (2, 7, fgc.noise.huber(0.8, fgc.noise.isotropic(3, 0.2)))]
    for i, j, noise in closures:
        meas = truth[i].inverse().compose(truth[j])
        if i == 2:
            meas = meas.retract(np.array([3.0, -2.0, 1.0]))  # an outlier
        g.add(BetweenFactor(f"p{i}", f"p{j}", meas, noise))
    g.add(PriorFactor("p0", truth[0], fgc.noise.isotropic(3, 0.01)))
    return g


def _rot3_point3_graph() -> fgc.Graph:
    rng = np.random.default_rng(4)
    g = fgc.Graph()
    rots = [Rot3.random(rng) for _ in range(4)]
    for i, r in enumerate(rots):
        g.add_variable(f"r{i}", r.retract(rng.normal(size=3) * 0.1))
        g.add_variable(f"t{i}", Point3(rng.normal(size=3)))
    for i in range(3):
        g.add(BetweenFactor(f"r{i}", f"r{i + 1}", rots[i].inverse().compose(rots[i + 1]),
                            fgc.noise.isotropic(3, 0.05)))
        g.add(BetweenFactor(f"t{i}", f"t{i + 1}", Point3(rng.normal(size=3)),
                            fgc.noise.diagonal([0.1, 0.2, 0.3])))
    g.add(BetweenFactor("r0", "r3", rots[0].inverse().compose(rots[3]),
                        fgc.noise.isotropic(3, 0.05)))
    g.add(PriorFactor("r0", rots[0], fgc.noise.isotropic(3, 0.01)))
    g.add(PriorFactor("t0", Point3(np.zeros(3)), fgc.noise.isotropic(3, 0.01)))
    return g


@pytest.mark.parametrize("linear", ["qr", "cholesky"])
@pytest.mark.parametrize("build", [_robust_pose2_graph, _rot3_point3_graph])
def test_robust_and_other_types_match_gtsam(build, linear):
    ref = Reference(build())
    ref.check_float64(ref.run(linear=linear))
    assert_float32_close(ref.run("float32", linear=linear), ref.run(linear=linear))


# --------------------------------------------------------------------------------------------
# incremental smoothing against ISAM2
# --------------------------------------------------------------------------------------------


def isam2_keyframe_by_keyframe(ref: Reference, clusters, extra_updates: int) -> dict:
    """ISAM2 (QR, relinearising every variable that moved) fed each keyframe's new variables
    and the factors it completes, then ``extra_updates`` more iterations per keyframe."""
    import gtsam

    params = gtsam.ISAM2Params()
    params.setFactorization("QR")
    params.setRelinearizeThreshold(0.0)
    params.relinearizeSkip = 1
    isam = gtsam.ISAM2(params)
    cluster_of = {key: c for c, keys in enumerate(clusters) for key in keys}
    for c, keys in enumerate(clusters):
        factors, values = gtsam.NonlinearFactorGraph(), gtsam.Values()
        for i, f in enumerate(ref.graph.factors):
            if max(cluster_of[str(k)] for k in f.keys) == c:
                factors.add(ref.problem.graph.at(i))
        for key in keys:
            graph_key = ref.keys[key]
            values.insert(ref.problem.keys[graph_key],
                          value_to_gtsam(ref.graph.variables[graph_key].initial))
        isam.update(factors, values)
        for _ in range(extra_updates):
            isam.update()
    return values_from_gtsam(ref.graph, ref.problem, isam.calculateEstimate())


def test_incremental_imu_window_matches_isam2_and_batch(imu20):
    """A zero-residual window: each new keyframe leaves the older optimum optimal, so the
    window-of-3 smoother (batch steps at 5 and 15) and an iterated ISAM2 both end at the batch
    optimum; agreement 1e-6 (measured ≈1e-9 between the two, ≈6e-8 to GTSAM's LM)."""
    program = compile_graph(imu20.graph, SolverConfig(incremental_k=3, batch_every=(5, 15)))
    result = sim.run(program, problem_data(imu20.graph, program),
                     policy=Incremental(3, (5, 15)))
    assert result.converged and len(result.updates) == 20
    values = imu20.by_graph_key(result)
    isam = isam2_keyframe_by_keyframe(imu20, program.schedule.clusters, extra_updates=5)
    for key, value in values.items():
        assert np.linalg.norm(isam[key].local(value)) <= STATE_TOL
        assert np.linalg.norm(imu20.values[key].local(value)) <= STATE_TOL


def isam2_per_keyframe(ref: Reference, clusters, windows, tol: float = 1e-11) -> list[dict]:
    """:func:`fgc.interop.oracles.isam2_per_keyframe` on the reference's graph."""
    return oracles.isam2_per_keyframe(ref.graph, ref.problem, clusters, windows, tol)


def per_step_distance(result: sim.SimResult, estimates: list[dict]) -> list[float]:
    """Per keyframe, the largest tangent-space distance between fgc's and another estimate."""
    return oracles.per_keyframe_distance(result.updates, estimates)


def test_incremental_lio_matches_isam2_after_every_keyframe(lio30):
    """Window-of-3 on LIO (N = 30) with batch steps at 5, 15, 25 (paper A), against ISAM2 fed
    the same factors keyframe by keyframe with the same policy (:func:`isam2_per_keyframe`):
    after every keyframe every variable agrees to 1e-6. Measured max over steps and variables:
    7.0e-8 (keyframe 3; 7.0e-8 also for N = 12), set by fgc's window stopping at a 1e-12
    relative cost decrease (≈1.6e-8 with 1e-16 tolerances). Plain ISAM2 (relinearising every
    variable) is the batch optimum of the graph so far: the window's kept linearisation differs
    from it by up to 1.3e-2, so this comparison would catch a change of policy."""
    program = compile_graph(lio30.graph, SolverConfig(incremental_k=3, batch_every=(5, 15, 25)))
    result = sim.run(program, problem_data(lio30.graph, program),
                     policy=Incremental(3, program.solver.batch_every))
    assert result.converged and len(result.updates) == 30
    plan = program.schedule.incremental.updates
    windows = [(u["first"], u["mode"] == "batch") for u in result.updates]
    assert windows == [(p.clusters[0], p.mode == "batch") for p in plan]
    clusters = program.schedule.clusters
    same = per_step_distance(result, isam2_per_keyframe(lio30, clusters, windows))
    assert max(same) <= STATE_TOL, same
    plain = per_step_distance(result, isam2_per_keyframe(lio30, clusters, None))
    assert max(plain) > 1e-3, plain


# --------------------------------------------------------------------------------------------
# heavy cases
# --------------------------------------------------------------------------------------------


@pytest.mark.heavy
@pytest.mark.parametrize("solver", [{"linear": "qr"}, {"linear": "cholesky"},
                                    {"linear": "qr", "ordering": "serial"},
                                    {"linear": "cholesky", "method": "gn"}])
def test_lio_200_matches_gtsam(solver):
    ref = Reference(lio.build(N=200))
    ref.check_float64(ref.run(**solver))
    if solver == {"linear": "qr"}:
        assert_float32_close(ref.run("float32"), ref.run())


@pytest.mark.heavy
@pytest.mark.parametrize("solver", [{"method": "gn"}, {"linear": "cholesky", "method": "gn"},
                                    {"ordering": "nested-dissection"}])
def test_more_solver_variants_match_gtsam(w100, imu20, solver):
    for ref in (w100, imu20):
        ref.check_float64(ref.run(**solver))


@pytest.mark.heavy
def test_incremental_lio_with_a_final_batch_step_reaches_the_optimum(lio30):
    """Window-of-3 updates on a kept linearisation drift from the batch optimum of the graph so
    far (measured: up to 1.3e-2 in tangent space, ~1 cm, with batch steps at 5, 15, 25); a batch
    step at the last keyframe brings the estimate back. Tolerance 1e-3: this
    large-residual problem converges linearly, and stopping at a 1e-12 relative cost decrease
    from the incremental estimate leaves ≈1e-4."""
    program = compile_graph(lio30.graph, SolverConfig(incremental_k=3,
                                                      batch_every=(5, 15, 25, 29)))
    result = sim.run(program, problem_data(lio30.graph, program),
                     policy=Incremental(3, program.solver.batch_every))
    assert result.converged and result.updates[-1]["mode"] == "batch"
    values = lio30.by_graph_key(result)
    assert max(np.linalg.norm(lio30.values[k].local(v)) for k, v in values.items()) <= 1e-3
