"""The HLS backend's configuration (backends/hls/config.py): the design options an HlsConfig
carries, the one place they are validated, and the plan options built from them."""

from __future__ import annotations

import dataclasses

import pytest
from hls_programs import chain

from fgc.errors import FgcError
from fgc_backends.hls.config import DesignOptions, HlsConfig, HlsConfigError
from fgc_backends.hls.plan import DEFAULT_ALLOCATION, PlanOptions, build_plan
from fgc_backends.hls.target import DEFAULT_PART, Target

ZU9 = "xczu9eg-ffvb1156-2-e"


def test_the_old_keywords_are_the_design_options():
    old = HlsConfig(scalar="double", part=ZU9, clock_ns=5.0, unit_sets=2,
                    allocation=(("mul", 48),))
    new = HlsConfig(scalar="double", design=DesignOptions(part=ZU9, clock_ns=5.0, unit_sets=2,
                                                          allocation=(("mul", 48),)))
    assert old == new and hash(old) == hash(new)
    assert (old.part, old.clock_ns, old.unit_sets, old.allocation) == (
        ZU9, 5.0, 2, (("mul", 48),))
    # a keyword given beside ``design`` overrides that one option
    assert HlsConfig(design=new.design, unit_sets=3).design == dataclasses.replace(
        new.design, unit_sets=3)
    # dataclasses.replace (cfamily.limits.for_program widens the linear solver) keeps the design
    wide = dataclasses.replace(old, linear_scalar="double")
    assert wide.design == old.design and wide.linear_scalar == "double"
    assert HlsConfig().design == DesignOptions() and HlsConfig().part == DEFAULT_PART
    with pytest.raises(AttributeError):
        old.part = DEFAULT_PART  # frozen: read through, never set
    with pytest.raises(HlsConfigError, match="DesignOptions, got dict"):
        HlsConfig(design={"part": ZU9})


@pytest.mark.parametrize("options, message", [
    ({"part": "xc7z045;rm"}, "is not a plain part name"),
    ({"part": "xc9z999"}, "fgc knows no capacities for its device"),
    ({"clock_ns": 0.1}, r"clock period 0.1 ns is outside 0.5 … 1000 ns"),
    ({"unit_sets": 9}, r"unit_sets must be 1 … 8, got 9"),
    ({"allocation": (("fma", 4),)}, r"allocation entry \('fma', 4\)"),
    ({"allocation": (("mul", 0),)}, r"allocation limit of mul must be 1 … 4096, got 0"),
    ({"allocation": (("mul", 4), ("mul", 8))}, "names a kind twice"),
])
def test_one_check_names_the_bad_option(options, message):
    design = DesignOptions(**options)
    for check in (design.check, HlsConfig(design=design).check):
        with pytest.raises(HlsConfigError, match=message) as err:
            check()
        assert isinstance(err.value, FgcError)  # one line at the command line, exit 2


def test_the_clock_agrees_with_the_programs():
    program = chain(4, linear="qr", clock_mhz=200.0)
    DesignOptions(clock_ns=5.0).check(program)
    DesignOptions().check(program)  # no period: the Program's clock
    with pytest.raises(HlsConfigError, match=r"clock mismatch: .* 200 MHz .*clock_ns=7"):
        HlsConfig(clock_ns=7.0).check(program)
    HlsConfig(clock_ns=7.0).check()  # without a Program there is nothing to agree with
    assert DesignOptions(part=ZU9).target(program) == Target(ZU9, 200.0)


@pytest.mark.parametrize("linear", ["qr", "cholesky"])
def test_the_plan_options_are_built_from_the_design(linear):
    program = chain(5, linear=linear)  # float32
    config = HlsConfig(scalar="double", part=ZU9, unit_sets=1, allocation=(("mul", 48),))
    options = config.plan_options(program)
    assert options == PlanOptions.for_config(config, program)
    assert (options.units, options.cpe) == (program.solver.units, program.solver.cpe)
    assert (options.part, options.unit_sets) == (ZU9, 1)
    assert dict(options.allocation) == {**dict(DEFAULT_ALLOCATION), "mul": 48}
    # priced in the scalar the design emits (double), not the Program's float32
    assert options.precision == options.les_precision == "float64"
    plan = build_plan(program, options)
    assert plan.target == DesignOptions(part=ZU9).target(program)
    assert HlsConfig().plan_options(program, cpe=3).cpe == 3  # a what-if change on top
