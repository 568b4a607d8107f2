"""What a hardware unit of the HLS accelerator declares: :class:`UnitSpec`.

A unit is one module of :mod:`fgc_backends.hls.units` holding everything the backend knows
about one piece of hardware: the static header that implements it (``backends/hls/include/``),
the constants the header is configured by, the loops it runs and their pricing, the plan phases
it contributes, and where its call is printed. The plan (:func:`fgc_backends.hls.plan.build_plan`)
is the units' contributions in the registry's order (:data:`fgc_backends.hls.units.REGISTRY`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

# where a phase runs in one LM/GN iteration (then once a call, then on a rejected step): the plan
# lists its phases in this order, each slot's phases in the registry's order
SLOTS = ("linearize", "solve", "retract", "cost", "control", "call", "rejection")


@dataclass(frozen=True)
class UnitSpec:
    """One unit of the accelerator.

    ``build(ctx)`` adds the unit's hardware to the plan under assembly (``ctx``:
    :class:`fgc_backends.hls.plan.assemble.PlanBuild`: its units, memories, channels and, per
    :data:`SLOTS` slot, phases) when ``applies(program, options)``; ``phases`` names the phase
    groups it contributes (the group of a levelled phase: ``qr`` for ``qr_level3``);
    ``header`` is its static header under ``backends/hls/include/`` (None: kernel code of the
    template), ``constants`` the compile-time constants that header takes (its ``CFG``), and
    ``printed_by`` where the call to it is printed (accel.cpp.jinja today; a unit whose call
    Python generates names the function). ``linear_solver``: its units compute in the linear
    solver's scalar (``L``: the Hessian/Gram accumulation, elimination, back-substitution), so
    the plan prices their operators in that precision's table (a mixed design's float64 solver
    beside float32 datapaths: :func:`fgc_backends.hls.plan.cost.plan_cost`)."""
    name: str
    role: str
    build: Callable
    phases: tuple[str, ...]
    header: str | None = None
    constants: tuple[tuple[str, str], ...] = ()
    printed_by: str = "accel.cpp.jinja"
    applies: Callable = lambda program, options: True
    linear_solver: bool = False

    def __post_init__(self):
        if not self.name.isidentifier():
            raise ValueError(f"unit name {self.name!r} is not an identifier")
