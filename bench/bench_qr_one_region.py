"""Would one DATAFLOW region per QR step pay? A model, measured before building it (issue 33
item 1; docs/hls.md, "The Evaluate applies the next column's update; one region per step").

On paper A's on-chip window kernel (LIO N = 30, K = 3, batch at 5 / 15 / 25, float32) the
plan's QR steps (``units/qr.py``'s ``qr_unit_loops``: one region per reflection, what
``fgc_qr.h`` runs and the C simulation counts) are set against two models of the same step
with no drain between reflections, built from the same loops and the operator table:

- ``one region``: the Update units and the Evaluate free-running over the step's reflections.
  Each unit runs its loops of reflection j (the vector, or the next pivot column streamed with
  it; v_0 / tau; ``dot_axpy``) back to back, starting reflection j when its previous one ended
  and reflection j's vector is ready; the Evaluate takes column j + 1 when its unit starts
  reflection j, and its vector is ready after the Evaluate's passes, fold, square root and
  divide (``qr_finish`` folded into it, as one region would have it).
- ``loop nest``: a lower bound for one pipelined loop nest that hid each unit's vector read
  and ``dot_axpy``'s lag entirely: per reflection the larger of the busiest unit's n r words
  and the Evaluate's chain.

Run from the repository: ``python bench/bench_qr_one_region.py`` (a few seconds a design).
Model estimates at the operator table's latencies; nothing here is emitted.
"""

from __future__ import annotations

import dataclasses
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bench_papers as b  # noqa: E402

from fgc.app import streaming  # noqa: E402
from fgc_backends.hls import HlsConfig  # noqa: E402
from fgc_backends.hls.units import qr as qr_unit  # noqa: E402


def _local(j, u, units, k, cols):
    """Unit u's first column right of j, whether it is the next pivot, its other columns."""
    c0 = j + 1 + (u - (j + 1)) % units
    next_here = c0 == j + 1 and c0 < k
    lb = c0 // units + (1 if next_here else 0)
    return next_here, ((cols - 1 - u) // units - lb + 1 if c0 < cols else 0)


def _evaluate_chain(rows, j, n, ops):
    """The Evaluate on column j + 1: receive and dot, pivot term, fold, scale, update and
    squares, fold, then square root, v_0, tau (qr_finish's)."""
    la, lm = ops.add.latency, ops.mul.latency
    tree, tree1 = math.ceil(math.log2(la)), math.ceil(math.log2(la + 1))
    span = rows - max(j, 0)
    t = span - 1 + lm + la
    if n > 1:
        t += lm + la * tree1 + lm
    t += span - 1 + 2 * (lm + la) + la * tree
    return t + ops.sqrt.latency + la + lm + ops.div.latency


def one_region(pattern, units, ops) -> int:
    la, lm = ops.add.latency, ops.mul.latency
    tree = math.ceil(math.log2(la))
    rows, cols, k, act = qr_unit.active_rows(pattern)
    clock = [0] * units
    start = {}
    ready = {0: _evaluate_chain(rows, -1, 0, ops)}  # reflection j's vector, v_0, tau
    evaluate = ready[0]
    for j in range(k):
        n = act[j]
        for u in range(units):
            next_here, r = _local(j, u, units, k, cols)
            t = start[u, j] = max(clock[u], ready[j])
            t += 1 + ((rows - j) + 1 if next_here else max(n - 1, 0))
            t = max(t, ready[j] + n + 2) + 3  # the vector as it streams; v_0, tau
            if r > 0 and n > 1:
                t += n * r + (n - 1 + (lm + la) + (la * tree + lm)) - 1 + lm + la
            elif r > 0:
                t += r
            clock[u] = t
        if j + 1 < k:
            evaluate = ready[j + 1] = max(evaluate, start[(j + 1) % units, j]) + \
                _evaluate_chain(rows, j, n, ops)
    return max(max(clock), evaluate)


def loop_nest_bound(pattern, units, ops) -> int:
    rows, cols, k, act = qr_unit.active_rows(pattern)
    total = 0
    for j in range(k):
        work = max(act[j] * _local(j, u, units, k, cols)[1] for u in range(units))
        chain = _evaluate_chain(rows, j, act[j], ops) + act[j] if j + 1 < k else 0
        total += max(work, chain)
    return total


def main() -> None:
    cfg = b.Config()
    n, kk = cfg.lio_n, 3
    batch = tuple(x for x in cfg.stream_batch if x < n)
    graph = b.lio.build(N=n)
    base = b._stream_solver(cfg)
    captured = []
    plan_loops = qr_unit.qr_unit_loops

    def spy(pattern, frontal, units, ops, partials=None, name="s", qr_rows=1):
        captured.append((np.array(pattern, dtype=bool), frontal, units, ops))
        return plan_loops(pattern, frontal, units, ops, partials, name, qr_rows)

    qr_unit.qr_unit_loops = spy  # the pricer's build calls it through the module
    try:
        for units, sets, alloc in ((2, 2, (("add", 1), ("mul", 1), ("div", 1))),
                                   (4, None, None)):
            solver = dataclasses.replace(base, units=units)
            prog = streaming.compile_stream(graph, solver, incremental=kk, batch_every=batch)
            captured.clear()
            streaming.WindowPricer(streaming.stream_program(graph, prog), config=HlsConfig(
                scalar="float", unit_sets=sets, allocation=alloc))
            now = one = nest = 0
            for pattern, frontal, nu, ops in captured:
                regions = sum(lp.cycles for lp in plan_loops(pattern, frontal, nu, ops))
                o, e = one_region(pattern, nu, ops), loop_nest_bound(pattern, nu, ops)
                now, one, nest = now + regions, one + o, nest + e
                print(f"  n_u {nu} step {pattern.shape[0]} x {pattern.shape[1] + 1}: regions "
                      f"{regions:,}, one region {o:,}, loop nest >= {e:,}")
            print(f"n_u {units}: the window kernel's QR steps {now:,} cycles as regions, "
                  f"{one:,} as one region ({one / now - 1:+.1%}), a loop nest >= {nest:,} "
                  f"({nest / now - 1:+.1%})")
    finally:
        qr_unit.qr_unit_loops = plan_loops


if __name__ == "__main__":
    main()
