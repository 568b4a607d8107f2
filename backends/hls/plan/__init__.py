"""The accelerator plan: typed hardware for one Program and design options, and its price.

:func:`build_plan` turns a :class:`fgc.ir.program.Program` and :class:`PlanOptions` (n_u Update
units, #CPE, QR unit sets, operator ALLOCATION limits) into an :class:`AcceleratorPlan`: units
with their allocated operators, memories, channels and *phases* of processes made of loops
(trip count, II, depth, all derived from :mod:`fgc_backends.cost.operators`). Each piece of
hardware is a unit of :mod:`fgc_backends.hls.units` (its loops, their pricing, its phases and
header); the plan is their contributions. :func:`plan_cost` is nothing but the arithmetic of a
plan (:mod:`.cost`).

Modules: :mod:`.model` (the data model), :mod:`.options` (design options), :mod:`.loops` (loop
rules shared by the units), :mod:`.assemble` (the units → a plan), :mod:`.cost` (the pricer),
:mod:`.report` (phase groups, the summary, the emitted process network); :mod:`.stream` and
:mod:`.update` price a stream's updates (the on-chip design; the host-kept path) and are imported
by their users, not here. This package re-exports
their public names (and the units' loop constructors, for the update and window models).

The HLS emitter prints this plan (accel.cpp.jinja): its units are the emitted processes, its
channels the emitted streams (:func:`process_network`), its factor-datapath operators the
``ALLOCATION`` limits and its instance-loop IIs the ``PIPELINE`` IIs (docs/hls.md). Options the
emitter does not build (raw Jacobian storage, a whole-matrix dense or blocked Hessian) are
what-if designs for the design space: :func:`emitted_options` says which.
"""

# the model, loop rules and options first: the units (imported by .assemble) build on them
from fgc_backends.hls.plan.model import (
    BRAM18_BITS,
    LUTRAM_MAX_BITS,
    PHASE_PER,
    PORTS,
    AcceleratorPlan,
    Channel,
    Cost,
    Loop,
    Memory,
    Phase,
    PlanError,
    Process,
    Unit,
)
from fgc_backends.hls.target import DEFAULT

from fgc_backends.hls.plan.loops import (  # isort: skip
    _assign,
    _block_shape,
    _ceil_log2,
    _ported,
    _region_cycles,
    _sim_table,
    _sizes,
    _tables,
    dot_loop,
    kernel_dot,
    kernel_loop,
    kernel_timing,
    plan_sizes,
)
from fgc_backends.hls.plan.options import (  # isort: skip
    ALLOCATION_SCALING,
    DEFAULT_ALLOCATION,
    HESSIAN_STORAGE,
    JACOBIAN_STORAGE,
    STATE_ALLOCATION,
    PlanOptions,
    scalar_precision,
)
from fgc_backends.hls.plan.cost import (  # isort: skip
    merge_plans,
    phase_cycles,
    plan_cost,
    plan_power_w,
)
from fgc_backends.hls.plan.assemble import PlanBuild, build_plan  # isort: skip
from fgc_backends.hls.plan.report import (  # isort: skip
    EMITTED,
    PHASE_TRIGGER,
    backsub_units,
    emitted_options,
    phase_group,
    phase_groups,
    plan_groups,
    plan_summary,
    process_network,
    unit_sets,
)
# the default device (hls/target.py); PlanOptions.part selects the fit verdict's
PART = DEFAULT.name
PART_DSP, PART_BRAM36, PART_LUT, PART_FF = DEFAULT.dsp, DEFAULT.bram36, DEFAULT.lut, DEFAULT.ff

__all__ = [
    "ALLOCATION_SCALING", "BRAM18_BITS", "DEFAULT_ALLOCATION", "EMITTED", "HESSIAN_STORAGE",
    "JACOBIAN_STORAGE", "LUTRAM_MAX_BITS", "PART", "PART_BRAM36", "PART_DSP", "PART_FF",
    "PART_LUT", "PHASE_PER", "PHASE_TRIGGER", "PORTS", "STATE_ALLOCATION", "AcceleratorPlan",
    "Channel", "Cost", "Loop", "Memory", "Phase", "PlanBuild", "PlanError", "PlanOptions",
    "Process", "Unit", "_assign", "_block_shape", "_ceil_log2", "_ported", "_region_cycles",
    "_sim_table", "_sizes", "_tables", "backsub_units", "build_plan", "dot_loop",
    "emitted_options", "kernel_dot", "kernel_loop", "kernel_timing", "merge_plans",
    "phase_cycles", "phase_group", "phase_groups", "plan_cost", "plan_groups", "plan_power_w",
    "plan_sizes", "plan_summary", "process_network", "scalar_precision", "unit_sets",
]
