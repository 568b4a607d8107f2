"""Random factor graphs for property tests: a recipe (:class:`GraphSpec`), its hypothesis
strategy, the deterministic builder, and the comparison with GTSAM's LM.

A recipe draws a family — Pose2 (odometry, loop closures, bearing-range landmarks, point priors),
Pose3 (between / LiDAR-odometry factors, loop closures, GPS) or an IMU chain (CombinedImuFactors
preintegrated by ``fgc.frontend.preintegration`` from synthetic samples, GPS) — with sizes, noise
kind
and level, robust loop closures, an initial perturbation, a duplicated factor and a solver
configuration. The builder is deterministic in the recipe's seeds: a recipe reproduces a case.

Initial perturbations stay small (≤ 0.1 in tangent space) so that fgc and GTSAM start in the
basin of the same minimum; a case where their final errors still differ is *excluded* from the
state comparison and counted (see :class:`Outcome`).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
from hypothesis import strategies as st

import fgc
from fgc.frontend.factors import (
    BearingRangeFactor,
    BetweenFactor,
    CombinedImuFactor,
    GPSFactor,
    LidarOdometryFactor,
    PriorFactor,
)
from fgc.frontend.geometry import ImuBias, Point2, Pose2, Pose3, Rot2, Rot3, Vector3
from fgc.frontend.preintegration import ImuParams, PreintegratedCombinedMeasurements
from fgc.ir.codes import NOISE_KINDS, ROBUST_KINDS

FAMILIES = ("pose2", "pose3", "imu")
ROBUST = (None, *ROBUST_KINDS)
CHAIN_ORDERINGS = ("auto", "serial", "min-degree", "nested-dissection")
GENERAL_ORDERINGS = ("auto", "min-degree", "nested-dissection")
STATE_TOL, ERROR_RTOL, ERROR_ATOL = 1e-6, 1e-6, 1e-12


@dataclass(frozen=True)
class GraphSpec:
    """The recipe of one random factor graph and the solver that runs it."""

    family: str
    poses: int
    landmarks: int
    loop_closures: int
    gps_every: int  # a GPS factor on every k-th pose (0: none; Pose3 and IMU families)
    noise_kind: str
    robust: str | None  # on loop closures
    sigma: float  # measurement noise level (rad / m)
    perturbation: float  # initial values: truth ⊕ N(0, perturbation²) in tangent space
    duplicate: bool  # the first odometry factor twice
    seed: int  # the numbers: trajectory, measurements, noise, initial values
    structure_seed: int = 0  # which loop closures, which poses see a landmark, ...
    linear: str = "qr"
    method: str = "lm"
    ordering: str = "auto"

    @property
    def chain(self) -> bool:
        """Whether the graph is a chain (no loop closure, no landmark)."""
        return self.family == "imu" or not (self.loop_closures or self.landmarks)


@st.composite
def graph_specs(draw, max_poses: int = 10) -> GraphSpec:
    """Hypothesis strategy of :class:`GraphSpec` recipes."""
    family = draw(st.sampled_from(FAMILIES))
    poses = draw(st.integers(2, max_poses if family != "imu" else min(max_poses, 6)))
    spec = GraphSpec(
        family=family, poses=poses,
        landmarks=draw(st.integers(0, 3)) if family == "pose2" else 0,
        loop_closures=draw(st.integers(0, 3)) if family != "imu" and poses > 2 else 0,
        gps_every=draw(st.integers(0, 3)) if family != "pose2" else 0,
        noise_kind=draw(st.sampled_from(NOISE_KINDS)),
        robust=draw(st.sampled_from(ROBUST)),
        sigma=draw(st.floats(0.005, 0.2)),
        perturbation=draw(st.floats(0.0, 0.1)),
        duplicate=draw(st.booleans()),
        seed=draw(st.integers(0, 2**31 - 1)),
        structure_seed=draw(st.integers(0, 2**31 - 1)),
        linear=draw(st.sampled_from(("qr", "cholesky"))),
        method=draw(st.sampled_from(("lm", "lm", "lm", "gn"))),
    )
    orderings = CHAIN_ORDERINGS if spec.chain else GENERAL_ORDERINGS
    return dataclasses.replace(spec, ordering=draw(st.sampled_from(orderings)))


# Three fixed structures for the native path: it builds C++ once per Program, so its
# property test varies only the data (numbers, noise level, robust loss, perturbation).
NATIVE_STRUCTURES = (
    GraphSpec("pose2", poses=6, landmarks=2, loop_closures=2, gps_every=0, noise_kind="full",
              robust=None, sigma=0.05, perturbation=0.05, duplicate=True, seed=0,
              structure_seed=11, linear="qr", ordering="min-degree"),
    GraphSpec("pose3", poses=5, landmarks=0, loop_closures=1, gps_every=2,
              noise_kind="diagonal", robust=None, sigma=0.05, perturbation=0.05,
              duplicate=False, seed=0, structure_seed=12, linear="cholesky"),
    GraphSpec("imu", poses=4, landmarks=0, loop_closures=0, gps_every=2, noise_kind="isotropic",
              robust=None, sigma=0.05, perturbation=0.05, duplicate=False, seed=0,
              structure_seed=13, linear="qr"),
)


@st.composite
def native_specs(draw) -> GraphSpec:
    """Recipes on :data:`NATIVE_STRUCTURES` with drawn data."""
    return dataclasses.replace(
        draw(st.sampled_from(NATIVE_STRUCTURES)), sigma=draw(st.floats(0.005, 0.2)),
        perturbation=draw(st.floats(0.0, 0.1)), robust=draw(st.sampled_from(ROBUST)),
        seed=draw(st.integers(0, 2**31 - 1)))


# --------------------------------------------------------------------------------------------
# the builder
# --------------------------------------------------------------------------------------------


def build(spec: GraphSpec) -> fgc.Graph:
    """The graph of ``spec``, deterministic in its two seeds: recipes that differ only in
    ``seed`` (and in data fields: sigma, perturbation, robust) share one structure."""
    rng, shape = np.random.default_rng(spec.seed), np.random.default_rng(spec.structure_seed)
    graph = fgc.Graph()
    if spec.family == "imu":
        _imu_chain(graph, spec, rng)
        return graph
    truth = _trajectory(spec, rng)
    for i, pose in enumerate(truth):
        graph.add_variable(f"x{i}", _perturb(pose, spec.perturbation, rng))
    graph.add(PriorFactor("x0", _perturb(truth[0], 0.01, rng), _noise(spec, truth[0].dim,
                                                                       0.01, rng)))
    for i in range(spec.poses - 1):
        lidar = spec.family == "pose3" and shape.random() < 0.5
        _relative(graph, spec, truth, (i, i + 1), rng, odometry=True, lidar=lidar)
    for pair in _closures(spec, shape):
        _relative(graph, spec, truth, pair, rng, odometry=False)
    if spec.family == "pose2":
        _landmarks(graph, spec, truth, (shape, rng))
    elif spec.gps_every:
        _gps(graph, spec, [p.t for p in truth], rng)
    if spec.duplicate:
        graph.add(graph.factors[1])
    return graph


def _trajectory(spec: GraphSpec, rng: np.random.Generator) -> list:
    if spec.family == "pose2":
        steps = [Pose2(1.0 + rng.uniform(-0.3, 0.3), rng.normal(0, 0.2), rng.normal(0, 0.5))
                 for _ in range(spec.poses - 1)]
        start = Pose2(*rng.normal(size=2), rng.uniform(-np.pi, np.pi))
    else:
        steps = [Pose3.Expmap(np.concatenate([rng.normal(0, 0.3, 3),
                                              [1.0, *rng.normal(0, 0.2, 2)]]))
                 for _ in range(spec.poses - 1)]
        start = Pose3.random(rng, 2.0)
    poses = [start]
    for step in steps:
        poses.append(poses[-1].compose(step))
    return poses


def _perturb(value, scale: float, rng: np.random.Generator):
    return value.retract(rng.normal(size=value.dim) * scale)


def _noise(spec: GraphSpec, dim: int, sigma: float, rng: np.random.Generator,
           robust: bool = False) -> fgc.noise.NoiseModel:
    """A noise model of the recipe's kind with standard deviations around ``sigma``."""
    sigmas = sigma * rng.uniform(0.5, 2.0, dim)
    if spec.noise_kind == "isotropic":
        model = fgc.noise.isotropic(dim, sigma)
    elif spec.noise_kind == "diagonal":
        model = fgc.noise.diagonal(sigmas)
    else:
        q, _ = np.linalg.qr(rng.normal(size=(dim, dim)))
        model = fgc.noise.covariance(q @ np.diag(sigmas**2) @ q.T)
    if robust and spec.robust is not None:
        k = float(rng.uniform(0.5, 3.0))
        model = (fgc.noise.huber if spec.robust == "huber" else fgc.noise.cauchy)(k, model)
    return model


def _relative(graph: fgc.Graph, spec: GraphSpec, truth: list, pair: tuple[int, int],
              rng: np.random.Generator, odometry: bool, lidar: bool = False) -> None:
    i, j = pair
    measured = _perturb(truth[i].between(truth[j]), spec.sigma, rng)
    noise = _noise(spec, truth[i].dim, spec.sigma, rng, robust=not odometry)
    if lidar:
        graph.add(LidarOdometryFactor(f"x{i}", f"x{j}", measured, noise))
    else:
        graph.add(BetweenFactor(f"x{i}", f"x{j}", measured, noise))


def _closures(spec: GraphSpec, rng: np.random.Generator) -> list[tuple[int, int]]:
    pairs = [(i, j) for i in range(spec.poses) for j in range(i + 2, spec.poses)]
    if not pairs or not spec.loop_closures:
        return []
    picks = rng.choice(len(pairs), size=min(spec.loop_closures, len(pairs)), replace=False)
    return [pairs[k] for k in sorted(picks)]


def _landmarks(graph: fgc.Graph, spec: GraphSpec, truth: list, generators) -> None:
    """Point2 landmarks 2–5 m from a pose that sees them, seen by bearing-range from 1–3 poses;
    some have a point prior too. ``generators``: (structure, numbers)."""
    shape, rng = generators
    for k in range(spec.landmarks):
        seen = sorted(shape.choice(len(truth), size=min(len(truth), int(shape.integers(1, 4))),
                                   replace=False))
        anchor = truth[int(seen[0])]
        angle, dist = rng.uniform(-np.pi, np.pi), rng.uniform(2.0, 5.0)
        point = anchor.transformFrom(np.array([np.cos(angle), np.sin(angle)]) * dist)
        key = f"l{k}"
        graph.add_variable(key, Point2(point + rng.normal(size=2) * spec.perturbation))
        for i in seen:
            bearing = truth[i].bearing(Point2(point)).compose(Rot2.fromAngle(
                rng.normal(0, spec.sigma)))
            rng_ = float(truth[i].range(Point2(point))) + rng.normal(0, spec.sigma)
            graph.add(BearingRangeFactor(f"x{i}", key, bearing, rng_,
                                         _noise(spec, 2, spec.sigma, rng)))
        if shape.random() < 0.3:
            graph.add(PriorFactor(key, Point2(point + rng.normal(size=2) * spec.sigma),
                                  _noise(spec, 2, 0.5, rng)))


def _gps(graph: fgc.Graph, spec: GraphSpec, positions: list, rng) -> None:
    for i in range(0, len(positions), spec.gps_every):
        fix = np.asarray(positions[i], float) + rng.normal(0, spec.sigma, 3)
        graph.add(GPSFactor(f"x{i}", fix, _noise(spec, 3, max(spec.sigma, 0.05), rng)))


# --------------------------------------------------------------------------------------------
# IMU chains
# --------------------------------------------------------------------------------------------

IMU_DT = 0.01


def imu_params(sigma: float) -> ImuParams:
    """Preintegration parameters with white-noise densities matched to the sample noise."""
    density = (sigma * 0.1) ** 2 * IMU_DT
    return ImuParams.make_u(accelerometer_covariance=np.eye(3) * density,
                            gyroscope_covariance=np.eye(3) * density * 0.01,
                            integration_covariance=np.eye(3) * 1e-8,
                            bias_acc_covariance=np.eye(3) * 1e-4,
                            bias_omega_covariance=np.eye(3) * 1e-6)


def _imu_chain(graph: fgc.Graph, spec: GraphSpec, rng: np.random.Generator) -> None:
    """Keyframes x_i, v_i, b_i joined by CombinedImuFactors over synthetic samples: the truth is
    the noiseless samples' prediction, the factors integrate noisy samples."""
    params = imu_params(spec.sigma)
    pose, vel = Pose3(Rot3.random(rng, 0.3), rng.normal(size=3)), rng.normal(0, 2, 3)
    acc, gyro = rng.normal(0, 1, 3) + [0, 0, 9.81], rng.normal(0, 0.3, 3)
    truth, pims = [(pose, vel)], []
    for _ in range(spec.poses - 1):
        clean = PreintegratedCombinedMeasurements(params)
        noisy = PreintegratedCombinedMeasurements(params)
        for _ in range(int(rng.integers(2, 12))):
            clean.integrate_measurement(acc, gyro, IMU_DT)
            noisy.integrate_measurement(acc + rng.normal(0, spec.sigma * 0.1, 3),
                                        gyro + rng.normal(0, spec.sigma * 0.01, 3), IMU_DT)
        rot, pos, vel = clean.predict((pose.r.R, pose.t), vel, np.zeros(6))
        pose = Pose3(Rot3(rot), pos)
        truth.append((pose, vel))
        pims.append(noisy)
    for i, state in enumerate(truth):
        _imu_state(graph, spec, state, i, rng)
    for i, pim in enumerate(pims):
        (x, v, b), (x2, v2, b2) = _imu_keys(i), _imu_keys(i + 1)
        graph.add(CombinedImuFactor(x, v, x2, v2, b, b2, pim))
    _imu_anchor(graph, spec, truth[0], rng)
    if spec.gps_every:
        _gps(graph, spec, [p.t for p, _ in truth], rng)
    if spec.duplicate:
        graph.add(graph.factors[0])


def _imu_keys(i: int) -> tuple[str, str, str]:
    return f"x{i}", f"v{i}", f"b{i}"


def _imu_state(graph: fgc.Graph, spec: GraphSpec, state, i: int, rng) -> None:
    pose, vel = state
    x, v, b = _imu_keys(i)
    graph.add_variable(x, _perturb(pose, spec.perturbation, rng))
    graph.add_variable(v, Vector3(vel + rng.normal(size=3) * spec.perturbation))
    graph.add_variable(b, ImuBias(rng.normal(size=6) * spec.perturbation * 0.01))


def _imu_anchor(graph: fgc.Graph, spec: GraphSpec, state, rng) -> None:
    pose, vel = state
    graph.add(PriorFactor("x0", pose, _noise(spec, 6, 0.01, rng)))
    graph.add(PriorFactor("v0", Vector3(vel), _noise(spec, 3, 0.01, rng)))
    graph.add(PriorFactor("b0", ImuBias(np.zeros(6)), _noise(spec, 6, 0.01, rng)))


# --------------------------------------------------------------------------------------------
# the oracle
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Outcome:
    """One case compared with GTSAM's LM (the better of multifrontal QR and Cholesky, relative
    tolerance 1e-12; :func:`gtsam_optimum`).

    ``verdict``: "match" (final errors agree to 1e-6 relative and every variable is within 1e-6
    in tangent space), "mismatch" (errors agree, states do not), "excluded" (the final errors
    differ: another local minimum or an unfinished run — not compared, counted) or "failed"
    (fgc's status is "failed").
    """

    spec: GraphSpec
    verdict: str
    state_distance: float
    fgc_error: float
    gtsam_error: float
    status: str
    reason: str

    def describe(self) -> str:
        return (f"{self.verdict}: state distance {self.state_distance:.2e}, error fgc "
                f"{self.fgc_error:.12g} vs GTSAM {self.gtsam_error:.12g}, fgc {self.status} "
                f"({self.reason}); {self.spec}")


def solver(spec: GraphSpec):
    """The recipe's SolverConfig."""
    from fgc.ir.program import SolverConfig

    return SolverConfig(linear=spec.linear, method=spec.method, ordering=spec.ordering)


def gtsam_optimum(graph: fgc.Graph) -> tuple[dict, float, object]:
    """GTSAM's LM optimum of ``graph`` as fgc values, its error, and the translated problem.

    LM runs twice, with multifrontal QR and with multifrontal Cholesky (tight tolerances, as
    ``fgc verify``), and the lower final error is the reference: either can stop short on its
    own (Cholesky stalls on badly scaled problems; on one random Pose2 graph with landmarks QR
    stops after 3 iterations 9e-9 above the optimum that Cholesky and fgc both reach, 1.4e-6
    away in state), and a reference that stopped short is not a finding about fgc."""
    from fgc.app.run_report import gtsam_optimize
    from fgc.interop.to_gtsam import to_gtsam, values_from_gtsam

    problem = to_gtsam(graph)
    best = min((gtsam_optimize(problem, linear)[0] for linear in ("qr", "cholesky")),
               key=problem.graph.error)
    return values_from_gtsam(graph, problem, best), float(problem.graph.error(best)), problem


def judge(spec: GraphSpec, graph: fgc.Graph, values: dict, status: tuple[str, str],
          reference: tuple[dict, float, object]) -> Outcome:
    """Compare fgc's ``values`` ({graph key: value}) with GTSAM's ``reference``."""
    from fgc.interop.to_gtsam import to_gtsam

    theirs, gtsam_error, problem = reference
    ours_error = float(problem.graph.error(to_gtsam(graph, values).values))
    distance = max(float(np.linalg.norm(theirs[k].local(v))) for k, v in values.items())
    if status[0] == "failed":
        verdict = "failed"
    elif abs(ours_error - gtsam_error) > ERROR_RTOL * gtsam_error + ERROR_ATOL:
        verdict = "excluded"
    else:
        verdict = "match" if distance <= STATE_TOL else "mismatch"
    return Outcome(spec, verdict, distance, ours_error, gtsam_error, *status)


def compare(spec: GraphSpec) -> Outcome:
    """Compile ``spec``'s graph, solve it with the simulator (float64) and judge it."""
    from fgc.compile import compile_graph
    from fgc.ir.datafile import problem_data
    from fgc_backends import sim

    graph = build(spec)
    program = compile_graph(graph, solver(spec))
    result = sim.run(program, problem_data(graph, program))
    keys = {str(k): k for k in graph.variables}
    values = {keys[k]: v for k, v in result.values.items()}
    return judge(spec, graph, values, (result.status, result.reason), gtsam_optimum(graph))


def compare_native(spec: GraphSpec) -> tuple[Outcome, float]:
    """Solve ``spec``'s graph with the native library (built once per structure) and judge
    it against GTSAM; also returns the largest tangent distance to the simulator's solution."""
    from fgc.compile import compile_graph
    from fgc.ir.datafile import problem_data
    from fgc_backends import native, sim

    graph = build(spec)
    program = compile_graph(graph, solver(spec), name=f"property_{spec.family}")
    data = problem_data(graph, program)
    result, reference = native.run(program, data), sim.run(program, data)
    keys = {str(k): k for k in graph.variables}
    values = {keys[k]: v for k, v in result.values.items()}  # fgc values, as the simulator's
    gap = max(float(np.linalg.norm(reference.values[str(k)].local(v)))
              for k, v in values.items())
    outcome = judge(spec, graph, values, (result.status, result.reason), gtsam_optimum(graph))
    return outcome, gap
