"""The QR unit (backends/hls/units/qr.py): its unit sets, streams and memories as the plan holds
them, and its step loops."""

from __future__ import annotations

import numpy as np
import pytest
from hls_programs import chain

from fgc_backends.cost.operators import FLOAT32
from fgc_backends.hls.plan import PlanOptions, build_plan, phase_cycles
from fgc_backends.hls.units.qr import qr_unit_loops, root_bank_parity_words, unit_sets_of


@pytest.fixture(scope="module")
def two_ended():
    return chain(7, linear="qr")  # auto ordering: two-ended on a chain


@pytest.fixture(scope="module")
def serial():
    return chain(7, linear="qr", ordering="serial")


def test_unit_sets_default_to_two_on_a_two_ended_chain_and_are_capped(two_ended, serial):
    widest = max(len(level) for level in two_ended.schedule.levels)
    assert widest == 2
    assert unit_sets_of(two_ended, PlanOptions.of(two_ended)) == 2
    assert unit_sets_of(two_ended, PlanOptions.of(two_ended, unit_sets=5)) == widest
    assert unit_sets_of(serial, PlanOptions.of(serial)) == 1


@pytest.mark.parametrize("n_u", [1, 3])
def test_each_set_has_an_evaluate_unit_n_u_update_units_and_their_streams(two_ended, n_u):
    plan = build_plan(two_ended, PlanOptions.of(two_ended, units=n_u))
    for s in range(2):
        assert plan.unit(f"qr{s}_evaluate").instances == 1
        assert plan.unit(f"qr{s}_update").instances == n_u
        assert plan.unit(f"qr{s}_backsub").instances == 1
        mine = [c for c in plan.channels if c.name.startswith(f"qr{s}_")]
        # per Update unit: the vector, tau/R_jj, its column to Evaluate (a stream per row
        # parity), its row out; R_jj once; the Evaluate's vector and v_0 / tau / R_jj, and its
        # row j entry to collect
        assert sum(c.kind == "stream" for c in mine) == 5 * n_u + 4
        assert {f"qr{s}_col0_even", f"qr{s}_col0_odd"} <= {c.name for c in mine}
        assert {f"qr{s}_ve", f"qr{s}_te", f"qr{s}_e"} <= {c.name for c in mine}
        assert sum(c.kind == "pingpong" for c in mine) == 2
        work = next(m for m in plan.memories if m.name == f"qr{s}_work")
        assert work.banks == 2 * n_u  # each bank two memories by row parity
    assert {"cond", "nf"} <= {m.name for m in plan.memories}


def test_more_update_units_never_slow_a_step():
    pattern = np.ones((9, 6), dtype=bool)
    cycles = [sum(lp.cycles for lp in qr_unit_loops(pattern, 3, u, FLOAT32)) for u in (1, 2, 4)]
    assert cycles[0] > cycles[1] >= cycles[2]


def test_a_zero_row_costs_nothing_in_the_reflections():
    dense = np.ones((6, 4), dtype=bool)
    sparse = dense.copy()
    sparse[5] = False  # a row with no structural non-zero (a factor absent from this update)
    full = [lp.cycles for lp in qr_unit_loops(dense, 2, 2, FLOAT32)]
    less = [lp.cycles for lp in qr_unit_loops(sparse, 2, 2, FLOAT32)]
    assert sum(less) < sum(full)


def test_the_qr_phases_are_the_solvers_linear_phases(serial):
    plan = build_plan(serial)
    qr = [ph for ph in plan.phases if ph.name.startswith("qr_")]
    assert qr and all(ph.linear for ph in qr)
    assert sum(phase_cycles(ph) for ph in qr) > 0


def test_one_step_rows_go_straight_into_the_banks_and_leave_the_first_stack():
    """Under the one-step policy (GN, one iteration: one linearisation, one solve) the factors
    of level 0's first steps (one per unit set) are written by the datapaths into their set's
    banks at the rows the stack would give them; the plan's level-0 stack of those steps has no
    factor rows loop, and every other stack, and LM's, keeps its own."""
    from fgc_backends.hls.plan.loops import _tables
    from fgc_backends.hls.units.qr import rows_in_banks

    one = chain(7, linear="qr", method="gn", max_iterations=1)
    lm = chain(7, linear="qr")
    t = _tables(one)
    banked = rows_in_banks(one, PlanOptions.of(one), t)
    assert rows_in_banks(lm, PlanOptions.of(lm), _tables(lm)) == {}
    first = t["LEVEL_STEPS"][:2]
    fb, cb = t["STEP_FACTOR_BEGIN"], t["FACTOR_COLMAP_BEGIN"]
    expected = {}
    for u, s in enumerate(first):
        row = 0
        for e in range(fb[s], fb[s + 1]):
            f = t["STEP_FACTORS"][e]
            expected[f] = (u, s, row)
            row += (t["FACTOR_A_OFF"][f + 1] - t["FACTOR_A_OFF"][f]) // (cb[f + 1] - cb[f] + 1)
        assert 0 < row <= t["STEP_ROWS"][s]
    assert banked == expected

    def stacks(program):
        plan = build_plan(program, PlanOptions.of(program))
        return {p.name: [lp.name for lp in p.loops] for ph in plan.phases
                if ph.name.startswith("qr_stack_level") for p in ph.processes}

    mine, theirs = stacks(one), stacks(lm)
    for s in first:
        assert "factor_rows" not in mine[f"stack{s}"]
        assert "factor_rows" in theirs[f"stack{s}"]
    later = [n for n in mine if n.startswith("stack") and int(n[5:]) not in first
             and fb[int(n[5:]) + 1] > fb[int(n[5:])]]  # the later steps with factors of their own
    assert later and all("factor_rows" in mine[n] for n in later)


# ---- two rows a cycle (PlanOptions / HlsConfig qr_rows = 2: fgc_qr.h's FGC_QR_TWO_ROWS) --------


def test_two_rows_a_cycle_price_a_column_by_the_longer_row_parity_lane():
    """qr_unit_loops(qr_rows=2): a reflection's words below the pivot go in two lanes by row
    parity, so a dense step (lanes even) takes far fewer of the Update units' cycles, and a step
    whose rows are all even (one lane holds every word) gains almost nothing."""
    from fgc_backends.hls.plan import PlanError

    def cycles(pattern, rows):
        return sum(lp.cycles for lp in qr_unit_loops(pattern, 10, 4, FLOAT32, qr_rows=rows))

    dense = np.ones((40, 20), dtype=bool)
    assert cycles(dense, 2) < 0.75 * cycles(dense, 1)
    even = dense.copy()
    even[1::2] = False  # the odd rows empty: reflection j's words below the pivot all even
    assert cycles(even, 1) >= cycles(even, 2) > 0.98 * cycles(even, 1)
    with pytest.raises(PlanError, match="qr_rows 3"):
        qr_unit_loops(dense, 10, 4, FLOAT32, qr_rows=3)


def test_two_rows_a_cycle_cost_two_adders_and_two_multipliers_an_update_unit(two_ended):
    """An Update unit's dot_axpy two rows an iteration: P + 3 adders and 5 multipliers (the
    dot's two products and their sum, the fold, the scale, the axpy's two multiply-adds) where
    one row takes P + 1 and 3; the Evaluate is unchanged; the broadcast's stream a pair wide."""
    one = build_plan(two_ended, PlanOptions.of(two_ended, units=3))
    two = build_plan(two_ended, PlanOptions.of(two_ended, units=3, qr_rows=2))
    for s in range(2):
        a, b = dict(one.unit(f"qr{s}_update").operators), dict(two.unit(f"qr{s}_update").operators)
        assert (b["add"] - a["add"], b["mul"] - a["mul"]) == (2, 2)
        assert b["mul"] == 5 and two.unit(f"qr{s}_update").instances == 3
        assert two.unit(f"qr{s}_evaluate") == one.unit(f"qr{s}_evaluate")
        width = {c.name: c.width for c in one.channels}
        assert all(c.width == 2 * width[c.name] for c in two.channels
                   if c.name.startswith(f"qr{s}_v") and c.name[len(f"qr{s}_v"):].isdigit())


def test_qr_rows_is_checked_and_reaches_the_emitted_kernel(tmp_path):
    """HlsConfig qr_rows: 1 or 2, the Householder unit's, a QR Program's; 2 defines
    FGC_QR_TWO_ROWS before fgc_qr.h in the kernel and prices the plan with it; 1 (the default)
    emits no such line."""
    from fgc_backends.hls import emit
    from fgc_backends.hls.config import DesignOptions, HlsConfig, HlsConfigError
    from fgc_backends.hls.emitter import accel_plan

    for bad, message in (({"qr_rows": 3}, "qr_rows must be one of"),
                         ({"qr_rows": True}, "qr_rows must be one of"),
                         ({"qr_rows": 2, "qr_unit": "stream"}, "not qr_unit 'stream'")):
        with pytest.raises(HlsConfigError, match=message):
            DesignOptions(**bad).check()
    with pytest.raises(HlsConfigError, match="this Program solves with cholesky"):
        HlsConfig(qr_rows=2).check(chain(4, linear="cholesky"))
    program = chain(4, linear="qr")
    two = emit(program, tmp_path / "two", HlsConfig(scalar="float", qr_rows=2))
    text = (tmp_path / "two" / f"{two.name}.cpp").read_text()
    assert text.index("#define FGC_QR_TWO_ROWS 1") < text.index('#include "fgc_qr.h"')
    assert two.config.qr_rows == 2
    assert accel_plan(program, two.config).options.qr_rows == 2
    one = emit(program, tmp_path / "one", HlsConfig(scalar="float"))
    assert "FGC_QR_TWO_ROWS" not in (tmp_path / "one" / f"{one.name}.cpp").read_text()


# heavy (a double LIO design's C simulation and a float one's counting run, about a minute on
# 2 cores): tests/hls/test_hls_units.py keeps the unit's results and counted cycles with two rows
# a cycle in the default run
@pytest.mark.heavy
def test_two_rows_a_cycle_match_the_simulator_and_count_their_price(tmp_path):
    """qr_rows=2 (FGC_QR_TWO_ROWS) in a whole design: the C simulation of LIO (LM, double, n_u
    3, two unit sets) equals the simulator within 1e-9, and a Gauss-Newton float run's counted
    cycles equal the plan's per phase within 2 %."""
    import sys
    from pathlib import Path

    from test_hls_csim import _check_against_reference

    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.datafile import problem_data
    from fgc.ir.program import SolverConfig
    from fgc_backends import sim
    from fgc_backends.hls import HlsConfig, emit, run_csim

    lio = example("lio")
    graph = lio.build(N=6)
    program = compile_graph(graph, SolverConfig(linear="qr", units=3), name="lio_rows")
    project = emit(program, tmp_path, HlsConfig(scalar="double", qr_rows=2))
    assert "#define FGC_QR_TWO_ROWS 1" in (tmp_path / "lio_rows.cpp").read_text()
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)
    _check_against_reference("lio_rows", program, result, reference, "double")

    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="gn", linear="qr", units=3, precision="float32")
    phases, _ = measure("t", graph, solver, HlsConfig(scalar="float", qr_rows=2))
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)
    assert phases["qr"][0] > 0


def test_the_roots_rows_split_by_row_parity_word_by_word():
    """lin_level's wave sends the root's own rows as two streams by stack row parity: a word
    (two values in AB's order) on rows of one parity goes whole, one spanning two rows half
    into each. Factor 0: 3 rows of 5 words (rows 0-2), factor 1: 1 row of 4 (row 3)."""
    tables = {"STEP_FACTOR_BEGIN": [0, 2], "STEP_FACTORS": [0, 1],
              "FACTOR_A_OFF": [0, 15, 19], "FACTOR_COLMAP_BEGIN": [0, 4, 7]}
    # factor 0's words 0-1, 2-3 (row 0), 4-5 (rows 0 and 1: both), 6-7, 8-9 (row 1),
    # 10-11, 12-13, 14 (row 2); factor 1's 0-1, 2-3 (row 3)
    assert root_bank_parity_words(tables, 0) == (6, 5)

