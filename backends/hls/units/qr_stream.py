"""The streaming Householder QR unit (``include/fgc_qr_stream.h``, ``--qr-unit stream``): per unit
set n_u reflection stages in a systolic chain, the matrix streamed through them column by column.

Stage t of a pass takes reflection j = j0 + t: its Evaluate receives column j (the squared norm
as it arrives) and computes alpha, v_0 and tau; its dot process takes each later column's dot
product with the vector as the column arrives (column j + 1's while the Evaluate still
computes), its fold adds the pivot's term and scales by tau, and its tail updates the column and
streams it (rows j + 1 ...) to stage t + 1. Stage t + 1 evaluates reflection j + 1 as soon as the
first column leaves stage t: the Evaluate of reflection j + 1 overlaps the Update of reflection
j (paper A's look-ahead), no region drains between reflections. A step of k reflections is
ceil(k / n_u) passes, one DATAFLOW region each (source, the stages, sink, collector).

The loops here are the header's FGC_CYCLES / FGC_WAIT counters, one for one; the region
arithmetic is :func:`fgc_backends.hls.plan.loops._region_cycles` (docs/hls.md, "The streaming
QR unit").
"""

from __future__ import annotations

import math

from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.plan.loops import _region_cycles
from fgc_backends.hls.plan.model import Loop


def _log2(n: int) -> int:
    return math.ceil(math.log2(n)) if n > 1 else 0


def evaluate_depth(ops: OperatorTable, partials: int) -> int:
    """The head's evaluate (fgc_qr_stream.h ``qrs_head``): the norm's partial sums folded,
    the square root, v_0 = x_0 - alpha beside alpha x_0, the subtract and tau's divide."""
    la, lm = ops.add.latency, ops.mul.latency
    return la * _log2(partials) + ops.sqrt.latency + max(la, lm) + la + ops.div.latency


def fold_depth(ops: OperatorTable, partials: int) -> int:
    """A column's tau v.x (``qrs_dot``'s fold): the pivot's term v_0 x_j, the fold of the P
    partials and that term, the scale by tau."""
    return ops.mul.latency + ops.add.latency * _log2(partials + 1) + ops.mul.latency


def qr_stream_loops(rows: int, cols: int, frontal: int, stages: int, ops: OperatorTable,
                    partials: int | None = None, local_cols: int | None = None,
                    name: str = "s") -> list[Loop]:
    """The loops of ``qrs_step`` on one step of ``rows`` stacked rows and ``cols`` = w + 1
    columns: one ``Loop`` (trip 1) per pass region, whose depth is the region's cycles, the
    copy of what is left back into the banks after each pass but the last, and the pivot check.
    ``local_cols``: the header's CFG::LOCAL_COLS, columns per bank of the work memory
    (default: ``cols`` over ``stages`` banks)."""
    la, lm = ops.add.latency, ops.mul.latency
    p = partials if partials is not None else la
    local = local_cols if local_cols is not None else -(-cols // stages)
    k = min(rows, cols)
    ev_depth, fd = evaluate_depth(ops, p), fold_depth(ops, p)
    out = []
    passes = -(-k // stages) if k > 0 else 0
    for q in range(passes):
        j0, j1 = q * stages, min(k, (q + 1) * stages)
        procs: list[list[Loop]] = []
        waits: list[tuple[int, int, int, str]] = []
        m0 = rows - j0
        procs.append([Loop(f"src@{c}", m0, 1, 2) for c in range(j0, cols)])
        up = 0  # the process whose streams stage t reads
        for t in range(j1 - j0):
            j = j0 + t
            m = rows - j
            ev = len(procs)  # the Evaluate: column j, then alpha, v_0, tau
            stem = "src" if t == 0 else "axpy"  # what the upstream's loop of a column is called
            waits.append((ev, 0, up, f"{stem}@{j}"))
            procs.append([Loop(f"receive@{j}", m, 1, lm + la), Loop("evaluate", 1, 1, ev_depth)])
            # the dot process: the vector as the Evaluate receives it, then per later column
            # v.x as it arrives and the fold with the pivot's term (after the Evaluate's end)
            dot = [Loop(f"vector@{j}", m - 1, 1, 1)]
            waits.append((ev + 1, 0, ev, "receive"))
            for c in range(j + 1, cols):
                waits.append((ev + 1, len(dot), up, f"{stem}@{c}"))
                dot += [Loop(f"dot@{c}", m, 1, lm + la), Loop(f"send@{c}", p + 1, 1, 1)]
            procs.append(dot)
            # the fold: per column the partials gathered, the pivot's term, the tree, the scale
            # (after the Evaluate)
            fold = []
            for c in range(j + 1, cols):
                waits.append((ev + 2, len(fold), ev + 1, f"send@{c}"))
                fold.append(Loop(f"gather@{c}", p + 1, 1, 1))
                waits.append((ev + 2, len(fold), ev, "evaluate"))
                fold.append(Loop(f"fold@{c}", 1, 1, fd))
            procs.append(fold)
            tail = [Loop("vector", m, 1, 1)]
            waits.append((ev + 3, 0, ev, "evaluate"))
            for c in range(j + 1, cols):
                # tau v.x gates the column's update: the axpy starts after it arrives
                waits.append((ev + 3, len(tail), ev + 2, f"fold@{c}"))
                tail += [Loop(f"scale@{c}", 1, 1, 1), Loop(f"axpy@{c}", m, 1, lm + la)]
            up = ev + 3
            procs.append(tail)
        if j1 < k:  # the sink: what is left, into the other banks
            waits.append((len(procs), 0, up, f"axpy@{j1}"))
            waits.append((len(procs), 1, up, f"axpy@{cols - 1}"))
            procs.append([Loop("sink_first", rows - j1, 1, 2),
                          Loop("sink", (cols - j1 - 1) * (rows - j1), 1, 2)])
        # the collector: per stage its row of R out (cond / update) and the running scale
        coll = []
        for t in range(j1 - j0):
            j = j0 + t
            first = 0 if j < frontal else frontal
            waits.append((len(procs), len(coll), 4 + 4 * t,
                          f"axpy@{cols - 1}" if j + 1 < cols else "vector"))
            coll.append(Loop(f"row@{j}", cols - first, 1, 2))
        procs.append(coll)
        region = _region_cycles(procs, tuple(waits))
        if q == 0:
            # the source's first word (depth 2) apart: what a unit set beside this one pays as
            # this step's fill (fgc_cycles.h's branch fill: its first loop's depth), the region's
            # cycles unchanged
            out += [Loop(f"{name}_pass0_first", 1, 1, 2), Loop(f"{name}_pass0", 1, 1, region - 2)]
        else:
            out.append(Loop(f"{name}_pass{q}", 1, 1, region))
        if j1 < k:
            out.append(Loop(f"{name}_copy{q}", (rows - j1) * local, 1, 2))
    out.append(Loop(f"{name}_pivot_check", frontal, 1, 2))
    return out


def stage_units(partials: int) -> tuple[tuple[str, str, tuple[tuple[str, int], ...]], ...]:
    """One stage's processes and their operators, each operation its own operator instance
    (none shared; every pipelined loop at II 1 holds its own): ``qrs_eval``'s receive loop
    (multiply-add) and evaluate (the fold's P - 1 adds, the square root, v_0's subtract, alpha
    x_0, the denominator's subtract, the divide); ``qrs_dot``'s loop (multiply-add) with
    ``qrs_fold`` (v_0 x_j, the P adds of the P + 1 leaves' tree, the scale by tau); ``qrs_tail``'s
    loop (multiply-add)."""
    p = partials
    return (("evaluate", "a stage's Householder vector (norm, square root, v_0, tau)",
             (("add", 1 + (p - 1) + 2), ("mul", 2), ("div", 1), ("sqrt", 1))),
            ("dot", "a stage's dot products and their fold and scale",
             (("add", 1 + p), ("mul", 3))),
            ("tail", "a stage's column update", (("add", 1), ("mul", 1))))


def build_sets(ctx, sets: int, patterns: dict) -> dict:
    """The streaming unit sets' operators, streams and memories; per step its process (one
    loop per pass region, the copies, the pivot check), for :func:`units.qr.build`."""
    from fgc_backends.hls.plan.model import Channel, Memory, Process, Unit
    opts, ops, sched = ctx.opts, ctx.les, ctx.program.schedule
    n_u, sizes = opts.units, ctx.sizes
    max_rows, max_cols = sizes["MAX_ROWS"], sizes["MAX_W"] + 1
    local = -(-max_cols // n_u)
    p = ops.add.latency  # CFG::PARTIALS
    bits = ops.word_bits
    for s in range(sets):
        for name, role, operators in stage_units(p):
            ctx.units.append(Unit(f"qr{s}_{name}", role, n_u, operators))
        ch = ctx.channels
        for t in range(n_u + 1):  # qrs_pass's first[] / rest[]: source -> stage 0 -> ... -> sink
            src = f"qr{s}_tail{t - 1}" if t else f"qr{s}_source"
            ch += [Channel(f"qr{s}_first{t}", "stream", 2 * max_rows, bits, src,
                           f"qr{s}_evaluate{t}" if t < n_u else f"qr{s}_sink"),
                   Channel(f"qr{s}_rest{t}", "stream", 3 * max_rows, bits, src,
                           f"qr{s}_dot{t}" if t < n_u else f"qr{s}_sink")]
        for t in range(n_u):
            ch += [Channel(f"qr{s}_vd{t}", "stream", max_rows, bits, f"qr{s}_evaluate{t}",
                           f"qr{s}_dot{t}"),
                   Channel(f"qr{s}_vt{t}", "stream", max_rows, bits, f"qr{s}_evaluate{t}",
                           f"qr{s}_tail{t}"),
                   Channel(f"qr{s}_e{t}", "stream", 2, bits, f"qr{s}_evaluate{t}",
                           f"qr{s}_fold{t}"),
                   Channel(f"qr{s}_p{t}", "stream", 2 * (p + 1), bits, f"qr{s}_dot{t}",
                           f"qr{s}_fold{t}"),
                   Channel(f"qr{s}_x{t}", "stream", 2 * max_rows, bits, f"qr{s}_dot{t}",
                           f"qr{s}_tail{t}"),
                   Channel(f"qr{s}_s{t}", "stream", 2, bits, f"qr{s}_fold{t}", f"qr{s}_tail{t}"),
                   Channel(f"qr{s}_r{t}", "stream", 2, bits, f"qr{s}_evaluate{t}",
                           f"qr{s}_collect"),
                   Channel(f"qr{s}_row{t}", "stream", max_cols, bits, f"qr{s}_tail{t}",
                           f"qr{s}_collect")]
        # qrs_step's `next` banks (the sink's), each head's and tail's vector
        ctx.memories.append(Memory(f"qr{s}_next", n_u * max_rows * local, bits, n_u))
        for t in range(n_u):
            ctx.memories.append(Memory(f"qr{s}_dot{t}_v", max_rows, bits, 1))
            ctx.memories.append(Memory(f"qr{s}_tail{t}_v", max_rows, bits, 1))
    out = {}
    for st in sched.steps:
        pattern = patterns[st.index]
        loops = qr_stream_loops(len(pattern), pattern.shape[1] + 1, st.frontal_dim, n_u, ops,
                                partials=p, local_cols=local, name=f"s{st.index}")
        out[st.index] = Process(f"qr_step{st.index}", "qr_stage", tuple(loops))
    return out
