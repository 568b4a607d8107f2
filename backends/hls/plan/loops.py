"""Loop pricing shared by the units: the dot-product rule, DATAFLOW regions, the kernel's own
loop kinds (:func:`kernel_timing`) and the emitted tables' sizes the loops run over.

Every II and depth here comes from the operator table the plan is built with
(:mod:`fgc_backends.cost.operators`); the units (:mod:`fgc_backends.hls.units`) build their
loops from these rules.
"""

from __future__ import annotations

import math

from fgc.ir.codes import NOISE_CODES
from fgc_backends.cfamily.sparsity import TILE, block_pattern
from fgc_backends.cfamily.tables import build_tables
from fgc_backends.cost.operators import OperatorTable
from fgc_backends.cost.params import view
from fgc_backends.hls.plan.model import PORTS, Loop, Process


def dot_loop(name: str, length: int, ops: OperatorTable, partials: int | None = None,
             repeat: int = 1) -> Loop:
    """A pipelined dot product: k interleaved partial sums give II = ceil(La / k); the depth
    holds one multiply, one add and the ⌈log₂ k⌉-level tree folding the partial sums."""
    la, lm = ops.add.latency, ops.mul.latency
    k = max(1, min(length, partials if partials is not None else la))
    tree = math.ceil(math.log2(k)) if k > 1 else 0
    return Loop(name, length, math.ceil(la / k), lm + la * (1 + tree), repeat)


def slowest_plus_fills(procs: list[tuple[int, int]]) -> int:
    """A DATAFLOW region's length from its processes' (cycles, fill) pairs: the slowest
    process's cycles plus the fill of every other (fgc_cycles.h's ``total``); 0 for none."""
    if not procs:
        return 0
    slow = max(range(len(procs)), key=lambda i: procs[i][0])
    return procs[slow][0] + sum(fill for i, (_, fill) in enumerate(procs) if i != slow)


def _region_cycles(processes: list[list[Loop]],
                   waits: tuple[tuple, ...] = ()) -> int:
    """A DATAFLOW region as :func:`phase_cycles` prices it: its slowest process plus the fill of
    the others (the depth of their first loop that runs); processes with no running loop are
    absent (fgc_cycles.h's ``total``). ``waits``: (process, loop, on process, loop name suffix):
    that loop of the process (or, if it does not run, the process's next one that does) reads
    the stream the other's first such loop writes, as it comes, so it ends no earlier than its
    depth after that loop; each process's loops follow one another, in the region's order, and
    the region takes no less than any process's last loop's end (fgc_cycles.h's FGC_WAIT). A
    fifth entry ``after``: the loop reads that stream in one iteration only, ``after`` cycles
    before its last iteration issues, so it ends no earlier than ``after`` + its depth after
    that loop (FGC_WAIT_AFTER)."""
    procs = [(sum(lp.cycles for lp in loops), next((lp.depth for lp in loops if lp.trip > 0), 0))
             for loops in processes if any(lp.trip > 0 for lp in loops)]
    if not procs:
        return 0
    total = slowest_plus_fills(procs)
    if not waits:
        return total
    ends: dict[tuple[int, int], int] = {}
    for p, loops in enumerate(processes):
        clock, pending = 0, None
        for li, lp in enumerate(loops):
            for wp, wl, q, suffix, *after in waits:
                if (wp, wl) != (p, li):
                    continue
                at = next((ends[q, x] for x, lq in enumerate(processes[q])
                           if lq.name.endswith(suffix) and (q, x) in ends), None)
                if at is not None:
                    at += after[0] if after else 0
                    pending = at if pending is None else max(pending, at)
            if lp.trip <= 0:
                continue
            end = clock + lp.cycles
            if pending is not None:
                end, pending = max(end, pending + lp.depth), None
            clock = ends[p, li] = end
            total = max(total, end)
    return total


def kernel_timing(ops: OperatorTable) -> dict[str, tuple[int, int]]:
    """(II, depth) of each kind of loop the emitted kernel runs around the units
    (accel.cpp.jinja prints these numbers into its FGC_CYCLES counters, so plan and count share
    them; what is counted is how often each loop runs and its trip count at run time):

    - ``move``: one word read and written a cycle (II 1, depth 2); ``fill``: one word written
      a cycle (II 1, depth 1);
    - ``acc``: a sum of products into one accumulator: the recurrence through the adder sets
      II = add latency, depth multiply + add (interleaved into partial sums by
      :func:`kernel_dot`); ``acc2``: a term through two multiply-adds before its sum (the
      rounding-noise pass's terms): II 3·TILE (at least the add latency), so TILE rows' three
      products and two adds each share one multiplier and one adder (the rejected step's pass
      is rare: operators there do not pay), depth 2 (multiply + add) after the last product;
    - ``scatter``: ``+=`` into a table-addressed memory where every iteration of the loop has
      its own address (II 1, depth read + add + write);
    - ``max``: a running maximum (compare and select: II = compare latency, depth + 2 for the
      read and |·|; into partial maxima by :func:`kernel_dot`, LM control's gradient maximum);
    - ``root``: one square root (√μ); ``decision``: LM control's scalar decision (gain ratio
      divide, two multiplies, two adds, a compare); ``retract``: one variable a cycle through a
      retraction-sized datapath (square root, divide, sin/cos, four multiply-adds deep), what
      the update model assumes for a Log pass (the emitted state update is priced per type by
      :func:`retract_datapath`).
    """
    la, lm, lc = ops.add.latency, ops.mul.latency, ops.compare.latency
    return {"move": (1, 2), "fill": (1, 1), "acc": (la, lm + la),
            "acc2": (max(la, 3 * TILE), 3 * TILE - 1 + 2 * (lm + la)),
            "scatter": (1, la + 2), "max": (lc, lc + 2),
            "root": (1, ops.sqrt.latency), "div": (ops.div.latency, ops.div.latency),
            "decision": (1, ops.div.latency + 2 * lm + 2 * la + lc),
            "retract": (1, ops.sqrt.latency + ops.div.latency + ops.sincos.latency
                        + 4 * (lm + la))}


def kernel_loop(name: str, trip: int, kind: str, timing: dict, repeat: int = 1) -> Loop:
    """A loop of the kernel's own code (not a unit's) with ``trip`` iterations of kind ``kind``
    (move, acc, retract, …): its II and depth from ``timing`` (:func:`kernel_timing`)."""
    ii, depth = timing[kind]
    return Loop(name, trip, ii, depth, repeat)


def kernel_dot(name: str, length: int, timing: dict, repeat: int = 1, kind: str = "acc",
               lead: int = 0) -> Loop:
    """A kernel loop summing ``length`` terms into the adder latency's interleaved partial sums
    (accel.cpp.jinja's T_PARTIALS / L_PARTIALS), priced by the dot-product rule
    (:func:`dot_loop`) with the latencies of ``timing`` (:func:`kernel_timing`).

    ``kind`` is the recurrence the partials break: ``"acc"`` (a sum: the adder's latency, the
    multiply ahead of it) or ``"max"`` (a running maximum into partial maxima: the compare's
    latency, the read and |·| ahead of it, the fold a tree of compares); ``lead``: latency
    ahead of the multiply (the step test's g + μδ)."""
    ii, depth = timing[kind]
    k = max(1, min(length, ii))
    return Loop(name, length, math.ceil(ii / k), lead + (depth - ii) + ii * (1 + _ceil_log2(k)),
                repeat)


def _ported(words: int) -> int:
    """Iterations of a copy of ``words`` words at :data:`PORTS` words a cycle."""
    return -(-words // PORTS)


def _ceil_log2(n: int) -> int:
    """⌈log₂ n⌉ (0 for n ≤ 1): the adds of a tree folding n sums (fgc_cycles.h's ceil_log2)."""
    return math.ceil(math.log2(n)) if n > 1 else 0


def _block_shape(block) -> tuple[int, int, int, object]:
    """(m, d, padded row stride, Gram tiles) of a block type as the emitted kernel lays it out
    (fgc_backends.cfamily.blocks' pattern: rows padded to whole TILEs)."""
    kinds = tuple(NOISE_CODES[m.noise_kind] for m in block.members)
    pattern = block_pattern(block, kinds, f"block {block.name!r}")
    return block.residual_dim, sum(block.variable_dims), pattern.padded, pattern.tiles()


def _tables(program) -> dict:
    """The emitted constant tables by name (the same arrays the kernel steps through)."""
    t = build_tables(program, damped=program.solver.method == "lm",
                     cholesky=program.solver.linear == "cholesky")
    return {a.name: a.values for a in t.arrays}


def plan_sizes(program) -> dict:
    """The emitted kernel's sizes (MAX_W, N_DATA, …) as the C++ tables define them."""
    return _sizes(program)


def _sizes(program) -> dict:
    """The emitted tables' sizes (MAX_ROWS, MAX_W, ...): the unit headers' CFG constants."""
    t = build_tables(program, damped=program.solver.method == "lm",
                     cholesky=program.solver.linear == "cholesky")
    return dict(t.constants)


def _assign(procs, sets, tag, li):
    """Independent steps on ``sets`` unit sets, longest first (one process per set that has
    a step)."""
    loads = [[] for _ in range(sets)]
    for p in sorted(procs, key=lambda p: -p.cycles):
        i = min(range(sets), key=lambda j: sum(q.cycles for q in loads[j]))
        loads[i].append(p)
    return tuple(Process(f"{tag}{li}_set{i}", f"set{i}",
                         tuple(lp for q in group for lp in q.loops))
                 for i, group in enumerate(loads) if any(q.loops for q in group))


def _sim_table(ops: OperatorTable):
    """The critical-path walker's per-kind view of ``ops`` (``cost.params.view``)."""
    return view(ops)


def tree_latencies(ops: OperatorTable) -> tuple[tuple[str, int], ...]:
    """The latencies the datapaths' kernels are printed with (their sums and products as the
    reduction trees ``cost.kernels.critical_path`` prices with the same table) and priced
    with."""
    from fgc_backends.cost.kernels import kernel_latencies

    return kernel_latencies(_sim_table(ops))
