"""Paper B's scaling from 5 to 80 CPEs (issue 33 item 4) by the plan: imu_window N = 50, LM,
float32 at 143 MHz, back-substitution by columns (the default on a chain).

    python bench/bench_flight.py                 # #CPE 5 ... 120, one and two cascades (x2 C:
                                                 # hgc_third_lane), one and
                                                 # two words a cycle: cycles / iteration, DSP,
                                                 # BRAM36, fits; the 5 -> 80 CPEs ratios
    python bench/bench_flight.py --pieces        # what each further piece would buy at #CPE 40
                                                 # x2, two words a cycle (``third`` built, the
                                                 # others what-ifs)
    python bench/bench_flight.py --where [--cpe 40 --sets 2 --lanes 2 --third]
                                                 # where a design's cycles an iteration go: the
                                                 # plan's phases, the first solve's passes by
                                                 # the process that bounds each, a steady
                                                 # region's processes, a retry's (:func:`where`)

The what-if pieces are the plan's arithmetic with a term replaced, not designs that are built:
``flight`` (a step enters its cascade as the first Schur-complement row of the step before on the
same end leaves that step's last pivot: the cascade's share of a region the interval, rows 0 ... f -
1 plus the f pivots' depth, not the whole round), ``pair`` (the feed-forward form of steps in
flight: a pass of two regions, each cascade factoring two consecutive steps of its end, A's pivots
on CPEs 0 ... f_A - 1 and B's on the CPEs past them, A's Schur-complement rows leaving its last
pivot's CPE into a merger that adds B's Grams and feeds CPE f_A: :func:`pair_passes`; canonical
DATAFLOW, no feedback channel, unlike ``flight``, whose next step's feed reads the drain of the same
cascade), ``loop`` (``flight`` as docs/hls.md says Vitis would build it: the first solve's region
loop a dataflow loop, each process a region after its last one and its inputs, no pass boundaries:
:func:`loop_model`), ``tail`` (the first solve's end on two cascades: the root's other child
added by the source, its conditional streamed to the committer beside its cascade:
:func:`tail_passes`). ``third`` is a built design option, not a what-if: the HGC's third entries
lane with two cascades (``hgc_third_lane``, units/cholesky.py's gram_third: the IMU Grams at the
datapath's pace, 166 words an instance instead of 248; it replaced the ``prod2`` what-if, which
halved the words an instance, more than two-port memories can take). Built since this was written
too: the grams process storing the two steps' first Grams side by side (fgc_cascades.h's
cholesky_set_firsts)."""

from __future__ import annotations

import argparse
from dataclasses import replace

import fgc_backends.hls.units.backsub as bs
import fgc_backends.hls.units.cholesky as ch
from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig
from fgc_backends.hls.emitter import accel_plan
from fgc_backends.hls.plan import phase_cycles, plan_cost
from fgc_backends.hls.plan.loops import slowest_plus_fills
from fgc_backends.hls.plan.model import Loop, Phase, Process

N = 50


def design(cpe: int, sets: int, lanes: int, third: bool = False):
    program = compile_graph(example("imu_window").build(N=N), SolverConfig(
        method="lm", linear="cholesky", cpe=cpe, precision="float32"), name=f"iw{cpe}")
    return plan_cost(accel_plan(program, HlsConfig(scalar="float", unit_sets=sets,
                                                   cascade_lanes=lanes, hgc_third_lane=third)))


def what_if(pieces: set[str]) -> None:
    """Replace the plan's terms named by ``pieces`` (module docstring) in units/cholesky.py."""
    cascades = ch.cascades_phases

    def phases(tables, order, dims, cpe, ops, timing, lanes=1, cond_banks=1,
               staged=frozenset()):
        out = []
        for ph in cascades(tables, order, dims, cpe, ops, timing, lanes, cond_banks, staged):
            procs = []
            for p in ph.processes:
                if "flight" in pieces and p.name.startswith("cascade"):
                    f, sep = dims[int(p.name[len("cascade"):])]
                    w = f + sep
                    if f <= cpe:  # one round: the next step after rows 0 ... f - 1, f pivots
                        waits = sum(ch.cpe_wait(q, w, ops, lanes) for q in range(f))
                        gap = (ch.cpe_vecs(0, w, lanes) - ch.cpe_vecs(f, w, lanes)
                               + ch.cpe_round_depth(f, cpe, ops, waits))
                        gap = max(gap, ch.cpe_vecs(0, w, lanes) + 1)
                        p = replace(p, loops=(p.loops[0], Loop("flight", 1, 1, gap)))
                procs.append(p)
            out.append(replace(ph, processes=tuple(procs)))
        return out

    ch.cascades_phases = phases
    if "tail" in pieces:
        ch.beside_set_passes = tail_passes(ch.beside_set_passes)
    if "pair" in pieces:
        ch.beside_set_passes = pair_passes(ch.beside_set_passes)
    if "loop" in pieces:
        ch.beside_set_passes, ch.beside_cycles = loop_model(ch.beside_set_passes,
                                                            ch.beside_cycles)


def flat_column_schedule(tables, ops):
    """The ``flat`` what-if (not built): each end of the column back-substitution one pipelined
    loop over its passes instead of a loop a pass, so a pass adds its trip, not trip - 1 + depth;
    a pass that takes in a conditional lasts at least its groups + Ld + Lm (its last group's
    scaled words written before the next pass reads them as its child's: the divide and the
    scaling are deeper than the column's read); end 1's feed pass issues its last column no
    earlier than end 0's root pass; the region as units/backsub.py's column_schedule."""
    depth = bs.column_pass_depth(ops)
    guard = ops.div.latency + ops.mul.latency
    timeline, root_issue = [], None
    for passes in bs.column_passes(tables):
        clock, rows = 0, []
        for p in passes:
            cols = 0
            if p.step >= 0:
                fc = tables["STEP_F"][p.child] if p.child >= 0 else 0
                cols = sum(bs.column_len(r, a, fc, ops, p.feed)
                           for r, a in enumerate(bs.column_sep(tables, p.step, p.child)))
            groups = bs.column_groups(tables, p.ingest) if p.ingest >= 0 else 0
            trip = max(cols, groups + guard if groups else 0)
            if trip <= 0:
                continue
            issue = clock + trip
            if p.feed and root_issue is not None:
                issue = max(issue, root_issue + 1)
            rows.append((p, issue - 1 + depth))
            clock = issue
            if p.root:
                root_issue = issue
        timeline.append(rows)
    loader = bs.column_loader_trip(tables)
    procs = [(loader - 1 + bs.COLUMN_LOAD_DEPTH, bs.COLUMN_LOAD_DEPTH)] if loader else []
    ends, last = {}, 0
    for rows in timeline:
        if not rows:
            continue
        procs.append((rows[-1][1], depth))
        for p, end in rows:
            if p.step >= 0 and not p.feed:
                ends[p.step] = end
            last = max(last, end)
    region = slowest_plus_fills(procs)
    return ends, max(region, last)


def tail_cut(cut: str):
    """Install the LM tail's what-if ``cut`` (not built): ``flat``
    (:func:`flat_column_schedule`). The ``no_accept`` what-if (no accepted copy) is built since
    (the trial held in X: fgc_lm.h's FGC_LM_TRIAL_IN_X), and with it ``accept8`` (the copy eight
    words a cycle) has no copy left to widen. Returns the undo."""
    saved = bs.column_schedule
    if cut == "flat":
        bs.column_schedule = flat_column_schedule

    def undo():
        bs.column_schedule = saved
    return undo


def tail_passes(base_passes):
    """The ``tail`` what-if (the first solve's end on two cascades, not built): the root
    region's child from the other cascade added by the source as it streams the root's words
    (a second adder a lane: the source's depth + La) instead of a pass of its own, and the
    root's conditional streamed from its drain to the committer (which copies it into COND
    beside the root's cascade, after the region before's), so the last pass is the root's
    pivot check alone, not its copy (fgc_cascades.h's committer alone: 465 pairs)."""

    def passes(tables, order, dims, cpe, ops, timing, *args, **kw):
        out = base_passes(tables, order, dims, cpe, ops, timing, *args, **kw)
        regions = [k for k, (ph, _) in enumerate(out) if ph.name.startswith("recholesky")]
        if len(regions) < 2:
            return out
        root, last = regions[-2], regions[-1]
        before = out[root - 1][0]
        if before.name.startswith("reassemble_level") and all(
                p.name.startswith("alone") for p in before.processes):
            ph, gate = out[root]
            out[root] = (replace(ph, processes=tuple(
                replace(p, loops=(*p.loops[:-1], replace(p.loops[-1], depth=p.loops[-1].depth
                                                         + ops.add.latency)))
                if p.name.startswith("source") else p for p in ph.processes)), gate)
            del out[root - 1]
            last -= 1
        ph, gate = out[last]
        out[last] = (replace(ph, processes=tuple(replace(p, loops=tuple(
            lp for lp in p.loops if lp.name.endswith(("_scale", "_pivot_check"))))
            for p in ph.processes)), gate)
        return out

    return passes


def _joined(name: str, procs: list) -> tuple:
    """One process running the loops of ``procs`` one after another (none if they have none)."""
    loops = tuple(lp for p in procs for lp in p.loops)
    return (Process(name, "cpe", loops),) if loops else ()


def _parse(base) -> tuple[dict, ...]:
    """beside_set_passes' passes by region x: the cascade processes of x, its source, the grams
    process that fills x's lanes, the committer of x, the Gram source of x (with the producer's
    instance it waits for), the pass adding x's children alone (if any)."""
    casc, src, fill, commit, gsrc, alone = {}, {}, {}, {}, {}, {}
    pending = None
    for phase, gate in base:
        procs = {p.name: p for p in phase.processes}
        for name, p in procs.items():  # the Gram source of region x
            if name.startswith("gram_source"):
                gsrc[int(name[len("gram_source"):])] = (p, gate)
        if phase.name == "reassemble":
            continue
        if phase.name.startswith("reassemble_level"):
            if "grams" in procs:  # the grams alone: region 0's
                fill[0] = procs["grams"]
            else:  # children added alone before the next region
                pending = phase
            continue
        r = int(phase.name[len("recholesky_level"):])
        if pending is not None:
            alone[r], pending = pending, None
        for name, p in procs.items():
            if name.startswith("cascade"):
                casc.setdefault(r, []).append(p)
            elif name.startswith("source"):
                src[r] = p
            elif name.startswith("grams"):
                fill[r + 1] = p
            elif name.startswith("committer"):
                commit[r - 1] = p
    return casc, src, fill, commit, gsrc, alone


def _gap(dim: tuple[int, int], cpe: int, ops, lanes: int) -> int:
    """A step's first word into its cascade to the next step's first (the ``flight`` gap): its
    rows 0 ... f - 1 through the feed, then its round's depth (its f pivots)."""
    f, sep = dim
    w = f + sep
    waits = sum(ch.cpe_wait(q, w, ops, lanes) for q in range(f))
    return (ch.cpe_vecs(0, w, lanes) - ch.cpe_vecs(f, w, lanes)
            + ch.cpe_round_depth(f, cpe, ops, waits))


def loop_model(base_passes, base_cycles):
    """The ``loop`` what-if: the first solve's elimination (beside_cycles on beside_set_passes'
    passes) as the dataflow loop docs/hls.md describes for steps in flight - the region loop
    with DATAFLOW on its body, each process starting region x + 1 when it has finished region
    x and its inputs are there, no pass boundaries: the Gram source of x after its x - 1 (and
    stage lane x % 2 free: the grams process of x - 2 done), no earlier than the producer's
    last instance of x + the move's depth; the grams process of x after its x - 1, the Gram
    source of x and the source of x - 2 (HA lane x % 2 free); the source of x after its x - 1
    and the grams process of x, no faster than its cascades' feeds take the words; cascade k's
    step of x from the source's first word, the flight gap after the step before on its end
    began (its streamed child: the drain's update rows fed back) and after that step's words
    have entered, its round's cycles; the committer of x after its x - 1 and both cascades of x.
    The regions from the first with a child added alone (the root's) on are today's passes after
    the loop (the first beside the loop's last committer). Operators and memories as built (a
    what-if of the cycles only)."""
    contexts = {}

    def passes(tables, order, dims, cpe, ops, timing, lay, relin, steps, ii, lanes=1,
               cond_banks=1):
        out = base_passes(tables, order, dims, cpe, ops, timing, lay, relin, steps, ii, lanes,
                          cond_banks)
        contexts[id(out)] = (out, tables, order, dims, cpe, ops, lanes)
        return out

    def cycles(producer, ready, plan_passes, move_depth):
        if id(plan_passes) not in contexts or contexts[id(plan_passes)][0] is not plan_passes:
            return base_cycles(producer, ready, plan_passes, move_depth)
        _, tables, order, dims, cpe, ops, lanes = contexts[id(plan_passes)]
        regions = ch.cascade_regions(tables, order)
        kids = ch.cascade_children(tables, regions)
        casc, src, fill, commit, gsrc, alone = _parse(plan_passes)
        n = len(regions)
        last = next((x for x in range(n) if x in alone
                     or any(len(p.loops) != 2 for p in casc.get(x, ()))), n)
        gs_end, grams_end, src_end, ends = {}, {}, {}, []
        t = 0
        for x in sorted(gsrc):
            proc, gate = gsrc[x]
            start = max(t, grams_end.get(x - 2, 0))
            t = max(start + proc.cycles, ready[gate] + move_depth if gate is not None else 0)
            gs_end[x] = t
        ends.append(t)
        g = s_ = c_ = 0
        end = [{"start": None, "gap": 0, "feed": 0, "step": -1} for _ in (0, 1)]
        for x in range(min(last + 1, n)):
            if x in fill:
                g = max(g, gs_end.get(x, 0), src_end.get(x - 2, 0)) + fill[x].cycles
                grams_end[x] = g
            if x >= last:
                break
            start = max(s_, grams_end.get(x, 0))
            lead = sum(lp.cycles for lp in src[x].loops[:-1]) + src[x].loops[-1].depth
            fed, done = start + src[x].cycles, 0
            for k, proc in enumerate(casc.get(x, ())):
                step = regions[x][k] if regions[x][k] >= 0 else regions[x][1 - k]
                e = end[k]
                begin = max(start + lead, e["feed"])
                if e["start"] is not None and kids[step][0] == e["step"] >= 0:
                    begin = max(begin, e["start"] + e["gap"])
                rnd = proc.loops[1]
                end[k] = {"start": begin, "gap": _gap(dims[step], cpe, ops, lanes),
                          "feed": begin + rnd.trip, "step": step}
                fed = max(fed, begin + rnd.trip)
                done = max(done, begin + rnd.cycles)
            s_ = src_end[x] = fed
            if x + 1 < last:  # (the last one's beside the first pass after the loop)
                c_ = max(c_, done) + (commit[x].cycles if x in commit else 0)
            ends += [g, s_, done, c_]
        t = max(ends)
        for x in range(last, n):  # the rest as today's passes
            if x in alone:
                t += phase_cycles(alone[x])
            before = (commit[x - 1],) if x == last and x - 1 in commit else ()
            t += phase_cycles(Phase(f"tail{x}", True, (*casc.get(x, ()), src[x], *before)))
        t += sum(commit[x].cycles for x in range(last, n) if x in commit)
        return max(producer, *ready, t), 0

    return passes, cycles


def pair_passes(base_passes, pairs: bool = True):
    """The ``pair`` what-if on the two-cascade design with the HGC beside (units/cholesky.py's
    beside_set_passes): regions r, r + 1 in one pass where both hold two steps of one round
    each, B = region r + 1's step on cascade k the parent of A = region r's (its streamed
    child), f_A + f_B <= #CPE, and B has no child added alone. Cascade k's process: A's feed
    fill, then B's first word enters CPE f_A the flight gap after A's first (A's rows 0 ... f_A
    - 1 through the feed, then A's round depth: its f_A pivots, the merger in place of the
    drain), then B's round (its words, its depth: the merger's add in place of a feed). Each
    other process does the work of both regions one after the other: the source streams both
    regions' steps, the grams process fills the next pass's two regions, the committer commits
    the pass before's, the Gram source stages the regions two passes on (the pass gated by the
    later of their producer's instances). Not priced: the merger's two adders a cascade, and
    the second stage / HA / NF lanes a pass of two regions needs (memory, not cycles). With
    ``pairs`` False the passes are rebuilt region by region: beside_set_passes' own price (a
    check of the rebuild)."""

    def passes(tables, order, dims, cpe, ops, timing, lay, relin, steps, ii, lanes=1,
               cond_banks=1):
        base = base_passes(tables, order, dims, cpe, ops, timing, lay, relin, steps, ii, lanes,
                           cond_banks)
        regions = ch.cascade_regions(tables, order)
        kids = ch.cascade_children(tables, regions)
        n = len(regions)
        casc, src, fill, commit, gsrc, alone = _parse(base)

        def gap(s):
            return _gap(dims[s], cpe, ops, lanes)

        def pairable(r):
            if not pairs or r + 1 >= n or r + 1 in alone:
                return False
            for k in (0, 1):
                a, b = regions[r][k], regions[r + 1][k]
                if a < 0 or b < 0 or kids[b][0] != a or dims[a][0] + dims[b][0] > cpe:
                    return False
            return all(len(p.loops) == 2 for x in (r, r + 1) for p in casc.get(x, ()))

        units, r = [], 0
        while r < n:
            units.append((r, r + 1) if pairable(r) else (r,))
            r += len(units[-1])

        def sources(u):  # the Gram source processes of unit u's regions, the later gate
            got = [gsrc[x] for x in (units[u] if 0 <= u < len(units) else ()) if x in gsrc]
            gates = [g for _, g in got if g is not None]
            return _joined(f"gram_source_u{u}", [p for p, _ in got]), max(gates, default=None)

        procs, gate = sources(0)
        out = [(Phase("reassemble", False, procs, linear=True), gate)]
        procs, gate = sources(1)
        procs = _joined("grams", [fill[x] for x in units[0] if x in fill]) + procs
        out.append((Phase("reassemble_level0", len(procs) > 1, procs, linear=True), gate))
        for u, unit in enumerate(units):
            for x in unit:
                if x in alone:
                    out.append((alone[x], None))
            if len(unit) == 2:
                cascades = tuple(Process(f"cascade{regions[unit[0]][k]}_{regions[unit[1]][k]}",
                                         "cpe", (pa.loops[0], Loop("flight", 1, 1, gap(
                                             regions[unit[0]][k])), pb.loops[1]))
                                 for k, (pa, pb) in enumerate(zip(casc[unit[0]],
                                                                   casc[unit[1]], strict=True)))
            else:
                cascades = tuple(casc.get(unit[0], ()))
            nxt = units[u + 1] if u + 1 < len(units) else ()
            prv = units[u - 1] if u > 0 else ()
            gs, gate = sources(u + 2)
            procs = (cascades + _joined(f"source_u{u}", [src[x] for x in unit if x in src])
                     + _joined(f"grams_u{u}", [fill[x] for x in nxt if x in fill])
                     + _joined(f"committer_u{u}", [commit[x] for x in prv if x in commit])
                     + gs)
            out.append((Phase(f"recholesky_level{u}", True, procs, linear=True), gate))
        procs = _joined("committer", [commit[x] for x in units[-1] if x in commit])
        out.append((Phase(f"recholesky_level{len(units)}", False, procs, linear=True), None))
        return out

    return passes


def _bound(phase: Phase) -> str:
    """The kind of process that bounds a pass (its slowest: the cascade, the source or
    assembler, the grams process, the committer, the Gram source, a child added alone)."""
    if not phase.processes:
        return "empty"
    slow = max(phase.processes, key=lambda p: p.cycles).name
    for kind in ("gram_source", "grams", "committer", "cascade", "source", "assembler",
                 "assemble", "alone", "check", "lanes"):
        if slow.startswith(kind):
            return kind
    return slow


def where(cpe: int, sets: int, lanes: int, third: bool = False) -> list[str]:
    """Where one LM iteration's cycles go by the plan (the arithmetic fgc_cycles.h's counting C
    simulation matches, bench_cycles.py): the iteration's phases; inside ``hgc_beside`` (the HGC
    producer beside the first solve, :func:`~fgc_backends.hls.units.cholesky.beside_cycles`) the
    first solve's passes as the plan prices them, grouped by the process that bounds each
    (the cycles it waited for the producer apart), the start (before the first region), a
    steady region's processes and the tail (children added alone, the root's region, the last
    committer); and a retry's passes (per rejection: not in the iteration's figure)."""
    rec = []
    base = ch.beside_cycles

    def spy(producer, ready, passes, move_depth):
        out = base(producer, ready, passes, move_depth)
        rec.append((out[0], producer, ready, passes, move_depth))
        return out

    ch.beside_cycles = spy
    try:
        program = compile_graph(example("imu_window").build(N=N), SolverConfig(
            method="lm", linear="cholesky", cpe=cpe, precision="float32"), name=f"iw{cpe}")
        plan = accel_plan(program, HlsConfig(scalar="float", unit_sets=sets,
                                             cascade_lanes=lanes, hgc_third_lane=third))
    finally:
        ch.beside_cycles = base
    cost = plan_cost(plan)
    label = f"#CPE {cpe} x{sets}{' C' if third else ''} L{lanes}"
    out = [f"{label}: {cost.cycles:,d} cycles an iteration, {cost.dsp:,d} DSP, "
           f"{cost.bram36:.1f} BRAM36, {'fits' if cost.fits else 'over: ' + ','.join(cost.over)}"
           f"; phases marked linear {cost.linear_cycles:,d} "
           f"({100 * cost.linear_cycles / cost.cycles:.1f} %, hgc_beside's producer inside)"]
    for ph in plan.phases:
        if ph.per == "iteration":
            procs = ", ".join(f"{p.name} {p.cycles:,d}" for p in ph.processes)
            out.append(f"  {ph.name:20s} {phase_cycles(ph):7,d}  ({procs})")
    if not rec:
        return out
    total, producer, ready, passes, move_depth = min(rec, key=lambda r: r[0])
    t = waited = 0
    by: dict[str, list[int]] = {}
    first = next((k for k, (ph, _) in enumerate(passes)
                  if ph.name.startswith("recholesky") and any(
                      p.name.startswith("cascade") for p in ph.processes)), len(passes))
    steady = []
    for k, (ph, gate) in enumerate(passes):
        c = phase_cycles(ph)
        t += c
        w = 0
        if gate is not None and ready[gate] + move_depth > t:
            w = ready[gate] + move_depth - t
            t += w
        waited += w
        if k == first:
            out.append(f"  first solve: the first region starts at {t - c - w:,d} "
                       f"(the producer's instances it waits for)")
        row = by.setdefault(_bound(ph) if k >= first else "start", [0, 0, 0])
        row[0] += 1
        row[1] += c
        row[2] += w
        if k >= first and _bound(ph) == "cascade" and len(ph.processes) >= 4:
            steady.append(ph)
    out.append(f"  hgc_beside {total:,d} = max(producer {max([producer, *ready]):,d}, "
               f"first solve {t:,d}); the first solve waited {waited:,d} for the producer")
    for kind, (n, c, w) in by.items():
        out.append(f"    bound by {kind:12s} {n:3d} passes {c:7,d} cycles"
                   + (f" + {w:,d} waiting" if w else ""))
    if steady:
        ph = steady[len(steady) // 2]
        out.append(f"    a steady region ({ph.name}, {phase_cycles(ph):,d}): " + ", ".join(
            f"{p.name} {p.cycles:,d} (fill {p.fill})" for p in ph.processes))
    retry = [ph for ph in plan.phases if ph.per == "rejection"]
    if retry:
        kinds: dict[str, int] = {}
        for ph in retry:
            kinds[_bound(ph)] = kinds.get(_bound(ph), 0) + phase_cycles(ph)
        out.append(f"  a retry (per rejection): {sum(map(phase_cycles, retry)):,d} cycles, "
                   + ", ".join(f"bound by {k} {c:,d}" for k, c in kinds.items()))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pieces", action="store_true", help="the what-if pieces at #CPE 40 x2")
    ap.add_argument("--where", action="store_true",
                    help="where a design's cycles go (--cpe, --sets, --lanes, --third)")
    ap.add_argument("--cpe", type=int, default=40)
    ap.add_argument("--sets", type=int, default=2)
    ap.add_argument("--lanes", type=int, default=2)
    ap.add_argument("--third", action="store_true")
    ap.add_argument("--tail-cuts", action="store_true",
                    help="the LM tail's what-if (flat) at 5 x1, 20 x2, 40 x2")
    args = ap.parse_args()
    if args.tail_cuts:
        for cut in ("as built", "flat"):
            undo = tail_cut(cut)
            d5 = design(5, 1, 1)
            row = [f"{cut:10s} #CPE 5 x1 {d5.cycles:7,d} ({d5.dsp:,d} DSP)"]
            for cpe, sets, lanes, third in ((20, 2, 1, False), (40, 2, 2, False),
                                            (40, 2, 2, True)):
                c = design(cpe, sets, lanes, third)
                row.append(f"#CPE {cpe} x{sets}{' C' if third else ''} L{lanes} {c.cycles:7,d} "
                           f"({d5.cycles / c.cycles:.4f}x, {c.dsp:,d} DSP"
                           f"{', fits' if c.fits else ''})")
            undo()
            print("; ".join(row), flush=True)
        return
    if args.where:
        print("\n".join(where(args.cpe, args.sets, args.lanes, args.third)))
        return
    if args.pieces:
        base = {"cpe": 40, "sets": 2, "lanes": 2}
        rows = [(), ("third",), ("flight",), ("flight", "third"), ("pair",), ("pair", "third"),
                ("loop",), ("loop", "third"), ("tail",), ("tail", "third"),
                ("tail", "flight", "third"), ("tail", "loop", "third")]
        saved = ch.cascades_phases, ch.beside_set_passes, ch.beside_cycles
        for pieces in rows:
            what_if(set(pieces))
            cost = design(**base, third="third" in pieces)
            print(f"{'+'.join(pieces) or 'as built':24s} #CPE 40 x2 L2 {cost.cycles:7,d} cycles "
                  f"{88584 / cost.cycles:.2f}x the default #CPE 5 x1, {cost.dsp:,d} DSP",
                  flush=True)
            ch.cascades_phases, ch.beside_set_passes, ch.beside_cycles = saved
        return
    table = {}
    for lanes in (1, 2):
        for cpe in (5, 20, 40, 80, 120):
            for sets, third in ((1, False), (2, False), (2, True)):
                cost = design(cpe, sets, lanes, third)
                table[cpe, sets + third, lanes] = cost
                print(f"#CPE {cpe:3d} x{sets}{' C' if third else '  '} L{lanes}: "
                      f"{cost.cycles:7,d} cycles, "
                      f"{cost.dsp:5,d} DSP, {cost.bram36:6.1f} BRAM36, "
                      f"{'fits' if cost.fits else 'over: ' + ','.join(cost.over)}", flush=True)
    default5 = table[5, 1, 1].cycles
    for lanes in (1, 2):
        for sets, cpe in ((1, 80), (2, 40), (3, 40)):
            c = table[cpe, sets, lanes].cycles
            same = table[5, 1, lanes].cycles
            name = "x2 + the third Gram lane" if sets == 3 else f"x{sets}"
            print(f"80 CPEs as #CPE {cpe} {name} L{lanes}: {default5 / c:.3f}x the default "
                  f"#CPE 5 x1 ({default5:,d}), {same / c:.3f}x #CPE 5 x1 L{lanes} ({same:,d})")


if __name__ == "__main__":
    main()
