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
from fgc_backends.hls.plan.cost import phase_cycles
from fgc_backends.hls.plan.loops import _tables
from fgc_backends.hls.plan.model import Loop, Phase, Process
from fgc_backends.hls.units.cholesky import gram_config, jacobian_cycles, jacobian_ii

CASES = [("lio", 30, c) for c in (10, 15, 20)] + [("imu_window", 50, c) for c in (5, 20, 80)]


def beside(program, plan, cost, variant: str = "source") -> dict:
    """The estimate for one design: cycles before / after, the span it replaces, when the
    first step's streamed Grams are complete, the producer's end, the consumer's waits after
    the first step, the streamed block type and the largest stage lane (words). ``variant``:
    "source" (a Gram source process beside the assembler fills stage lanes) or "assembler"
    (the assembler reads the stream itself in cholesky_assemble_first / its adds: the stream's
    words at the producer's rate, a word of 1, 2 or 3 entries (one lane, two, paired) every
    ceil(entries / 2) cycles when stored, an entry a cycle when added)."""
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
    _, lane_b, _, paired = gram_config(program, big, plan.options.hgc_lanes,
                                       jacobian_ii(procs.values()),
                                       jacobian_cycles(procs.values()))
    slots = 3 if paired else 2 if lane_b else 1
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
    def reads_stream(phase: Phase, assembler: str, s: int) -> int:
        """The phase's cycles with its assembler taking step s's Grams of the streamed block
        type from the stream (variant "assembler")."""
        facs = [tables["STEP_FACTORS"][e] for e in range(fb[s], fb[s + 1])]
        out, k = [], -1
        for lp in next(p for p in phase.processes if p.name == assembler).loops:
            if lp.name in ("map", "gram"):
                k += 1
            if lp.name in ("gram_first", "gram") and facs[k] in ready:
                lp = (Loop("gram_first", per, -(-slots // 2), lp.depth) if lp.name == "gram_first"
                      else Loop("gram", per * slots, 1, lp.depth))
            out.append(lp)
        procs = tuple(Process(p.name, p.unit, tuple(out)) if p.name == assembler else p
                      for p in phase.processes)
        return phase_cycles(Phase(phase.name, phase.dataflow, procs, phase.linear))

    first = step_ready(order[0])
    c = first + cycles["assemble"]
    if variant == "assembler":
        c += reads_stream(phases["assemble"], "assemble_first", order[0]) - cycles["assemble"]
    waits = 0
    for t in range(steps):
        region = cycles[f"cholesky_level{t}"]
        if t + 1 < steps:
            r = step_ready(order[t + 1])
            waits += max(0, r - c)
            c = max(c, r)
            if variant == "assembler":
                region = reads_stream(phases[f"cholesky_level{t}"], f"assembler{order[t]}",
                                      order[t + 1])
        if variant == "source" and t + 2 < steps and streamed(order[t + 2]):
            # the Gram source copies step t + 2's Grams beside the region
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
        for variant in ("source", "assembler"):
            r = beside(program, plan, cost, variant)
            ms = [x / r["clock"] / 1e3 for x in (r["before"], r["after"])]
            print(f"{ex} N={n} #CPE={cpe} [{variant}]: {r['before']:,} -> {r['after']:,} "
                  f"cycles/iteration ({ms[0]:.3f} -> {ms[1]:.3f} ms), DSP plan {cost.dsp}; "
                  f"linearise+eliminate {r['span']:,} -> {r['after_span']:,} (first step's "
                  f"Grams at {r['first']:,}, producer done at {r['produced']:,}, consumer "
                  f"waits after it {r['waits']:,}); streamed block {r['big']}, stage lane "
                  f"{r['lane']:,} words", flush=True)

if __name__ == "__main__":
    main()
