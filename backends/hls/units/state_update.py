"""The state update: one retraction datapath x ⊕ δ per variable type (``retract_<k>``, its
``ALLOCATION`` limits: ``PlanOptions.state_allocation``), its variables pipelined through it type by
type (retract_all). Kernel code of accel.cpp.jinja (no static header)."""

from __future__ import annotations

import math

from fgc.ir.program import KernelText
from fgc_backends.cfamily.retract import retract_kernel, variable_class
from fgc_backends.cost.kernels import critical_path
from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.plan.loops import _sim_table
from fgc_backends.hls.plan.model import Loop, Phase, Process, Unit
from fgc_backends.hls.plan.options import STATE_ALLOCATION
from fgc_backends.hls.units.spec import UnitSpec


def _type_counts(variables) -> dict[str, int]:
    """Variables per type, in first-seen order (retract_all's kinds)."""
    kinds: dict[str, int] = {}
    for v in variables:
        kinds[v.type_name] = kinds.get(v.type_name, 0) + 1
    return kinds


def retract_datapath(type_name: str, ops: OperatorTable,
                     allocation=STATE_ALLOCATION) -> tuple[tuple[tuple[str, int], ...], int, int]:
    """The state-update datapath of one variable type as emitted (accel.cpp.jinja's
    retract_<k>, its ALLOCATION limits): (allocated operators, II, depth). Operators per kind:
    the retraction's count, at most the ``allocation`` limit (the factor datapaths' rule,
    ``PlanOptions.state_allocation``'s limits); II:
    max over kinds of ⌈count × op II / allocated⌉; depth: the retraction's critical path."""
    kernel = retract_kernel(variable_class(type_name))
    counts = kernel.op_counts()
    alloc = dict(allocation)
    allocated = tuple((k, min(alloc[k], n)) for k, n in counts.items() if n > 0 and k in alloc)
    ii = max([1] + [math.ceil(counts[k] * ops.op(k).ii / n) for k, n in allocated])
    return allocated, ii, critical_path(KernelText.of(kernel), _sim_table(ops))


def retract_loops(variables, ops: OperatorTable,
                  allocation=STATE_ALLOCATION) -> tuple[Loop, ...]:
    """retract_all's loops over ``variables`` (VariableSpecs): one pipelined loop per variable
    type, in first-seen order, at its datapath's II and depth (:func:`retract_datapath`)."""
    loops = []
    for k, (name, n) in enumerate(_type_counts(variables).items()):
        _, ii, depth = retract_datapath(name, ops, allocation)
        loops.append(Loop(f"kind{k}", n, ii, depth))
    return tuple(loops)


def state_update_phase(variables, ops: OperatorTable, allocation=STATE_ALLOCATION) -> Phase:
    """The state update as emitted (retract_all) over ``variables``."""
    return Phase("state_update", False, (Process("retract", "state_update",
                                                 retract_loops(variables, ops, allocation)),))


def build(ctx) -> None:
    """One retract datapath unit per variable type and the state_update phase."""
    program, opts, ops = ctx.program, ctx.opts, ctx.ops
    for k, name in enumerate(_type_counts(program.variables)):
        ctx.units.append(Unit(f"state_update_{k}", f"retract x ⊕ δ of {name}", 1,
                              retract_datapath(name, ops, opts.state_allocation)[0]))
    ctx.add_phase("retract", state_update_phase(program.variables, ops, opts.state_allocation))


SPEC = UnitSpec(
    name="state_update", role="retraction x ⊕ δ per variable type", build=build,
    phases=("state_update",),
    constants=(("ALLOCATION", "per type: operator limits (PlanOptions.state_allocation)"),),
    printed_by="accel.cpp.jinja: retract_all -> retract_<k>")

