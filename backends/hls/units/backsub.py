"""Back-substitution (``include/fgc_backsub.h``'s ``cond_load`` and ``cond_backsub``): the
conditionals solved root first on two lanes, a step's solve on one lane beside the next step's
load into the other (the slot process's ``backsub_lane<p>`` regions, :func:`backsub_slots`), each
solved step's δ streamed to the state update beside them (``backsub_retire``,
:func:`retire_region`), for QR and Cholesky alike; a what-if whole-matrix Cholesky solves
Lᵀδ = z by rows instead."""

from __future__ import annotations

import dataclasses
import math

from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.plan.binding import BoundLoop, sum_operators
from fgc_backends.hls.plan.loops import _ceil_log2, _ported, _region_cycles, dot_loop, kernel_loop
from fgc_backends.hls.plan.model import PORTS, Channel, Loop, Phase, Process, Unit
from fgc_backends.hls.units.spec import UnitSpec

LANES = 2  # back-substitution lanes: one solves a step while the other loads the next


def backsub_chain(ops: OperatorTable) -> int:
    """The triangle's recurrence per unknown (fgc_backsub.h's CHAIN): the product (R_ir / R_ii) x_r
    and the subtraction from y_i (the rows are scaled by 1 / R_ii in the row loop, so x_r = y_r
    and the scaling of R_ir runs off the chain)."""
    return ops.mul.latency + ops.add.latency


def backsub_words(frontal: int, separator: int) -> int:
    """Words ``cond_load`` moves: each row i of the conditional from its diagonal on (R's
    structural zeros below the diagonal stay behind)."""
    return frontal * (frontal + separator + 1) - frontal * (frontal - 1) // 2


def triangle_trip(frontal: int, ops: OperatorTable, lanes: int = 1) -> int:
    """Iterations of cond_backsub's triangle loop: columns r = f − 1 … 1, each
    max(⌈r / lanes⌉, CHAIN + 1) (``lanes`` rows of a column an iteration; a column shorter than
    the recurrence padded to it)."""
    pad = backsub_chain(ops) + 1
    return sum(max(-(-r // lanes), pad) for r in range(1, frontal))


def rows_depth(ops: OperatorTable, lanes: int = 1) -> int:
    """cond_backsub's row loop: the row's partial sums (2 PARTIALS; ``lanes`` > 1, PARTIALS:
    cond_load_wide sums an iteration's words before its partial sum) folded and subtracted from
    d (La (1 + ⌈log₂ sums⌉)) beside the reciprocal of the diagonal (Ld), then the row scaled by
    it (Lm)."""
    la = ops.add.latency
    sums = 2 * la if lanes == 1 else la
    return max(la * (1 + _ceil_log2(sums)), ops.div.latency) + ops.mul.latency


def wide_trip(off: int, frontal: int, separator: int, lanes: int) -> int:
    """Iterations of ``cond_load_wide`` (fgc_backsub.h's backsub_wide_trip): row by row, the
    aligned groups of 2 ``lanes`` words of COND each row's words (from its diagonal to d) touch,
    the conditional at COND word ``off``."""
    width, cols = 2 * lanes, frontal + separator + 1
    return sum((off + i * cols + cols - 1) // width - (off + i * cols + i) // width + 1
               for i in range(frontal))


def load_loop(frontal: int, separator: int, ops: OperatorTable, name: str = "cond_load",
              lanes: int = 1, off: int = 0) -> Loop:
    """``cond_load``: the conditional's stored words two a cycle (the source memory's two
    ports), each S_ia x_a added into a partial sum as it passes (II 1: a lane's sum comes back
    PARTIALS iterations later); depth read + multiply-add + write. ``lanes`` > 1:
    ``cond_load_wide``, an aligned group of 2 ``lanes`` words of one row an iteration from COND
    cyclic over ``lanes`` banks (:func:`wide_trip`; ``off``: the conditional's first word in
    COND), the group's products summed by a tree before the row's partial sum: depth read +
    multiply + La (1 + log₂ 2 lanes) + write."""
    if lanes > 1:
        trip = wide_trip(off, frontal, separator, lanes) if frontal else 0
        return Loop(name, trip, 1, 2 + ops.mul.latency
                    + ops.add.latency * (1 + _ceil_log2(2 * lanes)))
    words = backsub_words(frontal, separator) if frontal else 0
    return Loop(name, -(-words // PORTS), 1, 2 + ops.mul.latency + ops.add.latency)


def backsub_loops(frontal: int, separator: int, ops: OperatorTable,
                  name: str = "bs", lanes: int = 1) -> list[Loop]:
    """The loops of ``cond_backsub`` (backends/hls/include/fgc_backsub.h) on one conditional of
    f frontal and s separator columns (S xs already summed by ``cond_load``), as its csim
    counters count them: per row (trip f, II 1) its partial sums folded and subtracted from d
    beside the diagonal's reciprocal, the row scaled by it (:func:`rows_depth`); the triangle
    as one flattened loop (trip :func:`triangle_trip`: columns padded to the chain Lm + La, II 1,
    depth Lm + CHAIN: R_ir / R_ii, its product with x_r, the subtraction); x_0 = y_0 (a move).
    Nothing for f = 0. ``lanes`` > 1 (``cond_backsub_wide``): the triangle alone, ``lanes``
    rows of a column an iteration (the row loop runs in the load, :func:`wide_load_loops`)."""
    if not frontal:
        return []
    rows = [Loop(f"{name}_rows", frontal, 1, rows_depth(ops))] if lanes == 1 else []
    return [*rows,
            Loop(f"{name}_triangle", triangle_trip(frontal, ops, lanes), 1,
                 ops.mul.latency + backsub_chain(ops)),
            Loop(f"{name}_last", 1, 1, 1)]


def backsub_slots(tables: dict) -> tuple[tuple[int, int, int], ...]:
    """back_substitute()'s schedule: (solve step, load step, lane) per slot (-1: none). The steps
    go root first (levels in turn, LEVEL_STEPS order), the t-th on lane t % 2 (:data:`LANES`).
    Slot t solves step t - 1 on its lane while step t's conditional loads into the other lane
    (``backsub_lane<p>``: p the solving lane), unless step t's separator holds a frontal column
    of step t - 1 (it waits for that solution: one slot solves t - 1 alone, the next loads t
    alone). The last slot solves the last step."""
    begin, level_steps = tables["LEVEL_BEGIN"], tables["LEVEL_STEPS"]
    order = [level_steps[i] for li in range(len(begin) - 2, -1, -1)
             for i in range(begin[li], begin[li + 1])]
    cols, cb = tables["STEP_COL"], tables["STEP_COL_BEGIN"]
    f_of, w_of = tables["STEP_F"], tables["STEP_W"]

    def frontal(s):
        return set(cols[cb[s]:cb[s] + f_of[s]])

    def separator(s):
        return set(cols[cb[s] + f_of[s]:cb[s] + w_of[s]])

    slots: list[tuple[int, int, int]] = []
    for t, step in enumerate(order):
        lane = t % LANES
        if t == 0:
            slots.append((-1, step, 1 - lane))
        elif separator(step) & frontal(order[t - 1]):
            slots += [(order[t - 1], -1, 1 - lane), (-1, step, 1 - lane)]
        else:
            slots.append((order[t - 1], step, 1 - lane))
    if order:
        slots.append((order[-1], -1, (len(order) - 1) % LANES))
    return tuple(slots)


def backsub_xoff(tables: dict) -> tuple[int, ...]:
    """Per slot of :func:`backsub_slots`: where the loaded step's separator solution sits in the
    loading lane's solution buffer (``BS_X<q>``, the frontal solution of the step lane q solved
    last, which no solve has overwritten since): the offset j0 when the separator's columns are
    that step's frontal columns j0 … j0 + s − 1 in order, so ``cond_load`` reads x there and the
    slot needs no ``separator_in`` copy from DELTA; −1 otherwise (no load, a separator from
    another step or lane: DELTA as before). On a two-ended chain every load after the root's
    first child is lane-local (the step's parent is the step two before it, on its own lane)."""
    cols, cb = tables["STEP_COL"], tables["STEP_COL_BEGIN"]
    f_of, w_of = tables["STEP_F"], tables["STEP_W"]
    last = [-1] * LANES  # per lane: the step it solved last
    out = []
    for solve, load, lane in backsub_slots(tables):
        xoff = -1
        prev = last[1 - lane]  # the loading lane's last solve (an earlier slot's)
        if load >= 0 and prev >= 0 and w_of[load] > f_of[load]:
            sep = list(cols[cb[load] + f_of[load]:cb[load] + w_of[load]])
            front = list(cols[cb[prev]:cb[prev] + f_of[prev]])
            if sep[0] in front:
                j0 = front.index(sep[0])
                if front[j0:j0 + len(sep)] == sep:
                    xoff = j0
        out.append(xoff)
        if solve >= 0:
            last[lane] = solve
    return tuple(out)


def wide_load_loops(frontal: int, separator: int, ops: OperatorTable, lanes: int, off: int,
                    name: str) -> list[Loop]:
    """A lane's load with ``lanes`` > 1 (fgc_backsub.h's backsub_load<u>): ``cond_load_wide``
    (:func:`load_loop`), then the row loop (``backsub_rows_wide``: trip f, II 1, the row's
    PARTIALS sums folded beside the reciprocal, :func:`rows_depth`), so the solving lane's
    process holds the triangle alone and the two lanes' work is nearer even."""
    loops = [load_loop(frontal, separator, ops, name=name, lanes=lanes, off=off)]
    if frontal:
        loops.append(Loop(f"{name}_rows", frontal, 1, rows_depth(ops, lanes)))
    return loops


def backsub_slot_loops(tables: dict, solve: int, load: int, ops: OperatorTable,
                       timing: dict, local: bool = False, lanes: int = 1) -> list[Loop]:
    """One slot of back_substitute() (:func:`backsub_slots`): the loaded step's separator
    solution in (:data:`PORTS` words a cycle; none when ``local``, :func:`backsub_xoff`), then
    the ``backsub_lane<p>`` DATAFLOW region (the solving lane's ``cond_backsub`` and its frontal
    solution out, ``backsub_out``, beside the other lane's ``cond_load``: the slower plus the
    other's fill); ``lanes``: :data:`PlanOptions.backsub_lanes`."""
    def sizes(s):
        return (tables["STEP_F"][s], tables["STEP_W"][s] - tables["STEP_F"][s]) if s >= 0 \
            else (0, 0)

    (sf, ss), (lf, ls) = sizes(solve), sizes(load)
    solve_loops = backsub_loops(sf, ss, ops, name=f"bs{solve}", lanes=lanes)
    if sf:
        solve_loops.append(kernel_loop("solution_out", _ported(sf), "move", timing))
    off = tables["STEP_COND_OFF"][load] if load >= 0 else 0
    load_loops = wide_load_loops(lf, ls, ops, lanes, off, f"cond_load{load}") if lanes > 1 \
        else [load_loop(lf, ls, ops, name=f"cond_load{load}")]
    region = _region_cycles([solve_loops, load_loops])
    return [kernel_loop("separator_in", 0 if local else _ported(ls), "move", timing),
            Loop("backsub_lane", 1, 1, region)]


def backsub_copies(tables: dict, s: int, timing: dict, ops: OperatorTable
                   ) -> tuple[list[Loop], list[Loop]]:
    """back_substitute()'s loops around cond_backsub for step s alone on one unit (one unit
    set, :data:`PORTS` words a cycle): the separator's solution in and the conditional's
    ``cond_load``; the frontal solution out."""
    w, f = tables["STEP_W"][s], tables["STEP_F"][s]
    return ([kernel_loop("separator_in", _ported(w - f), "move", timing),
             load_loop(f, w - f, ops)],
            [kernel_loop("solution_out", _ported(f), "move", timing)])


def retire_region(slots: list[list[Loop]], sent: list[int], counts: list[int], ii: int,
                  depth: int, ends: list[int] | None = None) -> int:
    """back_substitute's DATAFLOW region: the slot process (``slots``: each slot's loops, in
    order) beside ``backsub_retire``, one pipelined loop (``ii``, ``depth``) over the variables
    of the solved steps (``counts[i]`` of the i-th step the slots send; ``sent[i]``: the slot
    whose solution_out sends it): an iteration issues ``ii`` after the one before, a step's
    first no earlier than the end of the slot that sent it; the region ends when both
    processes have (fgc_cycles.h's outer group). ``ends``, if given, receives when each
    iteration ends (its variable's words sent on to trial_cost)."""
    out, ends, clock = ends, [], 0
    for loops in slots:
        clock += sum(lp.cycles for lp in loops)
        ends.append(clock)
    issue, last = None, 0
    for slot, n in zip(sent, counts, strict=True):
        for j in range(n):
            at = 0 if issue is None else issue + ii
            issue = max(at, ends[slot]) if j == 0 else at
            last = issue + depth
            if out is not None:
                out.append(last)
    return max(clock, last)


def backsub_phases(ctx, unit: str) -> None:
    """The emitted back_substitute (fgc_backsub.h): one phase ``backsub``, its DATAFLOW region
    of the slot process (per slot of :func:`backsub_slots` its copies, the separator's only
    where it is not lane-local (:func:`backsub_xoff`), and ``backsub_lane<p>`` region,
    :func:`backsub_slot_loops`) beside the state update's ``backsub_retire``
    (:func:`fgc_backends.hls.units.state_update.retire_timing`: a variable an iteration, as its
    step's solution arrives), priced by :func:`retire_region`: the slots' loops, then what the
    retire adds after the last slot (``retire_tail``)."""
    from fgc_backends.hls.units.state_update import retire_timing
    tables, timing, ops = ctx.tables, ctx.les_timing, ctx.les
    lanes = ctx.opts.backsub_lanes
    slots, sent, counts = [], [], []
    xoff = backsub_xoff(tables)
    for k, (solve, load, _) in enumerate(backsub_slots(tables)):
        slots.append(backsub_slot_loops(tables, solve, load, ops, timing, xoff[k] >= 0, lanes))
        if solve >= 0:
            sent.append(k)
            counts.append(len(ctx.program.schedule.steps[solve].frontals))
    ii, depth = retire_timing(ctx.program.variables, ctx.ops, ctx.sizes["MAX_F"],
                              ctx.opts.state_allocation)
    var_end: list[int] = []
    region = retire_region(slots, sent, counts, ii, depth, var_end)
    a = sum(lp.cycles for loops in slots for lp in loops)
    # the solved words to the state update, a pair a stream word (back_substitute's dx)
    ctx.channels.append(Channel("backsub_dx", "stream", ctx.sizes["MAX_F"], 2 * ops.word_bits,
                                "backsub_slots", "backsub_retire"))
    # the cost at X_TRIAL beside them (units.datapath's trial_cost), fed the retired
    # variables' storage words, a variable a stream word (as deep as the state: the retire
    # never waits for it)
    from fgc_backends.hls.units.datapath import trial_end
    cost = max(region, trial_end(ctx.shared["trial_loops"], var_end))
    words = max(v.storage_dim for v in ctx.program.variables)
    ctx.channels.append(Channel("trial_tx", "stream", len(ctx.program.variables),
                                words * ctx.ops.word_bits, "backsub_retire", "trial_cost"))
    ctx.add_phase("solve", Phase("backsub", False, (
        Process("backsub_slots", unit, tuple(lp for loops in slots for lp in loops)),
        Process("backsub_retire", "state_update", (Loop("retire_tail", 1, 1, region - a),)
                if region > a else ()),
        Process("trial_cost", "factor_cost", (Loop("cost_tail", 1, 1, cost - region),)
                if cost > region else ())), linear=True))


def retire_solved(tables: dict) -> list[int]:
    """The steps in the order back_substitute's slots solve (and send) them."""
    return [solve for solve, _, _ in backsub_slots(tables) if solve >= 0]


def backsub_operators(ops: OperatorTable, lanes: int = 1) -> tuple[tuple[str, int], ...]:
    """One back-substitution unit's operators as Vitis binds them
    (:mod:`fgc_backends.hls.plan.binding`), each pipelined loop its own at II 1: its
    ``cond_load`` (its own call site in back_substitute: two words an iteration, a multiply-add
    each), the row loop (2 PARTIALS − 1 adds folding, the subtraction from d, the reciprocal's
    divide, the row's scaling by it), the triangle (R_ir / R_ii, its product with x_r, the
    subtraction); x_0 a move; PARTIALS is the adder's latency. ``lanes`` > 1:
    ``cond_load_wide``'s 2 lanes multiplies, its tree's 2 lanes − 1 adds and the partial sum's
    add; the rows fold PARTIALS sums (PARTIALS − 1 adds and the subtraction); the triangle
    ``lanes`` times its operators."""
    partials = ops.add.latency
    if lanes > 1:
        width = 2 * lanes
        return sum_operators((BoundLoop("cond_load", (("add", width), ("mul", width)), 1),
                              BoundLoop("rows", (("add", partials), ("div", 1), ("mul", 1)), 1),
                              BoundLoop("triangle", (("add", lanes), ("mul", 2 * lanes)), 1)),
                             ops)
    return sum_operators((BoundLoop("cond_load", (("add", 2), ("mul", 2)), 1),
                          BoundLoop("rows", (("add", 2 * partials), ("div", 1), ("mul", 1)), 1),
                          BoundLoop("triangle", (("add", 1), ("mul", 2)), 1)), ops)


def build(ctx) -> None:
    """Both linear solvers: :data:`LANES` back-substitution units (QR: ``qr<l>_backsub``;
    Cholesky: ``trisolve``), whatever the unit sets (as emitted: one step's cond_backsub on one
    lane beside the next step's cond_load on the other; what-if whole-matrix Cholesky: Lᵀδ = z
    by rows, Lz = g riding the cascade)."""
    program, opts, ops = ctx.program, ctx.opts, ctx.les
    lanes = opts.backsub_lanes
    if lanes > 1:  # COND cyclic over ``lanes`` banks (backsub_slots' ARRAY_PARTITION)
        ctx.memories[:] = [dataclasses.replace(m, banks=lanes) if m.name == "cond" else m
                           for m in ctx.memories]
    if program.solver.linear == "qr":
        backsub_phases(ctx, "backsub")
        for lane in range(LANES):
            ctx.units.append(Unit(f"qr{lane}_backsub", f"back-substitution lane {lane} "
                                  "(cond_load, cond_backsub)", 1, backsub_operators(ops, lanes)))
        return
    if opts.hessian_storage == "frontal":
        ctx.units.append(Unit("trisolve", "back-substitution, one per lane (cond_load, "
                              "cond_backsub; Lz = g rides the cascade)", LANES,
                              backsub_operators(ops, lanes)))
        backsub_phases(ctx, "trisolve")
        return
    n = program.storage.columns
    ctx.units.append(Unit("trisolve", "Lᵀδ = z (Lz = g runs in the cascade)", 1,
                          (("add", 1), ("mul", 1), ("div", 1))))
    solve = dot_loop("rows", n, ops)
    ctx.add_phase("solve", Phase("trisolve", False, (Process("backward", "trisolve", (
        Loop("rows", n, max(1, math.ceil(n / 2)), solve.depth + ops.div.latency),)),),
        linear=True))


SPEC = UnitSpec(
    name="backsub", role="back-substitution through the conditionals",
    build=build, phases=("backsub", "trisolve"), header="fgc_backsub.h",
    constants=(("PARTIALS", "interleaved partial sums per row (the adder latency)"),
               ("MAX_F", "widest frontal block"), ("MAX_W", "widest step")),
    printed_by="accel.cpp.jinja: solve -> fgc_backsub.h back_substitute (the BS_* slot tables) -> "
               "backsub_lane<p> -> cond_backsub, cond_load")

