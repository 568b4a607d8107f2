"""The mixed design (``--precision float32 --linear-precision float64``): the linear solver's
units (the Cholesky cascades and HGC, the Householder units, back-substitution; typed ``L`` =
double in the emitted text) are priced in float64's operator table, the rest in float32's.
Before, plan_cost priced every unit in the working table: the mixed design's DSP equalled the
float32 design's (imu_window N = 50 #CPE 20 x2: 893 both; by units 1,967)."""

from __future__ import annotations

import pytest
from hls_programs import chain_graph

from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig
from fgc_backends.hls.emitter import for_program
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost


def _program(linear, precision, les=None, **solver):
    return compile_graph(chain_graph(6),
                         SolverConfig(method="lm" if linear == "cholesky" else "gn",
                                      linear=linear, precision=precision,
                                      linear_precision=les, **solver), name="chain")


def _plan(linear, precision, les=None, **solver):
    p = _program(linear, precision, les, **solver)
    cfg = for_program(p, HlsConfig(scalar="float" if precision == "float32" else "double"))
    return build_plan(p, PlanOptions.for_config(cfg, p))


@pytest.mark.parametrize("linear,solver", [("cholesky", {"cpe": 5}), ("qr", {"units": 2})])
def test_the_linear_solver_is_priced_in_its_own_table(linear, solver):
    single = _plan(linear, "float32", **solver)
    mixed = _plan(linear, "float32", "float64", **solver)
    double = _plan(linear, "float64", **solver)
    cs, cm, cd = plan_cost(single), plan_cost(mixed), plan_cost(double)
    # the mixed design binds double operators in its solver: more DSP than float32, fewer
    # than the all-double design (whose datapaths are double too)
    assert cs.dsp < cm.dsp < cd.dsp
    f64 = mixed.target.ops("float64")
    f32 = mixed.target.ops("float32")
    by_unit = dict(cm.dsp_by_unit)
    solver_units = [u for u in mixed.units if u.precision == "float64"]
    assert solver_units, "no unit of the linear solver is marked float64"
    for u in mixed.units:
        table = f64 if u.precision == "float64" else f32
        assert u.precision in ("", "float64")
        assert by_unit[u.name] == u.instances * (u.extra_dsp + sum(
            n * table.op(k).dsp for k, n in u.operators))
    # the datapaths stay in the working precision, the solver's units are the double ones
    names = {u.name for u in solver_units}
    assert not any(n.startswith(("factor", "state_update", "lm_control", "gradient"))
                   for n in names)
    if linear == "cholesky":
        assert {"cpe", "trisolve"} <= names
    else:
        assert any(n.endswith("_update") for n in names)
    # a pure design marks no unit: priced exactly as before
    assert all(u.precision == "" for u in single.units + double.units)


def test_the_search_prices_a_float64_solver_as_the_emitter_builds_it():
    from fgc.app.search import Candidate, Space, price

    mixed = _plan("cholesky", "float32", "float64", cpe=5)
    space = Space(linears=("cholesky",))
    cost, _, _ = price(_program("cholesky", "float32", "float64", cpe=5),
                       Candidate("cholesky", cpe=5), space)
    assert cost.dsp == plan_cost(mixed).dsp
    narrow, _, _ = price(_program("cholesky", "float32", cpe=5), Candidate("cholesky", cpe=5),
                         space)
    assert narrow.dsp < cost.dsp
