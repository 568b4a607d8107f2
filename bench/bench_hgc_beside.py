"""What the HGC beside the elimination would save (issue 33, Cholesky): a design estimate from
the emitted plan's own loops, not an emitted design (docs/hls.md, "The HGC beside the
elimination: designed, estimated, not yet emitted").

Today ``linearize_all`` runs every block type's linearize_<b> region (datapath + HGC) before
``cholesky_eliminate_all``, so the elimination's first step waits for the whole HGC. In the
design, G is zeroed and the block types with the shorter regions run first as today (their
Grams into GRAM); then one DATAFLOW region holds the producer, the block type with the longest
region (its instances in the order the elimination reaches their steps, each Gram into one
stream), beside the consumer, the elimination, whose every cholesky_overlap pass gains a third
process, the Gram source: it copies the next-but-one step's streamed Grams into a stage lane
(two lanes by the pass's parity, as NF's) and keeps them for LM's retries. This script replays
that schedule on the plan's loops:

- producer: instance k of the streamed block type (in step order) has its rows at the
  region's start + k II_jac + depth_jac (the datapath's instance loop), its entries start 2
  cycles later and no sooner than the previous instance's + STEPS II (reduce_<b>'s loop), and
  its Gram is complete (STEPS - 1) II + depth after its entries start;
- consumer: the ``assemble`` phase (the first step's Grams) starts when the first step's
  streamed Grams are complete; region ``cholesky_level<t>`` (whose assembler puts step t + 1's
  Grams into the other lane) starts when region t - 1 ended and step t + 1's Grams are
  complete (conservative: its source loop could start earlier) and takes what the plan prices
  it, plus the Gram source's fill (a move's depth) where the source copies a Gram, or the
  source's cycles (a stream word every II of reduce_<b>) if they are the longer;
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

CASES = [("lio", 30, c) for c in (10, 15, 20)] + [("imu_window", 50, c) for c in (5, 20, 80)]


def beside(program, plan, cost) -> dict:
    """The estimate for one design: cycles before / after, the span it replaces, when the
    first step's streamed Grams are complete, the producer's end, the consumer's waits after
    the first step, the streamed block type and the largest stage lane (words)."""
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
    big = max(blocks, key=lambda b: cycles[f"hgc_level{b}"])
    # G zeroed and the other block types' regions first, as today
    clock = cycles["hgc"] + sum(cycles[f"hgc_level{b}"] for b in blocks if b != big)
    procs = {p.name: p for p in phases[f"hgc_level{big}"].processes}
    facs = sorted((i for i, f in enumerate(program.factors) if f.block == big),
                  key=lambda f: pos[f])
    jac = procs[f"factor_{big}_jacobian"].loops[0]
    entries = procs[f"reduce_{big}"].loops[1]
    per = entries.trip // len(facs)  # STEPS
    ready, prev = {}, None
    for k, f in enumerate(facs):
        start = clock + k * jac.ii + jac.depth + 2
        if prev is not None:
            start = max(start, prev + per * entries.ii)
        ready[f] = start + (per - 1) * entries.ii + entries.depth
        prev = start
    produced = max(clock + cycles[f"hgc_level{big}"], max(ready.values()))

    def streamed(s: int) -> list[int]:
        return [tables["STEP_FACTORS"][e] for e in range(fb[s], fb[s + 1])
                if tables["STEP_FACTORS"][e] in ready]

    def step_ready(s: int) -> int:
        return max((ready[f] for f in streamed(s)), default=0)

    d = sum(program.blocks[big].variable_dims)
    lane = max(len(streamed(s)) for s in order) * (d * (d + 1) // 2 + d)
    first = step_ready(order[0])
    c = first + cycles["assemble"]
    waits = 0
    for t in range(steps):
        if t + 1 < steps:
            r = step_ready(order[t + 1])
            waits += max(0, r - c)
            c = max(c, r)
        region = cycles[f"cholesky_level{t}"]
        if t + 2 < steps and streamed(order[t + 2]):  # the Gram source copies step t + 2's
            source = len(streamed(order[t + 2])) * per * entries.ii + 2
            region = max(region + 2, source)
        c += region
    span = (cycles["hgc"] + sum(cycles[f"hgc_level{b}"] for b in blocks) + cycles["assemble"]
            + sum(cycles[f"cholesky_level{t}"] for t in range(steps)))
    after_span = max(c, produced)
    return {"before": cost.cycles, "after": cost.cycles - span + after_span, "span": span,
            "after_span": after_span, "first": first, "produced": produced, "waits": waits,
            "big": program.blocks[big].name, "lane": lane, "clock": cost.clock_mhz}


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
              f"streamed block {r['big']}, stage lane {r['lane']:,} words", flush=True)


if __name__ == "__main__":
    main()
