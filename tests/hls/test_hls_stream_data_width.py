"""The streaming top's data port two float words a beat (``HlsConfig.data_width = 64``, issue 33:
the update's start off the path; docs/hls.md, "The update's start off the path").

- the update's start with the window full takes the call's keyframe words two an iteration over
  DATA_BUF in 8 cyclic banks (window.py's ``start_plan(2)``): LIO's 557 moves, the newest
  prior's 137 tail words zeroed and the call's 242 words in 121 iterations (242 with a word a
  beat), each bank one read and one write, at most two keyframe words an iteration and in the
  call's order, DATA_BUF left as the moves one after another and then the keyframe leave it;
- the option is refused where it means nothing: another width, a double design, a design with no
  streaming top; the emitted top takes ``DataBeat`` words on its own m_axi bundle;
- heavy: paper A's design (n_u 4, two sets, two rows, the root in a wavefront; LIO N = 7, K = 3,
  a batch step at keyframe 4 swept through the window, float) with the 64-bit port: the counting
  C simulation within 2 % of the model on every update, the incremental update 113 cycles
  shorter than with a word a beat, every estimate within float's 1 cm / 1 mrad of the simulator;
  the host's words packed the other way round in each beat, or the update's start reading a
  beat's lanes the other way round, break the agreement.
"""

from __future__ import annotations

import dataclasses
import sys
from pathlib import Path

import numpy as np
import pytest

from fgc.app.specs import example
from fgc.app.streaming import compile_stream, keyframe_result, run_stream
from fgc_backends.hls import emit
from fgc_backends.hls.config import DesignOptions, HlsConfig, HlsConfigError
from fgc_backends.hls.emitter import emit as emit_layout
from fgc_backends.hls.window import WindowLayout, _check_start

FLOAT_TOL = 1e-2  # float design vs the double simulator: 1 cm / 1 mrad in the tangent space


@pytest.fixture(scope="module")
def lio6():
    graph = example("lio").build(N=6)
    program = compile_stream(graph, window=2, name="lio")
    return graph, program, WindowLayout(graph, program, 2)


def test_the_start_takes_two_keyframe_words_an_iteration(lio6):
    _, _, lay = lio6
    kf, moves = lay.kf_call, lay.start_moves()
    assert lay.start_plan(1) == (lay.start_banks, lay.start_rows, lay.sweep_rows)
    assert (lay.start_banks, len(lay.start_rows)) == (4, 242)  # a word a beat
    nb, rows, _ = lay.start_plan(2)
    writes = len(moves) + len(kf)
    assert (len(lay.data_moves), len(kf), nb, len(rows)) == (557, 242, 8, 121)
    assert len(rows) == -(-len(kf) // 2) and len(rows) >= -(-writes // nb)
    taken = []
    for row in rows:  # each bank one read and one write, at most two keyframe words, in order
        assert len(row) == nb
        words = sorted(s - nb for _, _, s in row if s is not None and s >= nb)
        assert words in ([], [0], [0, 1])
        taken += [w for _, w, s in sorted(row, key=lambda c: c[2] or 0)
                  if s is not None and s >= nb]
    assert taken == kf  # the call's order
    _check_start(moves, kf, lay.n_data, nb, rows)
    ctx = lay.start_context(2)
    assert (ctx["banks"], ctx["iterations"], ctx["words"]) == (8, 121, 2)
    # the sources: a bank (< 8), the iteration's first / second keyframe word (8, 9), zero (10)
    sources = {op >> 2 * ctx["row_bits"] for op in ctx["ops"]}
    assert sources <= set(range(11)) and {8, 9} <= sources


def test_the_option_is_refused_where_it_means_nothing(lio6, tmp_path):
    graph, program, lay = lio6
    with pytest.raises(HlsConfigError, match="data_width must be one of"):
        DesignOptions(data_width=48).check()
    with pytest.raises(HlsConfigError, match="two float words a beat"):
        HlsConfig(scalar="double", data_width=64).check()
    assert HlsConfig(data_width=64).data_words == 2 and HlsConfig().data_words == 1
    with pytest.raises(HlsConfigError, match="no streaming top"):
        emit(lay.template, tmp_path / "batch", HlsConfig(data_width=64))


@pytest.mark.heavy
def test_the_emitted_top_takes_beats_on_its_own_bundle(lio6, tmp_path):
    _, _, lay = lio6
    project = emit_layout(lay.template, tmp_path, HlsConfig(data_width=64), stream=lay)
    text = {p.name: p.read_text() for p in project.files}
    header = text[f"{project.name}.h"]
    assert "struct DataBeat {" in header and "const int DATA_BEAT = 2;" in header
    assert "const fgc::DataBeat data[fgc::STREAM_IN_BEATS]" in header
    cpp = text[f"{project.name}.cpp"]
    assert "#define FGC_DATA_BEAT" in cpp and "N_START = 121;" in cpp
    assert "#pragma HLS INTERFACE m_axi port=data offset=slave bundle=gmem1" in cpp
    assert "#pragma HLS AGGREGATE variable=data" in cpp
    assert "pack_data(words_in)" in text[f"tb_{project.name}.cpp"]


def _paper_a(n: int, data_width: int):
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
    from bench_stream_cycles import measure

    design = DesignOptions(root_wave=True, allocation=(("add", 8), ("mul", 12), ("div", 2)),
                           bind=(("add", "fabric"),), data_width=data_width)
    return measure(n, 3, "float", incremental=3, batch_every=(4,), one_step=True, qr_rows=2,
                   units=4, design=design)


def _distance(program, result, sim) -> float:
    worst = 0.0
    for record, expected in zip(result.updates, sim, strict=True):
        update = keyframe_result(program, record)
        worst = max(worst, max(float(np.linalg.norm(expected.values[k].local(v)))
                               for k, v in update.values.items()))
    return worst


@pytest.fixture(scope="module")
def paper_a64():
    graph, program, data, result, rows, stream = _paper_a(7, 64)
    sim = []
    run_stream(program, data, None, sim.append)
    return graph, program, data, result, rows, stream, sim


@pytest.mark.heavy
def test_two_words_a_beat_agree_with_the_simulator_and_the_model(paper_a64):
    _, program, _, result, rows, _, sim = paper_a64
    assert _distance(program, result, sim) <= FLOAT_TOL
    for record, cycles, price in rows:  # the counting C simulation = the plan, every update
        assert 0.98 <= cycles / price.cycles <= 1.02, (record["keyframe"], cycles, price.cycles)
    one = _paper_a(7, 32)[4]
    # the incremental updates once the window is full: the start's 242 + 1 cycles (the call's
    # words a word an iteration) -> X's moves, 130 (its words in 121 + 1)
    for (r2, _, p2), (_, _, p1) in zip(rows, one, strict=True):
        if r2["mode"] == "incremental" and r2["keyframe"] >= 3:
            assert p1.cycles - p2.cycles == 113
            assert p2.term("start_banks").each < p1.term("start_banks").each


@pytest.mark.heavy
def test_beats_packed_the_other_way_round_break_the_agreement(paper_a64, tmp_path):
    graph, program, data, _, _, stream, sim = paper_a64
    from fgc_backends.hls.streaming import OnChipIncrementalStream

    bad = OnChipIncrementalStream(graph, program, "float", out_dir=tmp_path,
                                  qr_rows=2, design=dataclasses.replace(
                                      stream.project.config.design, qr_rows=2))
    tb = bad.project.directory / f"tb_{bad.project.name}.cpp"
    text = tb.read_text()
    patched = text.replace(".lane_word[k % fgc::DATA_BEAT]",
                           ".lane_word[fgc::DATA_BEAT - 1 - k % fgc::DATA_BEAT]")
    assert patched != text
    tb.write_text(patched)
    try:
        result = bad.run(data)
    except Exception:  # noqa: BLE001 - a failure is as good as a disagreement here
        return
    assert _distance(program, result, sim) > 10 * FLOAT_TOL


@pytest.mark.heavy
def test_a_start_that_takes_a_beats_words_the_other_way_round_breaks_the_agreement(paper_a64,
                                                                                   tmp_path):
    # the host packs as it should; the update's start reads each beat's lanes swapped (the reset
    # and the window's filling read them right): the keyframes after the window is full go wrong
    graph, program, data, _, _, stream, sim = paper_a64
    from fgc_backends.hls.streaming import OnChipIncrementalStream

    bad = OnChipIncrementalStream(graph, program, "float", out_dir=tmp_path,
                                  qr_rows=2, design=dataclasses.replace(
                                      stream.project.config.design, qr_rows=2))
    header = bad.project.directory / "include" / "fgc_stream.h"
    text = header.read_text()
    patched = text.replace("const T b0 = beat.lane_word[0], b1 = beat.lane_word[1];",
                           "const T b0 = beat.lane_word[1], b1 = beat.lane_word[0];")
    assert patched != text
    header.write_text(patched)
    (bad.project.directory / f"{bad.project.name}.o").unlink(missing_ok=True)
    try:
        result = bad.run(data)
    except Exception:  # noqa: BLE001 - a failure is as good as a disagreement here
        return
    assert _distance(program, result, sim) > 10 * FLOAT_TOL
