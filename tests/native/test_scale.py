"""Large graphs: the native backend takes any size the Program has (no cap of its own), reports
per-iteration progress to a caller, and the progress display (fgc.app.progress) prints it.

The fast cases use a Pose2 ring with loop closures (a general graph, built in a second); the
heavy case runs ``w10000.graph`` natively and checks GTSAM's error at fgc's result against
GTSAM's own LM optimum.
"""

from __future__ import annotations

import io
import json
import math
import random
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.app.cli import main
from fgc.app.progress import Progress
from fgc.compile import compile_graph
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import native, sim
from fgc_backends.native import NativeConfig, NativeConfigError


def ring(n: int = 60, closures: int = 12, seed: int = 3) -> fgc.Graph:
    """Poses on a circle, odometry round it and random loop closures; initial values perturbed."""
    rng = random.Random(seed)
    xyt = [(10 * math.cos(2 * math.pi * i / n), 10 * math.sin(2 * math.pi * i / n),
            2 * math.pi * i / n + math.pi / 2) for i in range(n)]
    truth = [fgc.Pose2(*p) for p in xyt]
    graph = fgc.Graph()
    for i, (x, y, t) in enumerate(xyt):
        graph.add_variable(i, fgc.Pose2(x + rng.gauss(0, 0.3), y + rng.gauss(0, 0.3),
                                        t + rng.gauss(0, 0.1)))
    graph.add(PriorFactor(0, truth[0], noise.isotropic(3, 0.01)))
    pairs = [(i, (i + 1) % n) for i in range(n)]
    pairs += [tuple(rng.sample(range(n), 2)) for _ in range(closures)]
    for a, b in pairs:
        graph.add(BetweenFactor(a, b, truth[a].between(truth[b]), noise.isotropic(3, 0.1)))
    return graph


@pytest.fixture(scope="module")
def ring_program():
    graph = ring()
    program = compile_graph(graph, SolverConfig(), name="ring")
    return graph, program


def test_native_config_has_no_size_cap_by_default(ring_program, tmp_path):
    _, program = ring_program
    widest = max(s.frontal_dim + s.separator_dim for s in program.schedule.steps)
    assert program.schedule.structure_class == "general"
    config = NativeConfig()
    assert config.max_variables is None and config.max_step_columns is None
    native.emitter.check_limits(program, config)  # any size: no error
    # a bound is still available where one is wanted, and names itself
    with pytest.raises(NativeConfigError, match="NativeConfig.max_step_columns"):
        native.emitter.check_limits(program, NativeConfig(max_step_columns=widest - 1))
    with pytest.raises(NativeConfigError, match="NativeConfig.max_variables"):
        native.emitter.check_limits(program, NativeConfig(max_variables=10))
    with pytest.raises(NativeConfigError, match="max_variables must be ≥ 1"):
        NativeConfig(max_variables=0).check()


def test_native_progress_reports_every_accepted_iteration(ring_program):
    graph, program = ring_program
    data = problem_data(graph, program)
    records: list[dict] = []
    timings: dict = {}
    result = native.run(program, data, progress=records.append, timings=timings)
    assert result.status == "converged"
    its = [r["iteration"] for r in records]
    # one record per accepted iteration; the last iteration may stop without a step (gradient)
    assert its == sorted(set(its)) and its[-1] in (result.iterations, result.iterations - 1)
    assert records[-1]["error"] == pytest.approx(result.final_error, rel=1e-12)
    errors = [r["error"] for r in records]
    assert all(b <= a for a, b in zip(errors, errors[1:], strict=False))  # LM never goes up
    assert all(r["lambda"] > 0 and r["relative_decrease"] >= 0 for r in records)
    assert set(timings) == {"built", "build_seconds", "load_seconds", "solve_seconds"}
    # the hook is cleared after the call: a second solve without progress reports nothing
    again: dict = {}
    native.run(program, data, timings=again)
    assert not again["built"] and again["build_seconds"] == 0.0
    # and the simulator reports the same iterations of its batch solve
    sim_records: list[dict] = []
    sim_result = sim.run(program, data, progress=sim_records.append)
    assert [r["iteration"] for r in sim_records] == its and sim_result.iterations == \
        result.iterations
    np.testing.assert_allclose([r["error"] for r in sim_records], errors, rtol=1e-9,
                               atol=1e-9 * errors[0])


def test_progress_display_plain_lines_and_terminal():
    out = io.StringIO()
    display = Progress("fgc run g", max_iterations=10, stream=out, delay=0.0, interval=0.0)
    for it in range(1, 4):
        display({"iteration": it, "error": 10.0 / it, "lambda": 1e-5, "relative_decrease": 0.5})
    display.finish()
    lines = out.getvalue().splitlines()
    assert len(lines) == 3 and lines[0].startswith("fgc run g: iteration 1/10, error 10")
    assert "λ 1.0e-05" in lines[0] and "elapsed" in lines[0] and "more iterations" in lines[0]
    assert [r["iteration"] for r in display.records] == [1, 2, 3]

    class Tty(io.StringIO):
        def isatty(self) -> bool:
            return True

    tty = Tty()
    display = Progress("fgc run g", max_iterations=10, stream=tty, delay=0.0)
    display({"iteration": 1, "error": 2.0, "lambda": 1e-5})
    display({"iteration": 2, "error": 1.0, "lambda": 1e-6})
    display.finish()
    text = tty.getvalue()
    assert "\n" not in text and text.count("\r") == 4 and text.endswith("\r")
    # silent before the delay, quiet when not shown; records are kept either way
    quiet = io.StringIO()
    display = Progress("x", 5, stream=quiet, delay=3600.0)
    display({"iteration": 1, "error": 1.0, "lambda": 1.0})
    display.finish()
    hidden = Progress("x", 5, show=False, stream=quiet, delay=0.0)
    hidden({"iteration": 1, "error": 1.0, "lambda": 1.0})
    assert quiet.getvalue() == "" and len(hidden.records) == 1


def test_cli_run_reports_build_load_and_solve_separately(tmp_path, capsys):
    spec = tmp_path / "ring_spec.py"
    here = str(Path(__file__).resolve().parent)
    spec.write_text(f"import sys\nsys.path.insert(0, {here!r})\nfrom test_scale import ring\n"
                    "\n\ndef build():\n    return ring()\n")
    out = tmp_path / "run.json"
    for _ in range(2):  # the second run finds the library built (in this process: loaded)
        assert main(["run", str(spec), "--backend", "native", "--json", str(out)]) == 0
    text = capsys.readouterr().out
    assert "build/load included" not in text
    assert "native library already loaded" in text.splitlines()[-1]
    report = json.loads(out.read_text())
    assert {"solve_seconds", "build_seconds", "load_seconds", "total_seconds"} <= set(report)
    assert report["built"] is False and report["build_seconds"] == 0.0
    assert report["solve_seconds"] <= report["total_seconds"]
    assert report["progress"][-1]["iteration"] in (report["iterations"], report["iterations"] - 1)


@pytest.mark.heavy
def test_w10000_runs_natively_to_gtsams_optimum():
    gtsam = pytest.importorskip("gtsam")
    from fgc.app.specs import load_spec
    from fgc.interop.to_gtsam import to_gtsam, value_to_gtsam

    graph = load_spec(gtsam.findExampleDataFile("w10000.graph"), {})
    program = compile_graph(graph, SolverConfig(linear="cholesky"), name="w10000")
    assert len(program.variables) > 8192  # the old cap
    result = native.run(program, problem_data(graph, program))
    problem = to_gtsam(graph)
    params = gtsam.LevenbergMarquardtParams()
    params.setRelativeErrorTol(1e-12)
    params.setAbsoluteErrorTol(1e-14)
    params.setlambdaInitial(1e-5)
    optimum = gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params).optimize()
    values = gtsam.Values()
    for key in graph.variables:
        values.insert(problem.keys[key], value_to_gtsam(result.values[str(key)]))
    # both at the same optimum: GTSAM's own error at each, to 1e-6 relative
    assert problem.graph.error(values) == pytest.approx(problem.graph.error(optimum), rel=1e-6)


def test_cli_simulate_logs_progress_and_quiet_prints_none(tmp_path, capsys):
    spec = tmp_path / "ring_spec.py"
    here = str(Path(__file__).resolve().parent)
    spec.write_text(f"import sys\nsys.path.insert(0, {here!r})\nfrom test_scale import ring\n"
                    "\n\ndef build():\n    return ring(n=20, closures=4)\n")
    out = tmp_path / "sim.json"
    main(["-q", "simulate", str(spec), "--precision", "float64", "--json", str(out)])
    captured = capsys.readouterr()
    assert "iteration" not in captured.err  # -q: no progress display
    report = json.loads(out.read_text())
    its = [r["iteration"] for r in report["progress"]]
    assert its and its == sorted(set(its)) and its[-1] <= report["iterations"]
    assert all(r["elapsed_seconds"] >= 0 and r["error"] >= 0 for r in report["progress"])
    # verify's simulator solve is logged the same way
    main(["-q", "verify", str(spec), "--json", str(out)])
    report = json.loads(out.read_text())
    assert report["progress"] and report["progress"][-1]["iteration"] <= report["iterations"]


def sphere_ring(n: int = 60, closures: int = 60, seed: int = 5) -> fgc.Graph:
    """Pose3 on a helix, odometry and random loop closures: dense enough that the elimination's
    last fronts are wide (sphere2500's shape in small)."""
    rng = random.Random(seed)
    truth = [fgc.Pose3(fgc.Rot3.RzRyRx(0.0, 0.1 * math.sin(i), 2 * math.pi * i / n),
                       [10 * math.cos(2 * math.pi * i / n), 10 * math.sin(2 * math.pi * i / n),
                        0.2 * i])
             for i in range(n)]
    graph = fgc.Graph()
    for i, t in enumerate(truth):
        step = np.array([rng.gauss(0, 0.05) for _ in range(3)]
                        + [rng.gauss(0, 0.3) for _ in range(3)])
        graph.add_variable(i, t.retract(step))
    graph.add(PriorFactor(0, truth[0], noise.isotropic(6, 0.01)))
    pairs = [(i, i + 1) for i in range(n - 1)]
    pairs += [tuple(rng.sample(range(n), 2)) for _ in range(closures)]
    for a, b in pairs:
        graph.add(BetweenFactor(a, b, truth[a].between(truth[b]), noise.isotropic(6, 0.1)))
    return graph


def test_native_cholesky_on_wide_fronts_gives_the_simulators_numbers():
    """Fronts wide enough for the host's register blocks of 8 rows x 16 columns, frontal rows
    updated in blocks of 32 and the update matrices on a stack (postorder): the native Cholesky
    meets the float64 simulator's numbers within 1e-9 (relative, every storage entry; the same
    bound as the other native-vs-simulator checks), with the same iterations."""
    graph = sphere_ring()
    program = compile_graph(graph, SolverConfig(linear="cholesky", max_iterations=8),
                            name="sphere_ring")
    steps = program.schedule.steps
    assert max(s.frontal_dim for s in steps) > 32 + 8  # two frontal blocks, an 8-row block
    assert max(s.frontal_dim + s.separator_dim for s in steps) >= 64
    assert any(len(s.children) >= 2 for s in steps)  # children side by side on the stack
    order = native.emitter.postorder(program)
    position = {s: i for i, s in enumerate(order)}
    assert sorted(order) == list(range(len(steps)))
    assert all(position[c] < position[s.index] for s in steps for c in s.children)
    data = problem_data(graph, program)
    result = native.run(program, data, native.NativeConfig(scalar="double"))
    reference = sim.run(program, data, precision="float64")
    assert result.iterations == reference.iterations
    worst = max(float(np.max(np.abs(result.storage[k] - v) / np.maximum(1.0, np.abs(v))))
                for k, v in reference.storage.items())
    assert worst <= 1e-9
    assert result.final_error == pytest.approx(reference.final_error, rel=1e-9)
