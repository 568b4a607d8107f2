"""The Cholesky cascade two words a cycle (``HlsConfig.cascade_lanes = 2``, fgc_cpe.h's
STREAM_WORDS): every feed, tap, CPE and drain takes the pair of a row's words the assembly
streams each cycle. The C simulation's results are the simulator's, it counts what the plan
prices, and the plan prices each CPE's doubled multipliers and adders."""

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
from fgc_backends.hls.plan import plan_cost
from fgc_backends.hls.units.cholesky import cpe_step_loops, cpe_vecs, cpe_wait

ROOT = Path(__file__).resolve().parents[2]
lio = example("lio")
imu_window = example("imu_window")


def test_a_step_takes_half_the_cycles_in_two_lanes():
    from fgc_backends.cost.operators import FLOAT32

    # row i of w = 30: 31 - i words, ceil((31 - i) / 2) pairs: the assembly's pairs
    assert cpe_vecs(0, 30, 2) == sum(-(-(31 - i) // 2) for i in range(30)) == 255
    assert cpe_vecs(0, 30, 1) == 495
    assert cpe_vecs(15, 30, 2) == sum(-(-(31 - i) // 2) for i in range(15, 30))
    # a short pivot row waits longer for r = 1 / d when its words come two a cycle
    assert cpe_wait(29, 30, FLOAT32, 2) == FLOAT32.div.latency - 1
    one = cpe_step_loops(15, 15, 4, FLOAT32)
    two = cpe_step_loops(15, 15, 4, FLOAT32, lanes=2)
    assert [lp.name for lp in one] == [lp.name for lp in two]
    assert two[0].trip == 256 and one[0].trip == 496
    # the rounds after the first read the rows left for them two a cycle as well (a row of an
    # odd count ends in a half-empty pair)
    assert all(b.trip <= 0.6 * a.trip for a, b in zip(one, two, strict=True)
               if "_round" in a.name)


def test_lanes_double_each_cpe_and_are_checked():
    program = compile_graph(lio.build(N=6), SolverConfig(linear="cholesky", cpe=4,
                                                         precision="float32"), name="lanes")
    one = plan_cost(accel_plan(program, HlsConfig(scalar="float")))
    two = plan_cost(accel_plan(program, HlsConfig(scalar="float", cascade_lanes=2)))
    d1, d2 = dict(one.dsp_by_unit), dict(two.dsp_by_unit)
    assert d2["cpe"] == 2 * d1["cpe"]  # per CPE 2 L multipliers and L adders (the divide: none)
    assert two.cycles < one.cycles
    for bad in (0, 3, True):
        with pytest.raises(HlsConfigError, match="cascade_lanes"):
            HlsConfig(cascade_lanes=bad).check()
    qr = compile_graph(lio.build(N=3), SolverConfig(linear="qr"), name="lanesqr")
    with pytest.raises(HlsConfigError, match="Cholesky cascade"):
        HlsConfig(cascade_lanes=2).check(qr)


def test_a_qr_design_refuses_lanes(tmp_path):
    qr = compile_graph(lio.build(N=3), SolverConfig(linear="qr"), name="lanesqr")
    with pytest.raises(HlsConfigError, match="Cholesky cascade"):
        emit(qr, tmp_path, HlsConfig(cascade_lanes=2))


# one set is heavy (about 16 s of CPU), as below: two sets run the same lanes in each set
@pytest.mark.parametrize("sets", [pytest.param(1, marks=pytest.mark.heavy), 2])
def test_two_lanes_match_the_simulator(tmp_path, sets):
    # LM in double, #CPE = 4 < f = 15: every step in four rounds, the later ones read back
    # from H two words a cycle; the C simulation's estimates are the simulator's to 1e-9
    graph = lio.build(N=6)
    program = compile_graph(graph, SolverConfig(linear="cholesky", cpe=4), name=f"lanes{sets}")
    project = emit(program, tmp_path, HlsConfig(scalar="double", unit_sets=sets,
                                                cascade_lanes=2))
    text = (project.directory / f"{project.name}.cpp").read_text()
    assert "static const int STREAM_WORDS = 2;" in text
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(project, program, data, reference)
    assert result.status == reference.status
    assert relative_worst(result.values, reference.storage) <= 1e-9


# one set is heavy (about 30 s on 2 cores): two sets count the same lanes, each set's too
@pytest.mark.parametrize("sets", [pytest.param(1, marks=pytest.mark.heavy), 2])
def test_two_lanes_count_what_the_plan_prices(sets):
    sys.path.insert(0, str(ROOT / "bench"))
    from bench_cycles import measure

    solver = SolverConfig(method="gn", linear="cholesky", cpe=4, precision="float32")
    phases, events = measure(f"l2_{sets}", imu_window.build(N=5), solver,
                             HlsConfig(scalar="float", unit_sets=sets, cascade_lanes=2))
    assert events["solve"] >= 1
    assert phases["hgc_beside"][0] > 0
    for g, (counted, model) in phases.items():
        assert abs(counted - model) <= 0.02 * max(model, 1), (g, counted, model)


def test_the_search_tries_two_lanes_as_its_own_family():
    from fgc.app.search import SearchError, Space, candidates

    program = compile_graph(lio.build(N=3), SolverConfig(linear="cholesky", cpe=4),
                            name="lanessearch")
    space = Space(linears=("cholesky",), cpe=(5, 20), cascades=(1, 2), lanes=(1, 2))
    found = candidates(space, {"cholesky": program})
    assert len(found) == 8
    two = [c for c in found if c.extra == (("cascade_lanes", 2),)]
    assert len(two) == 4 and all(c.config(space).cascade_lanes == 2 for c in two)
    # the reader's DSP grows along the ordered axes within a family, not across lanes
    one = next(c for c in found if c.cpe == 20 and not c.extra and c.unit_sets is None)
    assert not one.below(next(c for c in two if c.cpe == 20 and c.unit_sets is None))
    with pytest.raises(SearchError, match="lanes"):
        Space(lanes=(3,))
