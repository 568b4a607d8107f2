"""Streaming (issue 19, simulator side): the fixed-lag window against GTSAM after every keyframe,
the CLI's --incremental / --batch-every / --window and ``fgc stream``, the refusal of the
backends that run batch solves only, the ``fgc.stream`` API.

Fixed-lag tolerances (LIO, W = 3): against ``gtsam.ISAM2`` run with the same policy (keyframes
before the window held, the factors across its edge kept linear where they were marginalised:
:func:`fgc.interop.oracles.isam2_per_keyframe`) every window variable agrees to 1e-6 after every
keyframe (measured 1.8e-7, N = 12: fgc's LM stopping at a 1e-12 relative cost decrease).
Against ``gtsam.BatchFixedLagSmoother`` (lag W − 1, timestamps = keyframe index) the estimates
agree to 1e-9 until the first keyframe is marginalised (measured 1e-14) and to 5e-2 after it
(measured 9.4e-3). Not proven, but the evidence points at GTSAM's LM stopping short: its marginal
LinearContainerFactor is relinearised with Jacobian A, not the derivative A·J of its error, so LM
stalls along weakly observed directions (velocities, biases); the same window built by hand and
solved by GTSAM's standard LM lands 9e-5 from fgc, the smoother's own LM loop 6e-3.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import fgc
import fgc.frontend.factors
from fgc.app.cli import main
from fgc.app.specs import example  # noqa: E402
from fgc.app.streaming import HW_REFUSAL, compile_stream, run_stream
from fgc.interop import oracles
from fgc.interop.to_gtsam import to_gtsam
from fgc.ir.datafile import problem_data

lio = example("lio")

ROOT = Path(__file__).resolve().parents[2]
LIO = str(ROOT / "examples" / "lio.py")


W = 3


@pytest.fixture(scope="module")
def lio8():
    graph = lio.build(N=8)
    program = compile_stream(graph, window=W)
    return graph, program, to_gtsam(graph)


@pytest.fixture(scope="module")
def fixed_lag(lio8):
    graph, program, _ = lio8
    return run_stream(program, problem_data(graph, program), window=W)


def test_fixed_lag_window_holds_w_keyframes_and_marginalises_the_oldest(lio8, fixed_lag):
    graph, program, _ = lio8
    assert fixed_lag.converged and len(fixed_lag.updates) == 8
    clusters = program.schedule.clusters
    for u in fixed_lag.updates:
        j = u["keyframe"]
        assert u["mode"] == "fixed-lag" and u["first"] == max(0, j - W)
        held = {k for c in clusters[max(0, j - W + 1):j + 1] for k in c}
        assert set(u["values"]) == held
        assert u["seconds"] > 0


def test_fixed_lag_matches_isam2_with_the_same_policy_after_every_keyframe(lio8, fixed_lag):
    graph, program, problem = lio8
    clusters = program.schedule.clusters
    windows = [(u["first"], False) for u in fixed_lag.updates]
    isam = oracles.isam2_per_keyframe(graph, problem, clusters, windows)
    isam = [{k: e[k] for k in u["values"]} for u, e in zip(fixed_lag.updates, isam, strict=True)]
    same = oracles.per_keyframe_distance(fixed_lag.updates, isam)
    assert max(same) <= 1e-6, same
    # the comparison can fail: plain ISAM2 (no marginalisation, everything relinearised) is
    # the batch optimum of the graph so far, which the window's marginal priors do not reach
    plain = oracles.isam2_per_keyframe(graph, problem, clusters, None)
    plain = [{k: e[k] for k in u["values"]} for u, e in zip(fixed_lag.updates, plain,
                                                            strict=True)]
    assert max(oracles.per_keyframe_distance(fixed_lag.updates, plain)) > 1e-3


def test_fixed_lag_against_gtsam_batch_fixed_lag_smoother(lio8, fixed_lag):
    graph, program, problem = lio8
    smoother = oracles.fixed_lag_per_keyframe(graph, problem, program.schedule.clusters, W,
                                              "batch")
    dist = oracles.per_keyframe_distance(fixed_lag.updates, smoother)
    assert max(dist[:W + 1]) <= 1e-9, dist  # nothing marginalised yet
    assert max(dist) <= 5e-2, dist


ONE_STEP_TOL = 1e-5  # one-step stream vs one-update ISAM2, incremental: tangent distance


@pytest.mark.parametrize("mode", ["incremental", "fixed-lag"])
def test_one_step_policy_is_one_isam2_update_per_keyframe(lio8, mode):
    """ISAM2's policy (one Gauss-Newton step an update, ``one_step_solver``; the store the
    step's own factorisation at its linearisation point) against ``gtsam.ISAM2`` fed one
    update per keyframe with the same window (older keyframes held, the factors across the
    window's edge linear at ISAM2's linearisation point): the fixed-lag window within 1e-8
    (measured 3.6e-10, LIO N = 8, W = 3), the incremental plan (K = 3, batch at 3) within 1e-5
    (measured 2.5e-6: its kept conditional re-expressed to first order at the parent's new
    estimate, where ISAM2 re-eliminates it); ISAM2 settled to convergence per keyframe is
    far (> 1e-3): the comparison sees the policy."""
    from fgc.app.streaming import one_step_solver

    graph, _, problem = lio8
    if mode == "incremental":
        program = compile_stream(graph, one_step_solver(), incremental=3, batch_every=(3,))
        result = run_stream(program, problem_data(graph, program))
        windows = [(u["first"], u["mode"] == "batch") for u in result.updates]
        tol = ONE_STEP_TOL
    else:
        program = compile_stream(graph, one_step_solver(), window=W)
        result = run_stream(program, problem_data(graph, program), window=W)
        windows = [(u["first"], False) for u in result.updates]
        tol = 1e-8
    assert [u["iterations"] for u in result.updates] == [1] * 8
    assert {u["status"] for u in result.updates[1:]} == {"max_iterations"}

    def distances(settle):
        isam = oracles.isam2_per_keyframe(graph, problem, program.schedule.clusters, windows,
                                          settle=settle)
        isam = [{k: e[k] for k in u["values"]}
                for u, e in zip(result.updates, isam, strict=True)]
        return oracles.per_keyframe_distance(result.updates, isam)

    same = distances(False)
    assert max(same) <= tol, same
    assert max(same[4:]) > 0.0
    assert max(distances(True)) > 1e-3


def test_a_graph_that_is_not_a_chain_is_refused():
    graph = lio.build(N=5)
    graph.add(fgc.factors.BetweenFactor("x0", "x3", fgc.Pose3(), fgc.noise.isotropic(6, 1)))
    with pytest.raises(fgc.FgcError, match="streaming needs a chain of keyframes"):
        compile_stream(graph, window=2)


def test_stream_api_yields_each_keyframe_as_it_is_done():
    graph = lio.build(N=5)
    results = list(fgc.stream(graph, window=2))
    assert [r.keyframe for r in results] == list(range(5))
    assert [r.first for r in results] == [0, 0, 0, 1, 2]
    assert all(r.status == "converged" and r.seconds > 0 for r in results)


# --------------------------------------------------------------------------------------------
# command line
# --------------------------------------------------------------------------------------------


def test_cli_stream_writes_tum_and_accuracy(tmp_path, capsys):
    tum, out = tmp_path / "stream.tum", tmp_path / "stream.json"
    rc = main(["stream", LIO, "-p", "N=6", "--window", "2", "--tum", str(tum),
               "--json", str(out)])
    text = capsys.readouterr().out
    assert rc == 0, text
    assert "keyframe    5 (fixed-lag, from 3)" in text and "(simulator wall time)" in text
    assert "ms (model estimate, 3-keyframe chain)" in text  # W + 1 keyframes re-eliminated
    assert "accelerator plan per update (model estimate)" in text
    lines = tum.read_text().splitlines()
    assert len(lines) == 6 and all(len(line.split()) == 8 for line in lines)
    report = json.loads(out.read_text())
    assert len(report["updates"]) == 6 and report["mode"] == "fixed-lag"
    ate = report["accuracy_vs_batch_optimum"]["final"]["translation"]["rmse"]
    assert 0 < ate < 1.0


def test_cli_verify_incremental_matches_isam2_per_keyframe(capsys):
    rc = main(["verify", LIO, "-p", "N=6", "--incremental", "2", "--batch-every", "3,"])
    text = capsys.readouterr().out
    assert rc == 0, text
    assert "batch steps 3" in text and "gtsam.ISAM2" in text and "PASSED" in text


def test_cli_verify_one_step_policy_against_one_isam2_update_per_keyframe(capsys):
    """``--solver gn --max-iterations 1``: the one-step policy, judged against one ISAM2 update
    per keyframe (tolerance 1e-5); its updates end at the iteration limit by design."""
    rc = main(["verify", LIO, "-p", "N=6", "--incremental", "3", "--batch-every", "3,",
               "--solver", "gn", "--max-iterations", "1"])
    text = capsys.readouterr().out
    assert rc == 0, text
    assert "one update per keyframe" in text and "ran its one step" in text
    assert "tolerance 1e-05" in text
    # fgc stream: the iteration limit is the policy's end, not a failure
    assert main(["stream", LIO, "-p", "N=5", "--incremental", "3", "--solver", "gn",
                 "--max-iterations", "1", "-q"]) == 0


def test_cli_simulate_incremental(capsys):
    rc = main(["simulate", LIO, "-p", "N=5", "--incremental", "2", "-q"])
    text = capsys.readouterr().out
    assert rc == 0 and text.startswith("fgc stream"), text


@pytest.mark.parametrize("argv", [
    ["run", LIO, "--backend", "native", "--incremental", "3"],
    ["compile", LIO, "--backend", "native", "--out", "unused", "--incremental", "3"],
])
def test_cli_refuses_incremental_on_hls_and_native(argv, capsys):
    rc = main(argv)
    err = capsys.readouterr().err
    assert rc == 2
    assert HW_REFUSAL in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("argv, message", [
    (["stream", LIO, "--window", "3", "--incremental", "2"], "excludes"),
    (["stream", LIO, "--batch-every", "5"], "needs --incremental"),
    (["stream", LIO, "--window", "0"], "not a positive integer"),
    (["compile", LIO, "-p", "N=4", "--incremental", "2", "--batch-every", "9,", "--out",
      "unused"], "batch steps [9] lie outside"),
])
def test_cli_bad_streaming_options(argv, message, capsys):
    assert main(argv) == 2
    assert message in capsys.readouterr().err


def test_cli_stream_without_a_mode_is_refused(capsys):
    assert main(["stream", LIO, "-p", "N=4"]) == 2
    assert "--incremental K or --window W" in capsys.readouterr().err


def test_fixed_lag_distance_helper_is_discriminating():
    a = {"x": fgc.Vector3(np.zeros(3))}
    b = {"x": fgc.Vector3(np.ones(3))}
    assert oracles.per_keyframe_distance([{"values": a}], [b]) == [pytest.approx(np.sqrt(3))]


@pytest.mark.heavy
def test_lio_400_keyframes_streamed_through_a_window_of_30():
    """Issue 19's real-data stream: 400 KITTI keyframes, fixed-lag W = 30; every update
    converges and holds the newest 30 keyframes. Against the batch optimum, measured ATE rmse
    1.21 m for the final (frozen) trajectory and 5.37 m online — plain ISAM2's online estimate
    is 5.37 m away too (bench/bench_stream.py): a keyframe's estimate on arrival has only its
    own GPS fix ahead of the IMU prediction; bounds 2 m and 6 m."""
    from fgc.app import streaming
    graph = lio.build(N=400)
    program = compile_stream(graph, window=30)
    online = {}
    result = run_stream(program, problem_data(graph, program), 30,
                        lambda u: online.update(u.newest(program)))
    assert result.converged and len(result.updates) == 400
    assert all(u["first"] == max(0, u["keyframe"] - 30) for u in result.updates)
    final = {str(k): v for k, v in result.values.items()}
    acc = streaming.accuracy(graph, final, online, streaming.batch_optimum(graph))
    assert acc["final"]["translation"]["rmse"] < 2.0, acc
    assert acc["online"]["translation"]["rmse"] < 6.0, acc
