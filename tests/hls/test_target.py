"""One target description (backends/hls/target.py): the cost model's device, the plan's fit
verdict and the lint's DSP budget all read the same capacities."""

from __future__ import annotations

import pytest

from fgc_backends.cost.params import CostParams
from fgc_backends.hls import plan
from fgc_backends.hls.lint import semantic_issues
from fgc_backends.hls.target import DEFAULT, DEVICES, UnknownPartError, capacity, device_of


def test_part_names_select_their_device_by_prefix():
    assert device_of("xc7z045ffg900-2") is DEVICES["xc7z045"]
    assert device_of("XCZU9EG-ffvb1156-2-e") is DEVICES["xczu9eg"]
    assert device_of("xc7z0") is None
    with pytest.raises(UnknownPartError, match="xcvu9p"):
        capacity("xcvu9p-flga2104-2L-e")


def test_cost_model_plan_and_lint_read_one_table():
    device = CostParams().device
    assert (device.name, device.dsp, device.bram36, device.lut, device.ff) == (
        DEFAULT.name, DEFAULT.dsp, DEFAULT.bram36, DEFAULT.lut, DEFAULT.ff)
    assert (DEFAULT.dsp, DEFAULT.bram36) == (plan.PART_DSP, plan.PART_BRAM36)
    code = "void f(float a[4]) {\n#pragma HLS ALLOCATION operation instances=fmul limit=100\n}\n"
    small, big = DEVICES["xc7z020"], DEVICES["xczu9eg"]
    # 100 float multipliers: over the xc7z020's DSP, within the xczu9eg's
    over = [i for i in semantic_issues([("k.cpp", code)], part="xc7z020-clg400-1", scalar="float")
            if i.rule == "dsp"]
    assert over and str(small.dsp) in over[0].message
    assert not [i for i in semantic_issues([("k.cpp", code)], part="xczu9eg-ffvb1156-2-e",
                                           scalar="float") if i.rule == "dsp"]
    assert big.dsp > 100 * 3 > small.dsp


def test_the_emitted_part_sets_the_fit_verdict():
    """A design that fits the xc7z045 does not fit an xc7z020 (220 DSP): the plan's verdict
    reads the HLS config's part, and an unknown part is refused by name."""
    from test_backends import _chain

    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls import HlsConfig, HlsConfigError

    program = compile_graph(_chain(), SolverConfig(precision="float32"), name="parts")
    verdicts = {}
    for part in ("xc7z045ffg900-2", "xc7z020clg400-1"):
        cost = plan.plan_cost(plan.build_plan(program, plan.PlanOptions.for_config(
            HlsConfig(scalar="float", part=part), program)))
        verdicts[part] = (cost.fits, cost.over, cost.dsp, cost.lut, cost.ff)
    assert verdicts["xc7z045ffg900-2"][:2] == (True, ()), verdicts
    _, _, dsp, lut, ff = verdicts["xc7z045ffg900-2"]
    small = DEVICES["xc7z020"]
    assert dsp > small.dsp, "the test needs a design over the xc7z020's DSP"
    # the verdict names exactly the resources over the small part's capacities
    expected = tuple(name for name, used, cap in (("DSP", dsp, small.dsp), ("LUT", lut, small.lut),
                                                  ("FF", ff, small.ff)) if used > cap)
    assert verdicts["xc7z020clg400-1"][:2] == (False, expected), verdicts
    with pytest.raises(HlsConfigError, match="xcvu9p.*known devices"):
        HlsConfig(part="xcvu9p-flga2104-2L-e").check()
