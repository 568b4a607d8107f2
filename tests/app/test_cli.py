"""The command line: verify against GTSAM end to end, and bad input → one line, exit code 2."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from fgc.app.cli import EXIT_BAD_INPUT, EXIT_OK, main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_verify_pose3example_matches_gtsam(tmp_path, capsys):
    out = tmp_path / "v.json"
    code = main(["verify", str(EXAMPLES / "pose_graph.py"), "-p", "dataset=pose3example.txt",
                 "--json", str(out)])
    assert code == EXIT_OK, capsys.readouterr().out
    report = json.loads(out.read_text())
    assert report["max_state_error"] <= 1e-6
    rel = abs(report["fgc_final_error"] - report["gtsam_final_error"]) / report["gtsam_final_error"]
    assert rel <= 1e-6
    assert report["linearization_error"] <= 1e-9
    assert report["iterations"] >= 1


def test_verify_w100_matches_gtsam(tmp_path):
    out = tmp_path / "v.json"
    assert main(["verify", str(EXAMPLES / "pose_graph.py"), "--json", str(out)]) == EXIT_OK
    report = json.loads(out.read_text())
    assert report["max_state_error"] <= 1e-6
    assert report["variables"] == 100 and report["factors"] == 301


def test_simulate_writes_the_report(tmp_path):
    out = tmp_path / "s.json"
    code = main(["simulate", str(EXAMPLES / "lio.py"), "-p", "N=6", "--json", str(out)])
    assert code == EXIT_OK
    r = json.loads(out.read_text())
    for key in ("final_error", "iterations", "cycles", "clock_mhz", "latency_ms", "energy_mj"):
        assert key in r
    assert set(r["resources"]) >= {"dsp", "bram", "lut", "ff"}
    assert r["storage"]["stored_words"] < r["storage"]["dense_words"]
    assert r["cycles"] > 0 and r["latency_ms"] == pytest.approx(r["cycles"] / 143e3)


def test_verify_float32_within_hardware_bounds(tmp_path):
    out = tmp_path / "v.json"
    code = main(["verify", str(EXAMPLES / "lio.py"), "-p", "N=6", "--precision", "float32",
                 "--linear", "cholesky", "--json", str(out)])
    assert code == EXIT_OK
    r = json.loads(out.read_text())
    assert r["max_rotation_error"] <= 1e-3 and r["max_translation_error"] <= 1e-2


def test_compile_emits_a_simulator_project(tmp_path):
    assert main(["compile", str(EXAMPLES / "pose_graph.py"), "-p", "dataset=pose3example.txt",
                 "--backend", "sim", "--out", str(tmp_path)]) == EXIT_OK
    assert (tmp_path / "program.json").is_file() and (tmp_path / "data.txt").is_file()
    assert any(p.suffix == ".py" for p in tmp_path.iterdir())


@pytest.mark.parametrize("argv, needle", [
    (["verify", "no/such/spec.py"], "no such file"),
    (["verify", str(EXAMPLES / "pose_graph.py"), "-p", "bogus=1"], "bogus"),
    (["verify", str(EXAMPLES / "lio.py"), "-p", "M=3"], "it takes: N=30,"),
    (["verify", str(EXAMPLES / "pose_graph.py"), "-p", "novalue"], "KEY=VALUE"),
    (["verify", str(EXAMPLES / "pose_graph.py"), "-p", "dataset=missing.g2o"], "missing.g2o"),
    (["simulate", "no/such/spec.py"], "no such file"),
    (["run", str(EXAMPLES / "lio.py"), "-p", "N=1"], "N=1"),
])
def test_bad_input_exit_code_2(argv, needle, capsys):
    assert main(argv) == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and needle in err


def test_malformed_g2o_line_names_the_line(tmp_path, capsys):
    bad = tmp_path / "bad.g2o"
    bad.write_text("VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 zero 1 0 0 1 0 1\n")
    assert main(["verify", str(bad)]) == EXIT_BAD_INPUT
    assert "bad.g2o:3" in capsys.readouterr().err


def test_g2o_file_from_gtsam_data_by_name(capsys):
    assert main(["simulate", "pose3example.txt", "--precision", "float64"]) == EXIT_OK
    assert "5 variables" in capsys.readouterr().out


# --------------------------------------------------------------------------------------------
# exit codes: non-finite starts, unwritable outputs, no tracebacks
# --------------------------------------------------------------------------------------------

INF_SPEC = '''
import fgc
from fgc import Point2
from fgc.frontend import noise
@fgc.factor
def inverse_x(p: Point2, *, target: float):
    return [1 / p.x() - target, p.y()]


def build():
    g = fgc.Graph()
    g.add_variable("p", Point2(0.0, 1.0))
    g.add(inverse_x("p", target=1.0, noise=noise.isotropic(2, 0.1)))
    return g
'''


@pytest.mark.parametrize("command", ["simulate", "verify", "report"])
def test_non_finite_initial_error_is_bad_input(command, tmp_path, capsys):
    spec = tmp_path / "inf.py"
    spec.write_text(INF_SPEC)
    assert main([command, str(spec)]) == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "initial values is not finite" in err and "factor 'inverse_x'" in err


@pytest.mark.parametrize("argv, needle", [
    (["simulate", "--json", "{tmp}/no/such/dir/s.json"], "--json {tmp}/no/such/dir/s.json"),
    (["verify", "--json", "{tmp}"], "is a folder"),
    (["run", "--backend", "sim", "--json", "{tmp}/file.txt/r.json"], "file.txt does not exist"),
    (["report", "--html", "{tmp}/no/r.html"], "--html {tmp}/no/r.html"),
    (["compile", "--out", "{tmp}/file.txt/out"], "file.txt is not a folder"),
    (["simulate", "--plot", "{tmp}/file.txt"], "--plot {tmp}/file.txt: exists and is not a folder"),
])
def test_unwritable_output_is_one_line_before_the_solve(argv, needle, tmp_path, capsys):
    (tmp_path / "file.txt").write_text("a file, not a folder\n")
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    spec = str(EXAMPLES / "pose_graph.py")
    assert main([argv[0], spec, "-p", "dataset=pose3example.txt", *argv[1:]]) == EXIT_BAD_INPUT
    captured = capsys.readouterr()
    assert captured.out == ""  # refused before solving: nothing was computed and lost
    err = captured.err.strip()
    assert len(err.splitlines()) == 1 and needle.replace("{tmp}", str(tmp_path)) in err


def test_write_failure_after_the_solve_keeps_the_result(tmp_path, capsys, monkeypatch):
    """A file that becomes unwritable during the solve: the summary is printed first, then one
    line naming the path (exit 2)."""
    import fgc.app.cli

    out = tmp_path / "s.json"
    write_text = fgc.app.cli.Path.write_text

    def refuse(self, *args, **kwargs):
        if str(self) == str(out):
            raise PermissionError(13, "Permission denied", str(self))
        return write_text(self, *args, **kwargs)

    monkeypatch.setattr(fgc.app.cli.Path, "write_text", refuse)
    code = main(["simulate", str(EXAMPLES / "pose_graph.py"), "-p", "dataset=pose3example.txt",
                 "--precision", "float64", "--json", str(out)])
    assert code == EXIT_BAD_INPUT
    captured = capsys.readouterr()
    assert "fgc simulate: 5 variables" in captured.out
    # on a loaded machine the solve may take long enough to print progress lines first
    *progress, last = captured.err.strip().splitlines()
    assert all(": iteration " in line for line in progress), progress
    assert last == (f"fgc: error: {EXAMPLES / 'pose_graph.py'}: --json {out}: "
                    "cannot write the file: Permission denied")


def test_unexpected_error_is_one_line(monkeypatch, capsys):
    import fgc.app.run_report

    def broken(*args, **kwargs):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(fgc.app.run_report, "simulate_report", broken)
    monkeypatch.delenv("FGC_TRACEBACK", raising=False)
    code = main(["simulate", str(EXAMPLES / "pose_graph.py"), "-p", "dataset=pose3example.txt"])
    assert code == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "internal error" in err and "ZeroDivisionError: float division by zero" in err
