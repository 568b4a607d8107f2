"""The on-chip stream's price (backends/hls/plan/stream.py): one design plan whose stream section's
loops are phases priced by ``plan_cost``, and the QR steps of an update on the rows non-zero in
it — a slot the update does not reach passes its parent rows that are zero in value, which the
Evaluate unit skips (measured against the counting C simulation by bench/bench_stream_cycles.py:
paper A's setting 0.989 … 1.010 per update, the batch steps included). No C simulation here."""

from __future__ import annotations

import numpy as np
import pytest

from fgc.app.specs import example
from fgc.app.streaming import compile_stream
from fgc.compiler.stream import stream_program
from fgc_backends.hls.config import HlsConfig
from fgc_backends.hls.plan import phase_cycles, plan_cost
from fgc_backends.hls.plan.stream import WindowUpdateModel, _zero_passed_rows, qr_solve_phases
from fgc_backends.hls.streaming import layout_of


def test_a_step_with_nothing_on_its_separator_passes_zero_rows():
    # frontal 2, separator 2: row 2 reaches the separator, so the first passed row is not zero;
    # the step has no fourth row, so the second is
    pattern = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [1, 0, 1, 1]], dtype=bool)
    assert _zero_passed_rows(pattern, 2, 2) == [False, True]
    # the fill of column 0 carries row 2's separator entries into row 0, not into row 1
    assert _zero_passed_rows(np.eye(2, 4, dtype=bool), 2, 2) == [True, True]
    dense = np.triu(np.ones((4, 4), dtype=bool))
    assert _zero_passed_rows(dense, 2, 2) == [False, False]


@pytest.fixture(scope="module")
def paper_a_n7():
    """Paper A's policy at N = 7 (K = 3, a batch step at keyframe 4), float design."""
    graph = example("lio").build(N=7)
    program = compile_stream(graph, incremental=3, batch_every=(4,), name="lio_k")
    layout = layout_of(stream_program(graph, program, None))
    return layout, WindowUpdateModel(layout, HlsConfig(scalar="float"))


def test_every_stream_figure_is_plan_cost_of_a_phase_of_the_design(paper_a_n7):
    _, model = paper_a_n7
    design = model.design_plan()
    stream = [ph for ph in design.phases if ph.per == "stream"]
    assert stream and all(ph.name.startswith("stream_") for ph in stream)
    assert {ph.name: phase_cycles(ph) for ph in stream} == {
        name: c for name, c in plan_cost(design).other_cycles if name.startswith("stream_")}
    # the design's resources are its kernels' and memories', whatever phases it runs
    assert plan_cost(design).dsp == model.resources()["dsp"]
    price = model.price(5, 2)  # the window holds keyframes 3 … 5: three kept below it
    assert price.term("kept_walk").each == (model.stream["stream_kept_walk_base"]
                                            + 3 * model.stream["stream_kept_walk_each"])
    assert price.term("x_out").each == model.stream["stream_x_out"]


def test_the_slots_a_batch_step_does_not_reach_cost_only_their_own_rows(paper_a_n7):
    _, model = paper_a_n7
    b, sets = model.batch["layout"], model.batch["sets"]
    assert b.size == 5 and sets == 1  # serial: one step a level, slot by slot

    def per_slot(j, unit=True):
        zero = b.zero_factors(j) if unit else b.zero_factors(j) - b.unit_factors(j)
        return [phase_cycles(ph) for ph in qr_solve_phases(
            b.template, zero, True, sets, model.les, unit=b.unit_factors(j) if unit else
            frozenset())]

    steps = [per_slot(j) for j in range(b.size)]
    for s in range(1, b.size - 1):
        # a held slot costs its own rows (its identity prior, its √μ rows), whatever the slots
        # before it passed (zero rows: they hold nothing on it), less than once it arrived
        held = {steps[j][s] for j in range(s)}
        assert len(held) == 1 and held.pop() < steps[s][s]
    # priced as structure (dense new factors, dense priors) the held slots cost more
    assert sum(per_slot(1, unit=False)) > sum(steps[1])
    # nothing held: the step's QR is the plan's, and with nothing masked the window's too
    assert sum(steps[-1]) == sum(per_slot(b.size - 1, unit=False))
    assert model.qr_cycles(frozenset(), True) == model.group["qr"]
