"""The unit registry (backends/hls/units/__init__.py): every unit declares what it contributes,
and a unit added to the registry is priced by plan_cost with no other change."""

from __future__ import annotations

from pathlib import Path

import pytest
from hls_programs import chain

from fgc_backends.hls import units
from fgc_backends.hls.plan import Loop, Phase, Process, Unit, build_plan, phase_group, plan_cost
from fgc_backends.hls.units.spec import SLOTS, UnitSpec

INCLUDE = Path(units.__file__).resolve().parent.parent / "include"


@pytest.fixture(scope="module")
def programs():
    return {"qr": chain(linear="qr", units=2), "cholesky": chain(linear="cholesky", cpe=2)}


def test_every_unit_is_named_once_and_its_header_exists():
    names = [s.name for s in units.REGISTRY]
    assert len(names) == len(set(names))
    for s in units.REGISTRY:
        assert s.header is None or (INCLUDE / s.header).is_file(), s.name
        assert units.spec(s.name) is s
    with pytest.raises(KeyError, match="registered"):
        units.spec("givens")


@pytest.mark.parametrize("linear", ["qr", "cholesky"])
def test_each_phase_comes_from_a_unit_that_declares_it(programs, linear):
    program = programs[linear]
    plan = build_plan(program)
    applying = [s for s in units.REGISTRY if s.applies(program, plan.options)]
    declared = {g for s in applying for g in s.phases}
    assert {phase_group(ph.name) for ph in plan.phases} <= declared
    # a unit that does not apply contributes nothing: the other solver's phases are absent
    other = "cholesky" if linear == "qr" else "qr"
    assert not {phase_group(ph.name) for ph in plan.phases} & set(units.spec(other).phases)


def _extra(ctx):
    ctx.units.append(Unit("extra", "a unit added by one registry line", 2, (("mul", 1),)))
    ctx.add_phase("solve", Phase("extra", False, (Process("extra", "extra", (
        Loop("extra", 5, 1, 3),)),), linear=True))


def test_a_registered_unit_is_assembled_and_priced(programs, monkeypatch):
    program = programs["qr"]
    before = build_plan(program)
    extra = UnitSpec("extra", "test unit", _extra, ("extra",))
    monkeypatch.setattr(units, "REGISTRY", units.REGISTRY + (extra,))
    after = build_plan(program)
    a, b = plan_cost(before), plan_cost(after)
    assert b.cycles - a.cycles == 4 * 1 + 3  # (trip - 1) × II + depth
    assert b.linear_cycles - a.linear_cycles == 7
    assert b.dsp - a.dsp == 2 * after.ops.mul.dsp
    # a "solve" phase runs after the linear solver's (back-substitution with the state update
    # it feeds) and before the cost pass
    names = [ph.name for ph in after.phases]
    assert names.index("extra") > max(i for i, n in enumerate(names) if n.startswith("backsub"))
    assert names.index("extra") < names.index("factor_cost")


def test_phases_follow_the_iteration_slots(programs):
    order = [ph.name for ph in build_plan(programs["qr"]).phases]
    # (QR: the gradient beside the datapaths, in factor_jacobian's region)
    assert order[0] == "factor_jacobian" and "gradient" not in order
    # the state update runs inside back-substitution's phase (fed by it)
    assert order[-7:] == ["backsub", "factor_cost", "lm_iteration", "lm_control",
                          "lm_accept", "setup", "rounding_noise"]
    assert SLOTS == ("linearize", "solve", "retract", "cost", "control", "call", "rejection")


def test_a_unit_name_must_be_an_identifier():
    with pytest.raises(ValueError, match="identifier"):
        UnitSpec("two words", "x", _extra, ())
