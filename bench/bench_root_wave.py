"""What-if (issue 33 item 2): paper A's window root step in a wavefront behind its children,
priced from the emitted design's own plan loops (model estimates; NOT an emitted design).

Paper A's incremental update (LIO N = 30 on KITTI, K = 3, batch at 5 / 15 / 25, one Gauss-Newton
step an update, float32 QR, n_u 4, two unit sets, ALLOCATION 2 / 3 / 1) runs the window's QR level
by level: level 0 = the two leaves (steps 0 and 1) side by side on unit sets 0 and 1, every
commit of level 0, then the root's stack (its own factor rows and both children's passed rows
from NF), then level 1 = the root alone. A leaf's passed row i is row f + i of its R, final when
its reflection f + i ends; the root's region j (its reflection j, and the Evaluate's column
j + 1) reads only the passed rows i <= j + 1 (row i is zero left of the root's column i: upper
triangular on the separator, whose columns are the root's first columns in order, checked here).
So the root can run region by region behind the children:

- variant A, a third unit set for the root: its own rows stacked before the region beside the
  leaves', each child's passed rows streamed from that child's collector into the root set,
  read (one loop of s + 1 words, II 1, depth 2, both children's streams at once) before the
  root region that first needs them, each read no earlier than its depth after the end of the
  child's region that wrote the row; every commit after the region.
- variant B, no third set: the root on the unit set of the child whose step ends sooner (set 1,
  step 1: 39 rows against step 0's 54), in that set's process after its own step: the child's
  commit, the root's stack (its own factor rows, that child's passed rows from NF), then the
  root's regions, each after the read of the other child's passed row it first needs (streamed
  from set 0's collector, as in A). After the region: set 0's commit and the root's.

Every loop is the plan's (``qr_unit_loops`` on the rows non-zero in that update, exactly as
``WindowUpdateModel.qr_cycles``; ``stack_loops``, ``commit_loops`` of the window plan); a
process's loops follow one another, a read waits as ``FGC_WAIT`` / ``_region_cycles`` price a
stream read, the region is its slowest process plus the other's fill (``phase_cycles``). Only
the incremental updates are repriced (the sweep and batch steps are left at today's price).

    python bench/bench_root_wave.py [--keyframes 5,14,25]
"""
from __future__ import annotations

import argparse
import dataclasses
import itertools
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_papers as b  # noqa: E402

from fgc.app import streaming  # noqa: E402
from fgc.ir.datafile import problem_data  # noqa: E402
from fgc_backends.cost.structure import stacked_pattern  # noqa: E402
from fgc_backends.hls import HlsConfig  # noqa: E402
from fgc_backends.hls.plan.cost import phase_cycles, plan_cost  # noqa: E402
from fgc_backends.hls.plan.loops import _tables, kernel_loop, kernel_timing  # noqa: E402
from fgc_backends.hls.plan.stream import qr_solve_phases  # noqa: E402
from fgc_backends.hls.units.qr import commit_loops, stack_loops  # noqa: E402

ALLOCATION = (("add", 2), ("mul", 3), ("div", 1))


def _loops_cycles(loops) -> int:
    return sum(lp.cycles for lp in loops)


def wave_price(m, keyframe: int) -> dict:
    """The QR group of keyframe ``keyframe``'s incremental solve (stack + regions + commit) today
    and in variants A and B (see the module's docstring)."""
    t, plan = m.layout.template, m.plan
    sched = t.schedule
    levels = sched.levels
    if len(levels) != 2 or len(levels[1]) != 1 or len(levels[0]) != 2:
        raise SystemExit(f"not a two-leaf window: levels {levels}")
    root = sched.steps[levels[1][0]]
    a, bstep = levels[0]  # set 0's step, set 1's step
    if tuple(root.children) != (a, bstep):
        raise SystemExit(f"the root's children {root.children} are not level 0's {levels[0]}")
    tables = _tables(t)
    # the separator order: child passed row i is zero left of the root's column i
    pat = stacked_pattern(t, root, False)
    own = root.rows - sum(sched.steps[c].new_factor_rows for c in root.children)
    for ci, c in enumerate(root.children):
        lo = own + ci * sched.steps[c].new_factor_rows
        for i in range(sched.steps[c].new_factor_rows):
            if pat[lo + i, :i].any():
                raise SystemExit(f"child {c}'s passed row {i} is not zero left of column {i}")
    zero, unit = m.zero_factors(keyframe), m.layout.unit_factors(keyframe)
    phases = qr_solve_phases(t, zero, True, m.sets, m.les, unit=unit)
    regions = {}
    for ph in phases:
        for pr in ph.processes:
            regions[int(pr.loops[0].name.split("_")[0][1:])] = list(pr.loops)
    today = {ph.name: phase_cycles(ph) for ph in plan.phases}
    qr_today = sum(phase_cycles(ph) for ph in phases)
    stack_today = today["qr_stack_level0"] + today["qr_stack_level1"]
    commit_today = today["qr_commit_level0"] + today["qr_commit_level1"]
    timing = kernel_timing(m.les)
    max_w = max(tables["STEP_W"])
    stack_root = stack_loops(tables, root.index, t.solver.units, max_w,
                             t.solver.method == "lm", timing)
    # stack_loops' order: factor rows, then one child_rows loop per child (STEP_CHILDREN order)
    n_fac = len(stack_root) - len(root.children) - (1 if t.solver.method == "lm" else 0)
    own_loops = stack_root[:n_fac] + stack_root[n_fac + len(root.children):]
    child_loops = stack_root[n_fac:n_fac + len(root.children)]
    commit = {s: commit_loops(tables, s, timing, False) for s in (a, bstep, root.index)}
    f = {c: sched.steps[c].frontal_dim for c in root.children}
    nf = {c: sched.steps[c].new_factor_rows for c in root.children}
    sc = sched.steps[a].separator_dims and sum(sched.steps[a].separator_dims)
    entry = kernel_loop("entry", sc + 1, "move", timing)  # a passed row, s + 1 words

    def ends(loops):  # each loop's end on the process's clock (loop 0 = region -1)
        return list(itertools.accumulate(lp.cycles for lp in loops))

    def ready(c, i):  # child c's passed row i: written in its region for reflection f + i
        return ends(regions[c])[f[c] + 1 + i]

    def root_after(clock: int, children) -> int:
        rl = regions[root.index]
        for idx, j in enumerate(range(-1, len(rl) - 2)):
            need = j + 1
            if need >= 0 and any(need < nf[c] for c in children):
                at = max(ready(c, need) for c in children if need < nf[c])
                clock = max(clock + entry.cycles, at + entry.depth)
            clock += rl[idx].cycles
        return clock + rl[-1].cycles  # the pivot check

    out = {"today": (stack_today, qr_today, commit_today)}
    # A: a third set; the root's own rows stacked before the region, every commit after it
    root_a = root_after(0, root.children)
    procs = [(ends(regions[a])[-1], regions[a][0].depth),
             (ends(regions[bstep])[-1], regions[bstep][0].depth),
             (root_a, entry.depth)]
    slow = max(range(3), key=lambda i: procs[i][0])
    region_a = procs[slow][0] + sum(p[1] for i, p in enumerate(procs) if i != slow)
    out["A"] = (today["qr_stack_level0"] + _loops_cycles(own_loops), region_a, commit_today)
    # B: the root on set 1 after its step, that step's commit and the root's stack there
    clock = ends(regions[bstep])[-1] + _loops_cycles(commit[bstep]) + _loops_cycles(own_loops) \
        + _loops_cycles(child_loops[1:])
    root_b = root_after(clock, (a,))
    procs = [(ends(regions[a])[-1], regions[a][0].depth), (root_b, regions[bstep][0].depth)]
    slow = max(range(2), key=lambda i: procs[i][0])
    region_b = procs[slow][0] + sum(p[1] for i, p in enumerate(procs) if i != slow)
    out["B"] = (today["qr_stack_level0"], region_b,
                _loops_cycles(commit[a]) + _loops_cycles(commit[root.index]))
    out["ready"] = (ends(regions[bstep])[-1], ready(a, 0), ends(regions[a])[-1], root_b)
    return out


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--keyframes", default="5,14,25", help="keyframes whose terms are printed")
    args = ap.parse_args(argv)
    shown = {int(k) for k in args.keyframes.split(",") if k.strip()}
    cfg = b.Config()
    graph = b.lio.build(N=cfg.lio_n)
    solver = dataclasses.replace(b._stream_solver(cfg), units=4)
    program = streaming.compile_stream(graph, solver, incremental=3,
                                       batch_every=tuple(cfg.stream_batch))
    sp = streaming.stream_program(graph, program)
    updates = []
    streaming.run_stream(sp, problem_data(graph, program), progress=updates.append)
    pricer = streaming.WindowPricer(sp, config=HlsConfig(scalar="float", unit_sets=2,
                                                         allocation=ALLOCATION))
    m = pricer.model
    res = m.resources()
    cost = plan_cost(m.design_plan())
    dsp = dict(cost.dsp_by_unit)
    third = dsp.get("qr0_evaluate", 0) + dsp.get("qr0_update", 0)
    print(f"today: n_u 4, 2 unit sets, ALLOCATION 2/3/1: {res['dsp']:,} DSP, "
          f"{res['bram36']:g} BRAM36 (plan; model estimates)")
    print(f"A (third set): + {third} DSP (qr2_evaluate {dsp.get('qr0_evaluate', 0)} + qr2_update "
          f"{dsp.get('qr0_update', 0)}) = {res['dsp'] + third:,}; B (root on set 1): + 0 DSP")
    lat = {"today": [], "A": [], "B": []}
    for u in updates:
        price = pricer.price(u)
        total = price.cycles
        lat["today"].append(total)
        if price.mode != "incremental":
            lat["A"].append(total)
            lat["B"].append(total)
            continue
        w = wave_price(m, u.keyframe)
        names = {"qr_stack", "qr", "qr_commit"}
        old = sum(t.cycles for t in price.terms if t.name in names)
        if old != sum(w["today"]):
            raise SystemExit(f"keyframe {u.keyframe}: the update's QR terms {old} are not the "
                             f"plan's {w['today']}")
        over = [t for t in price.terms if t.name == "overlap"]
        kept = sum(t.cycles for t in price.terms if t.name == "kept_reexpress")
        fj = sum(t.cycles for t in price.terms if t.name == "factor_jacobian")
        for v in ("A", "B"):
            # the pending re-expression runs beside the window's solve (the overlap term: the
            # shorter of the two hidden); it stays hidden whole while the solve is longer
            if over and not (-over[0].cycles == kept and fj + sum(w[v]) >= kept):
                raise SystemExit(f"keyframe {u.keyframe}: the overlap term would change")
            lat[v].append(total - old + sum(w[v]))
        if u.keyframe in shown:
            print(f"keyframe {u.keyframe}: today {total:,} cycles (stack {w['today'][0]:,}, "
                  f"qr {w['today'][1]:,}, commit {w['today'][2]:,})")
            for v in ("A", "B"):
                print(f"   {v}: {lat[v][-1]:,} cycles ({lat[v][-1] - total:+,}): stack "
                      f"{w[v][0]:,}, region {w[v][1]:,}, commit {w[v][2]:,}")
            r = w["ready"]
            print(f"   (B: set 1 free for the root at {r[0]:,} + its commit and stack; step 0's "
                  f"passed row 0 at {r[1]:,}; step 0 ends {r[2]:,}, the root {r[3]:,})")
    clock = m.clock_mhz
    for v in ("today", "A", "B"):
        x = np.array(lat[v]) / (clock * 1e3)
        inc = [c for c, u in zip(lat[v], updates, strict=True) if u.mode == "incremental"]
        print(f"{v:5s}: per update median {np.median(x):.3f} ms, p99 {np.percentile(x, 99):.3f} "
              f"ms; incremental median {int(np.median(inc)):,} cycles")


if __name__ == "__main__":
    main()
