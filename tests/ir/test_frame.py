"""float32 far from the origin: the local frame (``fgc.ir.frame``).

Before it, a 10-pose Pose2 chain at (1e4, 1e4) m (σ 1 cm / 5 mrad) solved in float32 said
"converged", without a warning, 1.6–2.9 σ from GTSAM's float64 optimum (bench/bench_frame.py
--no-frame). Now positions are written relative to an origin the compiler chooses and restored
on output. Tolerance: a float32 run that says "converged" is within 1 σ of GTSAM's LM optimum
(largest tangent component of local(GTSAM, fgc) over its σ; measured ≤ 0.01 σ on the
simulator, bench/bench_frame.py). The full grid (offsets 0 … 1e6 m, Pose2 and Pose3 chains,
simulator, HLS C simulation and native) is heavy.
"""

from __future__ import annotations

import json
import shutil
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.compile import compile_graph
from fgc.errors import DataError
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, GPSFactor, PriorFactor
from fgc.frontend.geometry import Point2, Point3, Pose2, Pose3, Rot3
from fgc.ir import frame
from fgc.ir.datafile import check_structure, problem_data, read_data, write_data
from fgc.ir.program import Program, SolverConfig
from fgc_backends import sim

ROOT = next(p for p in Path(__file__).resolve().parents  # wherever the test file sits
            if (p / "bench" / "bench_frame.py").is_file())
sys.path.insert(0, str(ROOT / "bench"))
from bench_frame import chain, gtsam_optimum, sigma_distance  # noqa: E402

SIGMA_GOAL = 1.0  # a converged float32 run is within this many σ of GTSAM's optimum
F32 = SolverConfig(precision="float32")


@fgc.factor
def range_to(pose: Pose2, landmark: Point2, *, measured: float):
    return [pose.range(landmark) - measured]


@fgc.factor
def absolute_x(pose: Pose2, *, x: float):
    """An absolute position in a float measurement: not translation-covariant by any shift of
    its geometry-typed measurements (it has none)."""
    return [pose.translation()[0] - x]


def test_origin_is_chosen_only_far_from_the_origin():
    import importlib

    sys.path.insert(0, str(ROOT / "examples"))
    for name, params in (("imu_window", {"N": 8}), ("lio", {}), ("range_beacons", {}),
                         ("pose_graph", {})):
        graph = importlib.import_module(name).build(**params)
        assert frame.choose(graph) is None, name  # every shipped example keeps world coords
    graph, _ = chain("pose2", 1e4)
    chosen = frame.choose(graph)
    assert chosen.origin == (10000.0, 10000.0, 0.0)
    assert chosen.shifted == (("PriorFactorPose2", "prior"),)  # between: invariant


def test_shift_rules_are_found_numerically():
    """GPS and a prior move with the positions; a between, a custom range factor do not; a
    custom factor reading an absolute position from a float leaves the problem unshifted."""
    g = fgc.Graph()
    for i in range(3):
        g.add_variable(f"x{i}", Pose3(Rot3.Expmap(np.array([0.0, 0.0, 0.1 * i])),
                                      np.array([5e4 + i, 5e4, 10.0])))
    g.add(PriorFactor("x0", g.variables["x0"].initial, noise.isotropic(6, 0.1)))
    for i in range(2):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose3(Rot3.Expmap(np.array([0, 0, 0.1])),
                                                        np.array([1.0, 0, 0])),
                            noise.isotropic(6, 0.1)))
        g.add(GPSFactor(f"x{i + 1}", Point3(5e4 + i + 1, 5e4, 10.0), noise.isotropic(3, 0.5)))
    chosen = frame.choose(g)
    assert chosen is not None and chosen.origin == (50000.0, 50000.0, 10.0)
    assert chosen.shifted == (("GPSFactor", "position"), ("PriorFactorPose3", "prior"))

    g = fgc.Graph()
    g.add_variable("x", Pose2(3e4, 3e4, 0.1)).add_variable("l", Point2(3e4 + 5, 3e4 + 1))
    g.add(PriorFactor("x", Pose2(3e4, 3e4, 0.1), noise.isotropic(3, 0.1)))
    g.add(PriorFactor("l", Point2(3e4 + 5, 3e4 + 1), noise.isotropic(2, 0.1)))
    g.add(range_to("x", "l", measured=5.1, noise=noise.isotropic(1, 0.1)))
    chosen = frame.choose(g)
    assert chosen is not None and ("range_to", "measured") not in chosen.shifted
    g.add(absolute_x("x", x=3e4, noise=noise.isotropic(1, 0.1)))
    assert frame.choose(g) is None


@pytest.mark.parametrize("kind, offset", [("pose2", 1e4), ("pose3", 1e6)])
def test_float32_simulator_far_from_the_origin_is_within_a_sigma(kind, offset):
    graph, sig = chain(kind, offset)
    program = compile_graph(graph, F32)
    assert program.frame is not None
    with warnings.catch_warnings():
        warnings.simplefilter("error", fgc.ir.conditioning.FgcWarning)
        result = sim.run(program, problem_data(graph, program))
    assert result.converged, (result.status, result.reason)
    assert sigma_distance(graph, result.values, gtsam_optimum(graph), sig) <= SIGMA_GOAL
    # values are world coordinates
    assert abs(float(result.values["x0"].to_storage()[-3 if kind == "pose3" else 0]) - offset) < 1


def _world(kind: str, offset: float, seed: int = 0):
    graph, sig = chain(kind, offset, seed=seed)
    program = compile_graph(graph, F32, local_frame=False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = sim.run(program, problem_data(graph, program))
    warned = [w for w in caught if issubclass(w.category, fgc.ir.conditioning.FgcWarning)]
    return result, warned, sigma_distance(graph, result.values, gtsam_optimum(graph), sig)


def test_world_coordinates_more_than_a_sigma_off_say_so():
    """Where the frame cannot help (here: ``local_frame=False``), a run more than 1 σ off is
    no longer "converged": the chain at 1e4 m (ρ = 0.48 < 1, before: "converged", 1.6 σ, no
    warning) fails with reason precision_limit and says how far it stopped."""
    result, warned, dsigma = _world("pose2", 1e4)
    assert dsigma > SIGMA_GOAL
    assert (result.status, result.reason) == ("failed", "precision_limit")
    assert len(warned) == 1 and "σ from the optimum" in str(warned[0].message)
    # no false alarm: at 3e3 m the same chain converges within 0.04 σ, without a warning
    result, warned, dsigma = _world("pose2", 3e3)
    assert result.converged and not warned and dsigma <= 0.1


@pytest.mark.heavy
def test_world_coordinates_are_never_silently_off():
    """World coordinates, offsets 3e3 … 3e4 m, Pose2 and Pose3 chains, four seeds each: every
    run either converged within 1 σ of GTSAM's optimum or failed saying why."""
    for kind in ("pose2", "pose3"):
        for offset in (3e3, 5e3, 6e3, 7e3, 1e4, 2e4, 3e4):
            for seed in range(4):
                result, warned, dsigma = _world(kind, offset, seed)
                assert (result.converged and dsigma <= SIGMA_GOAL) or (
                    result.reason == "precision_limit" and warned), (kind, offset, seed, dsigma)


def test_data_and_result_files_are_local_and_readers_restore(tmp_path):
    graph, _ = chain("pose2", 1e5)
    program = compile_graph(graph, F32)
    data = problem_data(graph, program)
    assert np.max(np.abs(data.variables[0][:2])) < 64  # local positions
    assert Program.from_json(program.to_json()) == program  # the frame round-trips
    # the emitted simulator run by hand writes local values; sim.read_result restores them
    out = tmp_path / "sim"
    result = sim.run(program, data, out_dir=out, in_process=False)
    raw = json.loads((out / "result.json").read_text())
    assert abs(raw["values"]["x0"]["value"][0]) < 64
    again = sim.read_result(program, out / "result.json")
    np.testing.assert_array_equal(again.storage["x0"], result.storage["x0"])
    assert abs(result.storage["x0"][0] - 1e5) < 1
    # a frame is part of the data layout: the world-coordinate Program refuses these data
    world = compile_graph(graph, F32, local_frame=False)
    assert world.structure_fingerprint != program.structure_fingerprint
    with pytest.raises(DataError, match="another structure"):
        check_structure(data, world)
    write_data(data, tmp_path / "data.txt")
    with pytest.raises(DataError, match="another structure"):
        sim.run(world, tmp_path / "data.txt", out_dir=tmp_path / "w", in_process=False)
    assert read_data(tmp_path / "data.txt").structure == program.structure_fingerprint


def _grid(backend: str) -> list[tuple[str, float, str, str, float]]:
    from bench_frame import OFFSETS, measure

    return [(r["chain"], r["offset"], r["status"], r["reason"], r["sigma"])
            for r in measure(("pose2", "pose3"), OFFSETS, (backend,), True)]


@pytest.mark.heavy
@pytest.mark.parametrize("backend", ["sim", "native", "hls"])
def test_full_grid_within_a_sigma_or_says_why(backend):
    """Offsets 0, 1e3, 1e4, 1e5, 1e6 m, Pose2 and Pose3 chains, float32: each run converged
    within 1 σ of GTSAM's optimum, or failed with the precision verdict."""
    if backend != "sim" and shutil.which("g++") is None:
        pytest.skip("no g++")
    for kind, offset, status, reason, dsigma in _grid(backend):
        assert (status == "converged" and dsigma <= SIGMA_GOAL) or (
            status == "failed" and reason == "precision_limit"), (kind, offset, status, dsigma)


@pytest.mark.heavy
@pytest.mark.skipif(shutil.which("g++") is None, reason="no g++")
def test_native_world_coordinates_more_than_a_sigma_off_say_so():
    """The host verdict (judge_precision) of the native float solver on the world-coordinate
    chain at 1e4 m: failed / precision_limit with the distance warning (before: "converged")."""
    from fgc_backends import native

    graph, sig = chain("pose2", 1e4)
    program = compile_graph(graph, F32, local_frame=False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = native.run(program, problem_data(graph, program),
                            native.NativeConfig(scalar="float"))
    dsigma = sigma_distance(graph, result.values, gtsam_optimum(graph), sig)
    assert (result.converged and dsigma <= SIGMA_GOAL) or (
        result.reason == "precision_limit" and any(
            "σ from the optimum" in str(w.message) or "cannot place" in str(w.message)
            for w in caught)), (result.status, dsigma)
