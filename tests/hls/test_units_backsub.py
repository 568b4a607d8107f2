"""Back-substitution (backends/hls/units/backsub.py): cond_load's and cond_backsub's loops by
hand, one unit per QR unit set, the operators as bound."""

from __future__ import annotations

import pytest
from hls_programs import chain

from fgc_backends.cost.operators import FLOAT32
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
from fgc_backends.hls.plan.loops import _tables
from fgc_backends.hls.plan.model import Loop
from fgc_backends.hls.units.backsub import (
    backsub_loops,
    backsub_operators,
    backsub_schedule,
    backsub_slots,
    backsub_words,
    backsub_xoff,
    load_loop,
    retire_region,
    triangle_trip,
    wide_load_loops,
)
from fgc_backends.hls.units.state_update import retire_order, retire_timing


def test_cond_backsub_loops_by_hand():
    # float32 on the xc7z045 at 143 MHz: add 4, mul 3, div 15; PARTIALS = 4 sums in each of the
    # two lanes, folded in ⌈log₂ 8⌉ = 3 beside the reciprocal, then the row scaled by it:
    # max(4 (1 + 3), 15) + 3 = 19
    loops = {lp.name: lp for lp in backsub_loops(2, 3, FLOAT32, name="b")}
    assert list(loops) == ["b_rows", "b_triangle", "b_last"]
    assert (loops["b_rows"].trip, loops["b_rows"].depth) == (2, 19)
    # one column (r = 1) padded to the chain Lm + La = 7, plus one; an iteration R_ir / R_ii,
    # its product and the subtraction deep: 2 Lm + La = 10
    assert (loops["b_triangle"].trip, loops["b_triangle"].depth) == (8, 10)
    assert loops["b_last"].depth == 1  # x_0 = y_0: a move
    assert backsub_loops(0, 3, FLOAT32) == []


def test_triangle_hides_its_chain_behind_long_columns():
    # f = 15: columns 14 … 1; the 7 shortest padded to 8 iterations, 8 … 14 as they are
    assert triangle_trip(15, FLOAT32) == 7 * 8 + 8 + 9 + 10 + 11 + 12 + 13 + 14
    assert triangle_trip(1, FLOAT32) == 0
    # a column per unknown at the chain's rate at most: never below the floor f - 1 chains
    for f in range(1, 40):
        assert triangle_trip(f, FLOAT32) >= (f - 1) * 8


def test_cond_load_moves_the_upper_triangle_two_words_a_cycle():
    # f = 3, s = 2: rows of 6, 5, 4 words from the diagonal on (the zeros below stay)
    assert backsub_words(3, 2) == 6 + 5 + 4
    lp = load_loop(3, 2, FLOAT32)
    assert (lp.trip, lp.ii, lp.depth) == (8, 1, 2 + 3 + 4)
    assert load_loop(0, 2, FLOAT32).trip == 0


def test_backsub_operators_as_bound():
    # cond_load 2 multiply-adds, the rows' 2 PARTIALS - 1 fold adds and the subtraction beside
    # a divide and the scaling multiply, the triangle's 2 multiplies and a subtraction (x_0 a
    # move: as many operators as when the triangle scaled x_r and x_0 had its own multiply)
    assert dict(backsub_operators(FLOAT32)) == {"add": 2 + 8 + 1, "mul": 2 + 2 + 1, "div": 1}


def test_two_backsub_lanes_whatever_the_unit_sets():
    plan = build_plan(chain(7, linear="qr"))  # two-ended: two unit sets
    assert [u.name for u in plan.units if u.name.endswith("_backsub")] == ["qr0_backsub",
                                                                           "qr1_backsub"]
    cholesky = build_plan(chain(5, linear="cholesky", cpe=2))
    assert cholesky.unit("trisolve").instances == 2  # the two lanes
    assert any(ph.name == "backsub" for ph in cholesky.phases)


def test_slots_overlap_a_solve_with_the_next_load_unless_it_needs_that_solution():
    # steps 0 (columns 0, 1 | separator 4) and 1 (2, 3 | 5) below the root 2 (4, 5): root
    # first; step 0 needs the root's x (it loads alone), step 1 only the root's, solved two
    # slots before: its load runs beside step 0's solve
    tables = {"LEVEL_BEGIN": (0, 2, 3), "LEVEL_STEPS": (0, 1, 2), "STEP_F": (2, 2, 2),
              "STEP_W": (3, 3, 2), "STEP_COL_BEGIN": (0, 3, 6), "STEP_COL": (0, 1, 4, 2, 3, 5,
                                                                             4, 5)}
    assert backsub_slots(tables) == ((-1, 2, 1), (2, -1, 0), (-1, 0, 0), (0, 1, 1), (1, -1, 0))
    # every step loaded once and solved once, after its load, on the lane it was loaded into
    # (lane of the t-th step: t % 2; the slot's lane is the solving one)
    serial = {**tables, "STEP_COL": (0, 1, 4, 2, 3, 0, 4, 5)}  # step 1 now needs step 0
    slots = backsub_slots(serial)
    assert slots == ((-1, 2, 1), (2, -1, 0), (-1, 0, 0), (0, -1, 1), (-1, 1, 1), (1, -1, 0))


def test_a_lane_local_separator_is_read_where_the_lanes_solve_left_it():
    # a two-ended chain of 2-column steps: root 4 (columns 8, 9), its children 2 (6 | 8) and
    # 3 (7 | 9), then 0 (4, 5 | 6) below 2 and 1 (2, 3 | 7) below 3 (frontal columns 6 and 7
    # split so that each child's separator is the last column of its parent's frontal block)
    tables = {"LEVEL_BEGIN": (0, 2, 4, 5), "LEVEL_STEPS": (0, 1, 2, 3, 4),
              "STEP_F": (2, 2, 1, 1, 2), "STEP_W": (3, 3, 2, 2, 2),
              "STEP_COL_BEGIN": (0, 3, 6, 8, 10),
              "STEP_COL": (4, 5, 6, 2, 3, 7, 6, 8, 7, 9, 8, 9)}
    slots = backsub_slots(tables)
    assert slots == ((-1, 4, 1), (4, -1, 0), (-1, 2, 0), (2, 3, 1), (3, 0, 0), (0, 1, 1),
                     (1, -1, 0))
    # the root's first child loads into lane 1 (the root is lane 0's: from DELTA); step 3
    # into lane 0, whose last solve is the root: its column 9 is the root's frontal column 1;
    # step 0 into lane 1 after step 2 (offset 0), step 1 into lane 0 after step 3
    assert backsub_xoff(tables) == (-1, -1, -1, 1, 0, 0, -1)
    # a separator that is not its lane's last solution in order stays with DELTA
    swapped = {**tables, "STEP_COL": (4, 5, 6, 2, 3, 9, 6, 8, 7, 9, 8, 9)}  # step 1 needs 9
    assert backsub_xoff(swapped)[5] == -1


def test_the_lane_local_separator_saves_its_copy_on_a_two_ended_chain():
    program = chain(7, linear="cholesky", cpe=2)
    tables = _tables(program)
    xoff = backsub_xoff(tables)
    loads = [ld for _, ld, _ in backsub_slots(tables) if ld >= 0]
    # the root and its first child come from DELTA (no separator, another lane's), the rest
    # from their own lane
    assert sum(1 for x in xoff if x >= 0) == len(loads) - 2
    phase = {ph.name: ph for ph in build_plan(program).phases}["backsub"]
    copies = [lp for lp in phase.processes[0].loops if lp.name == "separator_in"]
    # (and the root's first child takes the root's x as its solve finds them, not from DELTA:
    # units/backsub.py's backsub_schedule, part 3)
    assert [part for *_, part, _ in backsub_schedule(tables, build_plan(program).ops)][:3] \
        == [0, 3, 0]
    assert sum(1 for lp in copies if lp.trip > 0) == 0


def test_a_waiting_steps_s_loads_as_the_solve_finds_x():
    """cond_load's part 3 (units/backsub.py's backsub_schedule): a step whose separator is the
    step just solved's frontal columns 0 … s − 1 in order takes its R and d (two words a cycle)
    and then S column by column (⌈f / 2⌉ iterations a column, x_a from the solving lane's
    triangle) beside that solve, and no slot loads its S alone; by hand on f = s = 15, float32
    (CHAIN 7: a column of 8 iterations keeps pace with the triangle's x's, so only x_0 binds).
    A separator out of order, or a column longer than the triangle spaces its x's, keeps the
    two slots (parts 1 and 2)."""
    from fgc_backends.hls.units.backsub import stream_load_end, stream_load_loop, streamed_s
    ops = FLOAT32
    load = stream_load_loop(15, 15, ops, "cond_load")
    assert (load.trip, load.ii, load.depth) == (68 + 15 * 8, 1, 2 + 3 + 4)
    solve = backsub_loops(15, 0, ops)  # the root: rows 15, its triangle, x_0
    x0_at = sum(lp.cycles for lp in solve)
    assert x0_at == (14 + 19) + (133 - 1 + 10) + 1
    assert stream_load_end(load, x0_at, 15) == max(load.cycles, x0_at + 7 + 9) == load.cycles
    assert stream_load_end(load, 400, 15) == 400 + 7 + 9  # x_0 late: its column after it
    tables = {"STEP_COL": tuple(range(15, 30)) + tuple(range(15)) + tuple(range(15, 30)),
              "STEP_COL_BEGIN": (0, 15), "STEP_F": (15, 15), "STEP_W": (15, 30)}
    assert streamed_s(tables, 0, 1, ops)
    swapped = {**tables, "STEP_COL": tables["STEP_COL"][:15] + tables["STEP_COL"][15:30]
               + (16, 15) + tables["STEP_COL"][32:]}
    assert not streamed_s(swapped, 0, 1, ops)
    wide = {"STEP_COL": tuple(range(20, 40)) + tuple(range(20)) + tuple(range(20, 40)),
            "STEP_COL_BEGIN": (0, 20), "STEP_F": (20, 20), "STEP_W": (20, 40)}
    assert not streamed_s(wide, 0, 1, ops)  # ⌈20 / 2⌉ = 10 > CHAIN + 1 = 8


def test_two_lanes_on_a_one_set_qr_design():
    plan = build_plan(chain(5, linear="qr", ordering="serial"))
    assert [u.name for u in plan.units if u.name.endswith("_backsub")] == ["qr0_backsub",
                                                                           "qr1_backsub"]


def test_the_state_update_runs_beside_the_slots_as_steps_are_sent():
    # three slots of 100, 50 and 80 cycles; steps sent at the ends of slots 0 and 2 (100,
    # 230) with 2 and 3 variables; the retire issues a variable every 10 cycles, 40 deep
    slots = [[Loop("a", 1, 1, 100)], [Loop("b", 1, 1, 50)], [Loop("c", 1, 1, 80)]]
    # first step: 100, 110; second: 230, 240, 250 -> ends 290
    assert retire_region(slots, [0, 2], [2, 3], 10, 40) == 290
    # a slow retire (II 100): 100, 200; then max(300, 230) = 300, 400, 500 -> 540
    assert retire_region(slots, [0, 2], [2, 3], 100, 40) == 540
    # nothing to retire: the slots alone
    assert retire_region(slots, [], [], 10, 40) == 230


def test_back_substitution_feeds_the_state_update():
    program = chain(7, linear="qr")
    plan = build_plan(program)
    assert "state_update" not in {ph.name for ph in plan.phases}
    assert [u.name for u in plan.units if u.name.startswith("state_update")]  # its datapaths
    slots, retire, _ = {ph.name: ph for ph in plan.phases}["backsub"].processes  # + the cost
    solved = [s for s, _, _ in backsub_slots(plan_tables(program))]
    variables, first = retire_order(program, [s for s in solved if s >= 0])
    assert sorted(variables) == list(range(len(program.variables)))  # each retracted once
    assert sum(1 for s in first if s >= 0) == len(program.schedule.steps)
    # the retire adds at most its last variable's depth after the last slot here (a step's
    # solve is slower than its variables' retraction)
    ii, depth = retire_timing(program.variables, plan.ops, max(s.frontal_dim
                                                     for s in program.schedule.steps))
    assert 0 < retire.loops[0].cycles <= depth
    # the what-if whole-matrix Cholesky has no emitted driver: its state update is a pass
    whole = build_plan(chain(5, linear="cholesky", cpe=2),
                       PlanOptions.of(chain(5, linear="cholesky", cpe=2),
                                      hessian_storage="dense"))
    assert "state_update" in {ph.name for ph in whole.phases}
    assert plan_cost(whole).cycles > 0


def plan_tables(program):
    return _tables(program)


# ---- back-substitution two lanes wide (HlsConfig backsub_lanes=2, fgc_backsub.h's
# cond_load_wide / cond_backsub_wide)

def _wide_walk(off: int, f: int, s: int, lanes: int) -> int:
    """cond_load_wide's iterations walked as the header's loop walks them: row i from its
    diagonal, a group of 2 lanes words of COND an iteration, the row's last group ends it."""
    width, cols, w = 2 * lanes, f + s + 1, f + s
    trip, i, base, g = 0, 0, off, off // (2 * lanes)
    while i < f:
        trip += 1
        if width * g + width - 1 >= base + w:
            i, base = i + 1, base + cols
            g = (base + i) // width
        else:
            g += 1
    return trip


def test_the_wide_load_reads_aligned_groups_of_one_row():
    from fgc_backends.hls.units.backsub import wide_trip
    # f = 2, s = 1 at COND word 0: row 0 is words 0 … 3 (one group), row 1 words 5 … 7 (group
    # 1); at word 3: row 0 is words 3 … 6 (groups 0 and 1), row 1 words 8 … 10 (group 2)
    assert wide_trip(0, 2, 1, 2) == 2 and wide_trip(3, 2, 1, 2) == 3
    for off in range(8):
        for f in range(1, 9):
            for s in range(0, 7):
                assert wide_trip(off, f, s, 2) == _wide_walk(off, f, s, 2), (off, f, s)
                # never more than one group a row above its words at four a cycle
                assert wide_trip(off, f, s, 2) <= sum(-(-(f + s + 1 - i) // 4) + 1
                                                      for i in range(f))
    lp = load_loop(15, 15, FLOAT32, lanes=2, off=0)
    # LIO's f = s = 15 steps: 101 groups for 360 words (180 iterations two a cycle); depth
    # read + multiply + a tree of 4 (2 adds deep) + the partial sum + write: 2 + 3 + 3 * 4
    assert (lp.trip, lp.depth) == (wide_trip(0, 15, 15, 2), 17) and lp.trip <= 105
    assert load_loop(15, 15, FLOAT32).trip == 180


def test_the_wide_triangle_runs_two_rows_of_a_column_an_iteration():
    # f = 15: every column (⌈14 / 2⌉ = 7 rows an iteration at most) padded to the chain's 8
    assert triangle_trip(15, FLOAT32, lanes=2) == 14 * 8
    # f = 30 (a root): columns 17 … 29 take ⌈r / 2⌉ = 9 … 15
    assert triangle_trip(30, FLOAT32, lanes=2) == 16 * 8 + sum(-(-r // 2) for r in range(17, 30))
    for f in range(1, 40):
        assert (f - 1) * 8 <= triangle_trip(f, FLOAT32, lanes=2) <= triangle_trip(f, FLOAT32)
    # the solve is the triangle alone; the row loop runs in the load, after cond_load_wide,
    # folding PARTIALS sums, not 2 PARTIALS: max(4 (1 + 2), 15) + 3, the divide the longer path
    loops = {lp.name: lp for lp in backsub_loops(2, 3, FLOAT32, name="b", lanes=2)}
    assert list(loops) == ["b_triangle", "b_last"]
    # f = 2, s = 3: row 0 words 0 … 5 (groups 0, 1), row 1 words 7 … 11 (groups 1, 2)
    load = wide_load_loops(2, 3, FLOAT32, 2, 0, "c")
    assert [(lp.name, lp.trip, lp.depth) for lp in load] == [("c", 4, 17), ("c_rows", 2, 18)]
    assert wide_load_loops(0, 3, FLOAT32, 2, 0, "c")[0].trip == 0


def test_wide_backsub_operators_as_bound():
    # cond_load_wide: 4 multiplies, a tree of 3 adds and the partial sum's; rows: 3 fold adds
    # and the subtraction, the divide, the scaling; the triangle twice: 2 adds, 4 multiplies
    assert dict(backsub_operators(FLOAT32, lanes=2)) == {"add": 4 + 4 + 2, "mul": 4 + 1 + 4,
                                                          "div": 1}


def test_backsub_lanes_are_priced_and_checked():
    from fgc_backends.hls import HlsConfig, HlsConfigError
    program = chain(7, linear="cholesky", cpe=2)
    narrow = build_plan(program)
    wide = build_plan(program, PlanOptions.of(program, backsub_lanes=2))
    assert {m.name: m.banks for m in wide.memories}["cond"] == 2
    assert {m.name: m.banks for m in narrow.memories}["cond"] == 1
    assert dict(wide.unit("trisolve").operators) == dict(backsub_operators(wide.ops, 2))
    assert wide.unit("trisolve").instances == narrow.unit("trisolve").instances == 2
    # the slots priced with the wide loops (chain(7)'s small steps: the load's deeper pipeline
    # can cost more than its groups save; LIO's f = s = 15 steps gain, docs/hls.md)
    assert plan_cost(wide).cycles != plan_cost(narrow).cycles
    assert HlsConfig(backsub_lanes=2).plan_options(program).backsub_lanes == 2
    for bad in (0, 3, True):
        with pytest.raises(HlsConfigError, match="backsub_lanes"):
            HlsConfig(backsub_lanes=bad).check()


def test_the_streaming_designs_refuse_wide_back_substitution():
    # the window and incremental designs price back-substitution one lane wide (plan/update.py)
    from fgc_backends.hls import HlsConfig, HlsConfigError, emit

    class FakeLayout:  # emit refuses the option before it reads the layout
        template = None

    with pytest.raises(HlsConfigError, match="streaming designs"):
        emit(chain(4, linear="qr"), "/nonexistent", HlsConfig(backsub_lanes=2),
             stream=FakeLayout())


def _csim_against_the_simulator(graph, program, tmp_path, lanes, units=None):
    """Emit ``program`` with back-substitution ``lanes`` wide (2: two lanes, 4: by columns),
    double; its kernel defines that driver; with ``units`` (the elimination's header) the
    process network read back from the text is the plan's; the C simulation equals the
    simulator within 1e-9."""
    import numpy as np

    from fgc.ir.datafile import problem_data
    from fgc_backends import sim
    from fgc_backends.hls import HlsConfig, emit, run_csim
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.network import counts
    from fgc_backends.hls.plan import process_network

    config = HlsConfig(scalar="double", backsub_lanes=lanes)
    project = emit(program, tmp_path, config)
    text = (tmp_path / f"{program.name}.cpp").read_text()
    if lanes == 2:
        assert "#define FGC_BS_LANES 2" in text
    else:
        assert "#define FGC_BS_COLUMNS 1" in text and "#define FGC_BS_LANES" not in text
    if units is not None:
        # the process network read back from the text (the wide driver's backsub_lane<p>, the
        # column design's loader and ends) is the plan's
        procs, streams = process_network(accel_plan(program, config))
        include = tmp_path / "include"
        header = (include / units).read_text()
        if units == "fgc_cpe.h":  # the cascade's driver regions
            header += (include / "fgc_eliminate.h").read_text()
        assert counts(text, header, (include / "fgc_backsub.h").read_text()) == \
            (len(procs), len(streams))
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)  # the testbench checks it too
    assert result.status == reference.status
    for v in program.variables:  # double: 1e-9 relative to max(1, the largest entry)
        a, b = np.asarray(result.values[v.key]), np.asarray(reference.storage[v.key])
        assert np.max(np.abs(a - b)) <= 1e-9 * max(1.0, float(np.max(np.abs(b)))), v.key


def test_wide_back_substitution_matches_the_simulator_on_a_tree(tmp_path):
    """backsub_lanes=2 on a general elimination tree (pose_graph w100: steps of several
    children and many shapes, conditionals at every offset from a group boundary), LM,
    Cholesky, double: the C simulation equals the simulator within 1e-9."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    graph = example("pose_graph").build()
    program = compile_graph(graph, SolverConfig(linear="cholesky"), name="w100_wide")
    _csim_against_the_simulator(graph, program, tmp_path, 2, units="fgc_cpe.h")


# heavy (a second C simulation, ~20 s on 2 cores): the tree case above keeps the wide driver's
# results in the default run
@pytest.mark.heavy
def test_wide_back_substitution_matches_the_simulator_on_qr(tmp_path):
    """backsub_lanes=2 on a QR design (LIO N = 6, two unit sets: COND written by qr_commit two
    words a cycle into its two banks), LM, double: the C simulation equals the simulator within
    1e-9."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    graph = example("lio").build(N=6)
    program = compile_graph(graph, SolverConfig(linear="qr"), name="lio_wide")
    _csim_against_the_simulator(graph, program, tmp_path, 2, units="fgc_qr.h")


# ---- back-substitution by columns (HlsConfig backsub_lanes=4, the plan only: units/backsub.py's
# column design, docs/hls.md "Back-substitution by columns")

def test_the_column_design_finds_the_two_ends_of_a_chain():
    from fgc_backends.hls.units.backsub import column_chain, column_order
    tables = plan_tables(chain(7, linear="cholesky", cpe=2))
    end0, end1 = column_chain(tables)
    order = column_order(tables)
    assert end0[0] == order[0]  # the root first, on end 0
    assert sorted(end0 + end1) == sorted(order)  # every step on one end
    assert len(end0) - 1 >= 1 and len(end1) >= 1  # two ends below the root
    cols, cb, f_of, w_of = (tables[k] for k in ("STEP_COL", "STEP_COL_BEGIN", "STEP_F",
                                                  "STEP_W"))
    for seq in (end0, (end0[0], *end1)):  # a child's separator: its parent's columns
        for parent, child in zip(seq[:-1], seq[1:], strict=True):
            front = set(cols[cb[parent]:cb[parent] + f_of[parent]])
            assert set(cols[cb[child] + f_of[child]:cb[child] + w_of[child]]) <= front


def test_a_column_takes_its_rows_u_a_cycle_padded_to_the_chain():
    from fgc_backends.hls.units.backsub import column_len
    # LIO's f = s = 15 steps: column r its r rows above in blocks of 4 and the child's 15 in
    # blocks of 4, ⌈r / 4⌉ + 4 ≤ 8 = CHAIN + 1 for every r ≤ 14: 15 columns × 8
    assert sum(column_len(r, r, 15, FLOAT32) for r in range(15)) == 15 * 8
    # the last step (no child): columns 14 … 1 padded to 8, column 0 one iteration (x_0)
    assert sum(column_len(r, -1, 0, FLOAT32) for r in range(15)) == 14 * 8 + 1
    # the root's long columns take their blocks: ⌈29 / 4⌉ + ⌈15 / 4⌉ = 12
    assert column_len(29, 0, 15, FLOAT32) == 12 and column_len(29, -1, 15, FLOAT32) == 8
    # a feed pass (end 1 over the root's columns): the child's rows only, or x_r alone
    assert column_len(29, 3, 15, FLOAT32, feed=True) == 8
    assert column_len(29, -1, 15, FLOAT32, feed=True) == 1


def test_the_column_design_is_priced_and_refused_where_it_does_not_apply():
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls import HlsConfig, HlsConfigError
    from fgc_backends.hls.plan.model import PlanError
    from fgc_backends.hls.units.backsub import column_operators, column_schedule

    program = chain(9, linear="cholesky", cpe=2)
    narrow = build_plan(program)
    cols = build_plan(program, PlanOptions.of(program, backsub_lanes=4))
    assert {m.name: m.banks for m in cols.memories}["cond"] == 4
    unit = cols.unit("trisolve")
    assert unit.instances == 2 and dict(unit.operators) == dict(column_operators(cols.ops))
    # U = 4 multiply-subtracts, the ingestion's divide and 4 scaling multiplies
    assert dict(unit.operators) == {"add": 4, "mul": 8, "div": 1}
    ends, region = column_schedule(plan_tables(program), cols.ops)
    # the region: its slowest end plus the others' fill, no earlier than any pass's end
    assert region >= max(ends.values())
    bs = {ph.name: ph for ph in cols.phases}["backsub"]
    assert bs.processes[0].loops[0].cycles == region
    assert plan_cost(cols).cycles != plan_cost(narrow).cycles
    # a tree (pose_graph: steps with several children) is refused by name
    tree = compile_graph(example("pose_graph").build(), SolverConfig(linear="cholesky"),
                         name="w100")
    with pytest.raises(PlanError, match="backsub_lanes 4.*w100.*not a chain"):
        build_plan(tree, PlanOptions.of(tree, backsub_lanes=4))
    with pytest.raises(HlsConfigError, match="backsub_lanes"):
        HlsConfig(backsub_lanes=3).check()


def test_back_substitution_by_columns_matches_the_simulator(tmp_path):
    """backsub_lanes=4 on a two-ended chain (LIO N = 6: the root and two ends, every lane of
    both ends' passes, the feed pass and the loader's walk at several COND alignments), LM,
    Cholesky, double: the C simulation equals the simulator within 1e-9; the process network
    read back from the text is the plan's."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig

    graph = example("lio").build(N=6)
    program = compile_graph(graph, SolverConfig(method="lm", linear="cholesky", cpe=3),
                            name="lio_cols")
    _csim_against_the_simulator(graph, program, tmp_path, 4, units="fgc_cpe.h")


@pytest.mark.heavy
@pytest.mark.parametrize("case", ["serial", "qr"])
def test_columns_on_one_end_and_on_qr_match_the_simulator(tmp_path, case):
    """backsub_lanes=4 on a one-ended chain (LIO N = 5 serial: end 1 empty, no feed pass) and on
    QR (LIO N = 6 two-ended, n_u = 2: qr_commit writing COND), double: csim = simulator 1e-9."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls.units.backsub import column_chain

    if case == "serial":
        graph = example("lio").build(N=5)
        solver = SolverConfig(method="lm", linear="cholesky", cpe=3, ordering="serial")
    else:
        graph = example("lio").build(N=6)
        solver = SolverConfig(method="lm", linear="qr", ordering="two-ended", units=2)
    program = compile_graph(graph, solver, name=f"cols_{case}")
    assert (column_chain(plan_tables(program))[1] == ()) == (case == "serial")
    _csim_against_the_simulator(graph, program, tmp_path, 4)


def test_the_column_designs_state_update_keeps_up_with_both_ends():
    """backsub_lanes=4: two ends send their steps' solutions side by side into the one retire
    (backsub_retire_cols); its Pose3 datapath gets two special-function instances
    (STATE_ALLOCATION_COLUMNS), a variable every 22 cycles, so the retire ends within the last
    steps' variables after the ends' last sends (both ends end together: two steps of three
    variables). At the narrow limits (one instance, II 36) it falls behind the ends on
    imu_window."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls.plan.options import STATE_ALLOCATION, STATE_ALLOCATION_COLUMNS
    from fgc_backends.hls.units.backsub import column_schedule
    from fgc_backends.hls.units.state_update import retract_datapath

    program = compile_graph(example("imu_window").build(N=20),
                            SolverConfig(method="lm", linear="cholesky", cpe=5,
                                         precision="float32"), name="imu20")
    kinds = {v.type_name for v in program.variables}
    assert kinds == {"Pose3", "Vector3", "ImuBias"}
    cols = PlanOptions.of(program, backsub_lanes=4)
    assert cols.state_allocation == STATE_ALLOCATION_COLUMNS
    assert PlanOptions.of(program, backsub_lanes=2).state_allocation == STATE_ALLOCATION
    narrow = PlanOptions.of(program, backsub_lanes=4, state_limits=STATE_ALLOCATION)
    results = {}
    for name, opts in (("columns", cols), ("narrow", narrow)):
        plan = build_plan(program, opts)
        # the Pose3 datapath as bound: its special functions' instances (the emitter prints
        # the unit's operators as the ALLOCATION limits)
        pose = next(u for u in plan.units if u.role.endswith("of Pose3"))
        ii, depth = retire_timing(program.variables, plan.ops, max(
            s.frontal_dim for s in program.schedule.steps), opts.state_allocation)
        _, columns = column_schedule(plan_tables(program), plan.ops)
        solver, retire, _ = {ph.name: ph for ph in plan.phases}["backsub"].processes
        assert solver.loops[0].cycles == columns
        tail = sum(lp.cycles for lp in retire.loops)  # what the retire adds after the ends
        results[name] = (dict(pose.operators)["special"], ii, tail, depth, plan_cost(plan))
    special, ii, tail, depth, cost = results["columns"]
    assert (special, ii) == (2, 22) and retract_datapath("Pose3", FLOAT32,
                                                         STATE_ALLOCATION_COLUMNS)[1] == 22
    assert tail <= 2 * 3 * ii + depth  # the ends' last steps, then the datapath's depth
    special, ii, tail_narrow, depth, narrow_cost = results["narrow"]
    assert (special, ii) == (1, 36) and tail_narrow > 2 * 3 * ii + depth  # it falls behind
    assert cost.cycles < narrow_cost.cycles


def test_the_column_designs_trial_cost_reads_data_two_banks_and_keeps_up():
    """backsub_lanes=4: trial_cost reads DATA_BUF cyclic 2 through gather_trial_<b> (a line's
    words from the even address below it: trial_span), so the IMU cost's 193 data words take
    4 ports (trial_data_ii 49 against the slot designs' 97); each cost loop runs at the largest
    II that keeps trial_cost's end (keep_up_ii), never faster than one special-function
    instance allows here (72) nor slower than one bank (97). The slot designs keep one bank."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.cfamily.blocks import block_contexts
    from fgc_backends.hls.units.datapath import trial_data_ii, trial_span

    program = compile_graph(example("imu_window").build(N=20),
                            SolverConfig(method="lm", linear="cholesky", cpe=5,
                                         precision="float32"), name="imu20")
    plans = {bl: build_plan(program, PlanOptions.of(program, backsub_lanes=bl)) for bl in (1, 4)}
    banks = {bl: {m.name: m.banks for m in plan.memories}["data"] for bl, plan in plans.items()}
    assert banks == {1: 1, 4: 2}
    imu = next(i for i, b in enumerate(program.blocks) if b.name == "CombinedImuFactor")
    cost_ii = {bl: {p.name: p.loops[0].ii for ph in plan.phases for p in ph.processes
                    if p.loops}[f"factor_{imu}_cost"] for bl, plan in plans.items()}
    assert cost_ii[1] == 97 and 72 <= cost_ii[4] < 97
    bc = block_contexts(program, vector=False)[imu]  # 73 measurement, 120 noise words
    assert trial_span(bc) == {"lo": 0, "words": 194} and trial_data_ii(bc) == 49
