"""Two Cholesky cascades (unit_sets=2; units/cholesky.py's cascade_regions / cascades_phases,
fgc_eliminate.h's cholesky_sets): the regions pair independent steps, each step's child from
the region before is streamed into its cascade, the plan prices what the C simulation counts
and the results are the simulator's."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from test_hls_csim import relative_worst  # the C simulation against the simulator

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import sim
from fgc_backends.hls import HlsConfig, HlsConfigError, emit, run_csim
from fgc_backends.hls.emitter import accel_plan
from fgc_backends.hls.network import read_network
from fgc_backends.hls.plan import plan_cost
from fgc_backends.hls.plan.loops import _tables
from fgc_backends.hls.units.cholesky import (
    _gram_rows,
    beside_region_layout,
    cascade_children,
    cascade_regions,
    cond_pairs,
    gram_entries,
    gram_third,
    jacobian_cycles,
    jacobian_ii,
)

ROOT = Path(__file__).resolve().parents[2]
lio = example("lio")
imu_window = example("imu_window")


def _children(tables, s):
    cb = tables["STEP_CHILD_BEGIN"]
    return {tables["STEP_CHILDREN"][e] for e in range(cb[s], cb[s + 1])}


@pytest.fixture(scope="module")
def lio30():
    return compile_graph(lio.build(N=30), SolverConfig(linear="cholesky", cpe=15,
                                                       precision="float32"), name="lio30")


def test_regions_pair_the_two_ends_of_a_chain(lio30):
    tables = _tables(lio30)
    n = len(lio30.schedule.steps)
    order = [tables["LEVEL_STEPS"][i] for i in range(n)]
    regions = cascade_regions(tables, order)
    steps = [s for reg in regions for s in reg if s >= 0]
    assert sorted(steps) == list(range(n))  # every step once
    done = set()
    for a, b in regions:
        for s in (a, b):  # a step's children are factored in earlier regions
            assert s < 0 or _children(tables, s) <= done
        done |= {a, b} - {-1}
    # 29 steps from both ends: 14 regions of two, the root alone
    assert len(regions) == 15 and all(b >= 0 for _, b in regions[:14]) and regions[14][1] == -1
    kids = cascade_children(tables, regions)
    where = {s: (r, k) for r, reg in enumerate(regions) for k, s in enumerate(reg) if s >= 0}
    for s, (streamed, alone) in kids.items():
        r, k = where[s]
        if streamed >= 0:  # its own cascade's step of the region before
            assert where[streamed] == (r - 1, k) and streamed in _children(tables, s)
        assert set(alone) | ({streamed} - {-1}) == _children(tables, s)
    # every child is streamed but one of the root's two (the other end's: a pass of its own)
    assert sum(len(alone) for _, alone in kids.values()) == 1


def test_the_streamed_grams_go_region_by_region(lio30):
    """The HGC beside two cascades (beside_region_layout): the IMU block's instances in region
    order (a region's cascade 0 step's, then cascade 1's), each once; a region's streamed Grams
    in its stage lane, a memory a cascade's step; the first solve's passes gated by their
    region's last instance (beside_set_passes), and the region beside it priced from the
    replay."""
    tables = _tables(lio30)
    n = len(lio30.schedule.steps)
    order = [tables["LEVEL_STEPS"][i] for i in range(n)]
    regions = cascade_regions(tables, order)
    plan = accel_plan(lio30, HlsConfig(scalar="float", unit_sets=2))
    (beside,) = [ph for ph in plan.phases if ph.name == "hgc_beside"]
    big = int(beside.processes[0].name.rsplit("_", 1)[1])  # linearize_solve_<b>: the IMU block
    assert lio30.blocks[big].residual_dim == max(b.residual_dim for b in lio30.blocks)
    lay = beside_region_layout(lio30, tables, regions, big)
    step_of = {tables["STEP_FACTORS"][e]: s for s in range(n)
               for e in range(tables["STEP_FACTOR_BEGIN"][s], tables["STEP_FACTOR_BEGIN"][s + 1])}
    flat = [s for reg in regions for s in reg if s >= 0]
    assert [step_of[f] for f in lay["order"]] == sorted(
        (step_of[f] for f in lay["order"]), key=flat.index)
    assert sorted(lay["order"]) == [i for i, f in enumerate(lio30.factors) if f.block == big]
    for r, reg in enumerate(regions):
        mine = lay["order"][lay["step_first"][r]:lay["step_first"][r] + lay["step_count"][r]]
        assert {step_of[f] for f in mine} <= set(reg)
        # a lane a memory per cascade's step: cascade 0's instances first, each from 0
        n0 = lay["step_count0"][r]
        assert all(step_of[f] == reg[0] for f in mine[:n0])
        assert [lay["factor_stage"][f] for f in mine] == [
            (j if j < n0 else j - n0) * lay["nb"] for j in range(len(mine))]
    most = max(sum(step_of[f] == s for f in lay["order"]) for s in flat)  # of a step
    assert lay["n_stage"] == most * lay["nb"]
    before = plan_cost(accel_plan(lio30, HlsConfig(scalar="float", unit_sets=2,
                                                   hgc_beside=False)))
    cost = plan_cost(plan)
    assert cost.dsp == before.dsp and cost.cycles < before.cycles - 7000
    assert not any(ph.name.startswith("cholesky_level") for ph in plan.phases)


def test_two_cascades_price_the_ends_side_by_side(lio30):
    one = plan_cost(accel_plan(lio30, HlsConfig(scalar="float", hgc_beside=False)))
    two = plan_cost(accel_plan(lio30, HlsConfig(scalar="float", unit_sets=2)))
    dsp = dict(two.dsp_by_unit)
    assert dsp["cpe_set1"] == dict(one.dsp_by_unit)["cpe"]  # a second set of 15 CPEs
    # 14 regions of two steps each take about one step's time (48,091 -> 37,542 cycles)
    assert two.cycles < one.cycles - 9000
    with pytest.raises(HlsConfigError, match="one or two cascades"):
        accel_plan(lio30, HlsConfig(scalar="float", unit_sets=3))


def test_a_banked_cond_takes_both_conditionals_at_once(lio30):
    # COND cyclic over back-substitution's two banks: the committer writes an aligned pair of
    # each region's two conditionals a cycle (fgc_cascades.h's cholesky_set_commit_both), so
    # its copy is the larger step's pairs, not the two steps' one after the other
    tables = _tables(lio30)
    plans = {b: accel_plan(lio30, HlsConfig(scalar="float", unit_sets=2, backsub_lanes=b,
                                            cascade_lanes=2)) for b in (1, 2)}
    regions = cascade_regions(tables, [tables["LEVEL_STEPS"][i]
                                       for i in range(len(tables["LEVEL_STEPS"]))])
    a, b = regions[0]
    assert a >= 0 and b >= 0
    for banks, plan in plans.items():
        committer = next(p for ph in plan.phases if ph.name == "recholesky_level1"
                         for p in ph.processes if p.name.startswith("committer"))
        copies = [lp.trip for lp in committer.loops if lp.name.startswith("cond")]
        if banks == 1:
            assert copies == [-(-tables["STEP_F"][s] * (tables["STEP_W"][s] + 1) // 2)
                              for s in (a, b)]
        else:
            assert copies == [max(cond_pairs(tables, s) for s in (a, b))]
            c0, n = tables["STEP_COND_OFF"][a], tables["STEP_F"][a] * (tables["STEP_W"][a] + 1)
            assert cond_pairs(tables, a) == len({x // 2 for x in range(c0, c0 + n)})
    # the committer no longer bounds a region (two copies of 248 pairs and two checks, 570,
    # against the cascades' 525; the grams process, 560, does now), and no operator more
    one, two = (plan_cost(plans[b]) for b in (1, 2))
    assert dict(one.dsp_by_unit)["cpe"] == dict(two.dsp_by_unit)["cpe"]
    assert dict(two.phase_cycles)["hgc_beside"] < dict(one.phase_cycles)["hgc_beside"]


@pytest.mark.parametrize("banks", [1, 2])
def test_two_cascades_match_the_simulator(tmp_path, banks):
    # LM in double: the C simulation's estimates are the simulator's to 1e-9 (relative); banks:
    # COND cyclic over back-substitution's two banks, both conditionals of a region committed
    # at once (conditionals at even and odd offsets)
    graph = lio.build(N=6)
    program = compile_graph(graph, SolverConfig(linear="cholesky", cpe=4), name=f"casc{banks}")
    project = emit(program, tmp_path, HlsConfig(scalar="double", unit_sets=2,
                                                backsub_lanes=banks))
    regions = {r.function: r for r in read_network(
        (tmp_path / "include" / "fgc_cascades.h").read_text())}
    assert regions["cholesky_sets"].processes == (
        "cholesky_set_source", "cholesky_set_grams", "cholesky_set_cascade",
        "cholesky_set_cascade", "cholesky_set_commit")
    # the HGC beside the elimination (default on): the Gram source a sixth process of the region
    assert regions["cholesky_sets_beside"].processes == (
        "cholesky_set_gram_source", *regions["cholesky_sets"].processes)
    text = (project.directory / f"{project.name}.cpp").read_text()
    assert "cholesky_eliminate_sets_beside<SetConfig>(mu, relin, grams, solved);" in text
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)
    assert result.status == reference.status
    assert relative_worst(result.values, reference.storage) <= 1e-9


# (True, 1) is heavy (about 10 s idle): (False, 1) counts one bank, (True, 2) the HGC beside
@pytest.mark.parametrize("beside,banks", [(False, 1),
                                          pytest.param(True, 1, marks=pytest.mark.heavy),
                                          (True, 2)])
def test_two_cascades_count_what_the_plan_prices(beside, banks):
    # beside: the HGC beside the elimination (fgc_cascades.h's cholesky_eliminate_sets_beside,
    # units/cholesky.py's beside_set_passes): its passes inside phase hgc_beside; banks: COND
    # cyclic over two (backsub_lanes), the committer's both conditionals at once
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="gn", linear="cholesky", cpe=4, precision="float32")
    phases, events = measure(f"c2{banks}", imu_window.build(N=5), solver,
                             HlsConfig(scalar="float", unit_sets=2, hgc_beside=beside,
                                       backsub_lanes=banks))
    assert events["solve"] >= 1
    groups = {"hgc_beside"} if beside else {"assemble", "cholesky"}
    assert groups <= {g for g, (c, m) in phases.items() if c > 0 and m > 0}
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)


# heavy (about a minute on 2 cores): LM's retries with two cascades re-solve from GRAM_B
@pytest.mark.heavy
def test_two_cascades_retries_resolve_from_the_kept_grams_as_priced():
    """imu_window N = 50, LM, float32, #CPE = 5, two cascades with the HGC beside: the first
    solves fail (κ past 1/√eps32), LM re-solves the same linearisation (event resolve) with
    cholesky_eliminate_sets_beside's Gram source copying region by region from GRAM_B: the
    retry phases count what the plan prices (beside_set_passes, relin false)."""
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="lm", linear="cholesky", cpe=5, precision="float32")
    phases, events = measure("c2r", imu_window.build(N=50), solver,
                             HlsConfig(scalar="float", unit_sets=2))
    assert events.get("resolve", 0) >= 1
    assert phases["recholesky"][0] > 0 and phases["reassemble"][0] > 0
    for g in ("hgc", "hgc_beside", "reassemble", "recholesky"):
        counted, model = phases[g]
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)


def test_a_third_gram_lane_keeps_up_with_the_imu_datapath():
    # imu_window's IMU Gram (496 entries) in two lanes takes 248 words an instance: the Gram
    # source puts two entries a cycle into its stage lane and GRAM_B (two ports each), over the
    # datapath's II 233. gram_third's lane C (a run of the packed Gram over the first K' rows,
    # into memories of its own) takes three an iteration: every entry in exactly one lane,
    # each at most ceil(496 / 3) = 166, lane C's entries touched by its first K' rows only and
    # never the last row (the += into G stays in lane A)
    program = compile_graph(imu_window.build(N=50), SolverConfig(
        method="lm", linear="cholesky", cpe=40, precision="float32"), name="iw40")
    plans = {k: accel_plan(program, HlsConfig(scalar="float", unit_sets=k, cascade_lanes=2,
                                              hgc_third_lane=True)) for k in (1, 2)}
    procs = [p for ph in plans[2].phases for p in ph.processes]
    lane_a, lane_b, lane_c, kb, kc, c0 = gram_third(program, 0, 32, jacobian_ii(procs),
                                                    jacobian_cycles(procs))
    entries = gram_entries(program.blocks[0])
    assert sorted(lane_a + lane_b + lane_c) == sorted(entries) and len(entries) == 496
    assert max(map(len, (lane_a, lane_b, lane_c))) == 166
    assert [p * (p + 1) // 2 + q for p, q in lane_c] == list(range(c0, c0 + len(lane_c)))
    rows = _gram_rows(program.blocks[0])
    assert all(rows[e][-1] < kc and e[0] < 30 for e in lane_c)
    assert all(rows[e][-1] < kb and e[0] < 30 for e in lane_b)
    # the plan: 166 words an instance, lane C's memories, its multipliers and adders
    reduce = next(p for p in procs if p.name == "reduce_0")
    assert reduce.loops[1].trip == 49 * 166
    assert {"stage_c", "gram_kept_c"} <= {m.name for m in plans[2].memories}
    assert dict(plans[2].unit("hgc_0").operators) == {"add": 15 + kb + kc - 2,
                                                      "mul": 15 + kb + kc}
    # one cascade keeps two lanes (its stage lane is one memory a step: fgc_eliminate.h)
    assert "stage_c" not in {m.name for m in plans[1].memories}
    assert next(p for ph in plans[1].phases for p in ph.processes
                if p.name == "reduce_0").loops[1].trip == 49 * 248
    # off by default (DesignOptions.hgc_third_lane): two lanes, the plan's DSP without lane C
    off = accel_plan(program, HlsConfig(scalar="float", unit_sets=2, cascade_lanes=2))
    assert "stage_c" not in {m.name for m in off.memories}
    assert plan_cost(plans[2]).dsp - plan_cost(off).dsp == kc * 3 + (kc - 1) * 2
    assert plan_cost(plans[2]).cycles < plan_cost(off).cycles


# heavy (about two minutes on 2 cores): the third lane's Grams through the C simulation
@pytest.mark.heavy
def test_the_third_gram_lane_matches_the_simulator(tmp_path):
    # LM in double, imu_window N = 20, two cascades, the HGC beside with lane C (the plan picks
    # it at N = 20): the C simulation's estimates are the simulator's to 1e-9 (relative)
    graph = imu_window.build(N=20)
    program = compile_graph(graph, SolverConfig(method="lm", linear="cholesky", cpe=4),
                            name="lanec")
    project = emit(program, tmp_path, HlsConfig(scalar="double", unit_sets=2,
                                                hgc_third_lane=True))
    text = (project.directory / f"{project.name}.cpp").read_text()
    assert "BLOCK0_GRAM_PC" in text and "L GRAM_BC[" in text
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)
    assert result.status == reference.status
    assert relative_worst(result.values, reference.storage) <= 1e-9
