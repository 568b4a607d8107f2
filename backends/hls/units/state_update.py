"""The state update: one retraction datapath x ⊕ δ per variable type (``retract_<k>``, its
``ALLOCATION`` limits: ``PlanOptions.state_allocation``). Fed by back-substitution: each solved
step's frontal δ streams into back_substitute's ``backsub_retire`` process (fgc_backsub.h), one
pipelined loop over the variables in the order they are solved (:func:`retire_order`,
:func:`retire_timing`; the kernel's ``retract_variable`` picks the type's datapath), beside the
solves (the region's price: :func:`fgc_backends.hls.units.backsub.retire_region`). The what-if
whole-matrix Cholesky (no emitted driver) keeps a pass of its own after the solve
(:func:`state_update_phase`)."""

from __future__ import annotations

import math

from fgc.ir.program import KernelText
from fgc_backends.cfamily.printer import kernel_printed_ops
from fgc_backends.cfamily.retract import retract_kernel, variable_class
from fgc_backends.cost.kernels import critical_path
from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.plan.loops import _sim_table
from fgc_backends.hls.plan.model import PORTS, Loop, Phase, Process, Unit
from fgc_backends.hls.plan.options import STATE_ALLOCATION
from fgc_backends.hls.units.spec import UnitSpec
from fgc_backends.hls.units.special_ops import helper_ops


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
    max over kinds of ⌈count × op II / allocated⌉, and no less than the state's words a
    variable reads from X and writes to X_TRIAL through their :data:`PORTS` ports; depth: the
    retraction's critical path."""
    cls = variable_class(type_name)
    kernel = retract_kernel(cls)
    counts = kernel.op_counts()
    alloc = dict(allocation)
    allocated = tuple((k, min(alloc[k], n)) for k, n in counts.items() if n > 0 and k in alloc)
    # what one retraction issues through them: the printed kernel's operations and its
    # special functions' bodies, each body's branches sharing (units/special_ops.py; the
    # second reader reads the same text: a Pose3's 88 adds, 105 multiplies)
    issued = dict(kernel_printed_ops(kernel))
    for kind, n in helper_ops(kernel, exclusive=True):
        issued[kind] = issued.get(kind, 0) + n
    ii = max([1, -(-cls.storage_dim // PORTS)]
             + [math.ceil(issued.get(k, counts[k]) * ops.op(k).ii / n) for k, n in allocated])
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


def retire_order(program, solved: list[int]) -> tuple[tuple[int, ...], tuple[int, ...]]:
    """backsub_retire's tables for the steps in the order they are ``solved``: the variables
    (indices into ``program.variables``, each step's frontal variables in its order) and per
    variable its step if it is its step's first, else -1 (RETIRE_VARS, RETIRE_STEP)."""
    index = {v.key: i for i, v in enumerate(program.variables)}
    variables, first = [], []
    for s in solved:
        for j, key in enumerate(program.schedule.steps[s].frontals):
            variables.append(index[key])
            first.append(s if j == 0 else -1)
    return tuple(variables), tuple(first)


def retire_timing(variables, ops: OperatorTable, max_f: int,
                  allocation=STATE_ALLOCATION, in_place: bool = False) -> tuple[int, int]:
    """(II, depth) of backsub_retire's loop (a variable an iteration) over ``variables``
    (VariableSpecs): II the largest of the
    types' datapaths (:func:`retract_datapath`) and of the words an iteration moves through its
    copy of delta's :data:`PORTS` ports (a step's ``max_f`` words in when it arrives, a
    variable's tangent words out); ``in_place`` (the column design's LM, units/lm_control.py's
    retire_step_test: the trial written into X as X is read) also X's: the widest storage's
    words read and written through its :data:`PORTS` ports. Depth: the stream's words in (a
    pair a cycle), then the deepest datapath."""
    kinds = [retract_datapath(name, ops, allocation) for name in _type_counts(variables)]
    widest = max(v.dim for v in variables)
    ii = max([-(-(max_f + widest) // PORTS)] + [k[1] for k in kinds])
    if in_place:
        ii = max(ii, -(-2 * max(v.storage_dim for v in variables) // PORTS))
    return ii, -(-max_f // PORTS) + max(k[2] for k in kinds)


def state_update_phase(variables, ops: OperatorTable, allocation=STATE_ALLOCATION) -> Phase:
    """The state update as emitted (retract_all) over ``variables``."""
    return Phase("state_update", False, (Process("retract", "state_update",
                                                 retract_loops(variables, ops, allocation)),))


def fed_by_backsub(program, opts) -> bool:
    """True when back-substitution's emitted driver feeds the state update (both linear solvers
    as emitted; not the what-if whole-matrix Cholesky)."""
    return program.solver.linear == "qr" or opts.hessian_storage == "frontal"


def build(ctx) -> None:
    """One retract datapath unit per variable type; its loops run in back_substitute's
    backsub_retire (priced there), else (what-if) the state_update phase after the solve."""
    program, opts, ops = ctx.program, ctx.opts, ctx.ops
    for k, name in enumerate(_type_counts(program.variables)):
        ctx.units.append(Unit(f"state_update_{k}", f"retract x ⊕ δ of {name}", 1,
                              retract_datapath(name, ops, opts.state_allocation)[0]))
    if not fed_by_backsub(program, opts):
        ctx.add_phase("retract", state_update_phase(program.variables, ops,
                                                    opts.state_allocation))


SPEC = UnitSpec(
    name="state_update", role="retraction x ⊕ δ per variable type", build=build,
    phases=("state_update",),
    constants=(("ALLOCATION", "per type: operator limits (PlanOptions.state_allocation)"),),
    printed_by="fgc_backsub.h backsub_retire -> accel.cpp.jinja: LesConfig::retract_variable "
               "-> retract_variable -> retract_<k>")

