"""The examples through the HLS backend: emitted, built with the strict flags (``make csim``),
run, and compared with the simulator (``fgc_backends.sim``, the definition of what the hardware
computes) from the same data.

Tolerances:
- float64 (``double``): every variable's storage within 1e-9 of the simulator's, relative to
  max(1, its largest entry);
- float32 (``float``) against the float64 optimum: positions within 1 cm, rotations within 1 mrad
  (angle of R_aᵀR_b), other vectors within 1e-2;
- the testbench gives bit-identical numbers whatever the number of lanes a block evaluates side
  by side (the native backend's library gives them too: ``test_native.py``).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc import noise
from fgc.compile import compile_graph
from fgc.datafile import problem_data
from fgc.factors import BetweenFactor, PriorFactor
from fgc.geometry import Pose3
from fgc.program import SolverConfig
from fgc_backends import sim
from fgc_backends.hls import HlsConfig, HlsConfigError, emit, run_csim
from fgc_backends.hls.config import ap_types_include

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "examples"))

import imu_window  # noqa: E402
import lio  # noqa: E402
import pose_graph  # noqa: E402

F64_TOL = 1e-9
POS_TOL, ROT_TOL, VEC_TOL = 1e-2, 1e-3, 1e-2

CASES = {
    "lio": (lambda: lio.build(N=10), "qr", "double"),
    "imu_window": (lambda: imu_window.build(N=20), "qr", "float"),
    "w100": (lambda: pose_graph.build(), "cholesky", "double"),
    "pose3example": (lambda: pose_graph.build("pose3example.txt"), "qr", "double"),
    # the mixed design: float everywhere but a double linear solver (SolverConfig.linear_precision)
    "imu_mixed": (lambda: imu_window.build(N=20), "cholesky", "float", "float64"),
}
HEAVY_CASES = {
    "lio_f32": (lambda: lio.build(N=30), "qr", "float"),
    "lio_chol": (lambda: lio.build(N=30), "cholesky", "double"),
    "imu_chol": (lambda: imu_window.build(N=20), "cholesky", "double"),
    "w100_f32": (lambda: pose_graph.build(), "qr", "float"),
    # N = 50 is past what float Cholesky can solve (κ ≈ 5e3 > 1/√eps32); the mixed design is not
    "imu50_mixed": (lambda: imu_window.build(N=50), "cholesky", "float", "float64"),
}


def relative_worst(values: dict, reference: dict) -> float:
    return max(float(np.max(np.abs(values[k] - np.asarray(r))) / max(1.0, np.max(np.abs(r))))
               for k, r in reference.items())


def pose_errors(program, values: dict, reference: dict) -> tuple[float, float, float]:
    """Largest position (m), rotation (rad) and other-vector error of ``values``."""
    pos = rot = vec = 0.0
    for v in program.variables:
        a, b = np.asarray(values[v.key]), np.asarray(reference[v.key])
        if v.type_name in ("Pose3", "Rot3"):
            ra, rb = a[:9].reshape(3, 3), b[:9].reshape(3, 3)
            cos = np.clip((np.trace(ra.T @ rb) - 1) / 2, -1.0, 1.0)
            rot = max(rot, float(np.arccos(cos)))
            pos = max(pos, float(np.linalg.norm(a[9:] - b[9:])) if len(a) > 9 else 0.0)
        elif v.type_name == "Pose2":
            pos = max(pos, float(np.linalg.norm(a[:2] - b[:2])))
            rot = max(rot, abs(float(np.arctan2(a[3] * b[2] - a[2] * b[3],
                                                a[2] * b[2] + a[3] * b[3]))))
        else:
            vec = max(vec, float(np.max(np.abs(a - b))))
    return pos, rot, vec


def _run(name: str, case, tmp_path_factory):
    build, linear, scalar, *wide = case
    graph = build()
    solver = SolverConfig(linear=linear, precision="float32" if wide else "float64",
                          linear_precision=wide[0] if wide else None)
    program = compile_graph(graph, solver, name=name)
    project = emit(program, tmp_path_factory.mktemp(name), HlsConfig(scalar=scalar))
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)  # the testbench checks it too
    return program, project, data, result, reference


@pytest.fixture(scope="module", params=sorted(CASES))
def example(request, tmp_path_factory):
    return request.param, _run(request.param, CASES[request.param], tmp_path_factory)


def _check_against_reference(name, program, result, reference, scalar):
    assert result.iterations >= 1
    if scalar == "double":
        assert result.status == reference.status, (result.reason, reference.reason)
        assert relative_worst(result.values, reference.storage) <= F64_TOL
        assert abs(result.final_error - reference.final_error) <= \
            F64_TOL * max(1.0, reference.final_error)
    else:
        pos, rot, vec = pose_errors(program, result.values, reference.storage)
        assert pos <= POS_TOL and rot <= ROT_TOL and vec <= VEC_TOL, (name, pos, rot, vec)


def test_csim_matches_the_simulator(example):
    name, (program, _, _, result, reference) = example
    _check_against_reference(name, program, result, reference, CASES[name][2])


def robust_chain(n: int = 14) -> fgc.Graph:
    """Pose3 odometry and skip edges under Huber and Cauchy losses on diagonal and full noise,
    one gross outlier: robust reweighting, every noise kind and repeated step shapes."""
    rng = np.random.default_rng(3)
    g = fgc.Graph()
    truth = [Pose3.Expmap(np.r_[0.1 * i, 0.05 * i, 0.2, i * 1.0, 0.3, 0.0]) for i in range(n)]
    for i, p in enumerate(truth):
        g.add_variable(f"x{i}", p.retract(0.05 * rng.standard_normal(6)))
    g.add(PriorFactor("x0", truth[0], noise.isotropic(6, 0.01)))
    a = rng.standard_normal((6, 6)) * 0.02
    full = noise.covariance(a @ a.T + np.diag([0.01] * 3 + [0.04] * 3))
    diag = noise.diagonal([0.1] * 3 + [0.2] * 3)
    for step in (1, 2):
        for i in range(n - step):
            meas = truth[i].between(truth[i + step]).retract(0.02 * rng.standard_normal(6))
            if (i, step) == (3, 2):
                meas = meas.retract(np.r_[0.5, 0, 0, 2.0, 0, 0])
            base = full if (i + step) % 2 else diag
            model = noise.huber(1.345, base) if i % 3 else noise.cauchy(1.0, base)
            g.add(BetweenFactor(f"x{i}", f"x{i + step}", meas, model))
    return g


@pytest.mark.parametrize("solver", [SolverConfig(method="gn", linear="qr"),
                                    SolverConfig(linear="cholesky")], ids=["gn_qr", "lm_chol"])
def test_robust_losses_and_gauss_newton_match_the_simulator(solver, tmp_path):
    graph = robust_chain()
    program = compile_graph(graph, solver, name="robust")
    data = problem_data(graph, program)
    result = run_csim(emit(program, tmp_path, HlsConfig(scalar="double")), program, data)
    reference = sim.run(program, data, precision="float64")
    _check_against_reference("robust", program, result, reference, "double")


def test_lanes_do_not_change_the_numbers(tmp_path):
    graph = robust_chain()
    program = compile_graph(graph, SolverConfig(linear="qr"), name="lanes")
    data = problem_data(graph, program)
    results = [run_csim(emit(program, tmp_path / str(lanes), HlsConfig(scalar="double",
                                                                        lanes=lanes)),
                        program, data) for lanes in (1, None)]
    assert results[0].final_error == results[1].final_error
    for key, value in results[0].values.items():
        np.testing.assert_array_equal(results[1].values[key], value)


@pytest.mark.heavy
@pytest.mark.parametrize("name", sorted(HEAVY_CASES))
def test_heavy_cases_match_the_simulator(name, tmp_path_factory):
    program, _, _, result, reference = _run(name, HEAVY_CASES[name], tmp_path_factory)
    _check_against_reference(name, program, result, reference, HEAVY_CASES[name][2])


@pytest.mark.heavy
def test_fixed_point_builds_and_runs(tmp_path):
    try:
        ap_types_include()
    except HlsConfigError:
        pytest.skip("ap_fixed needs the optional hls4ml package (pip install 'fgc[hls-fixed]')")
    graph = pose_graph.build()
    program = compile_graph(graph, name="w100_fixed")
    # LM's default damping bound (1e10) does not fit ±32768: refused, never wrapped round
    with pytest.raises(HlsConfigError, match="LAMBDA_UPPER_BOUND"):
        emit(program, tmp_path / "default", HlsConfig(scalar="ap_fixed<40,16>"))
    project = emit(program, tmp_path, HlsConfig(scalar="ap_fixed<40,16>",
                                                lambda_upper_bound=1e4))
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)  # the testbench's float tolerance
    pos, rot, vec = pose_errors(program, result.values, reference.storage)
    assert result.converged and pos <= POS_TOL and rot <= ROT_TOL, (pos, rot)
