"""The command line: verify against GTSAM end to end, and bad input → one line, exit code 2."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from fgc.cli import EXIT_BAD_INPUT, EXIT_OK, main

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


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
