"""The one pricer (backends/hls/plan/cost.py): a design of two accelerators and extra memories
(the on-chip stream's window and batch kernels) is one merged plan that plan_cost prices."""

from __future__ import annotations

from hls_programs import chain

from fgc_backends.hls.plan import Memory, build_plan, merge_plans, plan_cost


def test_a_merged_plan_costs_its_parts():
    window = build_plan(chain(4, linear="qr"))
    batch = build_plan(chain(6, linear="qr"))
    extra = (Memory("kept_r", 2048, 32, 1),)  # 2048 words of 32 bits: 4 BRAM18 = 2 BRAM36
    a, b = plan_cost(window), plan_cost(batch)
    both = plan_cost(merge_plans(window, batch, extra))
    assert both.dsp == a.dsp + b.dsp
    assert both.bram36 == a.bram36 + b.bram36 + 2.0
    assert both.lut == a.lut + b.lut and both.words == a.words + b.words + 2048
    # the second accelerator's units keep their own names, prefixed
    names = {name for name, _ in both.dsp_by_unit}
    assert "factor_0" in names and "batch_factor_0" in names
    # its phases are its own calls', not the first plan's iteration
    assert both.cycles == a.cycles
    assert plan_cost(merge_plans(window)) == a
