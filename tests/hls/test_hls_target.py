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
