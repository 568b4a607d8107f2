"""The HGC beside the elimination (issue 33; units/cholesky.py's _beside, accel.cpp.jinja's
linearize_solve, fgc_eliminate.h's cholesky_eliminate_beside): the replay's arithmetic by hand,
the streamed block type's layout, the emitted region, and (C simulation) the counted cycles equal
to the plan, LM's retries among them (heavy); the result equal to the simulator's is
test_hls_csim's (its Cholesky cases emit this design)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.config import DesignOptions
from fgc_backends.hls.emitter import accel_plan
from fgc_backends.hls.network import read_network
from fgc_backends.hls.plan import plan_cost
from fgc_backends.hls.plan.loops import _tables
from fgc_backends.hls.plan.model import Loop, Phase, Process
from fgc_backends.hls.units.cholesky import beside_cycles, beside_layout, beside_ready

ROOT = Path(__file__).resolve().parents[2]
lio = example("lio")


@pytest.fixture(scope="module")
def lio5():
    return compile_graph(lio.build(N=5), SolverConfig(method="lm", linear="cholesky", cpe=3,
                                                      precision="float32"), name="b5")


def test_an_instances_gram_is_ready_after_its_rows_and_the_one_before():
    jac = Loop("instances", 3, 10, 50)  # the datapath: an instance every 10 cycles, 50 deep
    # the HGC faster than the datapath: each instance waits for its rows (k 10 + 50 + 5)
    assert beside_ready(3, jac, 5, 4, 2, 7) == [55 + 3 * 2 + 7, 65 + 13, 75 + 13]
    # slower: each instance's entries start 10 iterations (II 2) after the one before's
    assert beside_ready(3, jac, 5, 10, 2, 7) == [55 + 25, 75 + 25, 95 + 25]


def test_a_pass_waits_for_the_producers_instance_and_the_later_end_counts():
    def phase(cycles):
        return Phase("p", False, (Process("x", "cpe", (Loop("l", 1, 1, cycles),)),))

    # 30 + 40 = 70, but the second pass's source needs instance 0 (ready at 100) + its depth 2
    assert beside_cycles(50, [100], [(phase(30), None), (phase(40), 0)], 2) == (102, 32)
    # no wait: the consumer's 70; a producer that ends later sets the region's end
    assert beside_cycles(50, [20], [(phase(30), None), (phase(40), 0)], 2) == (70, 0)
    assert beside_cycles(90, [20], [(phase(30), None), (phase(40), 0)], 2) == (90, 0)


def test_the_streamed_block_goes_in_step_order_once_each(lio5):
    tables = _tables(lio5)
    order = [tables["LEVEL_STEPS"][i] for i in range(len(lio5.schedule.steps))]
    plan = accel_plan(lio5, HlsConfig(scalar="float"))
    (beside,) = [ph for ph in plan.phases if ph.name == "hgc_beside"]
    big = int(beside.processes[0].name.rsplit("_", 1)[1])
    lay = beside_layout(lio5, tables, order, big)
    mine = [i for i, f in enumerate(lio5.factors) if f.block == big]
    assert sorted(lay["order"]) == mine and len(lay["order"]) == len(mine)
    pos = {s: t for t, s in enumerate(order)}
    fb, sf = tables["STEP_FACTOR_BEGIN"], tables["STEP_FACTORS"]
    step_of = {sf[e]: s for s in order for e in range(fb[s], fb[s + 1])}
    assert [pos[step_of[f]] for f in lay["order"]] == sorted(pos[step_of[f]]
                                                            for f in lay["order"])
    for s in order:  # a step's streamed instances follow each other in the stream
        here = lay["order"][lay["step_first"][s]:lay["step_first"][s] + lay["step_count"][s]]
        assert all(step_of[f] == s for f in here)
        assert [lay["factor_stage"][f] for f in here] == [j * lay["nb"]
                                                          for j in range(len(here))]
    assert all(lay["factor_stage"][f] == -1 for f in range(len(lio5.factors)) if f not in mine)
    # the producer's region stays for the record, priced inside hgc_beside; LM's retries per
    # rejection; the other block types' regions before it as before
    pers = {ph.name: ph.per for ph in plan.phases}
    assert pers["hgc_producer"] == "beside" and pers["hgc_beside"] == "iteration"
    assert {n for n, p in pers.items() if n.startswith(("reassemble", "recholesky"))} and all(
        p == "rejection" for n, p in pers.items() if n.startswith(("reassemble", "recholesky")))
    assert f"hgc_level{big}" not in pers and "assemble" not in pers


def test_beside_is_faster_than_before_and_costs_no_operator(lio5):
    on = plan_cost(accel_plan(lio5, HlsConfig(scalar="float")))
    off = plan_cost(accel_plan(lio5, HlsConfig(scalar="float",
                                               design=DesignOptions(hgc_beside=False))))
    assert on.cycles < off.cycles
    assert on.dsp == off.dsp


def test_the_emitted_region_holds_the_producer_beside_the_elimination(lio5, tmp_path):
    project = emit(lio5, tmp_path / "p", HlsConfig(scalar="float"))
    text = (project.directory / f"{project.name}.cpp").read_text()
    regions = {r.function: r for r in read_network(text)}
    (producer,) = [p for p in regions["linearize_solve"].processes if p.startswith("produce_")]
    assert regions["linearize_solve"].processes == (producer, "cholesky_eliminate_beside")
    assert [s[0] for s in regions["linearize_solve"].streams] == ["grams"]
    header = (ROOT / "backends/hls/include/fgc_eliminate.h").read_text()
    overlap = {r.function: r for r in read_network(header)}["cholesky_overlap_beside"]
    assert [p.split("<")[0] for p in overlap.processes] == [
        "cholesky_gram_source", "cholesky_assembler", "cholesky_cascade"]


def test_counted_cycles_equal_the_plan():
    """LIO N=5, LM, float32: every phase group's counted cycles (hgc_beside among them: the
    producer beside the elimination's passes, each gated by its step's last Gram) equal the
    plan's, within 2 %. (The C simulation's result equal to the simulator's: test_hls_csim's
    Cholesky cases, which emit this design.)"""
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="lm", linear="cholesky", cpe=3, precision="float32")
    phases, events = measure("t", lio.build(N=5), solver)
    assert phases["hgc_beside"][0] > 0 and events["solve"] >= events["linearize"]
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)


# heavy (about 50 s on 2 cores): LM's retries at a raised mu re-solve from GRAM_B
@pytest.mark.heavy
def test_lms_retries_resolve_from_the_kept_grams_as_priced():
    """imu_window N = 50, LM, float32 (#CPE = 5): float32 Cholesky fails its first solves there
    (κ past 1/√eps32), so LM raises mu and re-solves the same linearisation (event resolve) from
    the Grams the Gram source kept in GRAM_B: the retry phases count what the plan prices.
    (backsub: the plan prices it per solve, a failed solve skips it - as before.)"""
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="lm", linear="cholesky", cpe=5, precision="float32")
    phases, events = measure("t", example("imu_window").build(N=50), solver)
    assert events.get("resolve", 0) >= 1
    assert phases["recholesky"][0] > 0 and phases["reassemble"][0] > 0
    for g in ("hgc", "hgc_beside", "reassemble", "recholesky"):
        counted, model = phases[g]
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)
