"""The second reader on a mixed design (float32 accelerator, float64 linear solver): each
module's operators are typed by what its ``T`` names there (its own typedef, its ``CFG``
struct's through bases, a kernel namespace whose own level says ``typedef L T;`` and the header
lines included there, a template on T its caller's) and priced in that type's table
(:func:`dsp_table`). Before, one table priced every operator: a mixed design read as the
float32 one."""

from __future__ import annotations

from pathlib import Path

import pytest

from fgc_backends.hls.reader import dsp_table, emitted_files, read_design
from fgc_backends.hls.target import target_of

HEADER = """
#ifndef SOLVER_H
#define SOLVER_H
template <class CFG>
void solver_step(typename CFG::T a[8], typename CFG::T b[8]) {
    typedef typename CFG::T T;
    for (int i = 0; i < 8; ++i) {
#pragma HLS PIPELINE II=1
        b[i] = a[i] * a[i] + b[i];
    }
}
#endif
"""

KERNEL = """
typedef float T;
typedef double L;
#include "solver.h"
template <class T>
T twice(T x) { return x + x; }
void datapath(T a[8], T b[8]) {
    for (int i = 0; i < 8; ++i) {
#pragma HLS PIPELINE II=1
        b[i] = a[i] * a[i] + b[i];
    }
}
void retract(T x[8]) {
    for (int i = 0; i < 8; ++i) {
#pragma HLS PIPELINE II=1
        x[i] = x[i] * x[i];
    }
}
namespace les {
typedef L T;
struct LesConfig { typedef ::L T; static void retract_variable(::T x[8]) { ::retract(x); } };
struct SetConfig : LesConfig { static const int N = 8; };
T acc[8];
void eliminate(T a[8]) {
    for (int i = 0; i < 8; ++i) {
#pragma HLS PIPELINE II=1
        acc[i] = twice(a[i]) * a[i];
    }
}
}
void top(T a[8], T b[8], L la[8], L lb[8]) {
    datapath(a, b);
    solver_step<les::SetConfig>(la, lb);
    les::eliminate(la);
    retract(a);
}
"""

F32 = {"add": 2, "mul": 3, "div": 0, "sqrt": 0, "special": 0}


def test_each_module_is_typed_by_its_scalar():
    d = read_design([("k.cpp", KERNEL), ("solver.h", HEADER)], "top", 4)
    ops = dict(d.operators)
    # datapath and retract: float (T); solver_step through SetConfig's base LesConfig: double;
    # eliminate in the namespace where T is L, its template-on-T helper with it: double
    assert ops == {"add": 1, "mul": 2, "add:double": 2, "mul:double": 2}
    table = {**F32, "add:double": 3, "mul:double": 8}
    assert d.dsp(table) == 1 * 2 + 2 * 3 + 2 * 3 + 2 * 8
    # a table without the double figures prices them as the working kind's (the old reading)
    assert d.dsp(F32) == 3 * 2 + 4 * 3


def test_one_scalar_reads_as_before():
    text = KERNEL.replace("typedef double L;", "typedef T L;")
    d = read_design([("k.cpp", text), ("solver.h", HEADER)], "top", 4)
    assert dict(d.operators) == {"add": 3, "mul": 4}


@pytest.mark.parametrize("linear,option", [("cholesky", "--cpe=5"), ("qr", "--units=2")])
def test_a_mixed_design_reads_above_the_float32_one(tmp_path: Path, linear, option):
    """imu_window (the example's default N) emitted twice, float32 and float32 with a float64
    linear solver: the reader's DSP of the mixed design is above the float32 design's, and the
    plan still prices at least what the reader reads."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls import HlsConfig, emit
    from fgc_backends.hls.emitter import for_program
    from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost

    graph = example("imu_window").build(N=6)
    kw = {"cpe": 5} if linear == "cholesky" else {"units": 2}
    reads, plans = {}, {}
    for les in (None, "float64"):
        p = compile_graph(graph, SolverConfig(method="lm", linear=linear, precision="float32",
                                              linear_precision=les, **kw))
        cfg = for_program(p, HlsConfig(scalar="float"))
        out = tmp_path / f"{linear}_{les}"
        emit(p, out, cfg)
        files, top = emitted_files(out)
        target = target_of(cfg.part, p.solver.clock_mhz)
        design = read_design(files, top, target.ops("float32").add.latency)
        reads[les] = design.dsp(dsp_table(target.ops, "float32"))
        plans[les] = plan_cost(build_plan(p, PlanOptions.for_config(cfg, p))).dsp
        if les:
            assert any(k.endswith(":double") for k, _ in design.operators)
        else:
            assert not any(":" in k for k, _ in design.operators)
    assert reads["float64"] > reads[None]
    assert plans["float64"] >= reads["float64"] and plans[None] >= reads[None]
