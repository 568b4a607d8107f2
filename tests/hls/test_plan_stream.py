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
from fgc_backends.hls.plan.model import PlanError
from fgc_backends.hls.plan.stream import (
    WindowUpdateModel,
    _zero_passed_rows,
    qr_solve_phases,
    step_patterns,
)
from fgc_backends.hls.streaming import layout_of
from fgc_backends.hls.units.qr import qr_unit_loops, reflection_lanes


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
    assert price.term("x_out").each == model.stream["stream_x_out"]
    # their estimates, asked for after the update (op 3): walked from slot 0, then out
    asked = model.price_estimates(5)
    assert asked.term("kept_walk").each == (model.stream["stream_kept_walk_base"]
                                            + 3 * model.stream["stream_kept_walk_each"])
    assert asked.term("x_kept_out").each == 3 * model.layout.kf_words + 1


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
        # a held slot costs its own rows (its identity prior, its √μ rows), whatever the held
        # slots before it passed (zero rows: they hold nothing on it), less than once it arrived;
        # the arrived slot just before it passes rows zero on its columns but for their
        # right-hand side (that slot's residual): the held step's last reflection takes them
        assert steps[s - 1][s] < steps[s][s]
        if s > 1:
            held = {steps[j][s] for j in range(s - 1)}
            assert len(held) == 1 and held.pop() < steps[s - 1][s]
    # priced as structure (dense new factors, dense priors) the held slots cost more
    assert sum(per_slot(1, unit=False)) > sum(steps[1])
    # nothing held: the step's QR is the plan's, and with nothing masked the window's too
    assert sum(steps[-1]) == sum(per_slot(b.size - 1, unit=False))
    assert model.qr_cycles(frozenset(), True) == model.group["qr"]


def test_a_step_prices_its_right_hand_side_only_on_rows_that_can_hold_one(paper_a_n7):
    """The right-hand side is priced by structure, not dense: a row without information (a
    factor the window does not hold, a child's zero passed row), a √μ row and a unit prior's
    row at its slot's reset value have a zero right-hand side, which the Evaluate skips (the
    counting C simulation keeps a row only if it is non-zero). Priced dense, keyframe 0 of the
    double N = 7 window with the root in a wavefront came out 0.974 of the count."""
    layout, model = paper_a_n7
    t = layout.template
    f = [st.frontal_dim for st in t.schedule.steps]

    def cycles(pattern, rhs, s):
        return sum(lp.cycles for lp in qr_unit_loops(pattern, f[s], 4, model.les, rhs=rhs))

    first = step_patterns(t, model.zero_factors(0), True, unit=layout.unit_factors(0))
    for s, (pattern, rhs) in first.items():
        rows, cols, k, active, kept, _ = reflection_lanes(pattern, rhs)
        dense = reflection_lanes(pattern)
        assert k == cols and active[-1] < dense[3][-1]  # the right-hand side's reflection
        assert not rhs[rows - f[s]:].any()  # [√μ I | 0]
        assert cycles(pattern, rhs, s) < cycles(pattern, None, s)
        if s > 0:  # held slots: unit priors and rows without information, no residual
            assert not rhs.any() and active[-1] == 0
    # keyframe 0: slot 0's priors and GPS rows (15 + 3) hold its only residuals
    assert first[0][1].sum() == 18
    # a full window: every row of slot 0's step that holds information can hold one (39 of
    # its 54 factor rows; the √μ rows not)
    pattern, rhs = step_patterns(t, model.zero_factors(5), True, unit=layout.unit_factors(5))[0]
    own = np.arange(len(rhs)) < len(rhs) - f[0]
    assert (rhs == (pattern.any(axis=1) & own)).all() and rhs.sum() == 39


def test_the_pending_reexpression_runs_beside_the_next_updates_solve(paper_a_n7):
    """An update leaves its kept re-expression pending (fgc_stream.h's KEPT_PENDING); the next
    call's region runs it beside the window's process (the solve and the marginal): the update
    waits for the longer of the two, here the solve, so the re-expression costs the update
    nothing but its point's copy. Asked for first (op 3), it is op 3's."""
    _, model = paper_a_n7
    assert model.leaves_pending(5) and not model.leaves_pending(4)  # 4: the batch step
    ev = model.events_of(2)
    ran = model.price(6, 2, {**ev, "kept_reexpress": 1})
    none = model.price(6, 2, {**ev, "kept_reexpress": 0})
    kept = ran.term("kept_reexpress").cycles
    assert kept == model.stream["stream_kept_reexpress"] > 0
    window = sum(t.cycles for t in none.terms if t.name in set(model.group) | {
        "marginal", "relinearize", "cost_x"})
    assert window > kept and ran.term("overlap").cycles == -kept
    assert ran.cycles == none.cycles
    assert "kept_reexpress" not in {t.name for t in none.terms}
    # not counted: the update before left it (no estimates asked for between them)
    assert model.price(6, 2).cycles == ran.cycles
    assert "kept_reexpress" not in {t.name for t in model.price(5, 2).terms}  # after the batch
    # the update's own: its point copied out after the solve, for the next call
    assert ran.term("kept_pending").each == model.stream["stream_kept_slot0"]
    # asked for right after the update: op 3 runs it, before the walk
    asked = model.price_estimates(5)
    assert [t.name for t in asked.terms][:2] == ["kept_reexpress", "kept_slot0"]
    assert "kept_reexpress" not in {t.name for t in model.price_estimates(4).terms}


def test_the_kept_walk_is_off_the_updates_path(paper_a_n7):
    """An update re-expresses the newest kept conditional and walks nothing: its price does not
    grow with the kept keyframes (ISAM2's update does not compute the estimates either). The
    walk is priced where it runs: when the estimates are asked for after an incremental update
    (op 3; after a batch step they are its optimum, nothing to walk), and at a batch step that
    starts from estimates the update before left stale (the leaving keyframe's estimate its
    first parent: one conditional fewer than the update before walked from slot 0)."""
    _, model = paper_a_n7
    five, six = model.price(5, 1), model.price(6, 1)  # three and four kept keyframes
    assert "kept_walk" not in {t.name for t in five.terms} | {t.name for t in six.terms}
    assert five.cycles == six.cycles
    each, base = model.stream["stream_kept_walk_each"], model.stream["stream_kept_walk_base"]
    assert model.price_estimates(6).term("kept_walk").each == base + 4 * each
    assert model.stale_after(3) and not model.stale_after(4)  # 4: the batch step
    assert "kept_walk" not in {t.name for t in model.price_estimates(4).terms}
    batch = model.price(4, 1)  # keyframe 3 left keyframe 0 stale: walked from keyframe 1
    assert batch.term("kept_walk").each == base + 1 * each
    # counted: the kept_walk event says whether it ran (the estimates asked for after 3)
    ev = model.events_of(1)
    assert "kept_walk" not in {t.name for t in model.price(4, 1, {**ev, "kept_walk": 0}).terms}


def test_the_marginal_reuses_the_rows_of_lms_last_linearisation(paper_a_n7):
    _, model = paper_a_n7
    events = model.events_of(2)  # the last iteration took no step: X is where LM linearised
    again = model.price(5, 2, {**events, "relinearize": 1})
    reused = model.price(5, 2, {**events, "relinearize": 0})
    # only the factors slot 0's step stacks (LM's linearisation instance, part 2: keyframe 0
    # has left, its priors hold nothing), not the whole window
    rows = model.stream["stream_leaf_linearize_live"]
    assert rows < model.stream["stream_leaf_linearize"]
    assert rows < model.group["factor_jacobian"]  # the datapaths and the gradient beside them
    assert "gradient" not in model.group
    # computed again before the marginal / kept region (stream_call, on LM's linearisation
    # instance): a term of its own, not hidden behind the kept net
    assert again.term("relinearize").each == rows
    assert again.term("marginal").each == reused.term("marginal").each
    assert again.cycles - reused.cycles == rows
    assert "relinearize" not in [t.name for t in reused.terms]
    assert model.price(5, 2).cycles == reused.cycles
    # a step accepted in the last iteration too: linearised again
    moved = {**events, "accept": events["linearize"]}
    assert model.price(5, 2, moved).term("relinearize").each == rows


def test_a_vector_variables_directions_need_no_datapath_pass(paper_a_n7):
    layout, model = paper_a_n7
    words = layout.vector_words()  # LIO's keyframe: a pose, a velocity, a bias
    assert len(words) == layout.kf_dim == 15
    assert words[:6] == [-1] * 6  # the pose: not a vector
    assert words[6:] == sorted(words[6:]) and len(set(words[6:])) == 9
    assert all(0 <= w < layout.kf_words for w in words[6:])
    # four passes per pose direction and the Log at the start, none for the nine others
    passes = [lp for ph in model.design_plan().phases if ph.name == "stream_kept_reexpress"
              for p in ph.processes for lp in p.loops if lp.name == "pass"]
    assert sum(lp.repeat for lp in passes) == 4 * 6 + 1


TASKS = r"""
#include <cstdio>
#include "fgc_cycles.h"
int main() {
    for (int longer = 0; longer < 2; ++longer) {
        FGC_CYCLES("a", 0, "before", 10, 1, 1);  // 10 cycles
        FGC_TASK();  // task 1: a parallel group, its slower branch plus the other's fill: 110
        FGC_BRANCH();
        FGC_CYCLES("b", 0, "l", 91, 1, 10);
        FGC_BRANCH();
        FGC_CYCLES("c", 0, "l", 41, 1, 10);
        FGC_JOIN();
        FGC_TASK();  // task 2: 120 cycles, or 105
        FGC_CYCLES("d", 0, "l", longer ? 101 : 86, 1, 20);
        FGC_TASKS_JOIN();
        FGC_CYCLES("e", 0, "after", 5, 1, 1);  // 5 cycles
#ifdef FGC_COUNT_CYCLES
        std::printf("%ld\n", fgc_cycles::total());
        fgc_cycles::reset();
#endif
    }
    return 0;
}
"""


def test_a_task_group_counts_its_slowest_task(tmp_path):
    """fgc_cycles.h: independent processes of one DATAFLOW region (FGC_TASK … FGC_TASKS_JOIN,
    the marginal beside the kept net) take the slowest one's cycles, whatever groups a task
    holds; without FGC_COUNT_CYCLES the macros compile to nothing."""
    import shutil
    import subprocess
    from pathlib import Path

    if shutil.which("g++") is None:
        pytest.skip("needs g++")
    include = Path(__file__).resolve().parents[2] / "backends" / "hls" / "include"
    src = tmp_path / "tasks.cpp"
    src.write_text(TASKS)
    exe = tmp_path / "tasks"
    flags = ["g++", "-std=c++17", "-Wall", "-Werror", "-Wno-unknown-pragmas", "-I", str(include)]
    subprocess.run([*flags, "-DFGC_COUNT_CYCLES", str(src), "-o", str(exe)], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    assert out.split() == [str(10 + 110 + 5), str(10 + 120 + 5)]
    subprocess.run([*flags, "-fsyntax-only", str(src)], check=True)


def test_each_stream_function_has_one_call_site_in_the_header():
    """The second reader (reader.py) reads every preprocessor branch of fgc_stream.h and takes
    each call site for an instance: a fallback call of the marginal in another branch would
    read as a second copy of the factor datapaths."""
    import re
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "backends" / "hls" / "include"
            / "fgc_stream.h").read_text()
    code = re.sub(r"//[^\n]*", "", text)
    # tau's and the kept conditional's parts: the marginal's (tau_and_keep's tasks), a batch
    # step's (write_tau, kept_conditional) and the one-step update's beside its
    # back-substitution (spec_tau_task, spec_keep: the kept scale its own loop there);
    # the call's reads of X beside tau's sign loop or beside the speculation's moves
    three = ("tau_sign", "tau_mean", "kept_reciprocals")
    two = ("kept_scale", "out_task")
    for name in ("marginalize", "reexpress", "kept_walk", "keep_points", "keep_task",
                 "window_task", "kept_task", "window_and_kept", "write_tau", "tau_tail",
                 "mean_task", "words_task", "tau_words", "tau_mean_out",
                 "tau_beside_keep", "tau_and_keep", "sign_task", "reciprocal_task",
                 "sign_beside_reciprocals", "kept_conditional", "update_start",
                 "start_x_task", "start_data_task", "tau_buffer", "spec_keep",
                 "tau_commit_task", "keep_commit_task", "out_beside_commit", *two, *three):
        sites = re.findall(rf"\b{name}<CFG>\(", code)
        assert len(sites) == (3 if name in three else 2 if name in two else 1), name


@pytest.fixture(scope="module")
def small_n7():
    """The stream design search's smallest candidate at paper A's policy, N = 7: n_u = 1, one
    unit set, the factor datapaths at one adder, multiplier and divider."""
    from fgc.ir.program import SolverConfig

    graph = example("lio").build(N=7)
    program = compile_stream(graph, SolverConfig(precision="float32", linear="qr", units=1),
                             incremental=3, batch_every=(4,), name="lio_k")
    sp = stream_program(graph, program, None)
    small = HlsConfig(scalar="float", unit_sets=1, allocation=(("add", 1), ("mul", 1),
                                                                ("div", 1)))
    return sp, small, WindowUpdateModel(layout_of(sp), small)


def test_the_searched_stream_design_is_priced_by_its_config(small_n7, paper_a_n7):
    """The stream design's search (bench_papers.stream_search) prices each candidate by the
    model of its HlsConfig: the smallest is smaller than the default design; what the window
    and batch kernels each hold (``duplicated``) adds up to their parts; the streaming QR unit,
    which the stream model does not price, is refused by name."""
    sp, _, model = small_n7
    res = model.resources()
    assert res["dsp"] < paper_a_n7[1].resources()["dsp"]
    dup = model.duplicated()
    assert {"factor datapaths", "gradient", "QR units", "lm control"} <= set(dup)
    for part in ("window kernel", "batch kernel"):
        assert sum(where.get(part, 0) for where in dup.values()) == res["parts"][part][0]
    with pytest.raises(PlanError, match="qr-unit stream"):
        WindowUpdateModel(layout_of(sp), HlsConfig(scalar="float", qr_unit="stream"))


@pytest.mark.heavy
def test_the_searched_stream_design_prices_at_least_what_its_text_holds(small_n7, tmp_path):
    """The smallest candidate emitted with its config: the plan prices each part (window kernel,
    batch kernel, stream section) at least what the second reader reads from the text."""
    import fgc_backends
    from fgc_backends.hls.reader import emitted_files
    from fgc_backends.hls.reader.design import _design, _Reader

    sp, small, model = small_n7
    res = model.resources()
    hls = fgc_backends.load("hls")
    hls.emit(sp, tmp_path, small)
    files, top = emitted_files(tmp_path)
    tab = model.plan.ops
    dsp_of = {"add": tab.add.dsp, "mul": tab.mul.dsp, "div": tab.div.dsp,
              "sqrt": tab.sqrt.dsp, "special": tab.special.dsp}
    reader = _Reader(files, tab.add.latency)
    design = _design(reader, top)
    name = top.removesuffix("_stream")
    batch_cpp = next(k for k, _ in files if k.endswith(".cpp") and k != f"{name}.cpp")
    window = _design(reader, f"{name}_top").dsp(dsp_of)
    batch = design.unit_dsp(dsp_of, batch_cpp)
    assert window <= res["parts"]["window kernel"][0]
    assert batch <= res["parts"]["batch kernel"][0]
    assert design.dsp(dsp_of) - window - batch <= res["parts"]["stream section"][0]


def test_one_step_policy_stores_the_steps_own_factorisation():
    """The one-step policy (one Gauss-Newton step an update): an update that took its step is
    priced without the marginal's linearisation and QR step and without the batch kernel's
    store (its solve's factorisation is the store, fgc_stream.h's took_step); its events
    (status max_iterations) count the step as accepted. One that took none is priced as
    before (its rows at X are LM's, the leaf step runs). (The two-kernel design, asked for:
    the one-step policy's default sweeps the window instead, test_hls_stream_sweep.py.)"""
    from fgc.app.streaming import one_step_solver

    graph = example("lio").build(N=7)
    program = compile_stream(graph, one_step_solver(), incremental=3, batch_every=(4,),
                             name="lio_k1")
    model = WindowUpdateModel(layout_of(stream_program(graph, program, None), sweep=False),
                              HlsConfig(scalar="float"))
    assert model.one_step
    ev = model.events_of(1, status="max_iterations")
    assert ev["accept"] == 1 and model.reuses(ev)
    took = model.price(5, 1, status="max_iterations")
    names = {t.name for t in took.terms}
    assert "relinearize" not in names and "lin_points" in names
    assert took.term("marginal").each == model.stream["stream_marginal_reused"]
    none = model.price(5, 1)  # converged on its gradient: no step, the leaf step runs
    assert not model.reuses(model.events_of(1))
    # (keyframe 5: keyframe 0 has left, its priors' rows are not stacked: live)
    assert none.term("marginal").each == (model.stream["stream_marginal_live"]
                                          + model.qr_cycles(model.zero_factors(5), False, True,
                                                            live=True))
    assert none.term("marginal").each > took.term("marginal").each
    batch = model.price(4, 1, status="max_iterations")
    assert batch.mode == "batch" and "batch_store" not in {t.name for t in batch.terms}
    assert "batch_store" in {t.name for t in model.price(4, 1).terms}


def test_lm_to_convergence_keeps_its_store(paper_a_n7):
    _, model = paper_a_n7
    assert not model.one_step
    ev = model.events_of(3, status="max_iterations")
    assert ev["accept"] == 3 and not model.reuses(ev)
    assert "batch_store" in {t.name for t in model.price(4, 3, ev).terms}


def test_the_cost_at_x_comes_from_the_first_linearisation(paper_a_n7):
    """LM's start needs the window's cost at X; the QR design's first linearisation gives it
    (the gradient pass's scatter takes the right-hand side's column too: ‖b‖² of each instance,
    one iteration more; fgc_lm.h's FGC_LM_COST_IN_LINEARIZE), so no cost pass at X runs: the
    plan's per-call ``factor_cost`` phase costs nothing, the update prices no ``cost_x`` (nor a
    batch step ``batch_cost_x``), and the gradient pass prices the extra column per instance."""
    from fgc_backends.hls.plan.loops import kernel_timing
    from fgc_backends.hls.units.datapath import cost_in_linearization, gradient_loops

    _, model = paper_a_n7
    for plan, program in ((model.plan, model.layout.template),
                          (model.batch["plan"], model.layout.batch.template)):
        assert cost_in_linearization(program)
        assert sum(phase_cycles(ph) for ph in plan.phases if ph.name == "factor_cost") == 0
        grad = gradient_loops(program, kernel_timing(plan.ops))
        scatter = {p.name: p.loops[-1] for p in grad if p.name.startswith("reduce_")}
        for i, b in enumerate(program.blocks):
            assert (scatter[f"reduce_{i}"].name, scatter[f"reduce_{i}"].trip) == \
                ("scatter", sum(len(blk[0]) for blk in b.structure if blk) + 1)
    assert model.cost_x == 0 and model.batch["cost_x"] == 0
    assert "cost_x" not in {t.name for t in model.price(5, 2).terms}
    assert "batch_cost_x" not in {t.name for t in model.price(4, 2).terms}


COLLAPSE = r"""
#include <cstdio>
#include "fgc_cycles.h"
int main() {
    FGC_REGION("outer");  // two processes: a's loop (100), b's fill waits on it, then a span
    FGC_CYCLES("a", 0, "feed", 100, 1, 1);
    FGC_WAIT("b", 0, "a", 0, "feed");
    FGC_CYCLES("b", 0, "fill", 10, 1, 2);
    FGC_COLLAPSE_BEGIN();  // b's step: a region of its own (50), a mark, sequential code (30)
    FGC_REGION("inner");
    FGC_CYCLES("s", 0, "l", 50, 1, 1);
    FGC_SEQUENTIAL();
    FGC_BRANCH();
    FGC_CYCLES("t", 0, "l", 30, 1, 1);
    FGC_COLLAPSE_END("b", 0, "step");  // the outer region current again
    FGC_CYCLES("c", 0, "beside", 20, 1, 1);  // a third process of the outer region
    FGC_SEQUENTIAL();
    FGC_CYCLES("z", 0, "after", 5, 1, 1);
#ifdef FGC_COUNT_CYCLES
    // b: its fill no sooner than 2 after a's loop (102), then its step's 80: 182 (the slowest
    // process plus the others' fills, 100 + 2 + 1, is less), then 5
    std::printf("%ld %zu\n", fgc_cycles::total(), fgc_cycles::log().size());
#endif
    return 0;
}
"""


def test_a_collapsed_span_is_one_record_of_its_region(tmp_path):
    """fgc_cycles.h's FGC_COLLAPSE_BEGIN / FGC_COLLAPSE_END (a unit set's step, whose
    reflections are regions of their own, as a process of lin_level's region): the span's
    records, priced as a branch is, become one record of the enclosing region, which stays
    current; its marks are dropped; the region's rule (the waits) applies to it."""
    import shutil
    import subprocess
    from pathlib import Path

    if shutil.which("g++") is None:
        pytest.skip("needs g++")
    include = Path(__file__).resolve().parents[2] / "backends" / "hls" / "include"
    src = tmp_path / "collapse.cpp"
    src.write_text(COLLAPSE)
    exe = tmp_path / "collapse"
    flags = ["g++", "-std=c++17", "-Wall", "-Werror", "-Wno-unknown-pragmas", "-I", str(include)]
    subprocess.run([*flags, "-DFGC_COUNT_CYCLES", str(src), "-o", str(exe)], check=True)
    out = subprocess.run([str(exe)], check=True, capture_output=True, text=True).stdout
    # a, the wait, b's fill, b's step (one record), c, z
    assert out.split() == [str(102 + 80 + 5), "6"]
    subprocess.run([*flags, "-fsyntax-only", str(src)], check=True)


def test_one_step_level0_runs_beside_the_linearisation():
    """The one-step window (rows straight into the banks): level 0's first steps are reflected
    in the linearisation's region (lin_level), each set from when its rows are in; the term is
    that region less the linearisation and level 0, and an update that stops before its solve
    pays the sets' steps instead. LM to convergence (its retries stack from AB) has no such
    sets."""
    from fgc.app.streaming import one_step_solver
    from fgc_backends.hls.plan.loops import kernel_timing
    from fgc_backends.hls.plan.stream import qr_step_processes
    from fgc_backends.hls.units.datapath import lin_level_cycles

    graph = example("lio").build(N=7)
    program = compile_stream(graph, one_step_solver(), incremental=3, batch_every=(4,),
                             name="lio_k1")
    model = WindowUpdateModel(layout_of(stream_program(graph, program, None), sweep=False),
                              HlsConfig(scalar="float"))
    t = model.layout.template
    assert [s for s, _, _ in model._lin_sets] == list(t.schedule.levels[0][:model.sets])
    # (keyframe 2: keyframe 0 still in the window, every instance linearised)
    zero, unit = model.zero_factors(2), model.layout.unit_factors(2)
    lin = next(ph for ph in model.plan.phases if ph.name == "factor_jacobian")
    level = next(ph for ph in qr_solve_phases(t, zero, True, model.sets, model.les, unit=unit)
                 if ph.name == "qr_level0_0")
    procs = qr_step_processes(t, zero, True, model.les, unit=unit)
    region = lin_level_cycles(t, kernel_timing(model.plan.ops),
                              [p for p in lin.processes if p.name != "gradient"],
                              [(w, f, procs[s].cycles) for s, w, f in model._lin_sets])
    # no set starts before its last datapath loop, so the region is longer than either alone
    assert region > max(phase_cycles(lin), phase_cycles(level))
    saved = model.beside_linearize(zero, unit)
    assert saved == region - phase_cycles(lin) - phase_cycles(level) < 0
    price = model.price(2, 1, status="max_iterations")
    assert price.term("qr_beside_linearize").cycles == saved
    assert price.term("factor_jacobian").cycles == phase_cycles(lin)
    stopped = model.price(2, 1, {"call": 1, "linearize": 1}, status="failed")
    assert stopped.term("qr_beside_linearize").cycles == region - phase_cycles(lin) > 0
    lm = compile_stream(graph, incremental=3, batch_every=(4,), name="lio_k")
    lm_model = WindowUpdateModel(layout_of(stream_program(graph, lm, None)),
                                 HlsConfig(scalar="float"))
    assert lm_model._lin_sets is None
    assert "qr_beside_linearize" not in {t.name for t in lm_model.price(5, 3).terms}


def test_one_step_linearisation_skips_what_holds_nothing_once_keyframe_0_has_left(tmp_path):
    """Once keyframe 0 has left the window (keyframe >= size), the one-step solve's
    linearisation (lin_level's part 3) does not evaluate keyframe 0's priors: every member of
    them is zero at every keyframe from then on, and all their rows go to a unit set's banks
    (none is read from AB: the solve takes that set's step, the marginal's live stack leaves
    them out). The plan prices the datapaths at the instances left, the set's fill at its words
    left; the emitted design passes part 3 when live, with BANK_FILL_LIVE."""
    from collections import Counter

    import fgc_backends
    from fgc.app.streaming import one_step_solver
    from fgc_backends.hls.plan.loops import _tables, kernel_timing
    from fgc_backends.hls.plan.stream import qr_step_processes
    from fgc_backends.hls.units.datapath import (
        bank_fill_words,
        lin_level_cycles,
        linearize_region,
    )
    from fgc_backends.hls.units.qr import rows_in_banks

    graph = example("lio").build(N=7)
    program = compile_stream(graph, one_step_solver(), incremental=3, batch_every=(4,),
                             name="lio_k1")
    sp = stream_program(graph, program, None)
    lay = layout_of(sp, sweep=False)
    config = HlsConfig(scalar="float")
    model = WindowUpdateModel(lay, config)
    t = lay.template
    skip = model._skip
    assert skip and skip == lay.leaf_skipped()
    in_banks = rows_in_banks(t, model.plan.options, _tables(t))
    assert all(f in in_banks for f in skip)
    n_kf = len(lay.program.schedule.clusters)
    for kf in range(lay.size, n_kf):
        zero = lay.zero_factors(kf, True)
        assert all(ti in zero for f in skip for ti in t.factors[f].factors)
    # the datapaths at the instances left: fewer cycles once keyframe 0 has left, none before
    lin = next(ph for ph in model.plan.phases if ph.name == "factor_jacobian")
    counts = model.solve_counts(True)
    assert model.solve_counts(False) is None
    assert sum(counts.values()) == len(t.factors) - len(skip)
    live = phase_cycles(linearize_region(t, kernel_timing(model.plan.ops),
                                         model._jac_at(Counter(counts)), counts))
    assert live < phase_cycles(lin)
    assert model.price(2, 1, status="max_iterations").term("factor_jacobian").cycles \
        == phase_cycles(lin)
    price = model.price(5, 1, status="max_iterations")
    assert price.term("factor_jacobian").cycles == live
    # level 0's sets beside it: the fill at the words left, the region at the instances left
    tables = _tables(t)
    full = bank_fill_words(t, tables, in_banks, len(model._lin_sets))
    left = bank_fill_words(t, tables, in_banks, len(model._lin_sets), skip)
    assert [f.trip for _, _, f in model._lin_sets_live] == left != full
    zero, unit = model.zero_factors(5), lay.unit_factors(5)
    level = next(ph for ph in qr_solve_phases(t, zero, True, model.sets, model.les, unit=unit)
                 if ph.name == "qr_level0_0")
    procs = qr_step_processes(t, zero, True, model.les, unit=unit)
    region = lin_level_cycles(t, kernel_timing(model.plan.ops),
                              model._jac_at(Counter(counts)),
                              [(w, f, procs[s].cycles) for s, w, f in model._lin_sets_live],
                              counts)
    assert price.term("qr_beside_linearize").cycles == region - live - phase_cycles(level)
    # the emitted design: part 3 when live, the fill's words left
    fgc_backends.load("hls").emit(sp, tmp_path, config)
    cpp = next(p.read_text() for p in sorted(tmp_path.rglob("*.cpp"))
               if "BANK_FILL_LIVE" in p.read_text())
    assert "linearize_all(X, LIN_LIVE ? 3 : 0)" in cpp
    assert "LIN_LIVE = live;" in cpp
    table = cpp.split(f"BANK_FILL_LIVE[{len(left)}] = {{", 1)[1].split("};", 1)[0]
    assert [int(v) for v in table.split("\n", 1)[1].replace(",", " ").split()] == left
