"""The one-step update's marginal beside its back-substitution (fgc_stream.h's
``spec_tau_task`` beside ``spec_keep_task``, docs/hls.md "The marginal beside the
back-substitution"): under the one-step policy the store is the update's own factorisation
whenever its step is taken, so τ and the leaving keyframe's conditional are formed beside the
slots, the state update and the cost at X_TRIAL, staged, and moved into place
(``out_beside_commit``) only once the cost says the step is taken; a step not taken drops
them and runs the marginal as before.

- the model (no C simulation): a taken step prices the marginal beside the back-substitution
  and the two moves beside the call's reads of X; a step not taken, and LM to convergence,
  price the marginal after the window's region as before; the speculation's operators (one
  more τ and one more kept scale call site) are in the design's resources;
- heavy: a stream whose step is not finite (keyframe 4's GPS measurement 1e154 m off: the cost
  at X is finite, at X_TRIAL it overflows, in double as in the simulator), double design, one C
  simulation of the whole stream: every update's status, iterations and cost are the
  simulator's, its estimates within 1e-8 of the simulator's, and the design's outputs are bit
  for bit those of the same design with the speculation never armed (the marginal after the
  window's region on every update) — on this stream whose keyframes 4 and 5 drop it. (The
  drop itself changes no output here: under the one-step policy the store is at the update's
  start whether or not the step is taken, and the marginal's leaf step there reproduces the
  solve's slot 0 step bit for bit on this stream — a design that commits the speculation of a
  refused step gives the same outputs; the drop keeps the design exactly the one before it
  wherever the two steps' rounding would differ.)
"""

from __future__ import annotations

import numpy as np
import pytest

from fgc.app.specs import example
from fgc.app.streaming import compile_stream, keyframe_result, one_step_solver, run_stream
from fgc.compiler.stream import stream_program
from fgc.ir.datafile import problem_data
from fgc_backends.hls.config import HlsConfig
from fgc_backends.hls.plan import plan_cost
from fgc_backends.hls.plan.stream import WindowUpdateModel
from fgc_backends.hls.streaming import OnChipIncrementalStream, layout_of

SIM_TOL = 1e-8  # double design vs simulator, tangent-space distance per variable
BAD = 1e154  # keyframe 4's GPS x: its cost at X below double's overflow, at X_TRIAL above


def test_a_taken_step_prices_the_marginal_beside_the_back_substitution():
    graph = example("lio").build(N=7)
    program = compile_stream(graph, one_step_solver(), incremental=3, name="lio_spec")
    layout = layout_of(stream_program(graph, program, None))
    assert layout.spec
    model = WindowUpdateModel(layout, HlsConfig(scalar="float"))
    st = model.stream
    took = model.price(5, 1, status="max_iterations")
    names = {t.name for t in took.terms}
    assert {"spec_beside_backsub", "tau_commit", "keep_commit", "out_beside_commit"} <= names
    assert not {"keep_beside_tau", "out_beside_sign"} & names
    # the speculation's two processes beside each other (τ; the kept conditional), each its
    # loops one after another, beside the region's others: hidden but what runs past them
    assert st["stream_spec_tau"] == st["stream_marginal_reused"]
    assert st["stream_spec_keep"] == st["stream_kept_store"]
    spec = max(st["stream_marginal_reused"], st["stream_kept_store"])
    assert spec < st["stream_marginal_reused"] + st["stream_kept_store"]
    over = max(0, spec - model.group["backsub"])
    # (the terms marginal and kept_store count both whole: all hidden but what runs past)
    whole = st["stream_marginal_reused"] + st["stream_kept_store"]
    assert took.term("spec_beside_backsub").cycles == -(whole - over)
    out = st["stream_x_out"] + st["stream_kept_slot0"]
    moves = [st["stream_tau_commit"], st["stream_keep_commit"], out]
    assert took.term("out_beside_commit").cycles == -(sum(moves) - max(moves))
    # a step not taken (converged on its gradient: the leaf step runs): the marginal after the
    # window's region, as before
    none = model.price(5, 1)
    assert "keep_beside_tau" in {t.name for t in none.terms}
    assert "spec_beside_backsub" not in {t.name for t in none.terms}
    assert took.cycles < none.cycles
    # its operators: one more call site of τ's and of the kept scale's, the window kernel's
    # (its top instantiates them: spec_tau_task, spec_keep_task), priced in that part
    res = model.resources()
    units = res["units"]["stream section"]
    window = res["units"]["window kernel"]
    lm = WindowUpdateModel(layout_of(stream_program(
        graph, compile_stream(graph, incremental=3, name="lio_lm"), None)),
        HlsConfig(scalar="float"))
    assert not lm.spec
    assert "spec_beside_backsub" not in {t.name for t in lm.price(5, 2).terms}
    lm_units = lm.resources()["units"]["stream section"]
    assert units["stream_write_tau"] == lm_units["stream_write_tau"] == window["spec_write_tau"]
    assert units["stream_kept_scale"] == lm_units["stream_kept_scale"] == window["spec_kept_scale"]
    assert "spec_write_tau" not in lm.resources()["units"]["window kernel"]
    assert res["parts"]["window kernel"][0] == plan_cost(model.plan).dsp + sum(
        d for name, d in window.items() if name.startswith("spec_"))


def _bad_graph(n: int):
    graph = example("lio").build(N=n)
    (gps,) = [f for f in graph.factors if f.type.name == "GPSFactor" and f.keys == ("x4",)]
    gps.measured["position"] = np.array([BAD, 0.0, 0.0])
    return graph


@pytest.fixture(scope="module")
def not_finite(tmp_path_factory):
    graph = _bad_graph(6)
    program = compile_stream(graph, one_step_solver(), incremental=3, name="lio_nf")
    data = problem_data(graph, program)
    sim = []
    with np.errstate(over="ignore", invalid="ignore"):
        run_stream(program, data, None, sim.append)
    stream = OnChipIncrementalStream(graph, program, "double",
                                     out_dir=tmp_path_factory.mktemp("spec"))
    return graph, program, data, sim, stream, stream.run(data)


def _variant(not_finite, tmp_path, old: str, new: str, file: str):
    graph, program, data, _, _, _ = not_finite
    other = OnChipIncrementalStream(graph, program, "double", out_dir=tmp_path)
    path = other.project.directory / file.format(name=other.project.name)
    text = path.read_text()
    patched = text.replace(old, new)
    assert patched != text
    path.write_text(patched)
    # the Makefile's objects do not list the headers: rebuild the kernel's
    (other.project.directory / f"{other.project.name}.o").unlink(missing_ok=True)
    return other.run(data)


def _outputs(csim) -> list:
    return [(u["iterations"], u["status"], u["reason"], u["cost"], u["marginal"],
             [None if v is None else list(v) for v in u["values"]]) for u in csim.updates]


@pytest.mark.heavy
def test_a_step_not_taken_reports_the_simulators_status_and_cost(not_finite):
    _, program, _, sim, _, csim = not_finite
    assert [u.status for u in sim] == ["converged", "max_iterations", "max_iterations",
                                       "max_iterations", "failed", "failed"]
    for record, expected in zip(csim.updates, sim, strict=True):
        update = keyframe_result(program, record)
        assert (update.keyframe, update.iterations, update.status) == (
            expected.keyframe, expected.iterations, expected.status)
        assert update.cost == pytest.approx(expected.cost, rel=1e-9, abs=1e-30)
        assert set(update.values) == set(expected.values)
        for k, v in update.values.items():
            assert float(np.linalg.norm(expected.values[k].local(v))) <= SIM_TOL
    assert all(u["marginal"] for u in csim.updates[2:])


@pytest.mark.heavy
def test_the_speculation_changes_no_output(not_finite, tmp_path):
    # the same design with the speculation never armed: the marginal after the window's
    # region on every update, as before it
    *_, csim = not_finite
    plain = _variant(not_finite, tmp_path, "SPEC_ON = SPEC_ARMED && !at_x;",
                     "SPEC_ON = false;", "{name}.cpp")
    assert _outputs(plain) == _outputs(csim)
