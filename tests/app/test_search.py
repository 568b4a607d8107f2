"""The design-space search (fgc.app.search) and the latency floor (fgc.app.floor): a design the
plan fits but the second reader does not is refused; designs are read fastest first until one
fits, so the fastest that fits is never missed; the floor is below every design's cycles."""

from __future__ import annotations

import pytest

import fgc
from fgc.app.floor import PARTS, latency_floor, limits_line, phase_excess
from fgc.app.search import Candidate, SearchError, Space, fit_warnings, search
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2
from fgc.ir.program import SolverConfig
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost

# the tests of the read logic search one QR unit kind (the qr_unit axis would double each family)
HOUSEHOLDER = (("qr_unit", ("householder",)),)


def _chain(n: int = 4) -> fgc.Graph:
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"x{i}", Pose2(float(i), 0.1 * i, 0.0))
    g.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    for i in range(n - 1):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0),
                            fgc.noise.isotropic(3, 0.1)))
    return g


@pytest.fixture(scope="module")
def programs():
    g = _chain()
    return {lin: compile_graph(g, SolverConfig(method=m, linear=lin, precision="float32"),
                               name="chain")
            for lin, m in (("qr", "gn"), ("cholesky", "lm"))}


def test_a_design_the_plan_fits_but_the_reader_does_not_is_refused(programs):
    """A 4-pose Pose2 chain, QR, n_u = 1, that the plan prices within the xc7z045's 900 DSP,
    and a reader that finds more than the part has (the real reader did, 1,056 DSP, before the
    plan priced the code around the units as Vitis binds it; it now reads about 550): the search
    refuses it, says the reader bound it, and raises it as a fit warning."""
    space = Space(linears=("qr",), units=(1,), unit_sets=(1,), extra=HOUSEHOLDER)
    result = search({"qr": programs["qr"]}, space, max_reads=1,
                    reader_fn=lambda program, config: ({"dsp": 2_000}, False), use_cache=False)
    (row,) = result.rows
    assert row.cost.fits and row.cost.dsp <= 900  # the plan alone would take it
    assert row.reader_dsp == 2_000
    assert row.verdict == "over" and row.bound.startswith("reader DSP")
    assert result.best is None
    assert len(fit_warnings(result, "chain")) == 1
    assert any("no design is known to fit" in line for line in result.lines())


def test_the_real_reader_reads_the_emitted_design(programs):
    """The same design read for real (emitted, then read back by backends/hls/reader/): a
    reading exists, and it judges the design on max(plan, reader)."""
    space = Space(linears=("qr",), units=(1,), unit_sets=(1,), extra=HOUSEHOLDER)
    (row,) = search({"qr": programs["qr"]}, space, max_reads=1).rows
    assert row.reader_dsp is not None and row.reader_dsp > 0
    assert row.verdict == ("fits" if max(row.reader_dsp, row.cost.dsp) <= 900 else "over")


def _stub(readings):
    """A reader returning ``readings[(units, sets, alloc)]`` and recording what was read."""
    seen = []

    def read(program, config):
        key = (program.solver.units, config.unit_sets,
               1 if config.allocation is None else config.allocation[0][1] // 16)
        seen.append(key)
        return {"dsp": readings[key]}, False

    return read, seen


def test_the_search_reads_fastest_first_and_cannot_miss(programs):
    """A stub reader over the part on the fast designs (reader > plan there, which the rule must
    survive): the search reads in plan-speed order, never a design the plan puts over the part,
    until one fits; that one is the best, every faster design was read (or is over by the
    plan) and found over, and each verdict is the one its own reading gives."""
    space = Space(linears=("qr",), units=(1, 2, 4, 8), unit_sets=(1, 2), alloc_scales=(1, 2),
                  extra=HOUSEHOLDER)

    def key(r):
        c = r.candidate
        return (c.units, c.unit_sets, c.alloc_scale)

    # the plan's speed order decides which designs are "fast"; the stub puts the two fastest the
    # plan fits over the part (whatever the units' prices make them), the rest under it
    probe = search({"qr": programs["qr"]}, space, reader_fn=lambda p, c: ({"dsp": 0}, False))
    over = [key(r) for r in probe.rows if r.cost.fits][:2]
    readings = {(u, s, a): 150 * u * s + 100 * a for u in (1, 2, 4, 8) for s in (1, 2)
                for a in (1, 2)}
    readings = {k: 901 + v if k in over else min(v, 850) for k, v in readings.items()}
    read, seen = _stub(readings)
    result = search({"qr": programs["qr"]}, space, reader_fn=read)

    def truth(r):
        return max(readings[key(r)], r.cost.dsp) <= 900 and r.cost.fits

    order = [r for r in result.rows if r.cost.fits]  # plan-speed order, plan-over skipped
    assert seen == [key(r) for r in order[:len(seen)]]
    assert result.best is not None and result.best.read and truth(result.best)
    faster = result.rows[:result.rows.index(result.best)]
    assert all(r.verdict == "over" and not truth(r) for r in faster)
    assert all(r.read or not r.cost.fits for r in faster)  # every faster one the plan fits
    # the faster designs the plan fits and the reader puts over: read and refused, in order
    refused = [key(r) for r in faster if r.read]
    assert refused == over and all(readings[k] > 900 for k in refused)
    assert len(seen) < len(result.rows) and result.unchecked_faster == 0
    for r in result.rows:
        assert r.verdict in ("fits", "over", "unread")
        if r.verdict != "unread":
            assert (r.verdict == "fits") == truth(r), r.label
    # a fitting read marks the slower designs below it fitting (for the table only)
    implied = [r for r in result.rows if r.implied_by]
    assert implied and all(r.cycles >= result.best.cycles for r in implied)
    # a cap stops it early and says how many faster designs were left
    read, seen = _stub(readings)
    capped = search({"qr": programs["qr"]}, space, max_reads=1, reader_fn=read)
    assert len(seen) == 1 and capped.best is None and capped.unchecked_faster > 0


def test_a_read_budget_leaves_designs_unread_and_says_so(programs):
    space = Space(linears=("qr",), units=(1, 2, 4, 8), unit_sets=(1,), extra=HOUSEHOLDER)
    read, seen = _stub({(u, 1, 1): 100 for u in (1, 2, 4, 8)})
    result = search({"qr": programs["qr"]}, space, max_reads=0, reader_fn=read)
    assert seen == [] and result.best is None and result.unchecked_faster == 4
    assert any("raise the read budget" in line for line in result.lines())


def test_a_design_the_emitter_refuses_is_no_candidate(programs):
    """A read that fails with an FgcError (the emitter refuses the design) marks that design
    unbuildable and implies nothing about the others; the search goes on."""
    from fgc.errors import FgcError

    def read(program, config):
        if program.solver.units == 2:
            raise FgcError("refused")
        return {"dsp": 100}, False

    space = Space(linears=("qr",), units=(1, 2), unit_sets=(1,), extra=HOUSEHOLDER)
    result = search({"qr": programs["qr"]}, space, max_reads=4, reader_fn=read)
    verdicts = {r.candidate.units: r.verdict for r in result.rows}
    assert verdicts == {2: "unbuildable", 1: "fits"} and result.best.candidate.units == 1
    assert "refused" in next(r.bound for r in result.rows if r.verdict == "unbuildable")


def test_the_qr_unit_axis_prices_each_unit_as_emitted(programs):
    """PlanOptions and DesignOptions both have ``qr_unit``: a QR space searches householder and
    stream designs (Cholesky ones have no QR unit), each emitted with its unit
    (``config.design.qr_unit``) and priced by the plan of that unit; a reading of one kind
    implies nothing about the other (an unordered axis)."""
    space = Space(linears=("qr", "cholesky"), units=(2,), unit_sets=(1,), cpe=(5,),
                  cascades=(1,))
    seen = []

    def read(program, config):
        seen.append((program.solver.linear, config.design.qr_unit))
        return {"dsp": 100}, False

    result = search(programs, space, max_reads=1, reader_fn=read)
    kinds = sorted(dict(r.candidate.extra).get("qr_unit", "-") for r in result.rows)
    assert kinds == ["-", "householder", "stream"]
    cycles = {}
    for r in result.rows:
        if r.candidate.linear != "qr":
            continue
        kind = dict(r.candidate.extra)["qr_unit"]
        config = r.candidate.config(space)
        assert config.design.qr_unit == kind and f"qr_unit={kind}" in r.label
        program = r.candidate.program(programs)
        options = PlanOptions.for_config(config, program)
        assert options.qr_unit == kind
        cycles[kind] = r.cycles
        assert r.cycles == plan_cost(build_plan(program, options)).cycles
    assert cycles["householder"] != cycles["stream"]
    # one read: the fastest design, which fits; it implies nothing about the other kinds
    assert len(seen) == 1 and result.best is result.rows[0] and result.best.read
    assert all(r.verdict == "unread" for r in result.rows[1:])


def test_monotone_order_and_space_checks():
    small, big = Candidate("qr", 1, 1, None, 1), Candidate("qr", 4, 2, None, 2)
    assert small.below(big) and not big.below(small)
    assert not Candidate("qr", 1, None, None, 1).below(big)  # the default sets: not ordered
    assert not Candidate("cholesky", cpe=5).below(big)
    with pytest.raises(SearchError):
        Space(units=())
    with pytest.raises(SearchError):
        Space(linears=("lu",))
    with pytest.raises(SearchError):
        Space(cpe=(0,))


@pytest.mark.parametrize("linear", ["qr", "cholesky"])
def test_the_floor_is_below_every_design(programs, linear):
    """The floor is a chain every design must run, at the operator table's latencies: each
    design's plan cycles (and each floor part's share of them) are at least the floor's."""
    program = programs[linear]
    ops = build_plan(program, PlanOptions.of(program)).ops
    floor = latency_floor(program, ops)
    assert [p for p, _ in floor.parts] == list(PARTS) and floor.cycles > 0
    by_index = {s.index: s for s in program.schedule.steps}
    paths = set()
    for leaf in (s for s in by_index.values() if not s.children):
        step, pivots = leaf, 0
        while step is not None:
            pivots += step.frontal_dim
            step = by_index.get(step.parent)
        paths.add(pivots)
    assert floor.pivots in paths  # one leaf-to-root path of the elimination tree
    for kw in ({"units": 1}, {"units": 32, "unit_sets": 2}, {"cpe": 5}, {"cpe": 120}):
        cost = plan_cost(build_plan(program, PlanOptions.of(program, **kw)))
        assert floor.cycles <= cost.cycles
        for part, design, part_floor in phase_excess(floor, cost.phase_cycles):
            if part in ("eliminate", "back-substitute"):
                assert part_floor <= design, (kw, part)
        assert "the floor; limited by" in limits_line(floor, cost)


def test_cholesky_floor_by_hand(programs):
    """The Cholesky chain floor by hand: every pivot on the path sqrt + div + mul + add, one
    add at each step with children, the leaf's H entries (mul + ⌈log₂ rows⌉ adds)."""
    import math

    program = compile_graph(_chain(), SolverConfig(method="lm", linear="cholesky",
                                                   ordering="serial", precision="float32"))
    ops = build_plan(program, PlanOptions.of(program)).ops
    floor = latency_floor(program, ops)
    steps = program.schedule.steps
    assert len(program.schedule.roots) == 1 and all(len(s.children) <= 1 for s in steps)
    la, lm = ops.add.latency, ops.mul.latency
    pivot = ops.sqrt.latency + ops.div.latency + lm + la
    leaf = next(s for s in steps if not s.children)
    expect = (sum(s.frontal_dim for s in steps) * pivot
              + la * sum(1 for s in steps if s.children)
              + lm + math.ceil(math.log2(leaf.rows)) * la)
    assert floor.part("eliminate") == expect
    assert floor.part("back-substitute") == floor.unknowns * (lm + la)


def test_a_cholesky_space_searches_one_and_two_cascades(programs):
    """Cholesky designs go with one cascade (the emitter's default) and with two side by side
    (``HlsConfig.unit_sets=2``), each priced by the plan of what it emits."""
    space = Space(linears=("cholesky",), cpe=(5,))
    result = search(programs, space, max_reads=0, reader=False)
    by_sets = {r.candidate.unit_sets: r for r in result.rows}
    assert set(by_sets) == {None, 2}
    assert "cascades=2" in by_sets[2].label and "cascades" not in by_sets[None].label
    assert by_sets[2].candidate.config(space).unit_sets == 2
    assert by_sets[2].cost.dsp > by_sets[None].cost.dsp  # a second cascade's CPEs
    with pytest.raises(SearchError):
        Space(cascades=(3,))


def test_the_search_sees_back_substitutions_width(programs):
    """``Space.backsub_lanes``: each design with back-substitution one lane wide
    (``HlsConfig.backsub_lanes=1``) and two (``=2``, fgc_backsub.h's cond_load_wide), each
    priced by the plan of what it emits; ``None`` (the default axis) is the candidate without
    the option, the emitter's automatic width (by columns on this chain)."""
    space = Space(linears=("cholesky",), cpe=(5,), cascades=(1,), backsub_lanes=(1, 2, None))
    result = search(programs, space, max_reads=0, reader=False)
    by_width = {dict(r.candidate.extra).get("backsub_lanes"): r for r in result.rows}
    assert set(by_width) == {1, 2, None}
    assert "backsub_lanes=2" in by_width[2].label and "backsub_lanes=1" in by_width[1].label
    assert "backsub" not in by_width[None].label
    assert by_width[1].candidate.config(space).backsub_lanes == 1
    auto = by_width[None].candidate
    assert auto.config(space).backsub_lanes is None
    plan = build_plan(auto.program(programs), PlanOptions.for_config(auto.config(space),
                                                                     auto.program(programs)))
    assert plan.options.backsub_lanes == 4 and by_width[None].cost == plan_cost(plan)
    assert Space().backsub_lanes == (None,)
    config = by_width[2].candidate.config(space)
    assert config.backsub_lanes == 2
    program = by_width[2].candidate.program(programs)
    plan = build_plan(program, PlanOptions.for_config(config, program))
    assert by_width[2].cost == plan_cost(plan) and plan.options.backsub_lanes == 2
    assert by_width[2].cost.dsp > by_width[1].cost.dsp  # the wider load and triangle
    with pytest.raises(SearchError):
        Space(backsub_lanes=(0,))


def test_the_search_sees_back_substitution_by_columns(programs):
    """``Space.backsub_lanes`` with 4 (back-substitution by columns, a process per end of the
    chain): priced by the plan of what it emits, fewer cycles than one lane on a chain; on a
    tree the plan refuses it and the search skips that candidate."""
    from fgc.app.specs import example

    space = Space(linears=("cholesky",), cpe=(5,), cascades=(1,), backsub_lanes=(1, 4))
    result = search(programs, space, max_reads=0, reader=False)
    by_width = {dict(r.candidate.extra).get("backsub_lanes"): r for r in result.rows}
    assert set(by_width) == {1, 4}
    config = by_width[4].candidate.config(space)
    program = by_width[4].candidate.program(programs)
    plan = build_plan(program, PlanOptions.for_config(config, program))
    assert by_width[4].cost == plan_cost(plan) and plan.options.backsub_lanes == 4
    tree = {"cholesky": compile_graph(example("pose_graph").build(), SolverConfig(
        method="lm", linear="cholesky", precision="float32"), name="w100")}
    skipped = search(tree, space, max_reads=0, reader=False)
    assert {dict(r.candidate.extra).get("backsub_lanes") for r in skipped.rows} == {1}
