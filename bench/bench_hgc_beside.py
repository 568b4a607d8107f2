"""What the HGC beside the elimination would save (issue 33, Cholesky): a design estimate from
the emitted plan's own loops, not an emitted design (docs/hls.md, "The HGC beside the
elimination: the design and its estimate").

Today ``linearize_all`` runs every block type's linearize_<b> region (datapath + HGC) before
``cholesky_eliminate_all``, so the elimination's first step waits for the whole HGC. In the
design, one DATAFLOW region holds two processes: the producer (G zeroed, then the block types'
linearize_<b> regions one after another, the one with the longest region last, each block
type's instances in the order the elimination reaches their steps, each Gram written into its
block type's stream) and the consumer (the elimination, unchanged, its assembler taking a
step's Grams from the streams). This script replays that schedule on the plan's loops:

- producer: instance k of block type b (in step order) has its rows at the region's start
  + k II_jac + depth_jac (the datapath's instance loop), its entries start 2 cycles later and
  no sooner than the previous instance's entries + STEPS II (reduce_<b>'s loop), and its Gram
  is complete (its last entry written) (STEPS - 1) II + depth after its entries start; a
  region ends no sooner than the plan prices it;
- consumer: the ``assemble`` phase (the first step's Grams) starts when the first step's
  factors' Grams are complete; region ``cholesky_level<t>`` (whose assembler puts step t + 1's
  Grams into the other lane) starts when region t - 1 ended and step t + 1's Grams are
  complete (conservative: its source loop could start earlier); each phase takes what the plan
  prices it;
- the linearisation + elimination span is the later of the two ends; the rest of the
  iteration (back-substitution, cost, LM control) is the plan's.

    python bench/bench_hgc_beside.py [--quick]

Model estimates at 143 MHz, float32 (no vendor tool here).
"""

from __future__ import annotations

import sys

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig
from fgc_backends.hls.emitter import accel_plan
from fgc_backends.hls.plan import plan_cost
from fgc_backends.hls.plan.loops import _tables
from fgc_backends.hls.units.cholesky import gram_entries

CASES = [("lio", 30, c) for c in (10, 15, 20)] + [("imu_window", 50, c) for c in (5, 20, 80)]


def beside(program, plan, cost) -> dict:
    """The estimate for one design: cycles before / after, the span it replaces, the first
    step's wait, the producer's end, the consumer's waits after the first step and the Gram
    streams' buffered words (every block type's structurally non-zero Gram entries but the
    last one's)."""
    tables = _tables(program)
    cycles = dict(cost.phase_cycles)
    phases = {ph.name: ph for ph in plan.phases}
    steps = len(program.schedule.steps)
    order = [tables["LEVEL_STEPS"][i] for i in range(steps)]
    pos = {}  # factor -> the position of its step in the elimination
    fb = tables["STEP_FACTOR_BEGIN"]
    for t, s in enumerate(order):
        for e in range(fb[s], fb[s + 1]):
            pos[tables["STEP_FACTORS"][e]] = t
    blocks = [i for i in range(len(program.blocks)) if f"hgc_level{i}" in cycles]
    blocks.sort(key=lambda b: cycles[f"hgc_level{b}"])  # the longest region last, stable
    clock = cycles["hgc"]  # G zeroed first
    ready, buffered = {}, 0
    for b in blocks:
        region = phases[f"hgc_level{b}"]
        procs = {p.name: p for p in region.processes}
        facs = sorted((i for i, f in enumerate(program.factors) if f.block == b),
                      key=lambda f: pos[f])
        if b != blocks[-1]:
            buffered += len(facs) * len(gram_entries(program.blocks[b]))
        if not facs:
            clock += cycles[f"hgc_level{b}"]
            continue
        jac = procs[f"factor_{b}_jacobian"].loops[0]
        entries = procs[f"reduce_{b}"].loops[1]
        per = entries.trip // len(facs)  # STEPS
        prev = None
        for k, f in enumerate(facs):
            start = clock + k * jac.ii + jac.depth + 2
            if prev is not None:
                start = max(start, prev + per * entries.ii)
            ready[f] = start + (per - 1) * entries.ii + entries.depth
            prev = start
        clock = max(clock + cycles[f"hgc_level{b}"], max(ready[f] for f in facs))
    produced = clock

    def step_ready(s: int) -> int:
        return max((ready.get(tables["STEP_FACTORS"][e], 0) for e in range(fb[s], fb[s + 1])),
                   default=0)

    first = step_ready(order[0])
    c = first + cycles["assemble"]
    waits = 0
    for t in range(steps):
        if t + 1 < steps:
            r = step_ready(order[t + 1])
            waits += max(0, r - c)
            c = max(c, r)
        c += cycles[f"cholesky_level{t}"]
    span = (cycles["hgc"] + sum(cycles[f"hgc_level{b}"] for b in blocks) + cycles["assemble"]
            + sum(cycles[f"cholesky_level{t}"] for t in range(steps)))
    after_span = max(c, produced)
    return {"before": cost.cycles, "after": cost.cycles - span + after_span, "span": span,
            "after_span": after_span, "first": first, "produced": produced, "waits": waits,
            "buffered": buffered, "clock": cost.clock_mhz}


def main() -> None:
    cases = CASES[1:2] + CASES[4:5] if "--quick" in sys.argv else CASES
    for ex, n, cpe in cases:
        program = compile_graph(example(ex).build(N=n), SolverConfig(
            method="lm", linear="cholesky", cpe=cpe, precision="float32"), name=f"{ex}{cpe}")
        plan = accel_plan(program, HlsConfig(scalar="float"))
        cost = plan_cost(plan)
        r = beside(program, plan, cost)
        ms = [x / r["clock"] / 1e3 for x in (r["before"], r["after"])]
        print(f"{ex} N={n} #CPE={cpe}: {r['before']:,} -> {r['after']:,} cycles/iteration "
              f"({ms[0]:.3f} -> {ms[1]:.3f} ms), DSP plan {cost.dsp}; linearise+eliminate "
              f"{r['span']:,} -> {r['after_span']:,} (first step's Grams at {r['first']:,}, "
              f"producer done at {r['produced']:,}, consumer waits after it {r['waits']:,}); "
              f"Gram words buffered in the streams {r['buffered']:,}", flush=True)


if __name__ == "__main__":
    main()
