"""The plan against the second reader on small emitted designs (issue 32 part 4): the plan
prices at least the DSP the emitted text instantiates (check_dsp), and no pipelined loop of the
kernel around the units (the emitted kernel, fgc_lm_units.h, fgc_backsub.h) declares an II its
memories or recurrences cannot give (check). The QR unit's and the Cholesky cascade's own
headers are held to this by their own tests."""

from __future__ import annotations

import pytest

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
from fgc_backends.hls.reader import check, check_dsp, emitted_files, read_design

AROUND = ("fgc_lm_units.h", "fgc_backsub.h")


def _read(program, tmp_path):
    config = HlsConfig()
    emit(program, tmp_path, config)
    plan = build_plan(program, PlanOptions.for_config(config, program))
    tab = plan.target.ops(plan.precision)
    dsp_of = {k: tab.op(k).dsp for k in ("add", "mul", "div", "sqrt", "special")}
    files, top = emitted_files(tmp_path)
    design = read_design(files, top, tab.add.latency)
    return plan_cost(plan), design, dsp_of


def _around(issues, name):
    return [i for i in issues if i.file in AROUND or i.file == f"{name}.cpp"]


def test_lio_plan_prices_at_least_what_the_text_instantiates(tmp_path):
    program = compile_graph(example("lio").build(N=4), name="lio", solver=SolverConfig(units=4))
    cost, design, dsp_of = _read(program, tmp_path)
    assert check_dsp(design, cost.dsp, dsp_of) == []
    assert _around(check(design.loops), "lio") == []
    # the gradient's accumulate: TILE multiply-adds a cycle, not a row's every column
    acc = [r for r in design.loops if r.function == "accumulate" and dict(r.ops).get("mul")]
    assert acc and all(dict(r.instances) == {"add": 4, "mul": 4} for r in acc)


@pytest.mark.heavy
def test_imu_window_plan_prices_at_least_what_the_text_instantiates(tmp_path):
    program = compile_graph(example("imu_window").build(N=10), name="imu",
                            solver=SolverConfig(linear="cholesky", cpe=5))
    cost, design, dsp_of = _read(program, tmp_path)
    assert check_dsp(design, cost.dsp, dsp_of) == []
    assert _around(check(design.loops), "imu") == []
