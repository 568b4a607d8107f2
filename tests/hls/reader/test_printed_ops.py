"""The plan's operation counts are the emitted text's (issue 32, the ALLOCATION rule): the
counts that size each factor datapath's ``ALLOCATION`` limits and its II
(``units/special_ops.printed_counts``, from the printer's own split of a product and a power)
equal what the second reader counts in the emitted ``factor_<b>`` / ``factor_cost_<b>``
functions, its project callees (``fgc_sqrt``, the Lie coefficients, ``so3_log``) read in
place. A factor with the forms the compiler's count and the printed text disagree on (x/2
printed as a multiply by 0.5, x/y, 1/x, x**-2, sqrt, x**0.5, a square of a sum, a sign) and a
LIO design (its special functions' bodies) are checked; with those counts every evaluate /
cost loop's declared II meets its ALLOCATION limits (rule ``ii_allocation``)."""

from __future__ import annotations

import pytest

import fgc
from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.frontend import noise
from fgc.frontend.factors import PriorFactor
from fgc.frontend.geometry import Point2
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.plan import PlanOptions, build_plan
from fgc_backends.hls.reader import check, emitted_files, read_design
from fgc_backends.hls.reader.design import _Reader
from fgc_backends.hls.units.special_ops import issued_counts, printed_counts

ARITHMETIC = ("add", "mul", "div", "sqrt")


@fgc.factor
def quotients(p: Point2, q: Point2, *, m: float):
    x, y = p.x(), q.y()
    return [x / 2 - m, x / y, 1 / x + y ** -2, (x * x + 1) ** 0.5 + fgc.sqrt(y * y + 2),
            (x + y) ** 2 / 3 - x * y ** 3 / (x - y), -x * y / 7]


def _quotients_program():
    g = fgc.Graph()
    g.add_variable("a", Point2(1.0, 2.0))
    g.add_variable("b", Point2(1.5, -2.5))
    g.add(PriorFactor("a", Point2(1.2, 2.1), noise.isotropic(2, 1.0)))
    g.add(PriorFactor("b", Point2(1.4, -2.4), noise.isotropic(2, 1.0)))
    g.add(quotients("a", "b", m=0.3, noise=noise.isotropic(6, 0.5)))
    return compile_graph(g, SolverConfig(), name="quot")


def _emit_and_read(program, tmp_path):
    config = HlsConfig()
    emit(program, tmp_path, config)
    plan = build_plan(program, PlanOptions.for_config(config, program))
    files, top = emitted_files(tmp_path)
    return _Reader(files, plan.target.ops(plan.precision).add.latency), files, top


def _read_function(reader, name: str, peak: bool = False) -> dict[str, int]:
    """The reader's count of function ``name`` run once, its callees read in place (``peak``:
    exclusive branches sharing, the larger of each kind)."""
    f = reader.functions[name]
    reader.flatten = True
    count = reader.count(f.text, {p.name: v for p in f.params
                                  if (v := reader._param_var(f, p)) is not None},
                         {}, None, frozenset())
    return {k: n for k, n in (count.peak if peak else count.ops).items()
            if n and k in ARITHMETIC}


def _plan(block, mode: str, issued: bool = False) -> dict[str, int]:
    counts = (issued_counts if issued else printed_counts)(block, mode)
    return {k: n for k, n in counts.items() if n and k in ARITHMETIC}


def test_counts_follow_the_printed_quotients(tmp_path):
    program = _quotients_program()
    reader, files, top = _emit_and_read(program, tmp_path)
    b = next(i for i, blk in enumerate(program.blocks) if blk.name == "quotients")
    block = program.blocks[b]
    for function, mode in ((f"factor_{b}", "jacobian"), (f"factor_cost_{b}", "cost")):
        assert _plan(block, mode) == _read_function(reader, function), function
    # the forms the compiler's own count takes otherwise: x/2 a divide there, a multiply by
    # T(0.5) in the text; the divides of x/y**2 once in the text (x/(y*y)), twice there
    text = dict(files)["quot.cpp"]
    assert "(T(0.5))*in[0]" in text
    assert _plan(block, "jacobian")["div"] < block.ops_after["div"]
    # every evaluate / cost loop issues its operations within its II on its ALLOCATION
    design = read_design(files, top, reader.add_latency)
    assert [i for i in check(design.reached_loops) if i.rule == "ii_allocation"] == []


@pytest.mark.parametrize("mode", ["jacobian", "cost"])
def test_counts_follow_the_printed_lio_datapaths(tmp_path, mode):
    """LIO's blocks: the SO(3) logarithm, Lie coefficients and their bodies, whitening-free
    datapath functions; what the plan counts is what the reader counts: every branch built
    (printed_counts) and, the special functions' exclusive branches sharing, what one
    evaluation issues (issued_counts, the reader's peak: what the plan's II is sized by)."""
    program = compile_graph(example("lio").build(N=3), name="lio", solver=SolverConfig())
    reader, _, _ = _emit_and_read(program, tmp_path)
    names = {"jacobian": "factor_{}", "cost": "factor_cost_{}"}
    seen = shared = 0
    for b, block in enumerate(program.blocks):
        function = names[mode].format(b)
        if function not in reader.functions:  # a small block type: in factor_small's branch
            continue
        assert _plan(block, mode) == _read_function(reader, function), (block.name, mode)
        issued = _plan(block, mode, issued=True)
        assert issued == _read_function(reader, function, peak=True), (block.name, mode)
        shared += issued != _plan(block, mode)
        seen += 1
    assert seen and shared  # some datapath's special functions branch
