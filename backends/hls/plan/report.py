"""What the plan reports: phase groups, the summary ``fgc simulate`` / ``fgc report`` print, the
options the emitter builds and the emitted process network."""

from __future__ import annotations

from fgc.ir.program import Program
from fgc_backends.hls.plan.assemble import build_plan
from fgc_backends.hls.plan.cost import phase_cycles, plan_cost, plan_power_w
from fgc_backends.hls.plan.model import AcceleratorPlan, Channel, Cost
from fgc_backends.hls.plan.options import PlanOptions


def phase_groups(cost: Cost) -> tuple[tuple[str, int], ...]:
    """Per-iteration cycles of the plan's phases with their level number dropped (``qr_level3``
    and ``qr_level4`` add up under ``qr``), in first-seen order."""
    groups: dict[str, int] = {}
    for name, cycles in cost.phase_cycles:
        key = phase_group(name)
        groups[key] = groups.get(key, 0) + cycles
    return tuple(groups.items())


def plan_summary(program: Program, iterations: int, options: PlanOptions | None = None) -> dict:
    """What ``fgc simulate`` / ``fgc report`` print as hardware figures, all from
    ``plan_cost(build_plan(program, options))``: ``iterations`` × one iteration's cycles by
    phase group, latency, resources and their share of the part's device (``options.part``,
    default the xc7z045), memory words, back-substitution's width (``backsub_lanes``, as
    the design was built: an automatic width resolved), and power / energy
    (:func:`plan_power_w`: the sim model's power approach on the plan's resources)."""
    plan = build_plan(program, options)
    c = plan_cost(plan)
    k = max(1, int(iterations))
    device = plan.target.device
    caps = {"dsp": device.dsp, "bram": device.bram36, "lut": device.lut, "ff": device.ff}
    res = {"dsp": c.dsp, "bram": c.bram36, "lut": c.lut, "ff": c.ff}
    power = plan_power_w(c)
    latency_ms = k * c.latency_ms
    return {"source": "accelerator plan (fgc_backends.hls.plan: plan_cost of build_plan)",
            "device": device.name, "part": plan.options.part, "clock_mhz": c.clock_mhz,
            "iterations": k,
            "cycles": k * c.cycles, "iteration_cycles": c.cycles, "latency_ms": latency_ms,
            "linear_cycles": k * c.linear_cycles,
            "cycles_by_unit": {name: k * cyc for name, cyc in phase_groups(c)},
            "resources": res, "utilization": {key: res[key] / caps[key] for key in caps},
            "fits": c.fits, "memory_words": c.words, "power_w": power,
            "energy_mj": power * latency_ms,
            # the priced design's back-substitution width, resolved (DesignOptions' auto)
            "backsub_lanes": plan.options.backsub_lanes}


EMITTED = {"jacobian_storage": ("whitened",), "hessian_storage": ("frontal",)}


def emitted_options(options: PlanOptions) -> list[str]:
    """The options of ``options`` the HLS emitter does not build (what-if designs), as text."""
    return [f"{k}={getattr(options, k)!r}" for k, ok in EMITTED.items()
            if getattr(options, k) not in ok]


def unit_sets(plan: AcceleratorPlan) -> int:
    """QR unit sets of ``plan`` (0 for Cholesky)."""
    return sum(1 for u in plan.units if u.name.endswith("_evaluate"))


def backsub_units(plan: AcceleratorPlan) -> int:
    """Back-substitution units of ``plan``: its two lanes, whatever the unit sets (the emitted
    ``backsub_set<l>`` and ``backsub_load<l>`` processes of back_substitute's
    ``backsub_lane<p>`` regions)."""
    return 2


def process_network(plan: AcceleratorPlan) -> tuple[tuple[str, ...], tuple[Channel, ...]]:
    """The dataflow processes and streams the emitter prints for ``plan``: the linear solver's
    (the unit headers' regions: per QR unit set broadcast, qr_finish, n_u Update units,
    Evaluate and collect; for Cholesky the feed, per process element its tap and CPE, and the
    drain, then fgc_eliminate.h's cholesky_overlap: the assembler beside the cascade; with two
    cascades both cascades' and fgc_cascades.h's cholesky_sets: the source, the grams process,
    the two cascades and the committer),
    then back-substitution's (fgc_backsub.h's ``backsub_lane<p>`` regions: lane p's
    ``backsub_set<p>`` beside the other lane's ``backsub_load``, :func:`backsub_units` lanes;
    and back_substitute's region: the slot process beside the state update it feeds,
    ``backsub_retire``, and the cost pass it feeds, ``trial_cost``). Streams are the plan's
    stream channels; the back-substitution lanes have none (a solve reads its lane's buffers,
    the load fills the other lane's: nothing passes between the two processes of a region);
    back_substitute has two (``backsub_dx``, ``trial_tx``)."""
    if plan.linear == "qr" and plan.options.qr_unit == "stream":  # fgc_qr_stream.h's qrs_pass
        procs = tuple(p for s in range(unit_sets(plan)) for p in (
            f"qr{s}_source", *(f"qr{s}_{k}{t}" for t in range(plan.options.units)
                               for k in ("evaluate", "dot", "fold", "tail")),
            f"qr{s}_sink", f"qr{s}_collect"))
    elif plan.linear == "qr":
        procs = tuple(p for s in range(unit_sets(plan)) for p in (
            f"qr{s}_broadcast", f"qr{s}_finish",
            *(f"qr{s}_update{u}" for u in range(plan.options.units)),
            f"qr{s}_evaluate", f"qr{s}_collect"))
    elif any(u.name == "cpe_set1" for u in plan.units):  # fgc_cascades.h's cholesky_sets
        procs = tuple(p for k in ("cpe_", "cpe1_") for p in (
            f"{k}feed", *(p for i in range(plan.options.cpe) for p in (
                f"{k}tap{i}", f"cpe{i}" if k == "cpe_" else f"{k}{i}")), f"{k}drain"))
        # the HGC beside the elimination: cholesky_sets_beside's Gram source (its Gram stream
        # is the plan's channel "grams")
        procs += ("cholesky_set_gram_source",) if any(
            ph.name == "hgc_beside" for ph in plan.phases) else ()
        procs += ("cholesky_set_source", "cholesky_set_grams", "cholesky_set_cascade0",
                  "cholesky_set_cascade1", "cholesky_set_commit")
    else:
        # the HGC beside the elimination: the Gram source beside the assembler (its Gram
        # stream is the plan's channel "grams")
        source = ("cholesky_gram_source",) if any(
            ph.name == "hgc_beside" for ph in plan.phases) else ()
        procs = ("cpe_feed", *(p for i in range(plan.options.cpe)
                               for p in (f"cpe_tap{i}", f"cpe{i}")), "cpe_drain",
                 *source, "cholesky_assembler", "cholesky_cascade")
    if any(ch.name == "backsub_xroot" for ch in plan.channels):  # by columns (backsub_lanes 4)
        procs += ("backsub_loader", "backsub_end0", "backsub_end1", "backsub_retire")
    else:
        procs += ("backsub_set0", "backsub_load1", "backsub_set1", "backsub_load0")
    if any(ch.name == "backsub_dx" for ch in plan.channels):  # the state update it feeds
        procs += ("backsub_slots", "backsub_retire")
    if any(ch.name == "trial_tx" for ch in plan.channels):  # the cost pass beside them
        procs += ("trial_cost",)
    if any(ch.name == "trial_tx2" and ch.consumer == "trial_cost_b"
           for ch in plan.channels):  # its second process (trial_cost a region of two)
        procs += ("trial_cost_b",)
    return procs, tuple(ch for ch in plan.channels if ch.kind == "stream")


# the plan phase group (a phase's name without its level number) -> the run event (FGC_EVENT in
# accel.cpp.jinja) that executes it once: how a counting C simulation's phases are priced
# (bench/bench_cycles.py) and how the on-chip stream's model counts a call's phases
# (fgc_backends.hls.window); back-substitution runs once per solve that did not fail (solve():
# a solve not positive definite or with a pivot too small skips it, LM raises mu and retries)
PHASE_TRIGGER = {"setup": "call", "factor_jacobian": "linearize", "gradient": "linearize",
                 "hgc": "linearize", "qr_stack": "solve", "qr": "solve", "qr_commit": "solve",
                 "backsub": "backsub", "assemble": "solve", "cholesky": "solve", "store": "solve",
                 "hgc_beside": "linearize", "reassemble": "resolve", "recholesky": "resolve",
                 "lm_control": "solve", "lm_iteration": "linearize", "lm_accept": "accept",
                 "lm_restore": "restore", "state_update": "retract", "factor_cost": "cost",
                 "rounding_noise": "noise"}


def phase_group(name: str) -> str:
    """A plan phase's group: its name without the level number (qr_level3 -> qr)."""
    head, _, tail = name.rpartition("_level")
    return head if head and tail.isdigit() else name


def plan_groups(plan: AcceleratorPlan) -> dict[str, int]:
    """Per phase group of ``plan`` the cycles of one execution of its per-iteration and
    per-rejection phases."""
    group: dict[str, int] = {}
    for ph in plan.phases:
        if ph.per in ("iteration", "rejection"):
            g = phase_group(ph.name)
            group[g] = group.get(g, 0) + phase_cycles(ph)
    return group


def datapath_depths(plan: AcceleratorPlan, program: Program) -> dict[str, int]:
    """The depth the plan prices each emitted factor datapath function's loop with: per
    ``factor_<b>`` (Jacobian mode) and ``factor_cost_<b>`` (cost mode) the instance loop of its
    unit's process in that mode (``factor_<b>_jacobian`` / ``factor_<b>_cost``; a small block
    type's: ``factor_small_*``'s, the deepest branch's), and per variable type the state
    update's ``retract_<k>`` (kinds in first-appearance order) its datapath's depth
    (``units/state_update.py`` ``retract_datapath``) — what the second reader's
    ``reader.depth.check_depths`` holds the text to."""
    from fgc_backends.hls.units.datapath import small_blocks
    from fgc_backends.hls.units.state_update import retract_datapath

    loops = {p.name: p.loops[0] for ph in plan.phases for p in ph.processes
             if p.loops and p.name.startswith("factor_")}
    small = small_blocks(program)
    out = {}
    for b in range(len(program.blocks)):
        unit = "small" if b in small else str(b)
        for mode, function in (("jacobian", f"factor_{b}"), ("cost", f"factor_cost_{b}")):
            loop = loops.get(f"factor_{unit}_{mode}")
            if loop is not None:
                out[function] = loop.depth
    kinds = dict.fromkeys(v.type_name for v in program.variables)
    for k, name in enumerate(kinds):
        out[f"retract_{k}"] = retract_datapath(name, plan.ops, plan.options.state_allocation)[2]
    return out
