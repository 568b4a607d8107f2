"""Tests of the accelerator plan (backends/hls/plan/) and its operator table (operators.py).

Cheap: a 3-pose Pose2 chain compiles in well under a second from a warm cache. The cost
arithmetic is checked against hand computations written out below from the float32 table
(the xc7z045 at 143 MHz: add 4, mul 3, div 15, sqrt 15, compare 1, sincos 40 cycles; add 2
DSP, mul 3 DSP).
"""

from __future__ import annotations

import dataclasses

import pytest
from hls_programs import chain_graph

import fgc
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose3
from fgc.ir.program import KernelText, SolverConfig
from fgc_backends.cfamily.retract import retract_kernel, variable_class
from fgc_backends.cost import operators
from fgc_backends.cost.kernels import critical_path
from fgc_backends.hls.plan import (
    PART_DSP,
    AcceleratorPlan,
    Loop,
    Memory,
    Phase,
    PlanError,
    PlanOptions,
    Process,
    Unit,
    _sim_table,
    build_plan,
    dot_loop,
    plan_cost,
)
from fgc_backends.hls.units.state_update import retract_datapath

F32 = operators.FLOAT32


def _chain(linear: str, precision: str = "float32", **solver) -> fgc.ir.program.Program:
    method = "gn" if linear == "qr" else "lm"
    return compile_graph(chain_graph(3), SolverConfig(method=method, linear=linear,
                                                      precision=precision, **solver))


@pytest.fixture(scope="module")
def qr_chain():
    return _chain("qr", units=2)


@pytest.fixture(scope="module")
def chol_chain():
    return _chain("cholesky", cpe=1)


# -- the operator table ----------------------------------------------------------------------


def test_table_is_frozen_and_every_entry_has_a_source():
    for t in operators.TABLES.values():
        for kind, op in t.entries():
            assert op.source and op.status in ("documented", "assumed"), kind
            assert op.latency >= 1 and min(op.dsp, op.lut, op.ff) >= 0, kind
        with pytest.raises(dataclasses.FrozenInstanceError):
            t.add = t.mul
        with pytest.raises(dataclasses.FrozenInstanceError):
            t.add.latency = 1
    with pytest.raises(ValueError, match="source"):
        operators.Operator(1, 0, 0, 0, "", "assumed")
    with pytest.raises(ValueError, match="status"):
        operators.Operator(1, 0, 0, 0, "x", "guessed")
    assert F32.op("trig") is F32.sincos
    with pytest.raises(ValueError, match="float16"):
        operators.table("float16")


# -- the cost arithmetic on hand-made and hand-checked cases ---------------------------------


def test_dot_loop_ii_from_adder_latency():
    # adder latency 4: one partial sum -> II 4; 3 partial sums -> II 2; 4 -> II 1
    assert F32.add.latency == 4 and F32.mul.latency == 3
    assert dot_loop("d", 20, F32, partials=1).ii == 4
    assert dot_loop("d", 20, F32, partials=3).ii == 2
    d = dot_loop("d", 20, F32)
    # k = 4 partial sums: II 1, depth mul 3 + add 4 × (1 + ⌈log2 4⌉ = 2) = 15; 19 + 15 = 34
    assert (d.ii, d.depth, d.cycles) == (1, 15, 34)


def test_cost_of_a_hand_made_plan():
    a = Process("a", "u", (Loop("a0", 10, 2, 7), Loop("a1", 3, 1, 4, repeat=2)))  # 25 + 12
    b = Process("b", "u", (Loop("b0", 5, 1, 9),))  # 13
    plan = AcceleratorPlan(
        "hand", "qr", "float32", 143.0, PlanOptions(),
        units=(Unit("u", "x", 3, (("add", 2), ("mul", 1)), extra_dsp=1),),
        memories=(Memory("m", 2048, 32, 2), Memory("small", 16, 32, 1)),
        channels=(), phases=(Phase("flow", True, (a, b)), Phase("seq", False, (a, b))),
        ops=F32)
    c = plan_cost(plan)
    # dataflow: slowest (a: 37) + fill of b (its first depth, 9) = 46; sequential 37 + 13 = 50
    assert c.phase_cycles == (("flow", 46), ("seq", 50)) and c.cycles == 96
    # 3 instances × (2 adds × 2 + 1 mul × 3 + 1 extra) = 24 DSP
    assert c.dsp == 24 and c.dsp_by_unit == (("u", 24),) and c.lut == 3 * (2 * 220 + 80)
    # 2048 words × 32 bits in 2 banks: 1024 words a bank = 2 BRAM18 a bank -> 4 BRAM18 = 2
    # BRAM36; 16 × 32 bits = 512 bits stay in LUTRAM
    assert c.bram36 == 2.0 and c.fits
    assert c.latency_ms == pytest.approx(96 / 143e3)


def test_pose2_chain_phases_by_hand(qr_chain):
    plan = build_plan(qr_chain)
    c = plan_cost(plan)
    phases = dict(c.phase_cycles)
    # retract: the Pose2 datapath (the state update's default limits add 4, mul 6, trig 2,
    # special 1) for the retraction's 8 adds, 17 multiplies, 2 sin/cos and 2 special functions;
    # II = max(8 / 4, ⌈17 / 6⌉, 2 / 2, 2 specials x II 12 / 1) = 24; its depth is the
    # retraction's critical path. It runs in back_substitute's region (below), no phase apart
    allocated, ii, depth = retract_datapath("Pose2", F32)
    assert dict(allocated) == {"add": 4, "mul": 6, "trig": 2, "special": 1} and ii == 24
    assert depth == critical_path(KernelText.of(retract_kernel(variable_class("Pose2"))),
                                  _sim_table(F32))
    assert "state_update" not in phases
    # LM control, every loop two words a cycle (two lanes of partials). Per linearisation the
    # gradient's largest entry and |x| in one loop over the 12 storage words (6 iterations):
    # the maxima (9 entries, 2 x 1 = compare latency partials: II 1, depth |.| 2 + compare 1
    # (1 + ⌈log₂ 2⌉) = 4), |x|² (2 x 4 partial sums: II 1, depth mul 3 + add 4 (1 + ⌈log₂ 8⌉)
    # = 19): 5 + 19 = 24; per solve: the step test (9 entries, 5 iterations, 2 x 4 partial
    # sums of δ·δ and δ·g: depth 19, then μ‖δ‖² and its add 7: 26 -> 30), the decision (div 15
    # + 2 mul + 2 add + compare 1 = 30); per accepted step: x copied (12 words two a cycle,
    # depth 2: 7)
    assert phases["lm_iteration"] == 24
    assert phases["lm_control"] == 30 + 30
    assert phases["lm_accept"] == 7
    # back-substitution (fgc_backsub.h; backsub.py's slots: a step's cond_backsub and its
    # solution out on one lane beside the next step's cond_load into the other, copies two words
    # a cycle). Steps root (f 3, s 0), then A and B (f 3, s 3), both separators in the root's
    # frontal columns. The root's load is its commit's (qr_commit writes lane 0's buffer as it
    # writes COND: backsub.py's root_in_commit), so slot 0 (the root's load) is not run; slot 1
    # solves the root (the rows 3 at max(add 4 (1 + ⌈log₂ 8⌉), div 15) + the scaling mul 3 = 19
    # deep: 21; the triangle's columns 2 and 1 each padded to the chain mul + add = 7, plus one:
    # 16 iterations 2 mul + add = 10 deep: 25; x_0 a move 1 -> 47; its 3 unknowns out (2 + 1:
    # 3) -> 50) and, beside it, A's R and d, which need no solution (backsub_parts: 3 + 2 + 1
    # + 3 = 9 words, 5 iterations 9 deep: 13): the slower plus the other's fill, max(50 + 9,
    # 13 + 19) = 59 — but A's separator is the root's frontal columns 0 … 2 in order and a
    # column of A's S is ⌈3 / 2⌉ = 2 iterations, no longer than the triangle's spacing (8), so
    # A's S streams in as the root's x arrives (units/backsub.py's streamed_s, cond_load's part
    # 3): A's R and d (5 iterations) then S column by column (3 x 2), 11 iterations 2 + mul 3 +
    # add 4 = 9 deep: 19, and no earlier than x_0 (47) + 2 - 1 + 9 = 57; the slot max(50 + 9,
    # 57 + 19) = 76, and no slot loads A's S alone. The next slot: A's solve and solution out
    # (50) beside B's load (7 + 6 + 5 = 18 words: 9 + 8 = 17), the slower plus the other's fill
    # (9) -> 59 (B loads into lane 0, whose last solve is the root: its separator is read from
    # that lane's solution, no copy in from DELTA); the last solves B -> 50: the slots end at 76,
    # 135, 185. Beside them the state update (backsub_retire: a variable an iteration at
    # II 24, 2 + depth deep: a step's 3 words in, a pair a cycle, then the datapath) retracts
    # the root at 76, A when it is sent at 135, B at 185: it ends at 185 + 2 + depth. Beside
    # them the cost at X_TRIAL (trial_cost, issue 33), fed the retired variables (x1, x0, x2:
    # the root's, A's, B's) as they end (78, 137, 187 + depth): the datapaths' loops one after
    # another, the one with more work first (the prior: 1 instance x II 24 against the between
    # factors' 2 x 12, a tie: block order), each its cost-mode II and depth + 2 (the taken
    # words written and read) where it takes variables. The prior's loop takes x1 in an entry
    # of its own (one variable an entry: its instances have one), then x0 and costs the prior
    # at 137 + depth; the between factors' loop starts when it has drained, costs x0-x1 (all
    # taken) and then x1-x2 once x2 is in (187 + depth); the phase ends with it.
    by_name = {ph.name: ph for ph in plan.phases}
    plan_phase = by_name["backsub"]
    slots, retire, cost = plan_phase.processes
    sizes = [sum(lp.cycles for lp in slots.loops[2 * k:2 * k + 2]) for k in range(3)]
    assert sizes == [76, 59, 50] and len(slots.loops) == 6
    assert retire.loops[0].cycles == 2 + depth
    (ii0, d0), (ii1, d1) = [(p.loops[0].ii, p.loops[0].depth)
                            for p in by_name["factor_cost"].processes[1:]]
    assert (ii0, ii1) == (24, 12)
    # In one process: 136 + depth + d0 + 2 for the prior, then the between factors' loop. The
    # plan runs them as two (units/datapath.py's slot_split_loops), as that ends sooner: the
    # between factors in trial_cost (after sending the prior's 7 data words: 8 cycles), x1 and
    # x0 taken at 137 + depth, x2 an II later or when it is in (187 + depth); the prior beside
    # them in trial_cost_b (its words in: 9), x0 at 137 + depth, ending d0 + 2 later
    one = max(137 + depth + d0 + 2 + ii1, 187 + depth) + d1 + 2
    prior = 137 + depth + d0 + 2
    end = max(137 + depth + ii1, 187 + depth) + d1 + 2
    assert prior < end < one
    assert cost.loops[0].cycles == end - (185 + 2 + depth)
    assert phases["backsub"] == end
    assert "factor_cost" not in phases  # the cost at X: once per call
    assert by_name["factor_cost"].per == "call"
    assert c.cycles == sum(phases.values())
    assert c.linear_cycles == sum(v for k, v in phases.items()
                                  if k.startswith(("qr_", "backsub")))


def _is_update(unit) -> bool:
    return unit.name.startswith("qr") and unit.name.endswith("_update")


# -- the plan follows the options -------------------------------------------------------------


def test_update_units_follow_n_u(qr_chain):
    plans = {u: build_plan(qr_chain, PlanOptions.of(qr_chain, units=u)) for u in (1, 3)}
    sets = sum(1 for u in plans[1].units if _is_update(u))
    assert sets == 2  # two-ended chain: two QR unit sets
    for n_u, plan in plans.items():
        assert all(u.instances == n_u for u in plan.units if _is_update(u))
    costs = {u: plan_cost(p) for u, p in plans.items()}
    # each extra Update unit is what fgc_qr.h's qr_update binds (units/qr.py's
    # householder_loops): P + 1 adders and 3 multipliers (dot_axpy's two multiply-adds and its
    # fold's P - 1 adders and scale; P = PARTIALS = the adder latency; the next pivot column's
    # update is the Evaluate's)
    tab = plans[1].target.ops(plans[1].precision)
    per_unit = (tab.add.latency + 1) * tab.add.dsp + 3 * tab.mul.dsp
    assert costs[3].dsp - costs[1].dsp == sets * 2 * per_unit
    # more Update units shorten a step wide enough to share: a Pose3 chain's (the Pose2 chain's
    # 3-column steps gain nothing past one unit, and each unit's fill costs a few cycles there)
    g = fgc.Graph()
    for i in range(6):
        g.add_variable(f"x{i}", Pose3())
    g.add(PriorFactor("x0", Pose3(), fgc.noise.isotropic(6, 0.1)))
    for i in range(5):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose3(), fgc.noise.isotropic(6, 0.1)))
    wide = compile_graph(g, SolverConfig(method="gn", linear="qr", precision="float32"))
    linear = [plan_cost(build_plan(wide, PlanOptions.of(wide, units=u))).linear_cycles
              for u in (1, 2, 3)]
    assert linear[0] > linear[1] > linear[2]
    one_set = build_plan(qr_chain, PlanOptions.of(qr_chain, unit_sets=1))
    assert sum(1 for u in one_set.units if _is_update(u)) == 1


def test_cpe_cascade_follows_cpe(chol_chain):
    n = chol_chain.storage.columns
    assert n == 9
    plans = {c: build_plan(chol_chain, PlanOptions.of(chol_chain, cpe=c, hgc_beside=False))
             for c in (1, 3)}
    for c, plan in plans.items():
        assert plan.unit("cpe").instances == c
        assert sum(1 for ch in plan.channels if ch.name.startswith("cpe_link")) == c
        assert sum(1 for ch in plan.channels if ch.name.startswith("cpe_tail")) == c
        # per step (multifrontal, as emitted; its cascade in its cholesky_level<t> region
        # beside the assembler) ⌈f / #CPE⌉ rounds; round r streams the step's trailing
        # m = w - r·c rows of [H | g], upper triangle plus g: m(m+1)/2 + m words, and the
        # status word
        steps = {st.index: st for st in chol_chain.schedule.steps}
        # (with the pivot check beside the next step, a last cholesky_level phase runs the last
        # step's check alone: its process is "check", not a cascade)
        levels = [ph for ph in plan.phases if ph.name.startswith("cholesky_level")]
        assert all(ph.processes[0].name == "check" for ph in levels
                   if not ph.processes[0].name.startswith("cascade"))
        cascades = [ph.processes[0] for ph in levels if ph.processes[0].name.startswith("cascade")]
        assert sorted(int(p.name.removeprefix("cascade")) for p in cascades) == sorted(steps)
        for cascade in cascades:
            st = steps[int(cascade.name.removeprefix("cascade"))]
            w, f = st.frontal_dim + st.separator_dim, st.frontal_dim
            want = [(w - r * c) * (w - r * c + 1) // 2 + w - r * c + 1
                    for r in range(-(-f // c))]
            # (cpe_step's copies back, scale and pivot-check loops are priced too)
            assert [lp.trip for lp in cascade.loops if "_round" in lp.name] == want
    c1, c3 = plan_cost(plans[1]), plan_cost(plans[3])
    assert c3.dsp - c1.dsp == 2 * 8  # a float32 CPE: add 2 + two mul 3 each = 8 DSP
    assert c3.cycles < c1.cycles


def test_fits_or_says_it_does_not(qr_chain, chol_chain):
    for p in (qr_chain, chol_chain):
        c = plan_cost(build_plan(p))
        assert c.fits and c.dsp <= PART_DSP and c.over == ()
    big = plan_cost(build_plan(chol_chain, PlanOptions.of(chol_chain, cpe=200)))
    assert not big.fits and "DSP" in big.over and big.dsp > PART_DSP


def test_bad_options_are_named(qr_chain):
    with pytest.raises(PlanError, match="units"):
        build_plan(qr_chain, PlanOptions.of(qr_chain, units=0))
    with pytest.raises(PlanError, match="ALLOCATION limit of mul"):
        build_plan(qr_chain, PlanOptions(allocation=(("mul", 0),)))


@pytest.mark.parametrize("linear", ["qr", "cholesky"])
def test_the_plan_prices_the_scalar_the_hls_config_emits(linear):
    """A float design emitted for a float64 Program is priced in float32 operators and 32-bit
    words (PlanOptions.for_config), as its unit headers' latencies are: the Program's precision
    would price float64 cores the design does not hold."""
    from fgc_backends.hls import HlsConfig
    from fgc_backends.hls.emitter import accel_plan

    program = _chain(linear, precision="float64")
    assert program.solver.precision == "float64"
    plan = accel_plan(program, HlsConfig(scalar="float"))
    assert plan.ops.precision == "float32" and plan.precision == "float32"
    assert {m.width for m in plan.memories} == {32}
    f32 = operators.table("float32")
    streams = [ch for ch in plan.channels if ch.kind == "stream"]
    if linear == "qr":  # the reflector streams to the Update units are 2 adder latencies deep
        # (fgc_qr.h's V_DEPTH; the Evaluate gets only the header, qr<s>_ve, 2 deep)
        reflector = [ch for ch in streams if ch.name.split("_")[-1][:1] == "v"
                     and ch.name.split("_")[-1][1:].isdigit()]
        assert reflector and {ch.depth for ch in reflector} == {2 * f32.add.latency}
    # the same design (back-substitution's width as the config resolves it for this chain)
    as_program = build_plan(program, PlanOptions.of(program,
                                                    backsub_lanes=plan.options.backsub_lanes))
    assert as_program.ops.precision == "float64"
    assert plan_cost(plan).cycles < plan_cost(as_program).cycles
    # a double design of the same Program is priced as the Program says
    same = accel_plan(program, HlsConfig(scalar="double"))
    assert plan_cost(same) == plan_cost(build_plan(program, PlanOptions.for_config(
        HlsConfig(scalar="double"), program)))
    assert plan_cost(same).cycles == plan_cost(as_program).cycles


def test_allocation_follows_the_instances():
    """A block type's datapath gets ⌈limit × instances / most instances⌉ of each operator
    (PlanOptions.allocation_scaling "instances"): imu_window N = 50's once-evaluated priors no
    longer hold the IMU datapath's 24 multipliers, which is what let #CPE = 80 fit the
    xc7z045's 900 DSP as the plan priced it before issue 32; a one-instance datapath's depth is
    at least its operators' issue time, and the priced cycles stay within 0.1 % of the uniform
    allocation's here."""
    from fgc.app.specs import example

    program = compile_graph(example("imu_window").build(N=50),
                            SolverConfig(linear="cholesky", cpe=40, precision="float32"))
    scaled = build_plan(program)
    uniform = build_plan(program, PlanOptions.of(program, allocation_scaling="uniform"))
    imu = next(i for i, b in enumerate(program.blocks) if b.name.startswith("CombinedImu"))
    prior = next(i for i, b in enumerate(program.blocks) if b.name == "PriorFactorPose3")
    # the emitted ALLOCATION limits (the unit's operators are what Vitis binds around them)
    from fgc_backends.hls.units.datapath import factor_allocation
    limits = factor_allocation(program, scaled.options)
    assert limits[imu] == factor_allocation(program, uniform.options)[imu]
    assert dict(limits[prior])["mul"] == 1  # ⌈24 × 1 / 49⌉
    a, b = plan_cost(scaled), plan_cost(uniform)
    # scaling saves DSP (priced as Vitis binds the loops, issue 32, neither fits #CPE = 80 on
    # the xc7z045 any more: the factor datapaths' two call sites and whitening count)
    assert a.dsp < b.dsp and not b.fits and "DSP" in b.over
    # the cycles move only where a one-instance datapath now waits for its operators to issue
    # (at the 143 MHz latencies the prior's issue time, not its critical path, sets its depth)
    # (Cholesky: a datapath's Jacobian pass runs in its block type's hgc_level<b> region)
    moved = {k for k, v in a.phase_cycles if v != dict(b.phase_cycles)[k]}
    one = {f.block for f in program.factors} - {imu}
    assert moved <= {"factor_jacobian", "factor_cost"} | {f"hgc_level{i}" for i in one}
    assert 0 <= a.cycles - b.cycles <= 0.001 * b.cycles
    for phase in scaled.phases:
        for proc in phase.processes:
            if proc.name == f"factor_{prior}_jacobian":
                loop, = proc.loops
                # the multiplies an evaluation issues on its one multiplier (as printed, its
                # so3_log's exclusive branches sharing it: special_ops.issued_counts)
                from fgc_backends.hls.units.special_ops import issued_counts, printed_counts
                ops = issued_counts(program.blocks[prior], "jacobian")
                assert loop.depth >= ops["mul"] and loop.ii >= ops["mul"]
                assert ops["mul"] < printed_counts(program.blocks[prior], "jacobian")["mul"]
    with pytest.raises(PlanError, match="allocation_scaling"):
        build_plan(program, PlanOptions.of(program, allocation_scaling="even"))
