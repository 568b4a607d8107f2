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
from fgc_backends.hls.plan.binding import BoundLoop, bound_unit, sum_operators
from fgc_backends.hls.plan.loops import (
    _ceil_log2,
    _ported,
    _region_cycles,
    dot_loop,
    kernel_loop,
    slowest_plus_fills,
)
from fgc_backends.hls.plan.model import PORTS, Channel, Loop, Phase, Process, Unit
from fgc_backends.hls.units.spec import UnitSpec

LANES = 2  # back-substitution lanes: one solves a step while the other loads the next


def backsub_chain(ops: OperatorTable) -> int:
    """The triangle's recurrence per unknown (fgc_backsub.h's CHAIN): the product (R_ir / R_ii) x_r
    and the subtraction from y_i (the rows are scaled by 1 / R_ii in the row loop, so x_r = y_r
    and the scaling of R_ir runs off the chain)."""
    return ops.mul.latency + ops.add.latency


def backsub_words(frontal: int, separator: int, part: int = 0) -> int:
    """Words ``cond_load`` moves: each row i of the conditional from its diagonal on (R's
    structural zeros below the diagonal stay behind); ``part`` (:func:`backsub_parts`) 1: R's
    upper triangle and d alone, 2: S alone."""
    if part == 1:
        return frontal * (frontal + 1) // 2 + frontal
    if part == 2:
        return frontal * separator
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
              lanes: int = 1, off: int = 0, part: int = 0) -> Loop:
    """``cond_load``: the conditional's stored words two a cycle (the source memory's two
    ports), each S_ia x_a added into a partial sum as it passes (II 1: a lane's sum comes back
    PARTIALS iterations later); depth read + multiply-add + write. ``lanes`` > 1:
    ``cond_load_wide``, an aligned group of 2 ``lanes`` words of one row an iteration from COND
    cyclic over ``lanes`` banks (:func:`wide_trip`; ``off``: the conditional's first word in
    COND), the group's products summed by a tree before the row's partial sum: depth read +
    multiply + La (1 + log₂ 2 lanes) + write. ``part``: :func:`backsub_parts` (one lane)."""
    if lanes > 1:
        trip = wide_trip(off, frontal, separator, lanes) if frontal else 0
        return Loop(name, trip, 1, 2 + ops.mul.latency
                    + ops.add.latency * (1 + _ceil_log2(2 * lanes)))
    words = backsub_words(frontal, separator, part) if frontal else 0
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


def root_in_commit(program, opts) -> bool:
    """Whether the root step's conditional reaches its back-substitution lane in its commit
    (fgc_eliminate.h's qr_commit with FGC_BS_ROOT_COMMIT: the same word into COND and into lane
    0's buffer BS_COND0 in the same cycle, as cond_load would copy it: the root has no
    separator, so its load is a plain copy), so back_substitute's slot process starts at slot 1,
    the root's solve (:func:`backsub_slots`' slot 0 loads the root alone): QR with the slot
    design one lane wide (``backsub_lanes`` 1; the wide lanes keep their own layout, Cholesky's
    drain writes COND elsewhere)."""
    return program.solver.linear == "qr" and opts.backsub_lanes == 1


def backsub_parts(tables: dict, lanes: int = 1) -> tuple[int, ...]:
    """Per slot of :func:`backsub_slots` (one lane wide; wider: all 0), what its load moves: 0
    the whole conditional; where a step waits for the step just solved (a slot solves alone,
    the next loads alone), the slot that solves alone takes in the waiting step's R (from its
    diagonal) and d, which need no solution, beside the solve (1: ``cond_load``'s part 1, into
    the same lane), and the next slot its S alone, S xs summed on the way (2)."""
    slots = backsub_slots(tables)
    parts = [0] * len(slots)
    if lanes != 1:
        return tuple(parts)
    for k in range(len(slots) - 1):
        (solve, load, _), (nsolve, nload, _) = slots[k], slots[k + 1]
        if solve >= 0 and load < 0 and nsolve < 0 and nload >= 0:
            parts[k], parts[k + 1] = 1, 2
    return tuple(parts)


def streamed_s(tables: dict, solve: int, load: int, ops: OperatorTable) -> bool:
    """Whether ``load``'s S can be loaded as ``solve``'s solution arrives (``cond_load``'s part
    3): its separator is ``solve``'s frontal columns 0 … s − 1 in order, so the solving lane's
    triangle produces x_a for column a = s − 1 … 0 in the order the load takes S's columns,
    and a column of S (⌈f / 2⌉ iterations, rows two a cycle) takes no longer than the triangle
    spaces its x's (a column at least CHAIN + 1 iterations): the load keeps pace with the
    solve, so it waits for x_0 alone (:func:`stream_load_end`)."""
    cols, cb = tables["STEP_COL"], tables["STEP_COL_BEGIN"]
    f_of, w_of = tables["STEP_F"], tables["STEP_W"]
    if solve < 0 or load < 0:
        return False
    lf, s = f_of[load], w_of[load] - f_of[load]
    sep = list(cols[cb[load] + lf:cb[load] + w_of[load]])
    front = list(cols[cb[solve]:cb[solve] + f_of[solve]])
    return (0 < s <= len(front) and sep == front[:s]
            and -(-lf // 2) <= backsub_chain(ops) + 1)


def backsub_schedule(tables: dict, ops: OperatorTable, lanes: int = 1
                     ) -> tuple[tuple[int, int, int, int, int], ...]:
    """back_substitute's slots as emitted (the BS_* tables): per slot (solve step, load step,
    solving lane, part, xoff) — :func:`backsub_slots`, :func:`backsub_parts` and
    :func:`backsub_xoff`, except that where a step waits for the step just solved and its S
    can be loaded as that solution arrives (:func:`streamed_s`), the slot that solves takes in
    its R, d and S (part 3: R and d first, then S column by column, x_a from the solving lane's
    triangle) and the slot that loaded S alone goes."""
    slots, parts, xoff = backsub_slots(tables), backsub_parts(tables, lanes), backsub_xoff(tables)
    out, k = [], 0
    while k < len(slots):
        solve, load, lane = slots[k]
        if (parts[k] == 1 and k + 1 < len(slots)
                and streamed_s(tables, solve, slots[k + 1][1], ops)):
            out.append((solve, slots[k + 1][1], lane, 3, -1))
            k += 2
            continue
        out.append((solve, load, lane, parts[k], xoff[k]))
        k += 1
    return tuple(out)


def stream_load_loop(frontal: int, separator: int, ops: OperatorTable, name: str) -> Loop:
    """``cond_load``'s part 3 (:func:`backsub_schedule`): R (from its diagonal) and d two words
    a cycle, then S column by column, a = s − 1 … 0, two rows of a column a cycle (⌈f / 2⌉
    iterations a column, x_a read from the solving lane at its first), one pipelined loop."""
    rd = -(-backsub_words(frontal, separator, 1) // PORTS)
    return Loop(name, rd + separator * -(-frontal // 2), 1, 2 + ops.mul.latency + ops.add.latency)


def stream_load_end(load: Loop, x0_at: int, frontal: int) -> int:
    """When part 3's load ends on its lane's clock: its own cycles, and no earlier than x_0's
    arrival (``x0_at``: the solving lane's rows, triangle and x_0 move) plus column 0's
    iterations after it (⌈f / 2⌉ − 1) and its depth (fgc_cycles.h's FGC_WAVE_WAIT_AFTER: the
    load keeps pace with the triangle, :func:`streamed_s`, so x_0 is the read that binds)."""
    return max(load.cycles, x0_at + -(-frontal // 2) - 1 + load.depth)


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
                       timing: dict, local: bool = False, lanes: int = 1,
                       part: int = 0) -> list[Loop]:
    """One slot of back_substitute() (:func:`backsub_slots`): the loaded step's separator
    solution in (:data:`PORTS` words a cycle; none when ``local``, :func:`backsub_xoff`), then
    the ``backsub_lane<p>`` DATAFLOW region (the solving lane's ``cond_backsub`` and its frontal
    solution out, ``backsub_out``, beside the other lane's ``cond_load``: the slower plus the
    other's fill); ``lanes``: :data:`PlanOptions.backsub_lanes`; ``part``: what the load moves
    (:func:`backsub_parts`; 1: no separator in)."""
    def sizes(s):
        return (tables["STEP_F"][s], tables["STEP_W"][s] - tables["STEP_F"][s]) if s >= 0 \
            else (0, 0)

    (sf, ss), (lf, ls) = sizes(solve), sizes(load)
    solve_loops = backsub_loops(sf, ss, ops, name=f"bs{solve}", lanes=lanes)
    if sf:
        solve_loops.append(kernel_loop("solution_out", _ported(sf), "move", timing))
    off = tables["STEP_COND_OFF"][load] if load >= 0 else 0
    if part == 3:  # R, d, then S as the solve's x arrives: the load waits for x_0
        load = stream_load_loop(lf, ls, ops, f"cond_load{load}")
        x0_at = sum(lp.cycles for lp in solve_loops if lp.name != "solution_out")
        region = slowest_plus_fills([(sum(lp.cycles for lp in solve_loops), solve_loops[0].depth),
                                     (stream_load_end(load, x0_at, lf), load.depth)])
        return [kernel_loop("separator_in", 0, "move", timing),
                Loop("backsub_lane", 1, 1, region)]
    load_loops = wide_load_loops(lf, ls, ops, lanes, off, f"cond_load{load}") if lanes > 1 \
        else [load_loop(lf, ls, ops, name=f"cond_load{load}", part=part)]
    region = _region_cycles([solve_loops, load_loops])
    return [kernel_loop("separator_in", 0 if local or part == 1 else _ported(ls), "move",
                        timing),
            Loop("backsub_lane", 1, 1, region)]


def serial_slots(sizes: list[tuple[int, int]], ops: OperatorTable, timing: dict,
                 root_commit: bool = False, lanes: int = 1) -> tuple[list[list[Loop]], list[int]]:
    """back_substitute's slots on a serial chain (the update model's window,
    plan/update.py): ``sizes`` the steps' (f, s) in the order they are solved, the root first,
    each step's separator the frontal columns of the step solved before it, so each waits for
    it (:func:`backsub_slots`' solve alone, load alone; one lane wide, the waiting step's R and
    d beside the solve and its S after, :func:`backsub_parts`; its separator in from DELTA: the
    step before is the other lane's — or, where its separator is all of that step's frontal
    columns, in order, and a column of S keeps pace, R, d and S beside the solve as its x
    arrives, :func:`backsub_schedule`'s part 3). ``root_commit`` (:func:`root_in_commit`): no
    slot loads the root. Returns the slots' loops (:func:`backsub_slot_loops`) and, per step,
    the index of the slot that solves it (:func:`retire_region`'s ``sent``)."""
    tables = {"STEP_F": [f for f, _ in sizes], "STEP_W": [f + s for f, s in sizes],
              "STEP_COND_OFF": [0] * len(sizes)}
    slots: list[list[Loop]] = []
    sent: list[int] = []
    if not sizes:
        return slots, sent
    one = lanes == 1
    if not root_commit:
        slots.append(backsub_slot_loops(tables, -1, 0, ops, timing, False, lanes))
    for t in range(1, len(sizes)):
        (pf, _), (f, s) = sizes[t - 1], sizes[t]
        if one and 0 < s == pf and -(-f // 2) <= backsub_chain(ops) + 1:
            # (its separator the step before's frontal columns in order: its R, d and S
            # as that solve's x arrives, :func:`backsub_schedule`'s part 3)
            slots.append(backsub_slot_loops(tables, t - 1, t, ops, timing, False, lanes, 3))
            sent.append(len(slots) - 1)
            continue
        slots.append(backsub_slot_loops(tables, t - 1, t if one else -1, ops, timing, False,
                                        lanes, 1 if one else 0))
        sent.append(len(slots) - 1)
        slots.append(backsub_slot_loops(tables, -1, t, ops, timing, False, lanes,
                                        2 if one else 0))
    slots.append(backsub_slot_loops(tables, len(sizes) - 1, -1, ops, timing, False, lanes))
    sent.append(len(slots) - 1)
    return slots, sent


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
    clock, slot_end = 0, []
    for loops in slots:
        clock += sum(lp.cycles for lp in loops)
        slot_end.append(clock)
    last = retire_sent([slot_end[slot] for slot in sent], counts, ii, depth,
                       ends if ends is not None else [])
    return max(clock, last)


COLUMN_LANES = 4  # backsub_lanes = 4: the column design's update lanes per end (U)
COLUMN_WIDTH = 4  # words of COND an aligned group holds (an end takes a group a cycle)
COLUMN_SLOTS = 3  # an end's conditional buffers: the step solved, its child, the one loading


def column_order(tables: dict) -> list[int]:
    """The steps root first, levels in turn (LEVEL_STEPS order): the order the slots solve
    and the state update retires them."""
    begin, level_steps = tables["LEVEL_BEGIN"], tables["LEVEL_STEPS"]
    return [level_steps[i] for li in range(len(begin) - 2, -1, -1)
            for i in range(begin[li], begin[li + 1])]


def column_chain(tables: dict) -> tuple[tuple[int, ...], tuple[int, ...]] | str:
    """The column design's two ends (``backsub_lanes = 4``): end 0 the root then the chain below
    its first child, end 1 the chain below its second (each root first); or, when the
    elimination tree is not such a chain (a step with two children below the root, the root
    with three, a separator column that is not a frontal column of the step's parent), a
    sentence saying why (the design is refused by name)."""
    order = column_order(tables)
    cols, cb = tables["STEP_COL"], tables["STEP_COL_BEGIN"]
    f_of, w_of = tables["STEP_F"], tables["STEP_W"]
    if not order:
        return "no elimination steps"
    owner = {c: s for s in order for c in cols[cb[s]:cb[s] + f_of[s]]}
    children: dict[int, list[int]] = {s: [] for s in order}
    for s in order[1:]:
        sep = cols[cb[s] + f_of[s]:cb[s] + w_of[s]]
        parents = {owner.get(c) for c in sep}
        if not sep or len(parents) != 1:
            return (f"step {s}'s separator is not the frontal columns of one step (a tree, "
                    "not a chain)")
        children[parents.pop()].append(s)
    root = order[0]
    if len(children[root]) > 2:
        return f"the root step {root} has {len(children[root])} children (at most two ends)"
    ends = []
    for first in children[root]:
        chain = [first]
        while children[chain[-1]]:
            if len(children[chain[-1]]) > 1:
                return (f"step {chain[-1]} has {len(children[chain[-1]])} children (a tree, "
                        "not a two-ended chain)")
            chain.append(children[chain[-1]][0])
        ends.append(tuple(chain))
    ends += [()] * (2 - len(ends))
    return (root, *ends[0]), ends[1]


def column_sep(tables: dict, step: int, child: int) -> list[int]:
    """Per frontal column r of ``step`` (r = 0 … f − 1): its position a in ``child``'s separator
    (the child's column f' + a), or −1 (not one of them, or no child: −1)."""
    cols, cb, f_of = tables["STEP_COL"], tables["STEP_COL_BEGIN"], tables["STEP_F"]
    pos = {}
    if child >= 0:
        sep = cols[cb[child] + f_of[child]:cb[child] + tables["STEP_W"][child]]
        pos = {c: a for a, c in enumerate(sep)}
    return [pos.get(cols[cb[step] + r], -1) for r in range(f_of[step])]


def column_len(r: int, a: int, child_f: int, ops: OperatorTable, feed: bool = False,
               lanes: int = COLUMN_LANES) -> int:
    """Iterations of column r in a pass (fgc_backsub.h's bsc_column_len): its own rows above r
    in blocks of U (lane l the row of residue l, :func:`backsub_triangle`'s rule; none in a
    feed pass), then, where the column is the child's separator column a ≥ 0, the child's f'
    rows in blocks of U; at least CHAIN + 1 (so x_{r−1} and a row's next update find it
    final), except a column with no rows at all: one iteration (x_r read and sent)."""
    own = 0 if feed else -(-r // lanes)
    n = own + (-(-child_f // lanes) if a >= 0 else 0)
    return max(n, backsub_chain(ops) + 1) if n else 1


def column_groups(tables: dict, step: int) -> int:
    """Aligned groups of :data:`COLUMN_WIDTH` COND words the loader streams an end for ``step``
    (row by row, a group two rows share sent for each: :func:`wide_trip`)."""
    f, w = tables["STEP_F"][step], tables["STEP_W"][step]
    return wide_trip(tables["STEP_COND_OFF"][step], f, w - f, COLUMN_WIDTH // 2) if f else 0


def column_pass_depth(ops: OperatorTable) -> int:
    """A column pass's iteration: the update's coefficient read, its product with x_r, the
    subtraction, the write (2 + CHAIN), beside the ingestion of a group: 1 / R_ii, the
    scaling, the write (2 + Ld + Lm); the deeper of the two."""
    return max(2 + backsub_chain(ops), 2 + ops.div.latency + ops.mul.latency)


@dataclasses.dataclass(frozen=True)
class ColumnPass:
    """One pass of an end's column loop (fgc_backsub.h's BSC_* tables): ``step`` whose columns
    it runs (−1: none), ``child`` whose rows they update too (−1: none), ``ingest`` the step
    whose groups it takes in (−1: none), the buffer slots of the three (an end's sequence
    index mod 3), ``feed``: end 1's pass over the root's columns (x_r from end 0's stream,
    the child's rows only), ``root``: end 0's pass that sends the root's x_r to end 1."""
    end: int
    step: int
    child: int
    ingest: int
    slot: int
    child_slot: int
    ingest_slot: int
    feed: bool = False
    root: bool = False


def column_passes(tables: dict) -> list[list[ColumnPass]]:
    """Per end, its column passes in order (fgc_backsub.h's backsub_end<e>): two passes taking
    in the end's first two steps' conditionals (no columns); on end 1 (when end 0 holds more
    than the root), then a pass over the root's columns, x_r from end 0's stream (its first
    step's rows updated where the root's column is in its separator; no groups: its buffers
    are full); then a pass per step t of the end (end 0: the root first), its columns
    updating its own rows and its child's (the step after it on the end), taking in step
    t + 2's groups beside them (into the slot step t − 1 freed)."""
    chain = column_chain(tables)
    assert not isinstance(chain, str), chain
    out = []
    for e, seq in enumerate(chain):
        passes = [ColumnPass(e, -1, -1, seq[k], -1, -1, k % COLUMN_SLOTS)
                  for k in range(min(2, len(seq)))]
        if e == 1 and seq:
            passes.append(ColumnPass(e, chain[0][0], seq[0], -1, -1, 0, -1, feed=True))
        for t, step in enumerate(seq):
            child = seq[t + 1] if t + 1 < len(seq) else -1
            ingest = seq[t + 2] if t + 2 < len(seq) else -1
            passes.append(ColumnPass(e, step, child, ingest, t % COLUMN_SLOTS,
                                     (t + 1) % COLUMN_SLOTS if child >= 0 else -1,
                                     (t + 2) % COLUMN_SLOTS if ingest >= 0 else -1,
                                     root=(e == 0 and t == 0 and bool(chain[1]))))
        out.append(passes)
    return out


def column_pass_trip(tables: dict, p: ColumnPass, ops: OperatorTable) -> int:
    """A pass's iterations: its columns' (:func:`column_len`, r = f − 1 … 0) and the groups it
    takes in side by side, the more of the two."""
    cols = 0
    if p.step >= 0:
        fc = tables["STEP_F"][p.child] if p.child >= 0 else 0
        cols = sum(column_len(r, a, fc, ops, p.feed)
                   for r, a in enumerate(column_sep(tables, p.step, p.child)))
    return max(cols, column_groups(tables, p.ingest) if p.ingest >= 0 else 0)


COLUMN_LOAD_DEPTH = 2  # the loader's loop: a group read from COND, written to an end's stream


def column_timeline(tables: dict, ops: OperatorTable) -> list[list[tuple[ColumnPass, int, int]]]:
    """Per end, its passes with their start and end as fgc_cycles.h's region arithmetic clocks
    a process (cycles from the region's start): back to back, a pass (trip − 1) + depth
    (:func:`column_pass_depth`), end 1's feed pass ending no earlier than its depth after end
    0's root pass (it reads x_r from end 0's stream as end 0's columns produce them:
    FGC_WAIT)."""
    depth = column_pass_depth(ops)
    out, root_end = [], None
    for passes in column_passes(tables):
        clock, rows = 0, []
        for p in passes:
            trip = column_pass_trip(tables, p, ops)
            if trip <= 0:
                continue
            start, end = clock, clock + (trip - 1) + depth
            if p.feed and root_end is not None:
                end = max(end, root_end + depth)
            rows.append((p, start, end))
            clock = end
            if p.root:
                root_end = end
        out.append(rows)
    return out


def column_loader_trip(tables: dict) -> int:
    """The loader's loop: an iteration sends each end its next group (the longer end's groups)."""
    return max(sum(column_groups(tables, s) for s in seq) for seq in column_chain(tables))


def column_schedule(tables: dict, ops: OperatorTable) -> tuple[dict[int, int], int]:
    """The column region as fgc_cycles.h's total_range prices a DATAFLOW region of the loader
    and the two ends: its slowest process plus the fill of the others (the loader's
    :data:`COLUMN_LOAD_DEPTH`, the other end's pass depth), and no earlier than any process's
    last pass (end 1's feed pass waits for end 0's root pass). Returns each solved step's end
    (its pass's end on its end's clock: when its last x has left for the state update) and
    the region's cycles."""
    timeline = column_timeline(tables, ops)
    loader = column_loader_trip(tables)
    procs = [(loader - 1 + COLUMN_LOAD_DEPTH, COLUMN_LOAD_DEPTH)] if loader else []
    ends, last = {}, 0
    for rows in timeline:
        if not rows:
            continue
        trips = [column_pass_trip(tables, p, ops) for p, _, _ in rows]
        procs.append((sum(t - 1 + column_pass_depth(ops) for t in trips),
                      column_pass_depth(ops)))
        for p, _, end in rows:
            if p.step >= 0 and not p.feed:
                ends[p.step] = end
            last = max(last, end)
    region = slowest_plus_fills(procs)
    return ends, max(region, last)


def column_fifo(tables: dict, ops: OperatorTable, end: int) -> int:
    """Depth of the loader's stream to ``end``: the loader sends both ends a group a cycle in
    step, so before the end takes its g-th group (a pass's i-th iteration takes the pass's
    i-th group) the stream holds the groups sent by then less g; the largest of these, + 1:
    the loader never waits on a full stream (the ends take a group a cycle at most, so it
    never runs behind either)."""
    total = sum(column_groups(tables, s) for s in column_chain(tables)[end])
    most, g = 0, 0
    for p, start, _ in column_timeline(tables, ops)[end]:
        if p.ingest < 0:
            continue
        for i in range(column_groups(tables, p.ingest)):
            most = max(most, min(start + i + 1, total) - g)
            g += 1
    return max(most, 0) + 1


def column_dx_depth(tables: dict, end: int) -> int:
    """Depth of an end's solution stream to the state update (pairs of words): all its steps'
    (the state update, a variable a retire II, falls behind the ends; they never wait on it)."""
    return max(1, sum((tables["STEP_F"][s] + 1) // 2 for s in column_chain(tables)[end]))


def column_tables(tables: dict, ops: OperatorTable) -> dict:
    """The BSC_* tables fgc_backsub.h's column driver runs over (accel.cpp.jinja prints them):
    per end its step sequence (BSC_SEQ, from BSC_SEQ_BEGIN[e]; the loader walks it), per pass
    (from BSC_PASS_BEGIN[e]) its step, child, ingested step, slots, feed and root flags, and
    per pass column r its child separator position (BSC_COLA[BSC_COLA_BEGIN[pass] + r]); per
    step its end (BSC_END_OF, the state update's stream); the streams' depths."""
    chain = column_chain(tables)
    seq, seq_begin = [], [0]
    for e in range(2):
        seq += list(chain[e])
        seq_begin.append(len(seq))
    rows = {k: [] for k in ("STEP", "CHILD", "INGEST", "SLOT", "CSLOT", "ISLOT", "FEED", "ROOT",
                            "COLA_BEGIN")}
    cola, pass_begin = [], [0]
    for passes in column_passes(tables):
        for p in passes:
            for k, v in (("STEP", p.step), ("CHILD", p.child), ("INGEST", p.ingest),
                         ("SLOT", p.slot), ("CSLOT", p.child_slot), ("ISLOT", p.ingest_slot),
                         ("FEED", int(p.feed)), ("ROOT", int(p.root)),
                         ("COLA_BEGIN", len(cola))):
                rows[k].append(v)
            if p.step >= 0:
                cola += column_sep(tables, p.step, p.child)
        pass_begin.append(len(rows["STEP"]))
    end_of = [-1] * len(tables["STEP_F"])
    for e in range(2):
        for s in chain[e]:
            end_of[s] = e
    return {"seq": seq, "seq_begin": seq_begin, "pass_begin": pass_begin,
            "cola": cola or [-1], "end_of": end_of,
            **{k.lower(): v for k, v in rows.items()},
            "fifo": [column_fifo(tables, ops, e) for e in range(2)],
            "dx": [column_dx_depth(tables, e) for e in range(2)]}


def column_operators(ops: OperatorTable) -> tuple[tuple[str, int], ...]:
    """One end's operators (its column pass, one pipelined loop at II 1 owning them): U
    multiply-subtracts (c_ir x_r from y_i), and the ingestion's 1 / R_ii (one divide a group)
    and the group's :data:`COLUMN_WIDTH` words scaled by it (c_ic = R_ic / R_ii, S_ia / R_ii,
    y_i = d_i / R_ii). The loader moves words (no operator)."""
    return sum_operators((BoundLoop("column_pass", (("add", COLUMN_LANES),
                                                    ("mul", COLUMN_LANES + COLUMN_WIDTH),
                                                    ("div", 1)), 1),), ops)


def column_phases(ctx, unit: str) -> None:
    """back_substitute with ``backsub_lanes = 4`` (the column design): one phase ``backsub``,
    its DATAFLOW region of the loader, the two ends (:func:`column_schedule`) and the state
    update beside them, each step's variables retired no earlier than the end of the pass that
    solved it (:func:`retire_region`'s arithmetic on those ends), then the cost at X_TRIAL."""
    tables, ops = ctx.tables, ctx.les
    columns, last, var_end = column_retire(ctx)
    region = max(columns, last)
    for e in range(2):
        ctx.channels.append(Channel(f"backsub_groups{e}", "stream", column_fifo(tables, ops, e),
                                    COLUMN_WIDTH * ops.word_bits, "backsub_loader",
                                    f"backsub_end{e}"))
        ctx.channels.append(Channel(f"backsub_dx{e}", "stream", column_dx_depth(tables, e),
                                    2 * ops.word_bits, f"backsub_end{e}", "backsub_retire"))
    ctx.channels.append(Channel("backsub_xroot", "stream", ctx.sizes["MAX_F"], ops.word_bits,
                                "backsub_end0", "backsub_end1"))
    _solve_phase(ctx, unit, Process("backsub_columns", unit,
                                    (Loop("column_region", 1, 1, columns),)),
                 columns, region, var_end)


def column_retire(ctx) -> tuple[int, int, list[int]]:
    """The column design's region (:func:`column_schedule`), when its state update ends
    (:func:`retire_sent`: each step's variables retired no earlier than the end of the pass
    that solved it) and when each variable is retired, in RETIRE_VARS order."""
    from fgc_backends.hls.units.lm_control import retire_step_test
    from fgc_backends.hls.units.state_update import retire_timing
    tables = ctx.tables
    ends, columns = column_schedule(tables, ctx.les)
    order = column_order(tables)
    counts = [len(ctx.program.schedule.steps[s].frontals) for s in order]
    ii, depth = retire_timing(ctx.program.variables, ctx.ops, ctx.sizes["MAX_F"],
                              ctx.opts.state_allocation,
                              retire_step_test(ctx.program, ctx.opts))
    var_end: list[int] = []
    last = retire_sent([ends[s] for s in order], counts, ii, depth, var_end)
    return columns, last, var_end


def retire_sent(sent_at: list[int], counts: list[int], ii: int,
                depth: int, ends: list[int]) -> int:
    """:func:`retire_region`'s state update with each step's solution sent at ``sent_at[i]``
    (the column design: the end of the pass that solved it): an iteration ``ii`` after the one
    before, a step's first no earlier than its send; returns when the last ends."""
    issue, last = None, 0
    for at_step, n in zip(sent_at, counts, strict=True):
        for j in range(n):
            at = 0 if issue is None else issue + ii
            issue = max(at, at_step) if j == 0 else at
            last = issue + depth
            ends.append(last)
    return last


def backsub_phases(ctx, unit: str) -> None:
    """The emitted back_substitute (fgc_backsub.h): one phase ``backsub``, its DATAFLOW region
    of the slot process (per slot of :func:`backsub_slots` its copies, the separator's only
    where it is not lane-local (:func:`backsub_xoff`), and ``backsub_lane<p>`` region,
    :func:`backsub_slot_loops`) beside the state update's ``backsub_retire``
    (:func:`fgc_backends.hls.units.state_update.retire_timing`: a variable an iteration, as its
    step's solution arrives), priced by :func:`retire_region`: the slots' loops, then what the
    retire adds after the last slot (``retire_tail``)."""
    ops = ctx.les
    slots, region, var_end = slot_retire(ctx)
    a = sum(lp.cycles for loops in slots for lp in loops)
    # the solved words to the state update, a pair a stream word (back_substitute's dx)
    ctx.channels.append(Channel("backsub_dx", "stream", ctx.sizes["MAX_F"], 2 * ops.word_bits,
                                "backsub_slots", "backsub_retire"))
    if ctx.opts.backsub_lanes == 1:  # per backsub_lane<p> region: the solve's x_r to the other
        # lane's load (fgc_backsub.h's xr, cond_load's part 3: as deep as a step's solution)
        for p in range(LANES):
            ctx.channels.append(Channel(f"backsub_xr{p}", "stream", ctx.sizes["MAX_F"],
                                        ops.word_bits, f"backsub_set{p}",
                                        f"backsub_load{1 - p}"))
    _solve_phase(ctx, unit, Process("backsub_slots", unit,
                                    tuple(lp for loops in slots for lp in loops)),
                 a, region, var_end)


def slot_retire(ctx) -> tuple[list, int, list[int]]:
    """The slot design's back_substitute region as :func:`backsub_phases` prices it: per slot
    its loops, the region's end (:func:`retire_region`) and ``var_end``, when each retired
    variable's words are in trial_cost's stream (in the retire order). The emitter asks it too
    (the order of trial_cost's loops is chosen on these ends: units/datapath.py's
    trial_loops)."""
    from fgc_backends.hls.units.lm_control import retire_step_test
    from fgc_backends.hls.units.state_update import retire_timing
    tables, timing, ops = ctx.tables, ctx.les_timing, ctx.les
    lanes = ctx.opts.backsub_lanes
    slots, sent, counts = [], [], []
    first = 1 if root_in_commit(ctx.program, ctx.opts) else 0  # (slot 0: the root's load)
    order = backsub_schedule(tables, ops, lanes)
    for k, (solve, load, _, part, xoff) in enumerate(order):
        if k < first:
            continue
        if part == 1:  # the next slot's step's R and d beside this solve
            load = order[k + 1][1]
        slots.append(backsub_slot_loops(tables, solve, load, ops, timing, xoff >= 0, lanes,
                                        part))
        if solve >= 0:
            sent.append(len(slots) - 1)  # (its index among the slots run)
            counts.append(len(ctx.program.schedule.steps[solve].frontals))
    ii, depth = retire_timing(ctx.program.variables, ctx.ops, ctx.sizes["MAX_F"],
                              ctx.opts.state_allocation,
                              retire_step_test(ctx.program, ctx.opts))
    var_end: list[int] = []
    region = retire_region(slots, sent, counts, ii, depth, var_end)
    return slots, region, var_end


def _solve_phase(ctx, unit: str, solver: Process, busy: int, region: int,
                 var_end: list[int]) -> None:
    """The phase ``backsub`` both drivers end with: ``solver`` (busy ``busy`` cycles) beside the
    state update's ``backsub_retire`` (what it adds after the solver, to ``region``) and the
    cost at X_TRIAL (units.datapath's trial_cost), fed the retired variables' storage words, a
    variable a stream word (as deep as the state: the retire never waits for it; ``var_end``:
    when each variable is retired)."""
    from fgc_backends.hls.units.datapath import trial_end, trial_positions
    split = any(lp.proc == 1 for lp in ctx.shared["trial_loops"])
    pos = trial_positions(ctx.program, ctx.tables) if split else None
    cost = max(region, trial_end(ctx.shared["trial_loops"], var_end, pos))
    words = max(v.storage_dim for v in ctx.program.variables)
    ctx.channels.append(Channel("trial_tx", "stream", len(ctx.program.variables),
                                words * ctx.ops.word_bits, "backsub_retire", "trial_cost"))
    # a second cost stream (fgc_backsub.h's tx2, both drivers), to trial_cost_b where trial_cost
    # is split in two (units/datapath.py's split_trial_loops, slot_split_loops: trial_cost a
    # DATAFLOW region of trial_cost_a and trial_cost_b), else declared and unused (by columns
    # as deep as the state, the slot design's one word: LesConfig's TRIAL_TX2_DEPTH)
    columns = any(ch.name == "backsub_xroot" for ch in ctx.channels)
    ctx.channels.append(Channel("trial_tx2", "stream",
                                len(ctx.program.variables) if split or columns else 1,
                                words * ctx.ops.word_bits, "backsub_retire",
                                "trial_cost_b" if split else "trial_cost"))
    if any(lp.feed for lp in ctx.shared["trial_loops"]):  # the slot design's: trial_cost_b's
        # data words from trial_cost (a word a cycle, both loops pipelined: two words deep)
        ctx.channels.append(Channel("trial_feed", "stream", 2, ctx.ops.word_bits, "trial_cost",
                                    "trial_cost_b"))
    ctx.add_phase("solve", Phase("backsub", False, (
        solver,
        Process("backsub_retire", "state_update", (Loop("retire_tail", 1, 1, region - busy),)
                if region > busy else ()),
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


def column_build(ctx) -> None:
    """``backsub_lanes = 4``: the column design (docs/hls.md, "Back-substitution by columns"):
    COND cyclic over 4 banks (the loader reads a group of 4 words for each end a cycle: two
    reads a bank), per end its three conditional buffers (``cbuf``, by row residue and word
    bank: U × 4 banks) and its unit (:func:`column_operators`); the phase by
    :func:`column_phases`. A Program whose elimination tree is not a two-ended chain is refused
    by name."""
    from fgc_backends.hls.plan.model import Memory, PlanError
    program, ops, tables = ctx.program, ctx.les, ctx.tables
    chain = column_chain(tables)
    if isinstance(chain, str):
        raise PlanError(f"backsub_lanes {COLUMN_LANES} (back-substitution by columns, per end "
                        f"of a two-ended chain): {program.name}'s elimination tree does not "
                        f"fit: {chain}; use backsub_lanes 1 or 2")
    ctx.memories[:] = [dataclasses.replace(m, banks=COLUMN_WIDTH) if m.name == "cond" else m
                       for m in ctx.memories]
    # fgc_backsub.h's cbuf: [U][W][slots × ⌈MAX_F / U⌉ rows × (MAX_W + 1) / W + 2 groups]
    words = (COLUMN_LANES * COLUMN_WIDTH * COLUMN_SLOTS * -(-ctx.sizes["MAX_F"] // COLUMN_LANES)
             * ((ctx.sizes["MAX_W"] + 1) // COLUMN_WIDTH + 2))
    for e in range(2):
        ctx.memories.append(Memory(f"bs_colbuf{e}", words, ops.word_bits,
                                   COLUMN_LANES * COLUMN_WIDTH))
    name = "backsub" if program.solver.linear == "qr" else "trisolve"
    ctx.units.append(Unit(name, "back-substitution by columns, one per end of the chain "
                          "(the column pass: U multiply-subtracts, the ingestion's 1 / R_ii "
                          "and scaling)", 2, column_operators(ops)))
    from fgc_backends.hls.units.lm_control import retire_step_test, retire_test_loop
    if retire_step_test(program, ctx.opts):  # LM's step test in the state update's loop
        from fgc_backends.hls.units.state_update import retire_timing
        ii, _ = retire_timing(program.variables, ctx.ops, ctx.sizes["MAX_F"],
                              ctx.opts.state_allocation,
                              retire_step_test(program, ctx.opts))
        ctx.units.append(bound_unit("retire_step_test", "LM's step test summed in the state "
                                    "update (|δ|², δᵀg and the trial's |x ⊕ δ|² a variable "
                                    "an iteration)",
                                    (retire_test_loop(program, ii),), table=ctx.ops))
    column_phases(ctx, name)


def _retire_solved_unit(ctx) -> None:
    """The one-step policy's sums in the slot design's state update (units/lm_control.py's
    retire_solved_test): per variable its |δ|², δᵀg, |g|'s maximum and |x|², summed by the
    retire's loop at its II (:func:`~fgc_backends.hls.units.lm_control.retire_solved_loop`). Its
    reads of G (a variable's tangent words, two a cycle) fit the II the δ copy's words set
    (a step's MAX_F and the variable's tangent words); X's words it reads already."""
    from fgc_backends.hls.units.lm_control import retire_solved_loop, retire_solved_test
    from fgc_backends.hls.units.state_update import retire_timing
    program = ctx.program
    if not retire_solved_test(program, ctx.opts):
        return
    ii, _ = retire_timing(program.variables, ctx.ops, ctx.sizes["MAX_F"],
                          ctx.opts.state_allocation)
    ctx.units.append(bound_unit("retire_solved_test", "the one-step policy's sums in the state "
                                "update (the gradient's largest |entry|, |X|², |δ|², δᵀg, a "
                                "variable an iteration)",
                                (retire_solved_loop(program, ii),), table=ctx.ops))


def build(ctx) -> None:
    """Both linear solvers: :data:`LANES` back-substitution units (QR: ``qr<l>_backsub``;
    Cholesky: ``trisolve``), whatever the unit sets (as emitted: one step's cond_backsub on one
    lane beside the next step's cond_load on the other; what-if whole-matrix Cholesky: Lᵀδ = z
    by rows, Lz = g riding the cascade)."""
    program, opts, ops = ctx.program, ctx.opts, ctx.les
    lanes = opts.backsub_lanes
    if lanes == COLUMN_LANES and (program.solver.linear == "qr"
                                  or opts.hessian_storage == "frontal"):
        column_build(ctx)
        return
    if lanes > 1:  # COND cyclic over ``lanes`` banks (backsub_slots' ARRAY_PARTITION)
        ctx.memories[:] = [dataclasses.replace(m, banks=lanes) if m.name == "cond" else m
                           for m in ctx.memories]
    _retire_solved_unit(ctx)
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
    linear_solver=True,
    build=build, phases=("backsub", "trisolve"), header="fgc_backsub.h",
    constants=(("PARTIALS", "interleaved partial sums per row (the adder latency)"),
               ("MAX_F", "widest frontal block"), ("MAX_W", "widest step")),
    printed_by="accel.cpp.jinja: solve -> fgc_backsub.h back_substitute (the BS_* slot tables) -> "
               "backsub_lane<p> -> cond_backsub, cond_load")

