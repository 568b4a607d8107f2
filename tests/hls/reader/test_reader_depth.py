"""The factor datapaths' depth read back from the emitted text (reader/depth.py) against the
plan's (cost.kernels.critical_path, the datapaths' instance loops; the retractions' too): Vitis
does not reassociate floating-point operations, so a flat ``a + b + c + d`` is a chain of three
adders; the HLS printer prints every sum and product as the reduction tree the plan prices
(cfamily/trees.py), and the reader, which parses the C++ on its own, must find no datapath
deeper than its plan loop. The golden designs were printed flat before: the reader found the IMU
block's Jacobian 664 cycles deep where the plan priced 621 (LIO, float32)."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
import sympy as sp

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.compiler.kernel import Kernel
from fgc.ir.program import KernelText, SolverConfig
from fgc_backends.cfamily.printer import UnsupportedExpressionError, print_kernel
from fgc_backends.cfamily.retract import retract_kernel, variable_class
from fgc_backends.cost.kernels import critical_path, kernel_latencies
from fgc_backends.cost.params import FLOAT32, view
from fgc_backends.hls import HlsConfig
from fgc_backends.hls.plan import PlanOptions, build_plan
from fgc_backends.hls.plan.report import datapath_depths as priced_depths
from fgc_backends.hls.reader import emitted_files, emitted_ops
from fgc_backends.hls.reader.depth import (
    check_depths,
    datapath_depths,
    function_depth,
    table_latency,
)

GOLDEN = Path(__file__).resolve().parents[2] / "golden" / "hls"
LAT = {"add": 4, "mul": 3, "div": 15, "sqrt": 15, "sincos": 40, "atan2": 48, "exp": 30,
       "log": 30, "compare": 1, "special": 160}


def _depth(body: str) -> int | None:
    return function_depth(body, LAT.__getitem__)


def test_the_reader_associates_as_cxx_does():
    assert _depth("raw[0] = in[0] + in[1] + in[2] + in[3];") == 3 * 4  # ((a + b) + c) + d
    assert _depth("raw[0] = (in[0] + in[1]) + (in[2] + in[3]);") == 2 * 4
    assert _depth("raw[0] = in[0]*in[1]*in[2] - in[3];") == 2 * 3 + 4
    assert _depth("raw[0] = -in[0]*(in[1]*in[2])/(in[3]*in[4]);") == 2 * 3 + 15  # sign free
    assert _depth("const T t0 = fgc_sqrt(in[0]);\n raw[0] = T(1)/t0 + in[1];") == 15 + 15 + 4
    assert _depth("T tlog0[3]; so3_log(in[0], in[1], in[2], in[3], in[4], in[5], in[6], "
                  "in[7], in[8], tlog0);\n const T t0 = tlog0[2];\n half[0] = t0*t0;") == 163
    assert _depth("#pragma HLS INLINE off\n raw[0] = fgc_atan2(in[0], in[1]);") == 48
    assert _depth("raw[0] = mystery(in[0]);") is None  # not judged


def _random_expr(rng: random.Random, syms, depth: int):
    if depth == 0 or rng.random() < 0.25:
        return rng.choice(syms)
    kind = rng.choice(["add", "add", "mul", "mul", "div", "pow", "sqrt", "neg", "coef"])
    parts = [_random_expr(rng, syms, depth - 1) for _ in range(rng.randint(2, 5))]
    if kind == "add":
        return sp.Add(*[p if rng.random() < 0.6 else -p for p in parts])
    if kind == "mul":
        return sp.Mul(*parts)
    if kind == "div":
        return parts[0] / sp.Mul(*parts[1:])
    if kind == "pow":
        return sp.Add(*parts[:2]) ** rng.choice([2, 3, 4, -2, sp.Rational(3, 2)])
    if kind == "sqrt":
        return sp.sqrt(sp.Add(*[p * p for p in parts]))
    if kind == "neg":
        return -sp.Add(*parts)
    return sp.Rational(rng.randint(1, 9), rng.randint(1, 9)) * parts[0] + parts[1]


def _body(kernel: Kernel, latencies) -> str:
    printed = print_kernel(kernel, [f"in[{i}]" for i in range(len(kernel.inputs))], "k",
                           latencies=latencies)
    return "\n".join(printed.intermediates) + "\n" + "\n".join(
        f"raw[{i}] = {e};" for i, e in enumerate(printed.outputs))


def test_the_printed_trees_are_what_the_critical_path_prices():
    """On random kernels: the text printed with the table's latencies reads back exactly as deep
    as critical_path prices it (one pairing rule, cfamily.trees), the flat text as deep as the
    left-to-right chains (balanced=False) — deeper than the plan where a sum has three terms
    or more."""
    rng = random.Random(7)
    syms = sp.symbols("x0:6", real=True)
    lat = dict(kernel_latencies(FLOAT32))
    table = {"add": lat["add"], "mul": lat["mul"], "div": lat["div"], "sqrt": lat["sqrt"],
             "sincos": lat["trig"], "atan2": lat["atan2"], "special": lat["special"],
             "compare": lat["special"]}  # |x| from sqrt(x**2): the plan prices it special
    deeper = tested = 0
    for case in range(24):
        t = sp.symbols(f"t{case}_0:3", real=True)
        assigns = []
        for k in range(3):
            assigns.append((t[k], _random_expr(rng, list(syms) + list(t[:k]), 3)))
        kernel = Kernel(tuple(syms), tuple(assigns),
                        (_random_expr(rng, list(syms) + list(t), 3), t[2]))
        text = KernelText.of(kernel)
        try:
            tree = function_depth(_body(kernel, kernel_latencies(FLOAT32)), table.__getitem__)
        except UnsupportedExpressionError:  # a power of a power beyond the printer's bound
            continue
        flat = function_depth(_body(kernel, None), table.__getitem__)
        assert tree == critical_path(text, FLOAT32), case
        assert flat == critical_path(text, FLOAT32, balanced=False), case
        tested += 1
        deeper += flat > tree
    assert tested > 15 and deeper > 5


@pytest.fixture(scope="module")
def lio_golden():
    """examples/lio.py N=8 (tests/golden/hls/lio, the default design, float32) and its text's
    datapath depths as the reader schedules them with run_hls.tcl's operator table."""
    program = compile_graph(example("lio").build(N=8), name="lio", solver=SolverConfig())
    files, _ = emitted_files(GOLDEN / "lio")
    table = emitted_ops(GOLDEN / "lio")("float32")
    return program, files, table


def test_the_golden_lio_datapaths_are_as_deep_as_their_critical_paths(lio_golden):
    """Every factor datapath function of the golden text is no deeper than its kernel's
    critical path (the least depth the plan prices its loop with); the IMU block's Jacobian
    exactly 621, its cost 596 (the plan times the residual's outputs too: 600). The same
    kernels printed flat, the text before the trees, read deeper: the check fails on them."""
    program, files, table = lio_golden
    read = datapath_depths(files, table_latency(table))
    ops = view(table)
    priced = {}
    for b, block in enumerate(program.blocks):
        priced[f"factor_{b}"] = critical_path(block.kernel, ops)
        priced[f"factor_cost_{b}"] = critical_path(block.cost_kernel, ops)
    for k, name in enumerate(dict.fromkeys(v.type_name for v in program.variables)):
        priced[f"retract_{k}"] = critical_path(
            KernelText.of(retract_kernel(variable_class(name))), ops)
    assert set(read) == set(priced)
    assert check_depths(read, priced) == []
    imu = next(i for i, b in enumerate(program.blocks) if b.name.startswith("CombinedImu"))
    assert read[f"factor_{imu}"] == priced[f"factor_{imu}"] == 621
    assert read[f"factor_cost_{imu}"] == 596 and priced[f"factor_cost_{imu}"] == 600
    assert read["retract_0"] == priced["retract_0"] == 203  # Pose3's (flat: 207)
    flat = {f"factor_{b}": function_depth(_body(block.kernel.kernel(), None),
                                          table_latency(table))
            for b, block in enumerate(program.blocks)}
    issues = check_depths(flat, {k: v for k, v in priced.items() if k in flat})
    assert [i.message for i in issues] == [
        "factor_0: the text schedules 428 cycles deep, the plan prices 416",
        f"factor_{imu}: the text schedules 664 cycles deep, the plan prices 621"]


@pytest.mark.heavy
def test_the_golden_lio_datapaths_are_no_deeper_than_their_plan_loops(lio_golden):
    """The plan's own loops (plan/report.py datapath_depths: max(critical path, issue), a small
    block type's the shared factor_small loop's) against the golden text (heavy: the plan;
    bench/bench_second_reader.py checks paper A's designs the same way)."""
    program, files, table = lio_golden
    plan = build_plan(program, PlanOptions.for_config(HlsConfig(), program))
    priced = priced_depths(plan, program)
    assert set(priced) == {f"factor{m}_{b}" for b in range(len(program.blocks))
                           for m in ("", "_cost")} | {"retract_0", "retract_1", "retract_2"}
    read = datapath_depths(files, table_latency(emitted_ops(GOLDEN / "lio")(plan.precision)))
    assert check_depths(read, priced) == []
    assert all(priced[k] >= read[k] for k in priced)
