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

import re
import sys
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Point2, Pose2, Pose3
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import sim
from fgc_backends.hls import HlsConfig, HlsConfigError, emit, make, run_csim

imu_window = example("imu_window")
lio = example("lio")
pose_graph = example("pose_graph")

ROOT = Path(__file__).resolve().parents[2]


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


def rotation_angle(ra, rb) -> float:
    """The angle between 3 × 3 rotations ``ra`` and ``rb`` from their chordal distance
    ‖ra − rb‖_F = 2√2 sin(angle / 2), as the testbench measures it (tb.cpp.jinja's
    rotation_angle). Not arccos((trace(raᵀrb) − 1) / 2): near 0 that turns a float matrix's
    orthonormality rounding e into an angle of about √e (1.06 mrad for imu_window N = 20's
    float32 Cholesky C simulation against the float32 simulator, whose rotations differ by
    0.27 mrad); the chord moves by about e."""
    half = np.linalg.norm(np.asarray(ra, float) - np.asarray(rb, float)) / np.sqrt(8.0)
    return float(2 * np.arcsin(min(half, 1.0))) if np.isfinite(half) else float("inf")


def pose_errors(program, values: dict, reference: dict) -> tuple[float, float, float]:
    """Largest position (m), rotation (rad) and other-vector error of ``values``."""
    pos = rot = vec = 0.0
    for v in program.variables:
        a, b = np.asarray(values[v.key]), np.asarray(reference[v.key])
        if v.type_name in ("Pose3", "Rot3"):
            rot = max(rot, rotation_angle(a[:9].reshape(3, 3), b[:9].reshape(3, 3)))
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


# heavy by default: imu_window (float QR; imu_mixed keeps a float imu_window design and
# test_hls_window / test_hls_stream_csim the float QR stream designs in the default run)
HEAVY_DEFAULT = ("imu_window",)


def case_params(heavy: tuple[str, ...] = HEAVY_DEFAULT) -> list:
    """CASES' names as parameters, those in ``heavy`` marked heavy."""
    return [pytest.param(name, marks=pytest.mark.heavy) if name in heavy else name
            for name in sorted(CASES)]


@pytest.fixture(scope="module", params=case_params())
def example(request, tmp_path_factory):
    return request.param, _run(request.param, CASES[request.param], tmp_path_factory)


def _check_against_reference(name, program, result, reference, scalar):
    assert result.iterations >= 1
    if scalar == "double":
        assert result.status == reference.status, (result.reason, reference.reason)
        assert relative_worst(result.values, reference.storage) <= F64_TOL
        assert abs(result.final_error - reference.final_error) <= \
            F64_TOL * max(1.0, reference.final_error)
        # the cost at the start, from the first linearisation (fgc_lm.h's
        # FGC_LM_COST_IN_LINEARIZE: QR's gradient pass, Cholesky's HGC)
        assert abs(result.initial_error - reference.initial_error) <= \
            F64_TOL * max(1.0, reference.initial_error)
    else:
        pos, rot, vec = pose_errors(program, result.values, reference.storage)
        assert pos <= POS_TOL and rot <= ROT_TOL and vec <= VEC_TOL, (name, pos, rot, vec)


def test_csim_matches_the_simulator(example):
    name, (program, _, _, result, reference) = example
    _check_against_reference(name, program, result, reference, CASES[name][2])


@pytest.mark.parametrize("example", ["lio"], indirect=True)
def test_the_suites_quick_build_computes_what_the_projects_flags_do(example, monkeypatch):
    """The suite builds its C simulations with FGC_CSIM_FLAGS=-O0 after the project's -O2
    (tests/conftest.py; the Makefile puts it last): LIO's testbench (IMU, trigonometry, square
    roots, QR) built both ways writes the same result.txt, byte for byte."""
    _, (program, project, data, _, reference) = example
    results = []
    for flags in ("-O0", None):
        if flags is None:
            monkeypatch.delenv("FGC_CSIM_FLAGS", raising=False)
        else:
            monkeypatch.setenv("FGC_CSIM_FLAGS", flags)
        make(project, "clean")
        run_csim(project, program, data, reference)
        results.append((project.directory / "result.txt").read_bytes())
    assert results[0] == results[1]


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


@pytest.mark.heavy
@pytest.mark.parametrize("name", sorted(HEAVY_CASES))
def test_heavy_cases_match_the_simulator(name, tmp_path_factory):
    program, _, _, result, reference = _run(name, HEAVY_CASES[name], tmp_path_factory)
    _check_against_reference(name, program, result, reference, HEAVY_CASES[name][2])


# heavy (about a minute on 2 cores): float32 LM with Cholesky against the float32 simulator
@pytest.mark.heavy
def test_imu_window_float_cholesky_matches_the_float_simulator(tmp_path):
    """imu_window N = 20, LM, float32 Cholesky: the C simulation against the float32 simulator
    (the testbench checks it too). The two take different LM paths from the second iteration
    (float32 Cholesky of these normal equations is decided by rounding: the simulator's breaks
    down at mu <= 1, the cascade's does not) and end 3.2 mm / 0.275 mrad / 3.1e-3 apart, each
    about 0.06 sigma (Mahalanobis) from the float64 optimum. Through acos of the trace the
    rotation read 1.06 mrad: the simulator's 84 float retractions leave its matrices 1.4e-6 off
    orthonormal."""
    graph = imu_window.build(N=20)
    program = compile_graph(graph, SolverConfig(linear="cholesky", precision="float32"),
                            name="iw_f32_chol")
    project = emit(program, tmp_path, HlsConfig(scalar="float"))
    data = problem_data(graph, program)
    f32 = sim.run(program, data, precision="float32")
    result = run_csim(project, program, data, f32)
    pos, rot, vec = pose_errors(program, result.values, f32.storage)
    assert pos <= POS_TOL and rot <= ROT_TOL and vec <= VEC_TOL, (pos, rot, vec)


def test_fixed_point_is_refused_with_the_reason(tmp_path):
    graph = pose_graph.build()
    program = compile_graph(graph, name="w100_fixed")
    # the dataflow accelerator has no fixed-point units: refused with the reason, never wrapped
    with pytest.raises(HlsConfigError, match="float or double only"):
        emit(program, tmp_path / "fixed", HlsConfig(scalar="ap_fixed<40,16>"))


COUNT_MAIN = r"""
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include "fgc_cycles.h"
// at exit: per DATAFLOW region name, the distinct (process, instance) pairs of its first entry
struct Dump {
    Dump() { fgc_cycles::state(); }  // constructed first, so destroyed after this
    ~Dump() {
        std::map<std::string, std::set<std::pair<std::string, int> > > first;
        std::map<std::string, long> first_id;
        for (const auto& r : fgc_cycles::log()) {
            if (r.region < 0) continue;
            auto it = first_id.find(r.region_name);
            if (it == first_id.end()) it = first_id.emplace(r.region_name, r.region).first;
            if (it->second == r.region) first[r.region_name].insert({r.process, r.instance});
        }
        for (const auto& kv : first) {
            std::printf("region %s %zu\n", kv.first.c_str(), kv.second.size());
        }
    }
} dump_at_exit;
"""


# n_u = 3 (heavy: about 30 s on 2 cores) repeats n_u = 1's check with more Update units
@pytest.mark.parametrize("linear, option, value", [
    ("qr", "units", 1), pytest.param("qr", "units", 3, marks=pytest.mark.heavy),
    ("cholesky", "cpe", 4)])
def test_executed_network_is_the_plans(linear, option, value, tmp_path):
    """The unit headers' cycle log (-DFGC_COUNT_CYCLES) of a C simulation run: the processes
    that ran in one reflection / one CPE round are the plan's, n_u + 4 or 2 #CPE + 2 (the plan's
    network adds one back-substitution unit per unit set); back-substitution's are the default
    width's: by columns on LIO's chain (the loader and two ends), the slots on pose_graph's
    tree."""
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.plan import process_network
    graph = lio.build(N=6) if linear == "qr" else pose_graph.build()
    program = compile_graph(graph, SolverConfig(linear=linear, **{option: value}), name="net")
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import counting_run

    project = emit(program, tmp_path, HlsConfig(scalar="double"))
    columns = project.config.backsub_lanes == 4  # the automatic width, resolved by emit
    assert columns == (linear == "qr")
    out = counting_run(project, graph, program, COUNT_MAIN)
    ran = dict((r, int(n)) for _, r, n in re.findall(r"^(region) (\w+) (\d+)$", out, re.M))
    procs, _ = process_network(accel_plan(program, project.config))
    region = "qr_reflection" if linear == "qr" else "cpe_round"
    sets = 2 if linear == "qr" else 1  # LIO is a two-ended chain: two unit sets
    # QR: broadcast, qr_finish, the Updates, Evaluate and collect; Cholesky: feed, per CPE its
    # tap and itself, drain
    per_set = value + 4 if linear == "qr" else 2 * value + 2
    expected = {region: per_set}
    if columns:  # back_substitute by columns: the loader and the two ends counted as a region
        expected["backsub_columns"] = 3
    if linear == "cholesky":  # per block type its linearize_<b>: the datapath beside its HGC
        expected |= {f"linearize_{b}": 2 for b in range(len(program.blocks))}
    else:  # linearize_rows: the datapaths beside the gradient
        expected["linearize"] = 2
    assert ran == expected
    # Cholesky's assembler beside the cascade (cholesky_overlap, counted as branches: no region),
    # back-substitution's two backsub_lane regions (a lane's solve beside the other's load) and
    # back_substitute's (the slots beside the state update they feed and the cost pass it
    # feeds)
    # (with the HGC beside the elimination its Gram source a third process there)
    beside = any(ph.name == "hgc_beside" for ph in accel_plan(program, project.config).phases)
    overlap = (3 if beside else 2) if linear == "cholesky" else 0
    tail = (("backsub_loader", "backsub_end0", "backsub_end1") if columns else (
        "backsub_set0", "backsub_load1", "backsub_set1", "backsub_load0", "backsub_slots")) + (
        "backsub_retire", "trial_cost")
    assert len(procs) == sets * per_set + overlap + len(tail) and procs[-len(tail):] == tail


# the serial ordering with 3 units (heavy: about 30 s on 2 cores) repeats the two-ended case's
# counting on a one-set design
@pytest.mark.parametrize("linear, option", [("qr", {"units": 2}),
                                            pytest.param("qr", {"units": 3, "ordering": "serial"},
                                                         marks=pytest.mark.heavy),
                                            ("cholesky", {"cpe": 4})])
def test_cycle_counting_csim_equals_the_model(linear, option):
    """Issue 18, item 5: the cycles the counters count as the C simulation runs (trip × II +
    depth of every executed loop of the units and of the kernel around them, regions and
    side-by-side unit sets as plan_cost combines them) equal the plan's figure for the same
    executions, per phase and in total, within 2 % (the plan adds a fill for each unit set of
    a level even when it has no step; LM control prices an accepted step's copy every solve)."""
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    graph = lio.build(N=6) if linear == "qr" else imu_window.build(N=5)
    solver = SolverConfig(method="gn", linear=linear, precision="float32", **option)
    phases, events = measure("t", graph, solver)
    assert events["solve"] >= 1 and events["call"] == 1
    # Cholesky: the Jacobian pass runs inside the hgc group's regions (evaluate_<b> alongside
    # its HGC, linearize_<b>), the longest block type's beside the first solve's elimination
    # (hgc_beside); the state update runs inside back_substitute's region, fed by it
    # QR: the gradient beside the datapaths, in factor_jacobian's region (no phase of its own)
    # the cost at X comes out of the first linearisation (QR: its gradient; Cholesky: its
    # HGC's b^T b): no cost pass at X, no "cost" event (a robust loss keeps it)
    expected = {"setup", "lm_control",
                "backsub"} | ({"factor_jacobian", "qr_stack", "qr", "qr_commit"}
                              if linear == "qr" else {"hgc", "hgc_beside"})
    assert "cost" not in events and phases.get("factor_cost", (0, 0)) == (0, 0)
    assert "state_update" not in phases
    assert expected <= {g for g, (c, m) in phases.items() if c > 0 and m > 0}
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)
    counted = sum(c for c, _ in phases.values())
    model = sum(m for _, m in phases.values())
    assert abs(counted / model - 1) <= 0.02, (counted, model)


# heavy (about 40 s on 2 cores): tests/hls/test_units_qr_stream.py keeps the unit's results
# (equal to fgc_qr.h's) and its counted cycles (equal to its price) in the default run
@pytest.mark.heavy
def test_the_streaming_qr_unit_matches_the_simulator_and_counts_its_price(tmp_path):
    """--qr-unit stream (fgc_qr_stream.h): the C simulation of LIO (LM, double, 3 reflection
    stages a pass, two unit sets) equals the simulator within 1e-9, and a Gauss-Newton float
    run's counted cycles equal the plan's per phase within 2 % (the QR and back-substitution
    phases exactly: the stages' loops are priced one for one)."""
    graph = lio.build(N=6)
    program = compile_graph(graph, SolverConfig(linear="qr", units=3), name="lio_stream")
    project = emit(program, tmp_path, HlsConfig(scalar="double", qr_unit="stream"))
    assert (tmp_path / "include" / "fgc_qr_stream.h").is_file()
    assert "fgc_units::qrs_step<LesConfig>" in (tmp_path / "lio_stream.cpp").read_text()
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)
    _check_against_reference("lio_stream", program, result, reference, "double")

    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="gn", linear="qr", units=3, precision="float32")
    phases, _ = measure("t", graph, solver, HlsConfig(scalar="float", qr_unit="stream"))
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)
    assert phases["qr"][0] == phases["qr"][1] > 0
    assert phases["backsub"][0] == phases["backsub"][1] > 0


def test_the_streaming_qr_unit_is_refused_for_the_streaming_designs():
    config = HlsConfig(qr_unit="stream")
    with pytest.raises(HlsConfigError, match="streaming designs"):
        emit(compile_graph(lio.build(N=4), SolverConfig(linear="qr")), "/nonexistent",
             config, stream=_FakeLayout())
    with pytest.raises(HlsConfigError, match="qr_unit 'givens'"):
        HlsConfig(qr_unit="givens").check()


class _FakeLayout:
    """Stands in for a WindowLayout: emit refuses the streaming QR unit before it is read."""

    template = None


def test_cycle_counting_covers_levenberg_marquardt_and_the_rounding_noise_pass():
    """An LM run that rejects a trial step (LIO N=5, Cholesky, float32; pose_graph's run no
    longer rejects one since the cascade's rows keep their pivots' scale, LIO N=6's no longer
    since the back-substitution sums S xs in two lanes): the rounding-noise
    pass the plan prices per rejection runs and counts as priced, and LM's damping rows and
    retries are in the counted phases too (within 2 %, as above)."""
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="lm", linear="cholesky", cpe=3, precision="float32")
    phases, events = measure("t", lio.build(N=5), solver)
    assert events.get("noise", 0) >= 1
    counted, model = phases["rounding_noise"]
    assert counted > 0 and counted == model
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)


def test_cycle_counting_prices_levels_wider_than_the_unit_sets():
    """A general graph (pose_graph: schedule levels of up to 4 steps) on 2 QR unit sets:
    eliminate_all hands a level's steps to the sets two at a time, one chunk after another, and
    the plan prices those chunks (pricing the whole level as one longest-first assignment over
    the sets, as it once did, came out 4 % under the count)."""
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="gn", linear="qr", units=2, precision="float32")
    phases, _ = measure("t", pose_graph.build(), solver, HlsConfig(scalar="float", unit_sets=2))
    counted, model = phases["qr"]
    assert counted > 0 and abs(counted - model) <= 0.01 * model, (counted, model)
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)


def test_one_step_rows_in_the_banks_match_the_simulator(tmp_path):
    """One Gauss-Newton step (the one-step policy): level 0's first steps take the rows the
    datapaths wrote into their banks (units/qr.py's rows_in_banks) instead of stacking them
    from AB; the solve is the simulator's."""
    graph = robust_chain(8)
    program = compile_graph(graph, SolverConfig(method="gn", linear="qr", max_iterations=1),
                            name="one_step")
    project = emit(program, tmp_path, HlsConfig(scalar="double"))
    text = (tmp_path / "one_step.cpp").read_text()
    assert "FACTOR_BANK_SET" in text and "in_place, dirty" in text
    data = problem_data(graph, program)
    result = run_csim(project, program, data)
    reference = sim.run(program, data, precision="float64")
    _check_against_reference("one_step", program, result, reference, "double")


def pose2_chain(n: int = 8) -> fgc.Graph:
    """Pose2 odometry: separators of 3 words (odd, fewer than back-substitution's
    2 PARTIALS sums a row: the lanes of a split load's S words then matter)."""
    rng = np.random.default_rng(5)
    g = fgc.Graph()
    truth = [Pose2(0.5 * i, 0.1 * i * i, 0.2 * i) for i in range(n)]
    for i, p in enumerate(truth):
        g.add_variable(f"x{i}", p.retract(0.05 * rng.standard_normal(3)))
    g.add(PriorFactor("x0", truth[0], noise.isotropic(3, 0.01)))
    for i in range(n - 1):
        meas = truth[i].between(truth[i + 1]).retract(0.02 * rng.standard_normal(3))
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", meas, noise.diagonal([0.1, 0.1, 0.05])))
    return g


@pytest.mark.parametrize("graph", [pytest.param(robust_chain, marks=pytest.mark.heavy),
                                   pose2_chain], ids=["pose3", "pose2"])
def test_one_step_sums_in_the_slot_designs_state_update_match_the_simulator(graph, tmp_path):
    """The one-step policy on the slot design (backsub_lanes 1): the gradient's largest |entry|,
    |X|², |δ|², δᵀg and δ's finiteness are summed by back_substitute's state update as δ
    arrives (units/lm_control.py's retire_solved_test, FGC_BS_STEP_TEST) instead of
    lm_solved_test's loop after the solve; LM's decisions on them are the simulator's (a
    gradient maximum left zero stops before the step: the solve would not be the simulator's).
    The root's conditional reaches back-substitution's lane 0 in its commit (units/backsub.py's
    root_in_commit: the slots start at the root's solve; without qr_commit's copy the root
    would be solved from a buffer nothing wrote). The root's first child waits for the root's
    solution: its R and d are taken in beside the root's solve, its S after it
    (units/backsub.py's backsub_parts; the split S load's word lanes read as such)."""
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.backsub import backsub_parts
    graph = graph(8)
    program = compile_graph(graph, SolverConfig(method="gn", linear="qr", max_iterations=1),
                            name="one_step_slots")
    project = emit(program, tmp_path, HlsConfig(scalar="double", backsub_lanes=1))
    text = (tmp_path / "one_step_slots.cpp").read_text()
    assert "#define FGC_BS_STEP_TEST 1" in text and "lm_solved_test<" not in text
    assert "#define FGC_BS_ROOT_COMMIT 1" in text
    # the first child waits for the root: its R, d and then S by columns as the root's x
    # arrives, in the slot that solves the root (units/backsub.py's backsub_schedule, part 3)
    assert 1 in backsub_parts(_tables(program)) and "BS_PART[BS_SLOTS] = {0, 3, 0" in text
    plan = accel_plan(program, project.config)
    assert "retire_solved_test" in {u.name for u in plan.units}
    decide = {lp.name for ph in plan.phases if ph.name == "lm_control"
              for p in ph.processes for lp in p.loops}
    assert decide == {"step_scalars", "decision"}, decide
    data = problem_data(graph, program)
    result = run_csim(project, program, data)
    reference = sim.run(program, data, precision="float64")
    _check_against_reference("one_step_slots", program, result, reference, "double")


def _two_beacons(y0: float = 0.001) -> fgc.Graph:
    """A Pose2 between two beacons (-1, 0) and (1, 0) at range √2 each, started at (0, y0)
    almost on the line between them: the ranges' Jacobians nearly parallel there, so the
    undamped step (μ₀ 1e-9) throws the pose ~0.4 / y0 away and raises the cost: LM rejects
    trial after trial, growing μ, before it walks to (0, 1)."""
    from fgc.app.specs import example as spec  # (``example`` is this module's fixture)

    range_to_beacon = spec("range_beacons").range_to_beacon
    g = fgc.Graph()
    beacons = {"b0": Point2(-1.0, 0.0), "b1": Point2(1.0, 0.0)}
    for key, where in beacons.items():
        g.add_variable(key, where)
        g.add(PriorFactor(key, where, noise.isotropic(2, 0.01)))
    g.add_variable("x", Pose2(0.0, y0, 0.0))
    g.add(PriorFactor("x", Pose2(0.0, y0, 0.0), noise.diagonal([100.0, 100.0, 0.1])))
    for key in beacons:
        g.add(range_to_beacon("x", key, measured=2 ** 0.5, noise=noise.isotropic(1, 0.05)))
    return g


def test_lm_rejections_restore_the_state_held_in_place(tmp_path):
    """The column design holds LM's trial in X (fgc_lm.h's FGC_LM_TRIAL_IN_X: the state update
    writes x ⊕ δ over X, backing X up into X_BACK, and moves G into G_BACK): every trial not
    taken must put X back before the next solve. A run of many rejections and retries (the
    counting build's events) equals the simulator at 1e-9 in double, and its counted phases
    the plan's (lm_restore once per trial not taken); without the restore the retries would
    start from the rejected trial."""
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    graph = _two_beacons()
    solver = SolverConfig(linear="cholesky", lambda_initial=1e-9, mu_min=1e-9)
    program = compile_graph(graph, solver, name="beacons")
    project = emit(program, tmp_path, HlsConfig(scalar="double"))
    assert "X_BACK" in (project.directory / "beacons.cpp").read_text()  # the column design
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)
    _check_against_reference("beacons", program, result, reference, "double")
    assert result.iterations == reference.iterations
    phases, events = measure("beacons", graph, solver, HlsConfig(scalar="double"))
    assert events.get("resolve", 0) >= 5 and events["restore"] >= events["resolve"]
    assert events["accept"] < events["backsub"]  # solves that ran and were not taken
    counted, model = phases["lm_restore"]
    assert counted > 0 and counted == model
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)
