"""bench/bench_solve_path.py's traces: its trace lines go into copies of the emitted simulator
and design at anchors that must still be there, and each trace must be the run it traces (one
LIN line a linearisation the result counts, the tries in order of μ).

imu_window N = 4, LM, float32 Cholesky, #CPE 5: the simulator and one small C simulation.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends.cfamily.results import read_result
from fgc_backends.hls import HlsConfig

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "bench"))
import bench_solve_path as path  # noqa: E402


def _check(its: list[dict], iterations: int) -> None:
    assert len(its) == iterations
    assert [it["it"] for it in its] == list(range(1, iterations + 1))
    for it in its:
        mus = [mu for mu, _ in it["tries"]]
        assert mus == sorted(mus)  # LM grows μ between the tries of one linearisation
        # every try but the last of a linearisation failed (not PD, or a rejected trial)
        for _, what in it["tries"][:-1]:
            assert what == "npd" or what[2] >= it["cost"]


@pytest.mark.heavy  # a simulator run and a C simulation build (about 90 s on 2 cores)
def test_both_traces_are_their_runs(tmp_path):
    graph = example("imu_window").build(N=4)
    program = compile_graph(graph, SolverConfig(method="lm", linear="cholesky", cpe=5,
                                                precision="float32"), name="path")
    data = problem_data(graph, program)
    (tmp_path / "sim").mkdir()
    lines, result = path.sim_trace(program, data, tmp_path / "sim")
    its = path.iterations(lines)
    assert its and its[0]["cost"] == result["initial_error"]
    _check(its, result["iterations"])
    lines, file = path.csim_trace(program, data, HlsConfig(scalar="float"), tmp_path / "hls")
    _check(path.iterations(lines), read_result(file, program, data, "float").iterations)


def test_a_missing_anchor_stops_the_bench(tmp_path):
    target = tmp_path / "f.h"
    target.write_text("int a;\n")
    try:
        path._insert(target, "int b;", "x")
    except SystemExit as exc:
        assert "anchor" in str(exc)
    else:
        raise AssertionError("no stop")
    path._insert(target, "int a;", "\nint c;")
    assert target.read_text() == "int a;\nint c;\n"
