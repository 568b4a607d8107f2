"""The plan's assembly: :func:`build_plan` asks each registered unit
(:data:`fgc_backends.hls.units.REGISTRY`) to add its hardware to a :class:`PlanBuild` and
returns the :class:`~fgc_backends.hls.plan.model.AcceleratorPlan` they make together."""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

from fgc.ir.program import Program
from fgc_backends.cfamily.blocks import block_contexts
from fgc_backends.cost.operators import BindError, OperatorTable, normalise_bind
from fgc_backends.hls import units as unit_registry
from fgc_backends.hls.plan.loops import _sizes, _tables, kernel_timing, tree_latencies
from fgc_backends.hls.plan.model import AcceleratorPlan, PlanError
from fgc_backends.hls.plan.options import (
    ALLOCATION_SCALING,
    HESSIAN_STORAGE,
    JACOBIAN_STORAGE,
    PlanOptions,
)
from fgc_backends.hls.target import target_of


@dataclass
class PlanBuild:
    """A plan under assembly: what the units add (units, memories, channels, phases by
    iteration slot) and what they read (the Program, the options, the operator tables of the
    accelerator, ``ops``, and of the linear solver, ``les``, the emitted tables and sizes).
    ``shared``: facts one unit decides and a later one reads (QR's unit sets)."""
    program: Program
    opts: PlanOptions
    ops: OperatorTable
    les: OperatorTable
    units: list = field(default_factory=list)
    memories: list = field(default_factory=list)
    channels: list = field(default_factory=list)
    phases: list = field(default_factory=list)  # (slot index, Phase)
    shared: dict = field(default_factory=dict)

    def add_phase(self, slot: str, phase) -> None:
        self.phases.append((unit_registry.SLOTS.index(slot), phase))

    @cached_property
    def timing(self) -> dict:
        return kernel_timing(self.ops)

    @cached_property
    def les_timing(self) -> dict:
        return kernel_timing(self.les)

    @cached_property
    def tables(self) -> dict:
        return _tables(self.program)

    @cached_property
    def blocks(self) -> tuple:
        """The block contexts the kernel is printed from (scalar T: the accelerator's; sums and
        products as the reduction trees of its operator table)."""
        return block_contexts(self.program, vector=False, latencies=tree_latencies(self.ops))

    @cached_property
    def sizes(self) -> dict:
        return _sizes(self.program)


def check_options(opts: PlanOptions) -> None:
    """Refuse options no plan can be built for."""
    for name in ("units", "cpe", "hgc_lanes"):
        if int(getattr(opts, name)) < 1:
            raise PlanError(f"plan option {name} must be ≥ 1, got {getattr(opts, name)}")
    for name, allowed in (("jacobian_storage", JACOBIAN_STORAGE),
                          ("hessian_storage", HESSIAN_STORAGE),
                          ("allocation_scaling", ALLOCATION_SCALING)):
        if getattr(opts, name) not in allowed:
            raise PlanError(f"plan option {name} must be one of {', '.join(allowed)}, "
                            f"got {getattr(opts, name)!r}")
    for kind, n in (*opts.allocation, *opts.state_allocation):
        if n < 1:
            raise PlanError(f"ALLOCATION limit of {kind} must be ≥ 1, got {n}")
    try:
        bind = normalise_bind(opts.bind)
    except BindError as exc:
        raise PlanError(f"plan option {exc}") from None
    if bind != tuple(opts.bind):
        raise PlanError(f"plan option bind {opts.bind!r} is not canonical: give {bind!r} "
                        "(operators.normalise_bind: sorted, default implementations left out)")


def factor_ops(program: Program, opts: PlanOptions) -> OperatorTable:
    """The operator table of the design's scalar T (its part, clock and binding): what the
    datapaths are priced with and their kernels' reduction trees printed with."""
    target = target_of(opts.part, program.solver.clock_mhz, opts.bind)
    return target.ops(opts.precisions(program)[0])


def build_plan(program: Program, options: PlanOptions | None = None) -> AcceleratorPlan:
    """The accelerator plan of ``program`` with ``options`` (default: the Program's solver):
    the registered units that apply, in the registry's order, their phases by iteration slot."""
    opts = options or PlanOptions.of(program)
    check_options(opts)
    precision, les_precision = opts.precisions(program)
    target = target_of(opts.part, program.solver.clock_mhz, opts.bind)
    ctx = PlanBuild(program, opts, factor_ops(program, opts), target.ops(les_precision))
    for unit in unit_registry.REGISTRY:
        if unit.applies(program, opts):
            before = len(ctx.units)
            unit.build(ctx)
            if unit.linear_solver and les_precision != precision:
                # the linear solver's units (typed L in the emitted text) are priced in L's
                # table: a double CPE binds double adders and multipliers, not float ones
                ctx.units[before:] = [replace(u, precision=les_precision)
                                      for u in ctx.units[before:]]
    phases = tuple(ph for _, ph in sorted(ctx.phases, key=lambda sp: sp[0]))
    return AcceleratorPlan(program.name, program.solver.linear, precision,
                           program.solver.clock_mhz, opts, tuple(ctx.units), tuple(ctx.memories),
                           tuple(ctx.channels), phases, ctx.ops)
