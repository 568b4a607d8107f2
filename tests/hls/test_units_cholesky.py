"""The Cholesky unit (backends/hls/units/cholesky.py): the cascade's round depth by hand, the
emitted multifrontal design and the what-if whole-matrix designs."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from hls_programs import chain

from fgc.app.specs import example
from fgc.ir.program import SolverConfig
from fgc_backends.cost.operators import FLOAT32
from fgc_backends.hls import HlsConfig
from fgc_backends.hls.plan import PlanOptions, build_plan, phase_cycles, plan_cost
from fgc_backends.hls.plan.loops import kernel_loop
from fgc_backends.hls.plan.model import Phase, Process
from fgc_backends.hls.units.cholesky import (
    cascade_process,
    cpe_depth,
    cpe_round_depth,
    cpe_step_loops,
    cpe_wait,
)


@pytest.fixture(scope="module")
def program():
    return chain(5, linear="cholesky", cpe=2)


def test_a_round_is_as_deep_as_what_each_process_adds_to_the_stream():
    # float32 on the xc7z045 at 143 MHz: add 4, mul 3, div 15. The feed La + 2 = 6; a CPE with
    # a pivot its tap 2 + its Update loop 2 Lm + La + 2 = 14; an idle tap and CPE nothing (the
    # stream leaves at the last pivot's CPE); the drain 2
    assert cpe_depth(FLOAT32) == 14
    assert cpe_round_depth(2, 3, FLOAT32) == 6 + 2 * 14 + 2
    assert cpe_round_depth(3, 3, FLOAT32, waits=5) == 6 + 3 * 14 + 5 + 2


def test_a_cpe_waits_for_its_reciprocal_only_after_a_short_row():
    # the tap's r = 1 / d comes Ld + 2 cycles after the pivot; the CPE needs it after the
    # pivot's row of w + 1 - p words
    assert cpe_wait(0, 30, FLOAT32) == 0  # 31 words
    assert cpe_wait(15, 30, FLOAT32) == 0  # 16 words, Ld = 15
    assert cpe_wait(29, 30, FLOAT32) == 13  # 2 words


def test_a_step_runs_one_round_per_cpe_pivots():
    loops = cpe_step_loops(5, 2, 2, FLOAT32, name="s")
    rounds = [lp for lp in loops if "_round" in lp.name]
    assert len(rounds) == 3  # ⌈5 / 2⌉
    w = 7
    assert rounds[0].trip == w * (w + 1) // 2 + w + 1  # + the status word
    # after each round but the last, the rows it leaves (2 ... 6, then 4 ... 6) back into H,
    # two words a cycle
    backs = [lp.trip for lp in loops if "_back" in lp.name]
    assert backs == [(5 * 6 // 2 + 5 + 1) // 2, (3 * 4 // 2 + 3 + 1) // 2]
    # one step's pivots (5) in one round of 20 CPEs: 15 idle taps and CPEs, which the stream
    # never reaches
    (one,) = [lp for lp in cpe_step_loops(5, 2, 20, FLOAT32) if "_round" in lp.name]
    assert one.depth == 6 + 5 * 14 + sum(cpe_wait(p, 7, FLOAT32) for p in range(5)) + 2


def test_more_cpes_than_a_steps_pivots_cost_no_cycles():
    # the round leaves the cascade at its last pivot's CPE (fgc_cpe.h's tail): 65 CPEs past a
    # step's 15 pivots add nothing (they added 2 cycles each when the stream passed them)
    few = sum(lp.cycles for lp in cpe_step_loops(15, 15, 15, FLOAT32))
    many = sum(lp.cycles for lp in cpe_step_loops(15, 15, 80, FLOAT32))
    assert many == few


def test_the_emitted_design_assembles_factors_and_the_cascade_stores_each_step(program):
    plan = build_plan(program, PlanOptions.of(program, hgc_beside=False))
    names = [ph.name for ph in plan.phases]
    assert names.index("hgc") < names.index("assemble") < names.index("cholesky_level0")
    assert "store" not in names  # the drain writes COND and NF
    assert plan.unit("cpe").instances == 2
    assert dict(plan.unit("cpe").operators) == {"add": 1, "mul": 2, "div": 1}
    assert sum(c.name.startswith("cpe_link") for c in plan.channels) == 2  # #CPE
    assert sum(c.name.startswith("cpe_tail") for c in plan.channels) == 2  # CPE K -> drain
    assert sum(c.name.startswith("cpe_tapped") for c in plan.channels) == 2
    assert sum(c.name.startswith("cpe_recip") for c in plan.channels) == 2
    assert {"gram", "frontal", "trailing", "cond", "nf"} <= {m.name for m in plan.memories}
    # no pass clears HF or GRAM
    loops = {lp.name for ph in plan.phases if ph.name == "assemble" for p in ph.processes
             for lp in p.loops}
    loops |= {lp.name for ph in plan.phases if ph.name == "hgc" for p in ph.processes
              if p.name.startswith("reduce_") for lp in p.loops}
    assert loops and not {"zero", "zero_gram"} & loops


@pytest.mark.parametrize("storage", ["dense", "blocked"])
def test_a_what_if_whole_matrix_design_has_its_own_phases(program, storage):
    plan = build_plan(program, PlanOptions.of(program, hessian_storage=storage))
    names = {ph.name for ph in plan.phases}
    assert {"cholesky", "cholesky_scalar", "trisolve"} <= names
    assert "assemble" not in names
    assert sum(c.name.startswith("cpe_fifo") for c in plan.channels) == 2
    # a chain's envelope is narrower than the dense triangle
    if storage == "blocked":
        dense = plan_cost(build_plan(program, PlanOptions.of(program, hessian_storage="dense")))
        assert plan_cost(plan).cycles < dense.cycles


def test_the_hgc_is_priced_per_block_type_as_its_gram_entries_bind_it():
    # a Pose2 chain: the between block (5 instances, m = 3 rows) gets a multiplier per row (its
    # entries at II 1: 3 multipliers, a tree of 2 adders), the prior (one instance) one
    # multiplier and one adder (II m = 3)
    from fgc_backends.hls.units.cholesky import gram_entries, gram_ii, hgc_operators

    program = chain(6, linear="cholesky")
    counts = {}
    for f in program.factors:
        counts[f.block] = counts.get(f.block, 0) + 1
    many = max(counts, key=counts.get)
    one = next(b for b, n in counts.items() if n == 1)
    m = program.blocks[many].residual_dim
    assert m == 3
    assert gram_ii(program, many, 32) == 1 and gram_ii(program, many, 2) == 2
    assert gram_ii(program, one, 32) == program.blocks[one].residual_dim
    ops = dict(hgc_operators(program, 32))
    # the tree's adders and the gradient's adder (the last row into G, in the same loop; at
    # the prior's II 3 one adder issues all three adds); the diagonal's finiteness check binds
    # no operator
    assert dict(ops[many]) == {"add": 2 + 1, "mul": 3}
    assert dict(ops[one]) == {"add": 1, "mul": 1}
    assert dict(hgc_operators(program, 2)[many][1]) == {"add": 2, "mul": 2}
    plan = build_plan(program)
    assert {f"hgc_{b}" for b in counts} <= {u.name for u in plan.units}
    (entries,) = [lp for ph in plan.phases if ph.name.startswith("hgc") for p in ph.processes
                  if p.name == f"reduce_{many}" for lp in p.loops if lp.name == "entries"]
    # a between factor's [A | b] is 3 x 7 (two poses and b), every entry of its packed
    # triangle structurally non-zero: 28 entries an instance, one a cycle, depth read +
    # multiply + a tree of ceil(log2 3) = 2 adds + the gradient's add + G read and the writes
    assert len(gram_entries(program.blocks[many])) == 28
    # all instances' entries one pipelined loop (the next instance's rows read alongside): the
    # HGC (28 entries an instance) is slower than the datapath, so a second lane over the
    # first rows takes some of them; paired (II 2: two lane-A entries and one lane-B entry an
    # iteration, which still ends within the datapath's loop), lane B a third: 10 iterations
    # an instance (more than m + 3 and than its last-row span + the add), one cycle
    # deeper
    from fgc_backends.hls.units.cholesky import gram_config, jacobian_cycles, jacobian_ii
    jac = [p for ph in plan.phases for p in ph.processes]
    lane_a, lane_b, k, paired = gram_config(program, many, 32, jacobian_ii(jac),
                                            jacobian_cycles(jac))
    assert paired and (len(lane_a), len(lane_b)) == (18, 10)
    assert (entries.trip, entries.ii, entries.repeat) == (10 * counts[many], 2, 1)
    assert entries.depth == 3 + 2 * 4 + 4 + 3 + 1
    # its operators at II 2: the two lane-A entries' 2m products on m multipliers, lane B's K
    # on ceil(K / 2)
    hgc = dict(plan.unit(f"hgc_{many}").operators)
    assert hgc == {"mul": m + -(-k // 2), "add": m + -(-(k - 1) // 2)}


def test_an_instance_of_few_gram_entries_is_padded_to_keep_its_hazards_apart(monkeypatch):
    # gram_entries' one loop over all instances declares no dependence on the row banks nor on
    # G: an instance takes at least m + 3 iterations (its successor's rows are read in the
    # first m) and at least its last row's span + the adder's latency + 3 (two instances' +=
    # into one entry of G); here a between block of 3 rows with 4 entries, two of them in the
    # last row (b^T A), one apart: 1 + 4 + 3 = 8 iterations an instance
    from fgc_backends.hls.plan.loops import kernel_timing
    from fgc_backends.hls.units import cholesky

    program = chain(6, linear="cholesky")
    counts = {}
    for f in program.factors:
        counts[f.block] = counts.get(f.block, 0) + 1
    many = max(counts, key=counts.get)
    timing = kernel_timing(FLOAT32)
    assert cholesky.gram_steps(program, many, timing) == 28  # its own 28 entries bind
    last = sum(program.blocks[many].variable_dims)
    monkeypatch.setattr(cholesky, "_gram_rows", lambda b: {
        (0, 0): (0,), (last, 0): (0,), (last, 1): (0,), (last, last): (0,)})
    assert cholesky.gram_steps(program, many, timing) == 1 + timing["acc"][0] + 3 == 8
    one = next(b for b, n in counts.items() if n == 1)  # one instance: nothing to keep apart
    assert cholesky.gram_steps(program, one, timing) == 4


def test_a_slower_hgc_gets_a_second_lane_over_the_first_rows():
    # the between block's HGC (28 entries an instance) is slower than its datapath: lane B of
    # K multipliers takes entries only the first K rows touch (never the last row: the += into
    # G stay in lane A), at most half of them; one lane when the datapath is the slower
    from fgc.ir.codes import NOISE_CODES
    from fgc_backends.cfamily.sparsity import block_pattern
    from fgc_backends.hls.units.cholesky import gram_entries, gram_lanes, hgc_operators

    program = chain(6, linear="cholesky")
    counts = {}
    for f in program.factors:
        counts[f.block] = counts.get(f.block, 0) + 1
    many = max(counts, key=counts.get)
    block = program.blocks[many]
    entries, last = gram_entries(block), sum(block.variable_dims)
    lane_a, lane_b, k = gram_lanes(program, many, 32, {many: 1})
    assert 0 < k < block.residual_dim and 0 < len(lane_b) <= len(entries) // 2
    assert sorted(lane_a + lane_b) == sorted(entries) and not set(lane_a) & set(lane_b)
    pattern = block_pattern(block, tuple(NOISE_CODES[m.noise_kind] for m in block.members), "t")
    assert all(p != last and max(pattern.gram_rows(p, q)) < k for p, q in lane_b)
    assert all((p, q) in lane_a for p, q in entries if p == last)
    assert len(lane_a) == len(entries) - len(entries) // 2
    ops = dict(dict(hgc_operators(program, 32, {many: 1}))[many])
    assert ops == {"add": 3 + k - 1, "mul": 3 + k}
    assert gram_lanes(program, many, 32, {many: 28}) == (entries, (), 0)  # datapath slower
    assert gram_lanes(program, many, 32, None) == (entries, (), 0)


def test_structurally_zero_gram_entries_are_never_computed():
    # a GPS-like block touching only a position: the entries (p, q) no whitened row touches
    # are left out of the tables (they keep GRAM's initial zeros)
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls.units.cholesky import gram_entries

    program = compile_graph(example("lio").build(N=3), SolverConfig(linear="cholesky"), name="g")
    gps = next(b for b in program.blocks if b.name == "GPSFactor")
    entries = gram_entries(gps)
    stride = sum(gps.variable_dims) + 1
    assert len(entries) < stride * (stride + 1) // 2
    assert (stride - 1, stride - 1) in entries  # b^T b
    assert all(q <= p < stride for p, q in entries)


def test_a_steps_first_factor_is_stored_two_entries_a_cycle(program):
    # HF is all zero when a step's assembly starts (the cascade clears what it reads): the
    # first factor's packed Gram is stored two entries a cycle after its column map; the other
    # factors and the children add one entry a cycle
    from fgc_backends.hls.plan.loops import _tables, kernel_timing
    from fgc_backends.hls.units.cholesky import assemble_loops

    tables, timing = _tables(program), kernel_timing(FLOAT32)
    fb, fs, cm = (tables[k] for k in ("STEP_FACTOR_BEGIN", "STEP_FACTORS",
                                      "FACTOR_COLMAP_BEGIN"))
    s = next(i for i in range(len(fb) - 1) if fb[i + 1] - fb[i] >= 2)
    loops = assemble_loops(tables, s, timing)
    d = [cm[fs[e] + 1] - cm[fs[e]] for e in range(fb[s], fb[s + 1])]
    assert [lp.name for lp in loops[:2]] == ["map", "gram_first"]
    assert loops[0].trip == d[0]
    assert (loops[1].trip, loops[1].ii) == (-(-(d[0] * (d[0] + 1) // 2 + d[0]) // 2), 1)
    gram = [lp for lp in loops if lp.name == "gram"]
    assert [lp.trip for lp in gram] == [x * (x + 1) // 2 + x for x in d[1:]]


def test_each_block_types_datapath_and_hgc_share_one_emitted_region(tmp_path):
    # the kernel as emitted: per block type a DATAFLOW region linearize_<b> of its datapath
    # (evaluate_<b>) and its HGC (reduce_<b>) linked by one row stream; the plan prices each as
    # phase hgc_level<b> with those two processes
    from fgc_backends.hls import HlsConfig, emit
    from fgc_backends.hls.config import DesignOptions
    from fgc_backends.hls.network import read_network

    program = chain(4, linear="cholesky", cpe=2)
    emit(program, tmp_path / "p", HlsConfig(design=DesignOptions(hgc_beside=False)))
    kernel = next(p for p in (tmp_path / "p").glob("*.cpp") if not p.name.startswith("tb_"))
    regions = {r.function: r for r in read_network(kernel.read_text())}
    plan = build_plan(program, PlanOptions.of(program, hgc_beside=False))
    levels = [ph for ph in plan.phases if ph.name.startswith("hgc_level")]
    assert levels and all(ph.dataflow for ph in levels)
    for ph in levels:
        b = ph.name.removeprefix("hgc_level")
        region = regions[f"linearize_{b}"]
        assert region.processes == (f"evaluate_{b}", f"reduce_{b}")
        assert len(region.streams) == 1
        assert [p.name for p in ph.processes] == [f"factor_{b}_jacobian", f"reduce_{b}"]
    assert "factor_jacobian" not in {ph.name for ph in plan.phases}


def test_a_steps_factor_grams_are_assembled_beside_the_cascade_before_it(program):
    # cholesky_eliminate_all: the steps' position parities, the first step's Grams before the
    # steps; per step (the t-th) its children of the other parity than t's (phase assemble: the
    # step before among them), then the cholesky_overlap region (phase cholesky_level<t>): the
    # cascade beside the assembler, which streams the step's words out two a cycle while it
    # stores the next step's first Gram into the other lane (one loop, the longer of the two),
    # then adds the next step's further Grams and its children from the NF lane step t's
    # cascade does not write
    from fgc_backends.hls.plan.loops import _tables, kernel_timing
    from fgc_backends.hls.units.cholesky import (
        assemble_loops,
        cpe_check_loops,
        cpe_pairs,
        first_gram_trip,
    )

    plan = build_plan(program, PlanOptions.of(program, hgc_beside=False))
    tables, timing = _tables(program), kernel_timing(FLOAT32)
    order = list(tables["LEVEL_STEPS"][:len(program.schedule.steps)])
    odd = {s: t % 2 for t, s in enumerate(order)}
    (assemble,) = [ph for ph in plan.phases if ph.name == "assemble"]
    lanes, first, *kids = assemble.processes
    assert lanes.loops[0].trip == len(order)
    assert first.name == "assemble_first"
    # the first step's first Gram: its column map (d iterations), 3 more, its packed entries
    # two a cycle, in the assembler's one loop with nothing to stream
    fb, fc = tables["STEP_FACTOR_BEGIN"], tables["FACTOR_COLMAP_BEGIN"]
    fac = tables["STEP_FACTORS"][fb[order[0]]]
    d = fc[fac + 1] - fc[fac]
    assert first.loops[0].name == "source"
    assert first.loops[0].trip == d + 3 + -(-(d * (d + 1) // 2 + d) // 2)
    assert all(lp.name == "child" for p in kids for lp in p.loops)
    *regions, check = [ph for ph in plan.phases if ph.name.startswith("cholesky_level")]
    assert len(regions) == len(order)
    # each step's pivot check off its cascade's path: in the next region's assembler, the last
    # step's in a pass of its own
    f = tables["STEP_F"]
    assert not check.dataflow and check.name == f"cholesky_level{len(order)}"
    assert list(check.processes[0].loops) == cpe_check_loops(f[order[-1]], FLOAT32,
                                                             f"s{order[-1]}")
    every = 0
    for t, (ph, s) in enumerate(zip(regions, order, strict=True)):
        assert ph.dataflow
        cascade, assembler = ph.processes
        assert cascade.name == f"cascade{s}" and assembler.name == f"assembler{s}"
        assert not any(lp.name.endswith(("_scale", "_pivot_check")) for lp in cascade.loops)
        assert assembler.loops[0].name == "source"
        nxt = order[t + 1] if t + 1 < len(order) else -1
        assert assembler.loops[0].trip == max(cpe_pairs(tables["STEP_W"][s]),
                                              first_gram_trip(tables, nxt))
        beside = [lp for lp in assemble_loops(tables, nxt, timing, odd=odd, par=1 - t % 2)
                  if lp.name not in ("map", "gram_first")] if nxt >= 0 else []
        if t > 0:
            prev = order[t - 1]
            beside += cpe_check_loops(f[prev], FLOAT32, f"s{prev}")
        assert list(assembler.loops[1:]) == beside
        # the region: the slower process plus the other's fill, not their sum
        assert phase_cycles(ph) < cascade.cycles + assembler.cycles
        every += sum(lp.name == "child" for lp in beside)
    # every child once: beside the cascade or alone
    between = sum(lp.name == "child" for p in kids for lp in p.loops)
    assert every + between == sum(len(assemble_loops(tables, s, timing, grams=False))
                                  for s in order)
    assert every > 0


def test_the_pivot_check_runs_where_the_elimination_is_faster():
    # one cascade: each step's pivot check ends its cascade (cpe_step) or runs in the next
    # region's assembler (FGC_CHECK_BESIDE); the plan prices both and keeps the faster (the
    # kernel defines FGC_CHECK_BESIDE when the plan's last pass is a "check": the imu_window
    # golden shows it). imu_window N = 50 at
    # #CPE = 20, two words: the cascade (round 525 + check 51) is the slower process, so the
    # check comes off its path (a step 576 -> 529 as the region)
    from fgc.compile import compile_graph
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.plan.loops import _tables, kernel_timing
    from fgc_backends.hls.units.cholesky import elimination_phases

    prog = compile_graph(example("imu_window").build(N=50), SolverConfig(
        method="lm", linear="cholesky", cpe=20, precision="float32"), name="imu")
    tables, timing = _tables(prog), kernel_timing(FLOAT32)
    order = list(tables["LEVEL_STEPS"][:len(prog.schedule.steps)])
    dims = {st.index: (st.frontal_dim, st.separator_dim) for st in prog.schedule.steps}
    cycles = {b: sum(phase_cycles(ph) for ph in elimination_phases(
        tables, order, dims, 20, FLOAT32, timing, 2, b)) for b in (False, True)}
    assert cycles[True] < cycles[False] - 40 * (len(order) - 1)
    plan = accel_plan(prog, HlsConfig(scalar="float", cascade_lanes=2, hgc_beside=False))
    got = sum(phase_cycles(ph) for ph in plan.phases
              if ph.name.startswith(("assemble", "cholesky_level")))
    assert got == min(cycles.values())
    assert any(p.name == "check" for ph in plan.phases for p in ph.processes)


def test_cpe_pairs_counts_two_words_of_a_row_a_pair():
    from fgc_backends.hls.units.cholesky import cpe_pairs

    for w in range(0, 40):
        assert cpe_pairs(w) == sum(-(-(w + 1 - i) // 2) for i in range(w))


def test_a_schedule_without_children_builds_and_matches_the_simulator(tmp_path):
    # one variable, one step: the kernel prints the children's tables empty, and the assembly's
    # children code is left out at compile time (g++ -Werror=array-bounds on the strict csim
    # build otherwise); the result equals the simulator's (double: 1e-9)
    import fgc
    from fgc import Vector2
    from fgc.compile import compile_graph
    from fgc.frontend.factors import PriorFactor
    from fgc.ir.datafile import problem_data
    from fgc.ir.program import SolverConfig
    from fgc_backends import sim
    from fgc_backends.hls import HlsConfig, emit, run_csim

    g = fgc.Graph()
    g.add_variable("p", Vector2([0.3, -0.2]))
    g.add(PriorFactor("p", Vector2([1.0, 2.0]), fgc.noise.isotropic(2, 0.1)))
    program = compile_graph(g, SolverConfig(method="gn", linear="cholesky"), name="one")
    assert len(program.schedule.steps) == 1
    project = emit(program, tmp_path / "one", HlsConfig(scalar="double"))
    data = problem_data(g, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)
    assert result.status == reference.status
    for key, value in reference.storage.items():
        assert abs(result.values[key] - value).max() <= 1e-9


def test_beside_a_slower_assembler_the_cascade_adds_its_feeds_depth():
    # a tree step with many factors (a pose graph's loop closures): the assembler streams the
    # step's words out first, then adds the next step's Grams for longer than the cascade
    # takes; what the cascade adds to the pass is its first loop's fill, the feed's La + 2 = 6
    # (fgc_cpe.h's cpe_feed, as the counting C simulation takes it), not its round's depth
    casc = cascade_process(0, 3, 6, 5, FLOAT32)
    assert casc.loops[0].name == "s0_round0" and casc.loops[0].depth > 6
    assert casc.fill == 6
    timing = {"move": (1, 2), "scatter": (1, 6)}
    slow = Process("assembler0", "cpe", tuple(
        [kernel_loop("source", 29, "move", timing)]
        + [kernel_loop("gram", 27, "scatter", timing)] * 11))
    assert slow.cycles > casc.cycles
    assert phase_cycles(Phase("p", True, (casc, slow))) == slow.cycles + 6
    # a step without pivots copies its words first: that copy's depth
    assert cascade_process(0, 0, 6, 5, FLOAT32).fill == 2


# the HGC before the elimination (hgc_beside off): heavy (another ~6 s); bench_cycles runs it
@pytest.mark.parametrize("beside", [pytest.param(False, marks=pytest.mark.heavy), True])
def test_a_tree_schedules_counted_cycles_equal_the_plan(beside):
    """pose_graph on w100_30.g2o (30 Pose2, 60 factors: a schedule with several children a
    step, steps of many factors), GN, float32, #CPE = 5: the counting C simulation's cholesky
    (hgc_beside on: hgc_beside) phase equals the plan's exactly, every group within 2 %. The
    plan before priced the cascade's fill as its round's depth: about 9 % above."""
    root = Path(__file__).resolve().parents[2]
    sys.path.insert(0, str(root / "bench"))
    from bench_cycles import measure

    graph = example("pose_graph").build(dataset="w100_30.g2o")
    solver = SolverConfig(method="gn", linear="cholesky", cpe=5, precision="float32")
    phases, events = measure("t", graph, solver, HlsConfig(scalar="float", hgc_beside=beside))
    group = "hgc_beside" if beside else "cholesky"
    counted, model = phases[group]
    assert events["solve"] >= 1 and counted > 0 and counted == model, (counted, model)
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)


def test_a_failed_solve_skips_back_substitution_as_priced():
    """imu_window N = 30, LM, float32, #CPE = 5: float32 Cholesky fails many solves there (not
    positive definite / a pivot too small: LM raises mu and re-solves), and a failed solve
    back-substitutes nothing. Back-substitution is priced per solve that did not fail (event
    ``backsub``), so the counted backsub phase equals the plan's; priced per solve it was
    about 1.8x the count."""
    root = Path(__file__).resolve().parents[2]
    sys.path.insert(0, str(root / "bench"))
    from bench_cycles import measure

    from fgc_backends.hls.plan import PHASE_TRIGGER

    assert PHASE_TRIGGER["backsub"] == "backsub"
    solver = SolverConfig(method="lm", linear="cholesky", cpe=5, precision="float32")
    phases, events = measure("t", example("imu_window").build(N=30), solver)
    assert events["solve"] - events["backsub"] >= 10 and events["backsub"] >= 1
    counted, model = phases["backsub"]
    assert counted > 0 and counted == model, (counted, model)
    for g in ("lm_control", "hgc_beside", "recholesky", "reassemble"):
        counted, model = phases[g]
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)
