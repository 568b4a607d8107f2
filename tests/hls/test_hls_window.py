"""The fixed-lag window on chip (issue 19: fgc_backends.hls.window): the design's ``<name>_stream``
top keeps the window between calls and takes one keyframe's words per call.

- the C simulation (double design, LIO N = 6, W = 2: the window fills, slides three times and
  marginalises four keyframes on the QR unit) agrees with the native fixed-lag stream, whose
  window is assembled and marginalised on the host, after every keyframe to 1e-10 in the tangent
  space (measured 1.6e-14 at N = 8, W = 3), with the same iteration counts; a wrong shift table
  breaks the agreement;
- a keyframe brings only its own words: the slot's factors and prior, far fewer than the window's;
- the update's start with the window full (the shift's words and the keyframe's in one loop over
  DATA_BUF's cyclic banks, window.py's _start_schedule) takes the keyframe's word an iteration
  (LIO: 557 moves, the newest prior's 137 tail words zeroed and the call's other 242 words in
  242 iterations over 4 banks) and leaves DATA_BUF as the moves one after another do; a table
  out of order is refused;
- the update model prices each call from the emitted plan: the shift once the window is full,
  the marginalisation when a keyframe leaves, the QR steps on the rows non-zero in the update
  (bench/bench_stream_cycles.py: within 0.988 … 0.998 of the counting C simulation per update
  at N = 8, W = 3); a Cholesky design is refused by name;
- ``fgc compile --backend hls --window W`` emits the streaming top as the synthesis top, with its
  testbench inputs; ``fgc stream --backend hls --window W`` runs it.
- paper A's incremental plan on chip (LIO N = 7, K = 3, a batch step at keyframe 4: keyframes
  kept as their conditionals in the design's memories and walked back every update, the batch
  step re-solved by the design's batch kernel, which rebuilds the kept net) agrees with the
  native incremental stream to 1e-8 (measured 1.9e-9 at N = 8, 2.7e-8 at paper A's N = 30) and
  with gtsam.ISAM2 fed the same keyframes with fgc's policy to 1e-6, after every keyframe; the
  model prices the batch step on the batch kernel's plan.
Heavy (tests/hls/test_hls_stream_csim.py): the fixed-lag window against GTSAM at W = 3.
"""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from fgc.app.cli import main
from fgc.app.specs import example
from fgc.app.streaming import compile_stream, keyframe_result
from fgc.interop import oracles
from fgc.interop.to_gtsam import to_gtsam
from fgc.ir.datafile import problem_data
from fgc_backends.hls.config import HlsConfig
from fgc_backends.hls.plan.stream import WindowUpdateModel
from fgc_backends.hls.streaming import OnChipFixedLagStream, OnChipIncrementalStream
from fgc_backends.hls.window import (
    OnChipWindowError,
    WindowLayout,
    _check_start,
    _start_schedule,
)
from fgc_backends.native.streaming import FixedLagStream, IncrementalStream

TOL = 1e-10  # tangent-space distance per variable, on-chip csim (double) vs native stream
# incremental: the kept conditional's re-expression differentiates Log by central differences
# (step 1.5e-7), whose rounding (eps / h ~ 1e-9) differs between two builds of the same formula
TOL_KEPT = 1e-8
ISAM2_TOL = 1e-6  # vs gtsam.ISAM2 fed the same keyframes with fgc's policy
LIO = str(Path(__file__).resolve().parents[2] / "examples" / "lio.py")


def _worst(program, a, b) -> float:
    worst = 0.0
    for ra, rb in zip(a.updates, b.updates, strict=True):
        ua, ub = keyframe_result(program, ra), keyframe_result(program, rb)
        assert (ua.keyframe, ua.first) == (ub.keyframe, ub.first)
        assert set(ua.values) == set(ub.values)
        worst = max(worst, max(float(np.linalg.norm(ub.values[k].local(v)))
                               for k, v in ua.values.items()))
    return worst


@pytest.fixture(scope="module")
def lio6(tmp_path_factory):
    graph = example("lio").build(N=6)
    program = compile_stream(graph, window=2, name="lio")  # as fgc stream names examples/lio.py
    data = problem_data(graph, program)
    stream = OnChipFixedLagStream(graph, program, 2, "double",
                                  out_dir=tmp_path_factory.mktemp("onchip"))
    return graph, program, data, stream, stream.run(data), FixedLagStream(graph, program, 2).run(
        data)


def test_on_chip_window_agrees_with_the_native_stream_after_every_keyframe(lio6):
    _, program, _, _, chip, native = lio6
    assert chip.status == "converged"
    assert [u["iterations"] for u in chip.updates] == [u["iterations"] for u in native.updates]
    assert _worst(program, chip, native) <= TOL
    # keyframes 2 … 5 fill the window: each then marginalises its oldest on the chip
    assert [u["marginal"] for u in chip.updates] == [False, False, True, True, True, True]


def test_a_keyframe_brings_only_its_own_words(lio6):
    _, _, _, stream, _, _ = lio6
    lay = stream.layout
    steady = len(lay.new_dest[-1])
    assert lay.kf_words == 21 and steady < lay.n_data / 2
    lines = (stream.project.directory / "stream.txt").read_text().splitlines()
    numbers = sum(int(line.split()[0]) for line in lines[2:])
    # (the window full: all but the newest prior's tail, which the start zeroes)
    assert numbers == sum(lay.kf_words + (len(lay.new_dest[j]) if j < 3 else len(lay.kf_call))
                          for j in range(6))
    assert len(lay.kf_call) + len(lay.kf_zero) == steady


def test_the_start_takes_a_keyframe_word_an_iteration(lio6):
    _, _, _, stream, _, _ = lio6
    lay = stream.layout
    kf, nb, moves = lay.kf_call, lay.start_banks, lay.start_moves()
    writes = len(moves) + len(kf)
    assert (len(lay.data_moves), len(lay.kf_zero), len(kf), nb) == (557, 137, 242, 4)
    assert len(lay.new_dest[-1]) == 379 and writes == 936
    # one keyframe word an iteration bounds it, the banks' write ports do not (936 / 4 = 234)
    assert len(lay.start_rows) == len(kf) > -(-writes // nb)
    for row in lay.start_rows:  # each bank one read and one write, at most one keyframe word
        assert len(row) == nb and sum(1 for _, _, s in row if s is not None and s >= nb) <= 1
    # two banks: two writes an iteration bound it (936 / 2 = 468)
    assert len(_start_schedule(moves, kf, 2)) == writes // 2
    # the call's keyframe in its order: a table whose iterations are swapped is refused
    rows = list(lay.start_rows)
    rows[0], rows[-1] = rows[-1], rows[0]
    with pytest.raises(OnChipWindowError, match="banked start"):
        _check_start(moves, kf, lay.n_data, nb, rows)
    # the newest prior's tail left as the shift leaves it (not zeroed) is refused
    with pytest.raises(OnChipWindowError, match="banked start"):
        _check_start(moves[:-1], kf, lay.n_data, nb, lay.start_rows)


def test_a_chain_of_moves_runs_in_one_iteration():
    # word 0 <- 1 <- 2 <- the keyframe's word, word 3 zeroed: one iteration over 4 banks (reads
    # before writes); two keyframe words an iteration only where asked for
    moves, kf = [(0, 1), (1, 2), (3, -2)], [2, 5]
    rows = _start_schedule(moves, kf, 4)
    assert len(rows) == 2 and [r[0] for r in rows[0][:3]] == [None, 1, 2]
    _check_start(moves, kf, 8, 4, rows)
    # (word 5's bank writes word 1 in the first iteration: the second keyframe word waits)
    assert [w for _, w, _ in rows[1]] == [None, 5, None, None]
    moves, kf = moves[:2], [2, 3]
    assert len(_start_schedule(moves, kf, 4)) == 2
    two = _start_schedule(moves, kf, 4, 2)
    assert len(two) == 1
    _check_start(moves, kf, 8, 4, two)
    with pytest.raises(OnChipWindowError, match="banked start"):
        _check_start(moves, kf, 8, 4, rows[::-1])


@pytest.mark.heavy
def test_a_wrong_shift_breaks_the_agreement(lio6, tmp_path):
    graph, program, data, _, _, native = lio6
    bad = OnChipFixedLagStream(graph, program, 2, "double", out_dir=tmp_path)
    cpp = bad.project.directory / "include" / "fgc_stream.h"  # the shift is the stream header's
    text = cpp.read_text()
    # the factors stay in their slots on a shift (the variables' move alone changes only
    # where LM starts: 9e-8 at the optimum)
    patched = text.replace("src < START_BANKS ? word[src] :",
                           "src < START_BANKS ? DATA_BUF[START_BANKS * to + c] :")
    assert patched != text
    cpp.write_text(patched)
    # the Makefile's objects do not list the headers: rebuild the kernel's from the patched one
    (bad.project.directory / f"{bad.project.name}.o").unlink(missing_ok=True)
    try:
        chip = bad.run(data)
    except Exception:  # noqa: BLE001 - a failure is as good as a disagreement here
        return
    assert _worst(program, chip, native) > 1e-3


def test_the_update_model_prices_the_calls_of_the_emitted_design(lio6):
    graph, program, _, stream, chip, _ = lio6
    model = WindowUpdateModel(stream.layout, HlsConfig(scalar="double"))
    prices = [model.price(u["keyframe"], u["iterations"]) for u in chip.updates]
    names = [{t.name for t in p.terms} for p in prices]
    assert all("shift" not in n for n in names[:3]) and all("shift" in n for n in names[3:])
    assert all("marginal" not in n for n in names[:2]) and all("marginal" in n for n in names[2:])
    assert all(not t.assumed for p in prices for t in p.terms)
    assert all(p.cycles > 0 and p.latency_ms > 0 for p in prices)
    # one more iteration costs one more iteration's phases
    one, two = model.price(4, 1), model.price(4, 2)
    assert two.cycles - one.cycles == sum(t.each for t in two.terms if t.name in model.group)
    # the QR steps on the rows non-zero in the update: fewer while the window fills
    assert model.price(1, 1).term("qr").each < model.price(4, 1).term("qr").each \
        <= model.group["qr"]


def test_a_cholesky_design_is_refused_by_name():
    graph = example("lio").build(N=4)
    program = compile_stream(graph, window=2)
    program = replace(program, solver=replace(program.solver, linear="cholesky"))
    with pytest.raises(OnChipWindowError, match="Cholesky"):
        WindowLayout(graph, program, 2)


def test_cli_compile_and_stream_the_on_chip_window(tmp_path, capsys):
    out = tmp_path / "w"
    assert main(["compile", LIO, "-p", "N=5", "--window", "2", "--backend", "hls",
                 "--scalar", "double", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    assert "on-chip fixed-lag window of 2 keyframes" in text
    tcl = (out / "run_hls.tcl").read_text()
    assert "set_top lio_window3_stream" in tcl and "--stream data.txt stream.txt" in tcl
    assert (out / "stream.txt").read_text().startswith("FGC-STREAM 1 ")
    # N = 6, W = 2: the fixture's template, whose built project the cache holds
    assert main(["stream", LIO, "-p", "N=6", "--window", "2", "--backend", "hls"]) == 0
    text = capsys.readouterr().out
    assert "on-chip design's C simulation" in text and "(model estimate, on chip)" in text


# --------------------------------------------------------------------------------------------
# the incremental plan on chip: the kept Bayes net in the design's memories
# --------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def lio7_paper_a(tmp_path_factory):
    """Paper A's policy at N = 7: K = 3, a batch step at keyframe 4 (the batch kernel holds
    keyframes 0 … 4), incremental updates before and after it."""
    graph = example("lio").build(N=7)
    program = compile_stream(graph, incremental=3, batch_every=(4,), name="lio_k")
    data = problem_data(graph, program)
    stream = OnChipIncrementalStream(graph, program, "double",
                                     out_dir=tmp_path_factory.mktemp("onchip_kept"))
    return graph, program, stream, stream.run(data), IncrementalStream(graph, program).run(data)


def test_on_chip_incremental_agrees_with_the_native_stream(lio7_paper_a):
    _, program, _, chip, native = lio7_paper_a
    assert chip.status == "converged"
    assert [(u["mode"], u["first"]) for u in chip.updates] == [
        ("incremental", 0), ("incremental", 0), ("incremental", 0), ("incremental", 1),
        ("batch", 0), ("incremental", 3), ("incremental", 4)]
    assert [u["iterations"] for u in chip.updates] == [u["iterations"] for u in native.updates]
    # every keyframe so far after every update: the kept ones as the on-chip walk (or the batch
    # kernel) left them
    assert [len(keyframe_result(program, u).values) for u in chip.updates] == [
        3 * (j + 1) for j in range(7)]
    assert _worst(program, chip, native) <= TOL_KEPT


def test_on_chip_incremental_against_isam2_with_the_same_policy(lio7_paper_a):
    graph, program, _, chip, _ = lio7_paper_a
    windows = [(u["first"], u["mode"] == "batch") for u in chip.updates]
    isam = oracles.isam2_per_keyframe(graph, to_gtsam(graph), program.schedule.clusters,
                                      windows)
    values = [{"values": keyframe_result(program, u).values} for u in chip.updates]
    dist = oracles.per_keyframe_distance(values, isam)
    assert len(dist) == 7 and max(dist) <= ISAM2_TOL, dist


def test_the_kept_estimates_asked_for_at_the_end_are_the_same(lio7_paper_a):
    """The walk through the kept conditionals is off the update's path (fgc_stream.h: op 3, or a
    batch step starting from stale estimates). Asked for only after the last update, the batch
    step at keyframe 4 walks the estimates keyframe 3's update left stale itself: every
    keyframe's estimate after the last update is the same to the bit as with the estimates
    asked for after every update (a batch step started from the stale ones would not be)."""
    graph, program, stream, chip, _ = lio7_paper_a
    end = stream.run(problem_data(graph, program), estimates_at_end=True)
    assert end.updates[-1]["values"] == chip.updates[-1]["values"]
    # the updates before it return the window's estimates, the kept ones as last returned
    assert [u["iterations"] for u in end.updates] == [u["iterations"] for u in chip.updates]


def test_the_model_prices_the_batch_step_on_the_batch_kernel(lio7_paper_a):
    _, _, stream, chip, _ = lio7_paper_a
    model = WindowUpdateModel(stream.layout, HlsConfig(scalar="double"))
    prices = [model.price(u["keyframe"], u["iterations"]) for u in chip.updates]
    assert [p.mode for p in prices] == [u["mode"] for u in chip.updates]
    batch = prices[4]
    names = {t.name for t in batch.terms}
    assert {"batch_gather", "batch_qr", "batch_store", "batch_out", "batch_kept"} <= names
    assert "qr" not in names  # the window does not solve
    # the batch step walks the kept estimates keyframe 3's update left stale (it starts from
    # them); an incremental update walks nothing, asking for the estimates does
    assert "kept_walk" in names and "kept_walk" not in {t.name for t in prices[5].terms}
    assert "kept_walk" in {t.name for t in model.price_estimates(5).terms}
    assert all(p.cycles > 0 for p in prices)



def _body(text: str, signature: str) -> str:
    """The body of the function whose definition starts with ``signature`` in ``text``."""
    start = text.index("{", text.index(signature))
    depth = 0
    for i in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        if depth == 0:
            return text[start + 1:i]
    raise AssertionError(f"{signature}: no closing brace")


def test_the_stream_section_is_the_static_header_and_the_kernel_only_wires_it(lio7_paper_a):
    """Issue 31 item 5: the streaming top and the batch kernel's entries hold no loop of their
    own, they call fgc_stream.h (configured by the kernels' StreamConfig); the header holds the
    stream section's loops and its memories."""
    _, _, stream, _, _ = lio7_paper_a
    folder, name = stream.project.directory, stream.project.name
    window = (folder / f"{name}.cpp").read_text()
    top = _body(window, f"void {name}_stream(")
    assert "for (" not in top and "fgc::stream_call<fgc::StreamConfig>(" in top
    assert "KEPT_R[" not in window and "BATCH_X[" not in window  # declared by the header
    batch_cpp = next(p for p in folder.glob("*.cpp")
                     if p.name not in (f"{name}.cpp", f"tb_{name}.cpp"))
    batch = batch_cpp.read_text()
    for entry in ("reset", "in", "solve"):
        body = _body(batch, f"void {batch_cpp.stem}_batch_{entry}(")
        assert "for (" not in body and f"fgc::batch_kernel_{entry}<fgc::StreamConfig>(" in body
    header = (folder / "include" / "fgc_stream.h").read_text()
    assert "void stream_call(" in header and "L KEPT_R[" in header

def test_a_cholesky_incremental_plan_stays_on_the_host():
    from fgc.app.streaming import on_chip, stream_program

    graph = example("lio").build(N=4)
    program = compile_stream(graph, incremental=2)
    assert on_chip(stream_program(graph, program))
    cholesky = replace(program, solver=replace(program.solver, linear="cholesky"))
    assert not on_chip(stream_program(graph, cholesky))


def test_cli_report_incremental_prices_the_on_chip_design(tmp_path, capsys):
    """``fgc report --incremental K``: the design fgc compile --backend hls emits for the
    stream (the on-chip incremental design), priced per update, with its DSP and BRAM."""
    out = tmp_path / "report.json"
    assert main(["report", LIO, "-p", "N=5", "--incremental", "2", "--batch-every", "3",
                 "--json", str(out)]) == 0
    text = capsys.readouterr().out
    assert text.startswith("fgc report") and "kept Bayes net on chip" in text
    assert "on-chip design:" in text and "batch kernel" in text
    report = json.loads(out.read_text())
    assert len(report["model_estimate"]) == 5 and report["on_chip_resources"]["dsp"] > 0
    assert main(["report", LIO, "-p", "N=5", "--incremental", "2", "--html",
                 str(tmp_path / "r.html")]) == 2


def test_the_on_chip_window_holds_a_prior_on_every_5th_keyframe():
    """The stream stage's template holds every factor any window holds (issue 34 item 7): the
    on-chip layout of a Pose2 chain with a prior on every 5th keyframe holds each window's
    factors after every call (check_holds, which refused it before), its priors on every slot."""
    from fgc import Graph, Pose2
    from fgc.compiler.stream import stream_program
    from fgc.frontend import noise
    from fgc.frontend.factors import BetweenFactor, PriorFactor
    from fgc_backends.hls.streaming import layout_of

    graph = Graph()
    for i in range(12):
        graph.add_variable(i, Pose2(float(i), 0.0, 0.0))
    for i in range(0, 12, 5):
        graph.add(PriorFactor(i, Pose2(float(i), 0.0, 0.0), noise.isotropic(3, 0.1)))
    for i in range(11):
        graph.add(BetweenFactor(i, i + 1, Pose2(1.0, 0.0, 0.0), noise.isotropic(3, 0.2)))
    program = compile_stream(graph, window=3)
    layout = layout_of(stream_program(graph, program, 3))
    priors = sorted(m.slots[0] for m in layout.members if m.kind.startswith("PriorFactor"))
    assert priors == [0, 1, 2, 3]
    held = None
    for j in range(12):
        held = layout.check_holds(held, j)
    assert sum(h is not None for h in held) == 4  # keyframes 8 … 11: 3 betweens, the prior on 10
