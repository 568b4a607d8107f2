"""Streaming on the HLS design's C simulation (issue 19: fgc_backends.hls.stream): the template
window emitted once, its testbench re-run per keyframe on that update's numbers, the kept Bayes
net on the host.

- the incremental plan on the double design agrees with the simulator's after every keyframe to
  1e-8 in the tangent space (measured 1.0e-9 on LIO N = 8, K = 3 and K = 4: τ's Jacobian, exact
  in the compiled code and by central differences in the simulator), with the same iteration
  counts; a corrupted kept conditional is caught;
- heavy: the float design within 1 cm / 1 mrad of the simulator per keyframe (measured 5.1e-5
  in the tangent space, K = 3, batch at 3); the fixed-lag window on the double design; ``fgc
  stream --backend hls`` runs the C simulation and prints the update model beside it.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from fgc.app.cli import main
from fgc.app.specs import example
from fgc.app.streaming import compile_stream, keyframe_result, run_stream
from fgc.ir.datafile import problem_data
from fgc_backends.hls.stream import CsimFixedLagStream, incremental_stream
from fgc_backends.native.stream import WindowSolver

STREAM_TOL = 1e-8  # double design vs simulator, tangent-space distance per variable
LIO = str(Path(__file__).resolve().parent.parent / "examples" / "lio.py")


def _distances(program, stream_result, sim_updates):
    out = []
    for record, expected in zip(stream_result.updates, sim_updates, strict=True):
        update = keyframe_result(program, record)
        assert (update.keyframe, update.mode, update.first) == (expected.keyframe, expected.mode,
                                                                expected.first)
        assert set(update.values) == set(expected.values)
        out.append(max(float(np.linalg.norm(expected.values[k].local(v)))
                       for k, v in update.values.items()))
    assert len(out) == len(sim_updates)
    return out


@pytest.fixture(scope="module")
def lio8():
    """LIO N = 8, K = 4: one 4-keyframe template, emitted and built once."""
    graph = example("lio").build(N=8)
    program = compile_stream(graph, incremental=4)
    data = problem_data(graph, program)
    sim_updates = []
    run_stream(program, data, None, sim_updates.append)
    stream = incremental_stream(graph, program, "double")
    return program, data, sim_updates, stream, stream.run(data)


def test_hls_csim_incremental_agrees_with_the_simulator_after_every_keyframe(lio8):
    program, _, sim_updates, stream, csim = lio8
    assert stream.sizes == [4] and csim.status == "converged"
    assert [r["iterations"] for r in csim.updates] == [u.iterations for u in sim_updates]
    dist = _distances(program, csim, sim_updates)
    assert max(dist) <= STREAM_TOL, dist
    assert max(dist[4:]) > 0.0  # the testbench and the host, not the simulator read twice


def test_a_corrupted_kept_conditional_is_caught_on_the_csim_path(lio8, monkeypatch):
    program, data, sim_updates, stream, _ = lio8
    eliminate = WindowSolver.eliminate

    def corrupted(self, x, d, count, pass_last=False):
        conds, passed = eliminate(self, x, d, count, pass_last)
        r, s, dv = conds[0]
        conds[0] = (r, s, dv + 1e-4)
        return conds, passed

    monkeypatch.setattr(WindowSolver, "eliminate", corrupted)
    dist = _distances(program, stream.run(data), sim_updates)
    assert max(dist) > 100 * STREAM_TOL


@pytest.mark.heavy
def test_hls_csim_float_design_within_a_centimetre_and_a_milliradian():
    """The float design (the hardware's scalar) on paper A's K = 3 with a batch step: every
    keyframe's estimate within 1 cm and 1 mrad of the double simulator's (each tangent
    component: rotation in rad, translation in m, the other variables as they come)."""
    graph = example("lio").build(N=8)
    program = compile_stream(graph, incremental=3, batch_every=(3,))
    data = problem_data(graph, program)
    sim_updates = []
    run_stream(program, data, None, sim_updates.append)
    csim = incremental_stream(graph, program, "float").run(data)
    assert csim.status == "converged"
    worst = 0.0
    for record, expected in zip(csim.updates, sim_updates, strict=True):
        for k, v in keyframe_result(program, record).values.items():
            worst = max(worst, float(np.max(np.abs(expected.values[k].local(v)))))
    assert 0.0 < worst <= 1e-3


@pytest.mark.heavy
def test_hls_csim_fixed_lag_agrees_with_the_simulator():
    graph = example("lio").build(N=8)
    program = compile_stream(graph, window=3)
    data = problem_data(graph, program)
    sim_updates = []
    run_stream(program, data, 3, sim_updates.append)
    csim = CsimFixedLagStream(graph, program, 3, "double").run(data)
    assert csim.status == "converged"
    assert max(_distances(program, csim, sim_updates)) <= STREAM_TOL


@pytest.mark.heavy
def test_cli_stream_backend_hls_runs_the_c_simulation(tmp_path, capsys):
    out = tmp_path / "stream.json"
    assert main(["stream", LIO, "-p", "N=6", "--incremental", "3", "--backend", "hls",
                 "--json", str(out)]) == 0
    text = capsys.readouterr().out
    assert "compiling the HLS C simulation's 3-keyframe template window" in text
    assert "(HLS C simulation wall time)" in text and "kept on the host, not on chip" in text
    assert "ms assumed (model estimate" in text
    report = json.loads(out.read_text())
    assert report["solved_by"] == "HLS C simulation" and len(report["model_estimate"]) == 6
    assert report["csim_update_time"]["updates"] == 6
