"""fgc sweep: the design space, one compile per linear solver, identical simulator numerics across
unit counts, local-process and Dask runs, and bad input → one line, exit 2."""

from __future__ import annotations

import csv
import dataclasses
import json
import os
import sys
from pathlib import Path

import pytest

from fgc.app.cli import EXIT_BAD_INPUT, EXIT_OK, load_spec, main
from fgc.app.sweep import Design, design_space, group_programs
from fgc.ir.program import SolverConfig

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
POSE3 = [str(EXAMPLES / "pose_graph.py"), "-p", "dataset=pose3example.txt"]
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def pose3_graph():
    return load_spec(str(EXAMPLES / "pose_graph.py"), {"dataset": "pose3example.txt"})


def test_design_space_takes_only_the_axes_that_apply():
    designs = design_space((1, 4), (5, 20, 40), ("float32", "float64"), ("qr", "cholesky"))
    assert len(designs) == 2 * 2 + 3 * 2  # QR × n_u, Cholesky × #CPE, × precision
    assert Design("qr", "float32", units=4) in designs
    assert Design("cholesky", "float64", cpe=40) in designs
    assert all(d.cpe is None for d in designs if d.linear == "qr")
    assert all(d.units is None for d in designs if d.linear == "cholesky")
    solver = Design("cholesky", "float32", cpe=40).solver(SolverConfig(units=2))
    assert (solver.linear, solver.precision, solver.units, solver.cpe) == (
        "cholesky", "float32", 2, 40)


def test_group_programs_equal_separate_compiles(pose3_graph):
    from fgc.compile import compile_graph

    designs = design_space((1,), (5,), ("float32", "float64"), ("qr", "cholesky"))
    base = SolverConfig(max_iterations=50)
    groups = dict(group_programs(pose3_graph, base, designs, name="p3"))
    assert sorted(groups) == [("cholesky", "float32"), ("cholesky", "float64"),
                              ("qr", "float32"), ("qr", "float64")]
    for (linear, precision), program in groups.items():
        direct = compile_graph(pose3_graph, dataclasses.replace(
            program.solver, linear=linear, precision=precision), name="p3")
        assert program == direct


def test_simulator_does_not_depend_on_unit_counts(pose3_graph, tmp_path):
    """Why the sweep simulates once per (linear, precision): n_u and #CPE do not reach the
    emitted simulator, so its numerics are the same for every unit count."""
    from fgc_backends import sim

    (_, program), = group_programs(pose3_graph, SolverConfig(),
                                   [Design("cholesky", "float32", cpe=5)])
    files = {}
    for units, cpe in ((1, 5), (8, 120)):
        variant = dataclasses.replace(program, solver=dataclasses.replace(
            program.solver, units=units, cpe=cpe))
        out = tmp_path / f"u{units}"
        files[units] = {p.relative_to(out): p.read_bytes() for p in sim.emit(variant, out)}
    assert files[1] == files[8]


def test_a_failing_group_is_reported_not_raised(pose3_graph):
    from fgc.app.sweep import evaluate_group
    from fgc.ir.datafile import ProblemData

    designs = (Design("qr", "float64", units=1),)
    (_, program), = group_programs(pose3_graph, SolverConfig(), designs)
    group = evaluate_group(program, ProblemData((), ()), designs)  # data of no problem
    assert group.status == "error" and group.costs == () and group.error


def _read_csv(path: Path) -> list[dict]:
    with path.open() as fh:
        return list(csv.DictReader(fh))


def test_sweep_on_local_processes(tmp_path, capsys):
    out = tmp_path / "sweep"
    code = main(["sweep", *POSE3, "--units", "1,4", "--cpe", "5", "--linear", "qr,cholesky",
                 "--precision", "float32,float64", "--jobs", "2", "--out", str(out),
                 "--fit-reads", "0"])
    stdout = capsys.readouterr().out
    assert code == EXIT_OK, stdout
    rows = _read_csv(out / "sweep.csv")
    assert len(rows) == 2 * 2 + 1 * 2
    assert all(r["status"] == "converged" for r in rows)
    for r in rows:  # accuracy vs GTSAM's LM optimum (verify's tolerances)
        rot_tol, pos_tol = (1e-6, 1e-6) if r["precision"] == "float64" else (1e-3, 1e-2)
        assert float(r["max_rotation_error"]) <= rot_tol
        assert float(r["max_translation_error"]) <= pos_tol
    front = [r for r in rows if r["pareto"] == "True"]
    assert front and all(r["fits"] == "True" for r in front)
    qr32 = {int(r["units"]): float(r["latency_ms"]) for r in rows
            if (r["linear"], r["precision"]) == ("qr", "float32")}
    assert qr32[4] < qr32[1]  # more Update units: faster
    report = json.loads((out / "sweep.json").read_text())
    assert report["timing"]["tasks"] == 4 and report["timing"]["workers"] == 2
    assert str(os.getpid()) not in " ".join(report["timing"]["task_workers"])
    assert "qr f32 n_u=4" in stdout
    # the plan alone (no reads): no design is known to fit, the plan-fitting ones stay unread
    assert {r["fit"] for r in rows} <= {"unread", "over"} and "re-priced fit, float32:" in stdout
    if _has("matplotlib"):
        for name in ("pareto.png", "accuracy.png"):
            assert (out / name).read_bytes()[:8] == PNG_MAGIC


def test_sweep_fit_verdicts_best_and_warnings(tmp_path, capsys, monkeypatch):
    """The sweep's re-priced fit: each design's verdict from the search, the fastest that fits
    marked best, HlsFitWarning for a design the plan fits but the reader puts over the part
    (a stub reader here, its DSP growing with n_u: over the xc7z045 from n_u = 4; the real
    reader is exercised in test_search.py)."""
    from fgc.app import search
    from fgc_backends.hls.lint import HlsFitWarning

    def reader(program, config, digest=None, use_cache=True):
        return {"dsp": 300 * program.solver.units}, False

    monkeypatch.setattr(search, "read_dsp", reader)
    out = tmp_path / "sweep"
    with pytest.warns(HlsFitWarning, match="n_u=4 .* does not fit xc7z045 as re-priced"):
        code = main(["sweep", *POSE3, "--units", "1,4", "--linear", "qr", "--precision",
                     "float32", "--jobs", "1", "--out", str(out), "--fit-reads", "2"])
    stdout = capsys.readouterr().out
    assert code == EXIT_OK, stdout
    rows = {int(r["units"]): r for r in _read_csv(out / "sweep.csv")}
    assert rows[4]["fit"] == "over" and rows[4]["reader_dsp"] == "1200"
    assert rows[1]["fit"] == "fits" and rows[1]["best"] == "True"
    assert "best design that fits: qr n_u=1" in stdout
    assert "latency floor" in stdout and "the floor; limited by" in stdout
    if _has("matplotlib"):
        assert (out / "fit.png").read_bytes()[:8] == PNG_MAGIC


def _has(module: str) -> bool:
    import importlib.util

    return importlib.util.find_spec(module) is not None


def test_sweep_on_a_dask_cluster(tmp_path, capsys):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, processes=True, host="127.0.0.1",
                                  threads_per_worker=1, dashboard_address=None) as cluster:
        code = main(["sweep", *POSE3, "--units", "2", "--linear", "qr", "--precision",
                     "float32,float64", "--executor", cluster.scheduler_address,
                     "--out", str(tmp_path), "--fit-reads", "0"])
    assert code == EXIT_OK, capsys.readouterr().out
    report = json.loads((tmp_path / "sweep.json").read_text())
    assert report["timing"]["executor"].startswith("Dask cluster at tcp://127.0.0.1:")
    assert report["timing"]["tasks"] == 2
    assert str(os.getpid()) not in " ".join(report["timing"]["task_workers"])
    f64 = next(r for r in report["rows"] if r["precision"] == "float64")
    assert f64["max_rotation_error"] <= 1e-6


def test_executor_without_dask_is_a_clear_error(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed → ImportError
    assert main(["sweep", *POSE3, "--executor", "tcp://127.0.0.1:8786"]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "pip install 'fgc[sweep]'" in err


@pytest.mark.parametrize("extra, needle", [
    (["--units", "1,x"], "--units: '1,x' is not a comma-separated list of positive integers"),
    (["--cpe", "5,,20"], "--cpe: '5,,20'"),
    (["--units", "0"], "--units: '0'"),
    (["--precision", "float32,float16"], "'float16' not among float32, float64"),
    (["--linear", "lu"], "'lu' not among qr, cholesky"),
    (["--jobs", "0"], "--jobs: '0' is not a positive integer"),
    (["--executor", "localhost"], "--executor: 'localhost' is not a scheduler address"),
    (["-p", "bogus=1"], "bogus"),
    (["--fit-reads", "-1"], "--fit-reads: '-1' is not a non-negative integer"),
])
def test_bad_sweep_input_exit_code_2(extra, needle, capsys):
    assert main(["sweep", *POSE3, *extra]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and needle in err, err


def test_missing_spec_exit_code_2(capsys):
    assert main(["sweep", "no/such/spec.py"]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "no such file" in err
