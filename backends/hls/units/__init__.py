"""The HLS accelerator's units, one module each (:class:`~fgc_backends.hls.units.spec.UnitSpec`).

The plan (:func:`fgc_backends.hls.plan.build_plan`) asks each unit of :data:`REGISTRY`, in this
order, to add its hardware; the order is the order of the plan's units and, within an iteration
slot (:data:`~fgc_backends.hls.units.spec.SLOTS`), of its phases. Adding a unit: one module
defining ``SPEC`` and one line here (docs/design.md, "Adding an HLS unit").
"""

from fgc_backends.hls.units import (
    backsub,
    cholesky,
    datapath,
    lm_control,
    memories,
    qr,
    state_update,
)
from fgc_backends.hls.units.spec import SLOTS, UnitSpec

# the units import the plan's data model and loop pricing (plan.model, plan.loops); the plan
# package imports no unit at load time (only plan.assemble reads this registry), so either entry
# point loads the model before any unit and no import circle runs through the two packages

REGISTRY: tuple[UnitSpec, ...] = (
    datapath.SPEC,
    qr.SPEC,
    cholesky.SPEC,
    backsub.SPEC,
    state_update.SPEC,
    lm_control.SPEC,
    memories.SPEC,
)


def spec(name: str) -> UnitSpec:
    """The registered unit called ``name``."""
    for s in REGISTRY:
        if s.name == name:
            return s
    raise KeyError(f"no HLS unit {name!r} (registered: {', '.join(s.name for s in REGISTRY)})")


__all__ = ["REGISTRY", "SLOTS", "UnitSpec", "spec"]
