"""The design's Target (backends/hls/target.py): part → device, family and operator table; the
plan priced through it at the Program's clock."""

from __future__ import annotations

import pytest
from hls_programs import chain

from fgc_backends.hls.config import HlsConfig, check_clock
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
from fgc_backends.hls.target import DEFAULT_PART, Target, UnknownPartError, target_of


def test_a_part_names_its_device_and_family():
    assert Target(DEFAULT_PART).device.name == "xc7z045"
    assert Target(DEFAULT_PART).family == "7series"
    assert Target("xczu9eg-ffvb1156-2-e").family == "ultrascale+"
    with pytest.raises(UnknownPartError, match="xcvu9p"):
        target_of("xcvu9p-flga2104-2L-e", 143.0)
    with pytest.raises(UnknownPartError, match="positive"):
        target_of(DEFAULT_PART, 0.0)


def test_the_plan_is_priced_for_its_part_at_the_programs_clock():
    program = chain(4, linear="qr", clock_mhz=200.0)
    plan = build_plan(program, PlanOptions.of(program, part="xczu9eg-ffvb1156-2-e"))
    assert plan.target == Target("xczu9eg-ffvb1156-2-e", 200.0)
    assert plan.ops == plan.target.ops(plan.precision)
    cost = plan_cost(plan)
    assert cost.clock_mhz == 200.0 and cost.fits  # the xczu9eg's 2,520 DSP


def test_the_programs_clock_is_the_designs_unless_a_period_is_given():
    assert HlsConfig().clock_ns is None
    check_clock(200.0, HlsConfig())  # no second clock to disagree with
    check_clock(200.0, HlsConfig(clock_ns=5.0))
    with pytest.raises(Exception, match="clock mismatch"):
        check_clock(200.0, HlsConfig(clock_ns=7.0))


def test_the_operator_table_follows_family_and_clock():
    # ≤ 150 MHz: the stage counts of Vitis's generated cores (7-series the deeper binding)
    slow = Target(DEFAULT_PART, 143.0).ops("float32")
    assert (slow.add.latency, slow.mul.latency, slow.div.latency, slow.sqrt.latency) == \
        (4, 3, 15, 15)
    fast_fabric = Target("xczu9eg-ffvb1156-2-e", 143.0).ops("float32")
    assert (fast_fabric.add.latency, fast_fabric.mul.latency, fast_fabric.div.latency) == \
        (3, 2, 9)
    # above 150 MHz: the core's maximum latencies (PG060)
    hot = Target(DEFAULT_PART, 250.0).ops("float32")
    assert (hot.add.latency, hot.mul.latency, hot.div.latency) == (11, 8, 28)
    # and the plan prices with its target's table
    program = chain(4, linear="qr")
    a = build_plan(program)
    b = build_plan(program, PlanOptions.of(program, part="xczu9eg-ffvb1156-2-e"))
    assert a.ops.add.latency == 4 and b.ops.add.latency == 3
    assert plan_cost(b).cycles < plan_cost(a).cycles


def test_every_row_has_a_source_and_the_analytic_model_reads_the_same_table():
    from fgc_backends.cost import operators
    from fgc_backends.cost.params import FLOAT32 as MODEL32

    for key, t in operators.TABLES.items():
        for kind, op in t.entries():
            assert op.source and op.status in ("documented", "assumed"), (key, kind)
            if op.status == "documented" and "Vitis core name" in op.source:
                assert "assumed" in op.note, (key, kind)  # the family/clock pairing
    f32 = operators.table("float32")
    assert (MODEL32.add.latency, MODEL32.mul.latency, MODEL32.div.latency) == \
        (f32.add.latency, f32.mul.latency, f32.div.latency)
    with pytest.raises(ValueError, match="family"):
        operators.table("float32", "virtex2")
