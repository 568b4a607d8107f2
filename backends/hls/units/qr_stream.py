"""The streaming Householder QR unit (``include/fgc_qr_stream.h``, ``--qr-unit stream``): per unit
set n_u reflection stages in a systolic chain, the matrix streamed through them column by column.

Stage t of a pass takes reflection j = j0 + t: its head receives column j (the squared norm as
it arrives), evaluates the Householder vector (square root, v_0, tau), then takes each later
column's dot product with the vector as the column arrives and hands tau v.x to its tail, which
updates the column and streams it (rows j + 1 ...) to stage t + 1 while the head already takes
the next column. Stage t + 1 evaluates reflection j + 1 as soon as the first column leaves
stage t: the Evaluate of reflection j + 1 overlaps the Update of reflection j (paper A's
look-ahead), no region drains between reflections. A step of k reflections is ceil(k / n_u)
passes, one DATAFLOW region each (source, the stages, sink, collector).

The loops here are the header's FGC_CYCLES / FGC_WAIT counters, one for one; the region
arithmetic is :func:`fgc_backends.hls.plan.loops._region_cycles`.
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
    """A column's dot product folded and scaled by tau (``qrs_head``'s fold)."""
    return ops.add.latency * _log2(partials) + ops.mul.latency


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
    ev, fd = evaluate_depth(ops, p), fold_depth(ops, p)
    out = []
    passes = -(-k // stages) if k > 0 else 0
    for q in range(passes):
        j0, j1 = q * stages, min(k, (q + 1) * stages)
        procs: list[list[Loop]] = []
        waits: list[tuple[int, int, int, str]] = []
        m0 = rows - j0
        src = [Loop(f"src@{c}", m0, 1, 2) for c in range(j0, cols)]
        procs.append(src)
        up = 0  # the process whose stream stage t reads
        for t in range(j1 - j0):
            j = j0 + t
            m = rows - j
            head = [Loop(f"receive@{j}", m, 1, lm + la), Loop("evaluate", 1, 1, ev)]
            waits.append((len(procs), 0, up, f"@{j}"))
            for c in range(j + 1, cols):
                waits.append((len(procs), len(head), up, f"@{c}"))
                head += [Loop(f"dot@{c}", m, 1, lm + la), Loop(f"fold@{c}", 1, 1, fd)]
            hi = len(procs)
            procs.append(head)
            tail = [Loop("vector", m, 1, 1)]
            waits.append((len(procs), 0, hi, "evaluate"))
            for c in range(j + 1, cols):
                waits.append((len(procs), len(tail), hi, f"fold@{c}"))
                tail.append(Loop(f"axpy@{c}", m, 1, lm + la))
            up = len(procs)
            procs.append(tail)
        last_tail = up
        if j1 < k:  # the sink: what is left, into the other banks
            waits.append((len(procs), 0, last_tail, f"@{cols - 1}"))
            procs.append([Loop("sink", (cols - j1) * (rows - j1), 1, 2)])
        # the collector: per stage its row of R out (cond / update) and the running scale
        coll = []
        for t in range(j1 - j0):
            j = j0 + t
            first = 0 if j < frontal else frontal
            tail_of = 1 + 2 * t + 1
            waits.append((len(procs), len(coll), tail_of,
                          f"@{cols - 1}" if j + 1 < cols else "vector"))
            coll.append(Loop(f"row@{j}", cols - first, 1, 2))
        procs.append(coll)
        out.append(Loop(f"{name}_pass{q}", 1, 1, _region_cycles(procs, tuple(waits))))
        if j1 < k:
            out.append(Loop(f"{name}_copy{q}", (rows - j1) * local, 1, 2))
    out.append(Loop(f"{name}_pivot_check", frontal, 1, 2))
    return out
