"""The pricer: :func:`plan_cost` is nothing but the arithmetic of a plan.

- a loop takes ``(trip - 1) * ii + depth`` cycles (0 when ``trip == 0``), repeated ``repeat``
  times; a process runs its loops one after another;
- a dataflow phase (processes overlapping through channels) takes its slowest process plus the
  fill of the others (their first-item depth); a sequential phase sums its processes;
- one LM/GN iteration runs the phases one after another;
- resources are the units' allocated operators × instances (each unit in its precision's
  operator table: a mixed design's linear solver in its own) + memories as placed (BRAM36 from
  words × width and banks, BRAM18 granularity; small memories in LUTRAM).
"""

from __future__ import annotations

from dataclasses import replace

from fgc_backends.cost.params import CostParams
from fgc_backends.hls.plan.model import AcceleratorPlan, Cost, Memory, Phase


def phase_cycles(phase: Phase) -> int:
    if not phase.processes:
        return 0
    lat = [p.cycles for p in phase.processes]
    if not phase.dataflow:
        return sum(lat)
    slow = max(range(len(lat)), key=lambda i: lat[i])
    return lat[slow] + sum(p.fill for i, p in enumerate(phase.processes) if i != slow)


def plan_cost(plan: AcceleratorPlan) -> Cost:
    per = tuple((ph.name, phase_cycles(ph)) for ph in plan.phases if ph.per == "iteration")
    other = tuple((ph.name, phase_cycles(ph)) for ph in plan.phases if ph.per != "iteration")
    cycles = sum(c for _, c in per)
    linear = sum(phase_cycles(ph) for ph in plan.phases if ph.linear and ph.per == "iteration")
    lut = ff = 0
    by_unit = []
    tables = {"": plan.ops}
    for u in plan.units:
        unit_dsp = u.instances * u.extra_dsp
        if u.precision not in tables:  # a mixed design's linear solver: its own table
            tables[u.precision] = plan.target.ops(u.precision)
        table = tables[u.precision]
        for kind, n in u.operators:
            o = table.op(kind)
            unit_dsp += u.instances * n * o.dsp
            lut += u.instances * n * o.lut
            ff += u.instances * n * o.ff
        by_unit.append((u.name, unit_dsp))
    dsp = sum(d for _, d in by_unit)
    channel_mems = tuple(Memory(ch.name, ch.depth * (2 if ch.kind == "pingpong" else 1), ch.width,
                                2 if ch.kind == "pingpong" else 1) for ch in plan.channels)
    bram36 = sum(m.bram18 for m in plan.memories + channel_mems) / 2
    device = plan.target.device
    over = tuple(name for name, used, cap in (("DSP", dsp, device.dsp),
                                              ("BRAM36", bram36, device.bram36),
                                              ("LUT", lut, device.lut), ("FF", ff, device.ff))
                 if used > cap)
    return Cost(cycles, per, linear, dsp, lut, ff, bram36, plan.clock_mhz, not over, over,
                tuple(by_unit), sum(m.words for m in plan.memories), other)


def rebind(plan: AcceleratorPlan, bind=()) -> AcceleratorPlan:
    """``plan``'s design with its floating-point operators bound as ``bind`` says
    (``PlanOptions.bind``): the same units, loops and phases, the operator tables bound anew.
    Exact, not an estimate: a binding keeps every latency (run_hls.tcl's ``config_op`` pins
    it) and no unit reads an operator's DSP, LUT or FF while it is built, so the plan built
    with ``bind`` is this one (tests/hls/test_operator_binding.py checks it); the design search
    prices a design's bindings so, without building its plan again."""
    from fgc_backends.cost.operators import normalise_bind
    from fgc_backends.hls.target import Target

    bind = normalise_bind(bind)
    if bind == plan.options.bind:
        return plan
    options = replace(plan.options, bind=bind)
    ops = Target(options.part, plan.clock_mhz, bind).ops(plan.precision)
    return replace(plan, options=options, ops=ops)


def merge_plans(plan: AcceleratorPlan, other: AcceleratorPlan | None = None,
                memories: tuple[Memory, ...] = ()) -> AcceleratorPlan:
    """One plan of a design made of ``plan``, a second accelerator ``other`` beside it (its
    units, memories and channels, names prefixed ``batch_``; its phases are its own calls',
    not this plan's iteration) and extra ``memories``: what :func:`plan_cost` prices as one
    design (the on-chip stream's window and batch kernels)."""
    units, mems, channels = plan.units, plan.memories + tuple(memories), plan.channels
    if other is not None:
        units += tuple(replace(u, name=f"batch_{u.name}") for u in other.units)
        mems += tuple(replace(m, name=f"batch_{m.name}") for m in other.memories)
        channels += tuple(replace(c, name=f"batch_{c.name}") for c in other.channels)
    return replace(plan, units=units, memories=mems, channels=channels)


def plan_power_w(cost: Cost) -> float:
    """Power of a plan's design, W: not modelled by the plan itself. This applies the sim cost
    model's approach (``backends/cost/resources.power_w``: static power plus per-DSP, LUT,
    FF and BRAM36 dynamic power, linear in the clock; coefficients fitted to paper B's three
    Vivado estimates) to the plan's resources."""
    params = CostParams()
    dynamic_mw = (cost.dsp * params.power_dsp_mw + cost.lut * params.power_lut_mw
                  + cost.ff * params.power_ff_mw + cost.bram36 * params.power_bram_mw)
    return params.power_static_w + dynamic_mw * 1e-3 * cost.clock_mhz / params.power_reference_mhz
