"""The factor datapaths (backends/hls/units/datapath.py): the per-member robust flag
(``MemberSpec.robust``) from the graph through the Program, the data files, the emitted kernel,
the plan and the second reader."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

import fgc
from fgc.compile import compile_graph
from fgc.errors import DataError, FgcError
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2
from fgc.ir.datafile import problem_data
from fgc.ir.program import Program, SolverConfig
from fgc_backends.cfamily.blocks import block_contexts
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
from fgc_backends.hls.reader import emitted_files, read_design
from fgc_backends.hls.units.datapath import instance_accesses, robust_ops, whitening_ops


def _graph(robust_between: int | None = None) -> fgc.Graph:
    """A Pose2 chain: a prior and four odometry edges; edge ``robust_between`` under Huber."""
    g = fgc.Graph()
    for i in range(5):
        g.add_variable(f"x{i}", Pose2(1.0 * i + 0.05, 0.02 * i, 0.01))
    g.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    for i in range(4):
        model = fgc.noise.diagonal([0.1, 0.1, 0.05])
        if i == robust_between:
            model = fgc.noise.huber(1.345, model)
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0), model))
    return g


SOLVER = SolverConfig(linear="cholesky", cpe=1)


def _flags(program: Program) -> dict[str, bool]:
    return {m.factor_type: m.robust for b in program.blocks for m in b.members}


def test_the_flag_says_whether_any_factor_of_the_member_is_robust():
    plain = compile_graph(_graph(), SOLVER, name="plain")
    mixed = compile_graph(_graph(robust_between=2), SOLVER, name="mixed")
    assert _flags(plain) == {"PriorFactorPose2": False, "BetweenFactorPose2": False}
    # one robust instance of four makes the block type's member robust; the prior stays plain
    assert _flags(mixed) == {"PriorFactorPose2": False, "BetweenFactorPose2": True}
    # a factor type named robust (a stream template's later windows) is flagged without one
    hinted = compile_graph(_graph(), SOLVER, name="hinted",
                           robust_types=frozenset({"BetweenFactorPose2"}))
    assert _flags(hinted) == _flags(mixed)
    # the flag is structure: data of one do not feed the other
    assert plain.structure_fingerprint != mixed.structure_fingerprint
    assert plain.fingerprint != mixed.fingerprint
    assert Program.from_json(mixed.to_json()) == mixed
    # a Program written before the flag existed reads back with every member robust
    old = json.loads(plain.to_json())
    for b in old["blocks"]:
        for m in b["members"]:
            del m["robust"]
    assert set(_flags(Program.from_dict(old)).values()) == {True}


def test_robust_data_on_a_member_built_without_a_robust_loss_is_refused():
    plain = compile_graph(_graph(), SOLVER, name="plain")
    with pytest.raises(DataError, match=r"factor 3 .*huber robust loss.*BetweenFactorPose2") as e:
        problem_data(_graph(robust_between=2), plain)
    assert isinstance(e.value, FgcError)
    problem_data(_graph(), plain)  # its own data pass


def test_plan_prices_no_robust_datapath_for_plain_members():
    plain = compile_graph(_graph(), SOLVER, name="plain")
    mixed = compile_graph(_graph(robust_between=2), SOLVER, name="mixed")
    (prior, between), (_, rbetween) = block_contexts(plain, False), block_contexts(mixed, False)
    for ops in (robust_ops(prior), robust_ops(between), whitening_ops(prior)):
        assert not any(ops.get(k) for k in ("div", "sqrt", "special")), ops
    assert robust_ops(prior) == {"add": 2}  # the member's sum and the total's
    assert robust_ops(rbetween)["special"] == 1 and whitening_ops(rbetween)["sqrt"] == 2
    # a plain member reads no robust words from DATA_BUF
    assert instance_accesses(rbetween, "cost")[1][0] == instance_accesses(between, "cost")[1][0] + 2
    dsp = {}
    for p in (plain, mixed):
        units = dict(plan_cost(build_plan(p, PlanOptions.for_config(HlsConfig(), p))).dsp_by_unit)
        dsp[p.name] = units
    assert dsp["plain"]["factor_0"] == dsp["mixed"]["factor_0"]  # the prior: plain in both
    assert dsp["plain"]["factor_1"] < dsp["mixed"]["factor_1"]


def _kernel_calls(text: str, block: int) -> tuple[str, str]:
    """The bodies of evaluate_<block> and of trial_cost's loop over <block> (issue 33: the cost
    pass beside back-substitution) in the emitted kernel."""
    start = text.index(f"void evaluate_{block}(")
    evaluate = text[start:text.index("\n}\n", start)]
    start = text.index(f"    // block {block} (", _trial_start(text))
    return evaluate, text[start:text.index("\n    }\n", start)]


def _trial_start(text: str) -> int:
    """Where trial_cost's loops start: its own body, or (the column design's LM, split in two:
    units/datapath.py's split_trial_loops) trial_cost_a's, trial_cost_b's after it."""
    return text.index("void trial_cost_a(" if "void trial_cost_a(" in text
                      else "void trial_cost(")


def _trial_loops(text: str, loops) -> dict:
    """Per key of trial_cost's loops (a block type, or "small") its reading among ``loops``
    (the second reader's): the first of trial_cost's (or trial_cost_b's, the column design's
    LM: units/datapath.py's split_trial_loops) after the loop's comment."""
    at = _trial_start(text)
    mine = sorted((r for r in loops if r.function in ("trial_cost", "trial_cost_a",
                                                       "trial_cost_b")),
                  key=lambda r: r.line)
    out = {}
    for m in re.finditer(r"\n    // (?:block (\d+)|the small datapath) \(", text[at:]):
        line = text.count("\n", 0, at + m.start() + 1) + 1  # the comment's line
        out[int(m.group(1)) if m.group(1) else "small"] = next(r for r in mine if r.line > line)
    return out


def _emit_and_read(robust_between, tmp_path) -> tuple[str, dict, dict]:
    """The emitted kernel's text and, per block, the plan's and the second reader's DSP of its
    factor datapath (the reader: the block's Jacobian and cost loops, each once per module
    instance of its function)."""
    program = compile_graph(_graph(robust_between), SOLVER, name="chain")
    config = HlsConfig()
    out = tmp_path / str(robust_between)
    emit(program, out, config)
    plan = build_plan(program, PlanOptions.for_config(config, program))
    units = dict(plan_cost(plan).dsp_by_unit)
    tab = plan.target.ops("float32")
    dsp_of = {"add": tab.add.dsp, "mul": tab.mul.dsp, "div": tab.div.dsp,
              "sqrt": tab.sqrt.dsp, "special": tab.special.dsp}
    files, top = emitted_files(out)
    design = read_design(files, top, tab.add.latency)
    modules = dict(design.modules)
    plan_dsp, reader_dsp = {}, {}
    text = (out / "chain.cpp").read_text()
    trial = _trial_loops(text, design.loops)
    for block in range(len(program.blocks)):
        loops = [r for r in design.loops if r.function == f"evaluate_{block}"] + [trial[block]]
        assert len(loops) == 2
        reader_dsp[block] = sum(r.dsp(dsp_of) * modules[r.function] for r in loops)
        plan_dsp[block] = units[f"factor_{block}"]
        if not program.blocks[block].members[0].robust:  # no robust loss's operators
            assert not {"sqrt", "special"} & {k for r in loops for k, _ in r.ops}
    return (out / "chain.cpp").read_text(), plan_dsp, reader_dsp


def _check_emitted(robust_between, tmp_path) -> tuple[dict, dict]:
    text, plan_dsp, reader_dsp = _emit_and_read(robust_between, tmp_path)
    for block, robust in ((0, False), (1, robust_between is not None)):
        evaluate, cost = _kernel_calls(text, block)
        assert ("reweight<" in evaluate) == robust and ("robust_loss(" in cost) == robust
    # a design without a robust member prints neither helper
    assert ("T robust_loss(" in text) == (robust_between is not None)
    for block in plan_dsp:  # the reader's count is a lower bound of what Vitis binds
        assert reader_dsp[block] <= plan_dsp[block], (block, reader_dsp, plan_dsp)
    return plan_dsp, reader_dsp


def test_emitted_kernel_reweights_only_robust_members(tmp_path):
    _check_emitted(2, tmp_path)  # the prior plain, the odometry robust


@pytest.mark.heavy
def test_second_reader_prices_the_robust_datapath_as_the_plan(tmp_path):
    read = {robust_between: _check_emitted(robust_between, tmp_path)
            for robust_between in (None, 2)}
    (plan0, reader0), (plan1, reader1) = read[None], read[2]
    # the robust loss's datapath: what the plan adds for it, the text adds (within 15 %)
    added_plan, added_reader = plan1[1] - plan0[1], reader1[1] - reader0[1]
    assert added_reader > 0 and abs(added_plan - added_reader) <= 0.15 * added_reader, (
        added_plan, added_reader)
    assert plan0[0] == plan1[0] and reader0[0] == reader1[0]  # the prior: plain in both


def test_template_window_flags_what_later_windows_make_robust():
    from fgc.compiler.stream import WindowTemplate, compile_chain
    graph = _graph(robust_between=3)  # the last edge: outside a two-keyframe template
    program = compile_chain(graph, SOLVER)
    template = WindowTemplate(graph, program, 2)
    assert not any(f.noise.robust for f in template.template_factors)
    assert _flags(template.template)["BetweenFactorPose2"] is True
    words = template._factor(4, template.template.blocks[1].members[0])
    assert np.count_nonzero(words[-2:]) == 2  # the robust loss's code and k, as written


# -- small block types share one datapath ---------------------------------------------------


@pytest.fixture(scope="module")
def lio_small():
    """LIO's unary factors alone (a pose with its prior and two GPS fixes, a velocity and a
    bias with theirs): the big Pose3 prior and the three small block types."""
    from fgc.frontend.factors import GPSFactor
    from fgc.frontend.geometry import ImuBias, Pose3, Vector3
    g = fgc.Graph()
    pose = Pose3.Expmap(np.r_[0.1, 0.2, 0.3, 1.0, 2.0, 3.0])
    g.add_variable("x0", pose)
    g.add_variable("v0", Vector3(np.r_[1.0, 0.0, 0.0]))
    g.add_variable("b0", ImuBias(np.zeros(6)))
    g.add(PriorFactor("x0", pose, fgc.noise.diagonal([0.1] * 3 + [1.0] * 3)))
    g.add(PriorFactor("v0", Vector3(np.r_[1.0, 0.1, 0.0]), fgc.noise.isotropic(3, 1.0)))
    g.add(PriorFactor("b0", ImuBias(np.zeros(6)), fgc.noise.isotropic(6, 0.1)))
    for dx in (0.0, 0.1):
        g.add(GPSFactor("x0", np.r_[1.0 + dx, 2.0, 3.0], fgc.noise.isotropic(3, 0.5)))
    # a QR design: a Cholesky design's datapaths each stream to their own HGC and share none
    cholesky = compile_graph(g, SOLVER, name="lio")
    from fgc_backends.hls.units import datapath
    assert datapath.small_blocks(cholesky) == ()
    return compile_graph(g, SolverConfig(linear="qr", units=1), name="lio")


def _plan(program):
    plan = build_plan(program, PlanOptions.for_config(HlsConfig(), program))
    return plan, plan_cost(plan)


def test_small_block_types_share_one_datapath(lio_small, monkeypatch):
    from fgc_backends.hls.units import datapath
    names = [lio_small.blocks[i].name for i in datapath.small_blocks(lio_small)]
    assert names == ["PriorFactorVector3", "PriorFactorImuBias", "GPSFactor"]
    plan, cost = _plan(lio_small)
    units = dict(cost.dsp_by_unit)
    small = datapath.small_blocks(lio_small)
    apart_units = {f"factor_{b}" for b in small}
    assert "factor_small" in units and not apart_units & set(units)
    jac = next(p for ph in plan.phases if ph.name == "factor_jacobian" for p in ph.processes
               if p.name == "factor_small_jacobian")
    assert jac.loops[0].trip == sum(1 for f in lio_small.factors if f.block in small) == 4
    monkeypatch.setattr(datapath, "SMALL_OPS", -1)  # every block type its own datapath
    assert datapath.small_blocks(lio_small) == ()
    _, alone = _plan(lio_small)
    apart = sum(d for u, d in alone.dsp_by_unit if u in apart_units)
    assert units["factor_small"] < apart
    # the shared loop is slower for those instances (its II serves the largest branch and
    # every branch's memory accesses)
    assert alone.cycles <= cost.cycles


def test_shared_datapath_as_emitted_and_read(lio_small, tmp_path):
    from fgc_backends.hls.reader import check
    out = tmp_path / "lio"
    emit(lio_small, out, HlsConfig())
    text = (out / "lio.cpp").read_text()
    one = text[text.index("void evaluate_small_one("):text.index("void evaluate_small(")]
    assert one.count("ALLOCATION operation instances=") >= 2
    small = [int(b) for b in re.findall(r"\(b == (\d+)\)", one)]
    assert [lio_small.blocks[b].name for b in small] == [
        "PriorFactorVector3", "PriorFactorImuBias", "GPSFactor"]
    for b in small:  # the small kernels are inlined into the shared function
        fn = text[text.index(f"void factor_{b}("):]
        assert fn[:fn.index("}")].count("#pragma HLS INLINE\n") == 1
        assert f"evaluate_{b}(x)" not in text and f"// block {b} (" not in text
    plan, cost = _plan(lio_small)
    tab = plan.target.ops("float32")
    dsp_of = {"add": tab.add.dsp, "mul": tab.mul.dsp, "div": tab.div.dsp,
              "sqrt": tab.sqrt.dsp, "special": tab.special.dsp}
    files, top = emitted_files(out)
    design = read_design(files, top, tab.add.latency)
    modules = dict(design.modules)
    loops = [r for r in design.loops if r.function == "evaluate_small"]
    loops.append(_trial_loops(text, design.loops)["small"])
    assert len(loops) == 2 and not check(loops)  # the declared IIs are what the text allows
    reader = sum(r.dsp(dsp_of) * modules[r.function] for r in loops)
    assert 0 < reader <= dict(cost.dsp_by_unit)["factor_small"]


# -- the gradient beside the datapaths (QR: one DATAFLOW region, linearize_rows) -------------


def test_the_gradient_runs_beside_the_datapaths(lio_small, tmp_path):
    """QR's linearisation is one region: each instance's rows go from its datapath into AB and,
    PORTS words a stream word, to reduce_all, which forms A^T b from them (AB is not read
    again). The plan prices the region as fgc_cycles.h counts it: the datapaths, then what the
    gradient adds after them - at least the last instance's gradient (its rows come when its
    datapath loop ends), less than the gradient's own loops added on."""
    from fgc_backends.hls.plan.loops import kernel_timing
    from fgc_backends.hls.units import datapath
    plan, _ = _plan(lio_small)
    names = [ph.name for ph in plan.phases]
    assert "gradient" not in names
    (lin,) = [ph for ph in plan.phases if ph.name == "factor_jacobian"]
    jac = [p for p in lin.processes if p.name != "gradient"]
    (beside,) = [p for p in lin.processes if p.name == "gradient"]
    timing = kernel_timing(plan.ops)
    alone = sum(p.cycles for p in datapath.gradient_loops(lio_small, timing))
    tail = beside.cycles
    # the last datapath loop's last block type: its instance's gradient after the rows
    last = jac[-1].name
    small = datapath.small_blocks(lio_small)
    b = small[-1] if last == "factor_small_jacobian" else int(last.split("_")[1])
    columns, rows, scatter = datapath.reduce_loops(lio_small.blocks[b], timing, 1)
    assert rows.depth + scatter.cycles <= tail < alone
    # the datapaths' II leaves room for the stream's words (one a cycle; the shared loop's
    # for every branch's, as the reader sums the text's accesses)
    from fgc_backends.hls.plan.loops import _block_shape
    words = {i: _block_shape(blk)[0] * _block_shape(blk)[2] // 2
             for i, blk in enumerate(lio_small.blocks)}
    for p in jac:
        k = p.name[len("factor_"):-len("_jacobian")]
        need = sum(words[i] for i in small) if k == "small" else words[int(k)]
        assert p.loops[0].ii >= need
    # as emitted: one region of the two processes, the gradient from the stream
    out = tmp_path / "lio"
    emit(lio_small, out, HlsConfig())
    text = (out / "lio.cpp").read_text()
    region = text[text.index("void linearize_rows("):]
    region = region[:region.index("\n}\n")]
    assert "#pragma HLS DATAFLOW" in region
    assert "evaluate_all(" in region and "reduce_all(" in region
    acc = text[text.index("bool accumulate("):]
    acc = acc[:acc.index("\n}\n")]
    assert "grad.read()" in acc and "AB[" not in acc


def _trial_program():
    """Four variables retired a, b, c, d and three datapaths of one instance each: block 0's
    (the most work) on c and d (ready last), block 1's on a, block 2's on b."""
    from types import SimpleNamespace as Ns
    variables = [Ns(key=k, storage_dim=3) for k in "abcd"]
    factors = [Ns(keys=("c", "d")), Ns(keys=("a",)), Ns(keys=("b",))]
    return Ns(variables=variables, factors=factors)


def test_the_cost_pass_runs_its_loops_as_they_are_ready_when_that_ends_sooner():
    from fgc_backends.hls.units.datapath import trial_end, trial_loops
    program = _trial_program()
    costs = {0: ([0], 300, 500), 1: ([1], 100, 200), 2: ([2], 100, 200)}
    accesses = {0: 6, 1: 3, 2: 3}
    base = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses)
    assert [lp.key for lp in base] == [0, 1, 2]  # without the retire's ends: the most work first
    # the retire sends a at 100, b at 200, c and d at 900 and 1,000: the most work first waits
    # for d (1,000) and drains 502 + 200 + 200 after it; ready first, blocks 1 and 2 run before
    var_end = [100, 200, 900, 1000]
    ready = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, var_end)
    assert [lp.key for lp in ready] == [1, 2, 0]
    assert trial_end(ready, var_end) == 1000 + 502 < trial_end(base, var_end) == 1000 + 502 + 400
    # whatever the retire's ends, the order kept never ends later than the most work first
    rng = np.random.default_rng(7)
    for _ in range(20):
        ends = np.cumsum(rng.integers(1, 600, size=4)).tolist()
        chosen = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, ends)
        assert trial_end(chosen, ends) <= trial_end(base, ends)
        assert chosen == base or trial_end(chosen, ends) < trial_end(base, ends)


def test_the_slot_designs_cost_pass_splits_in_two_processes_only_when_that_ends_sooner():
    """units/datapath.py's slot_split_loops: with the emitted tables the cost pass may run as
    trial_cost ‖ trial_cost_b, the second fed its instances' data words first (the feed's
    cycles at each process's start); kept only where its later process ends before the one
    process would."""
    from fgc_backends.hls.units.datapath import (
        FEED_SEND_DEPTH,
        FEED_TAKE_DEPTH,
        trial_end,
        trial_loops,
    )
    program = _trial_program()
    costs = {0: ([0], 300, 500), 1: ([1], 100, 200), 2: ([2], 100, 200)}
    accesses = {0: 6, 1: 3, 2: 3}
    tables = {"FACTOR_DATA_OFF": [0, 10, 20, 30]}
    pos = {v: v for v in range(4)}
    # b is sent late (950): in one process block 2 drains 202 before block 0 can start after d
    # (1,000): 950 + 202 + 502 = 1,654; block 0 beside blocks 1 and 2 ends at 1,000 + 502
    var_end = [100, 950, 960, 1000]
    one = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, var_end)
    assert trial_end(one, var_end) == 950 + 202 + 502
    two = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, var_end, tables)
    assert {lp.proc for lp in two} == {0, 1}
    assert trial_end(two, var_end, pos) == 1000 + 502
    second = [lp for lp in two if lp.proc == 1]
    words = (10 if [lp.key for lp in second] == [0] else 20)  # its data span (lines of 10)
    assert second[0].feed == words - 1 + FEED_TAKE_DEPTH
    assert [lp for lp in two if lp.proc == 0][0].feed == words - 1 + FEED_SEND_DEPTH
    # each process takes only its instances' variables, every variable some process reads
    taken = {q: [v for lp in two if lp.proc == q for _, vs in lp.entries for v in vs]
             for q in (0, 1)}
    assert sorted(taken[0] + taken[1]) == [0, 1, 2, 3]
    # b sent early: the ready order already ends when block 0 does (1,000 + 502): not split
    early = [100, 200, 300, 1000]
    kept = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, early, tables)
    assert {lp.proc for lp in kept} == {0} and all(lp.feed == 0 for lp in kept)
    assert kept == trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, early)
    # a feed longer than what the split saves: not split either
    far = {"FACTOR_DATA_OFF": [0, 4000, 8000, 12000]}
    assert {lp.proc for lp in trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, var_end,
                                          far)} == {0}


def test_the_slot_designs_cost_process_fuses_its_block_datapaths_when_that_ends_sooner():
    """units/datapath.py's slot_split_loops: a process's block datapaths may run as one loop
    (an entry costs one instance through its block's datapath: the largest II and depth, no
    drain between them), kept only where that ends sooner (paper A's trial_cost_b: the Pose3
    prior, then the IMU block, which drained one after the other)."""
    from types import SimpleNamespace as Ns

    from fgc_backends.hls.units.datapath import trial_end, trial_loops
    variables = [Ns(key=k, storage_dim=3) for k in "abcd"]
    # block 0 on d; block 1 (shallow) on a; block 2 (deep, slow) on b and c
    program = Ns(variables=variables,
                 factors=[Ns(keys=("d",)), Ns(keys=("a",)), Ns(keys=("b", "c"))])
    costs = {0: ([0], 300, 500), 1: ([1], 24, 380), 2: ([2], 184, 600)}
    accesses = {0: 3, 1: 3, 2: 6}
    tables = {"FACTOR_DATA_OFF": [0, 10, 20, 30]}
    pos = {v: v for v in range(4)}
    var_end = [800, 850, 900, 1000]
    data = {0: 10, 1: 10, 2: 300}  # the data words an instance reads (two ports: 155 < 184)
    loops = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, var_end, tables, data)
    fused = [lp for lp in loops if lp.fused]
    assert len(fused) == 1 and fused[0].fused == (1, 2) and fused[0].key == "1_2"
    lp = fused[0]
    # its entries in the order they are ready (block 1's instance on a, block 2's on b, c),
    # at the larger II and depth
    assert [f for f, _ in lp.entries] == [1, 2] and (lp.ii, lp.depth) == (184, 602)
    # block 1's instance issues at a's end (800), block 2's an II later (984 > c's 900):
    # 984 + 602; block 0 beside it ends at 1,000 + 502
    assert trial_end(loops, var_end, pos) == 800 + 184 + 602
    # unfused, the best split ran block 1 then block 0 (drained: 800 + 382, then 1,000 + 502
    # would be 1,684) beside block 2 (900 + 602)
    # a sends early: block 1's loop drains (100 + 382) before block 2's variables come, the
    # fused loop would end no sooner (900 + 602): the loops stay apart
    early = [100, 850, 900, 1000]
    apart = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, early, tables, data)
    assert all(not lp.fused for lp in apart)
    assert trial_end(apart, early, pos) == 1000 + 502
    # the fused loop's II covers every branch's data reads through the memory's two ports (the
    # second reader counts them as one iteration's): 300 + 90 words, II 195, not 184
    wide = trial_loops(program, (0, 1, 2, 3), costs, 3, accesses, var_end, tables,
                       {0: 10, 1: 90, 2: 300})
    lp = next(lp for lp in wide if lp.fused)
    assert lp.ii == 195 and trial_end(wide, var_end, pos) == 800 + 195 + 602
    # without the data words (a caller that cannot tell them) nothing is fused
    assert all(not lp.fused for lp in trial_loops(program, (0, 1, 2, 3), costs, 3, accesses,
                                                  var_end, tables))
