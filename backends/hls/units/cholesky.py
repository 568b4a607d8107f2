"""The Cholesky unit (paper B): the HGC (H = JᵀJ, g = Jᵀr per instance) and the cascade of #CPE
process elements (``include/fgc_cpe.h``'s ``cpe_step``), each elimination step's frontal
[H | g] assembled, factored and stored (multifrontal, as emitted); what-if designs factor the
whole [H | g] (dense, or its envelope: "blocked") through one cascade."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from fgc.ir.codes import NOISE_CODES
from fgc_backends.cfamily.sparsity import block_pattern
from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.plan.cost import phase_cycles
from fgc_backends.hls.plan.loops import _block_shape, _ported, kernel_loop
from fgc_backends.hls.plan.model import (
    Channel,
    Loop,
    Memory,
    Phase,
    PlanError,
    Process,
    Unit,
)
from fgc_backends.hls.units.memories import solver_memories
from fgc_backends.hls.units.spec import UnitSpec


def cpe_depth(ops: OperatorTable) -> int:
    """What a CPE with a pivot adds to its round's stream (backends/hls/include/fgc_cpe.h): its
    tap 2 (read, write; the divide 1 / d runs beside the stream) and its Update loop
    2 Lm + La + 2 (h[c] r, times h[i], subtracted; read, write)."""
    return 2 + 2 * ops.mul.latency + ops.add.latency + 2


def cpe_wait(p: int, w: int, ops: OperatorTable, lanes: int = 1) -> int:
    """The cycles the CPE of pivot p waits for r = 1 / d (fgc_cpe.h's cpe_wait): the tap sends
    it Ld + 2 cycles after the pivot, the CPE needs it after the pivot's row of w + 1 - p
    words, ``lanes`` a cycle."""
    return max(0, ops.div.latency - -(-(w + 1 - p) // lanes))


def cpe_vecs(first: int, w: int, lanes: int = 1) -> int:
    """The stream words of rows first … w - 1 through the cascade (fgc_cpe.h's cpe_vecs): row
    i's w + 1 - i words, ``lanes`` (1 or 2) a stream word, a row's last word-pair half empty
    when its count is odd."""
    m = w - first
    if m <= 0:
        return 0
    return m * (m + 1) // 2 + m if lanes == 1 else (m + 2) * (m + 2) // 4 - 1


def cpe_round_depth(active: int, cpe: int, ops: OperatorTable, waits: int = 0) -> int:
    """Depth of one ``cpe_round`` (backends/hls/include/fgc_cpe.h) as a loop of trip = its words
    + 1 (the status word) at II 1: every process of the region is one pipelined loop of those
    words, so the region takes the words plus what each process adds to the stream: the feed
    La + 2, each CPE with a pivot :func:`cpe_depth` (+ ``waits``, the sum of their
    :func:`cpe_wait`), the drain 2. The ``cpe`` - ``active`` CPEs past the round's pivots add
    nothing: the stream leaves the cascade at its last pivot's CPE (cpe's tail, the drain's
    multiplexer), and their taps and CPEs do nothing."""
    return ops.add.latency + 2 + active * cpe_depth(ops) + waits + 2


def cpe_step_loops(frontal: int, separator: int, cpe: int, ops: OperatorTable,
                   name: str = "s", lanes: int = 1) -> list[Loop]:
    """The loops of ``cpe_step`` (backends/hls/include/fgc_cpe.h) on one step's [H | g] of f
    frontal and s separator columns, as the csim counters count them: one ``Loop`` per round
    (trip = its words + the status word at II 1, depth :func:`cpe_round_depth`), after each
    round but the last the copy of the rows it leaves back into H (two words a cycle), the copy of
    [H | g] when f = 0, the singularity scale with the smallest pivot (trip f, depth Lm + Ld + 2)
    and the pivot check (the smallest pivot over the scale: trip 1, depth Ld + 2). The whole
    matrix as one step (f = n, s = 0) is what the Cholesky phase of :func:`build_plan` prices; a
    multifrontal design sums this over its steps. ``lanes`` (fgc_cpe.h's STREAM_WORDS): the words a
    cycle through the cascade, a round's trip its :func:`cpe_vecs` + 1."""
    w = frontal + separator
    loops = []
    for r, p0 in enumerate(range(0, frontal, cpe)):
        pivots = range(p0, min(frontal, p0 + cpe))
        waits = sum(cpe_wait(p, w, ops, lanes) for p in pivots)
        loops.append(Loop(f"{name}_round{r}", cpe_vecs(p0, w, lanes) + 1, 1,
                          cpe_round_depth(len(pivots), cpe, ops, waits)))
        done = p0 + cpe
        if done < frontal:  # the rows left for the next round back into H
            k = w - done
            loops.append(Loop(f"{name}_back{r}", (k * (k + 1) // 2 + k + 1) // 2, 1, 2))
    if frontal == 0:
        loops.append(Loop(f"{name}_no_pivots", w * (w + 1) // 2 + w, 1, 2))
    return loops + cpe_check_loops(frontal, ops, name)


@dataclass(frozen=True)
class CascadeProcess(Process):
    """The cascade's process of a ``cholesky_overlap`` pass: ``cpe_step``'s loops, whose first
    loop that runs is its round's feed (``cpe_feed``, the first process of the round's own
    DATAFLOW region, ``feed`` = La + 2 deep), not the round as a whole. Beside a slower
    assembler (a step with many factors: a pose graph's loop closures) what the cascade adds
    to the pass is that fill, as fgc_cycles.h counts it; the round's depth (a word through
    every CPE) lies under the assembler's further Grams, which come after its last word."""
    feed: int = 0

    @property
    def fill(self) -> int:
        return self.feed if self.feed and self.loops and "_round" in self.loops[0].name \
            else super().fill


def cascade_process(s: int, frontal: int, separator: int, cpe: int,
                    ops: OperatorTable, lanes: int = 1, check: bool = True) -> CascadeProcess:
    """Step s's cascade (:func:`cpe_step_loops`; but its pivot check with ``check`` false:
    fgc_eliminate.h's cholesky_cascade with FGC_CHECK_BESIDE runs cpe_rounds, the next pass's
    assembler the check) as the process of its pass."""
    loops = cpe_step_loops(frontal, separator, cpe, ops, name=f"s{s}", lanes=lanes)
    return CascadeProcess(f"cascade{s}", "cpe", tuple(loops if check else loops[:-2]),
                          feed=ops.add.latency + 2)


def cpe_check_loops(frontal: int, ops: OperatorTable, name: str = "s") -> list[Loop]:
    """fgc_cpe.h's cpe_check (the end of cpe_step): the singularity scale with the smallest
    pivot beside it (trip f, depth Lm + Ld + 2) and the pivot check (the smallest pivot over
    the scale: trip 1, depth Ld + 2)."""
    return [Loop(f"{name}_scale", frontal, 1, ops.mul.latency + ops.div.latency + 2),
            Loop(f"{name}_pivot_check", 1 if frontal else 0, 1, ops.div.latency + 2)]


def _gram_rows(block) -> dict[tuple[int, int], tuple[int, ...]]:
    """The structurally non-zero entries (p, q), q <= p, of block ``block``'s Gram of [A | b]
    in packed order, each with the whitened rows that touch both of its columns."""
    kinds = tuple(NOISE_CODES[m.noise_kind] for m in block.members)
    pattern = block_pattern(block, kinds, f"block {block.name!r}")
    return {(p, q): rows for p in range(pattern.stride) for q in range(p + 1)
            if (rows := pattern.gram_rows(p, q))}


def gram_entries(block) -> tuple[tuple[int, int], ...]:
    """The (p, q), q <= p, of a block type's Gram of [A | b] that are structurally non-zero (some
    whitened row touches both columns), in packed order: what accel.cpp.jinja's
    ``gram_entries`` computes (its tables BLOCK<b>_GRAM_P / _Q); the rest of the instance's
    packed triangle is never written and keeps GRAM's initial zeros."""
    return tuple(_gram_rows(block))


def gram_ii(program, block: int, lanes: int) -> int:
    """The II of block ``block``'s Gram entries (accel.cpp.jinja's gram_entries<..., GII>): an
    entry is a dot product of the block's m rows (m multiplies, m - 1 adds in a tree), so
    ``lanes`` multipliers take ceil(m / lanes) cycles an entry; a block type with one instance
    (a prior: a few hundred cycles an iteration at one lane) gets one multiplier and one adder
    (II m)."""
    m = program.blocks[block].residual_dim
    if sum(1 for f in program.factors if f.block == block) <= 1:
        return m
    return -(-m // max(1, min(lanes, m)))


def gram_config(program, block: int, lanes: int, jac_ii: dict | None,
                jac_cycles: dict | None = None):
    """How block ``block``'s Gram entries are computed: (lane A's entries, lane B's entries, K,
    paired). Lane A is the block's full width (its m rows); lane B, when there is one (K > 0),
    the dot product over the first K rows only, for entries no other row touches (the rest of
    the column pair is structurally zero: exact zeros its sum leaves out). An entry of the last
    row (b^T A: the += into G) stays in lane A, so the += keep to one lane. A second lane is
    built only where the HGC is the slower process of its linearize_<b> region: more than one
    instance at II 1, more entries than the datapath's II an instance (``jac_ii``: block -> its
    Jacobian loop's II; None: no second lane), and K is the fewest rows that bring the region's
    time an instance, max(lane A's entries, the datapath's II), to its least (the eligible
    entries balanced between the lanes, lane A keeping the rest in packed order).

    ``paired`` (accel.cpp.jinja's gram_entries_pair): the loop at II 2 with two lane-A entries
    and one lane-B entry an iteration (a third of the entries in lane B), which binds m +
    ceil(K / 2) multipliers instead of m + K; chosen when its iterations, 2 cycles each, take
    no longer than the datapath's process (``jac_cycles``: block -> its Jacobian loop's
    cycles; None: never paired)."""
    b = program.blocks[block]
    rows = _gram_rows(b)
    entries = tuple(rows)
    none = (entries, (), 0, False)
    n = sum(1 for f in program.factors if f.block == block)
    if jac_ii is None or n <= 1 or gram_ii(program, block, lanes) != 1:
        return none
    ii, m, last = jac_ii.get(block, 0), b.residual_dim, sum(b.variable_dims)
    if len(entries) <= ii:
        return none
    best, best_k = max(len(entries), ii), 0
    for k in range(1, m):
        eligible = sum(1 for (p, q), r in rows.items() if p != last and r[-1] < k)
        a = len(entries) - min(eligible, len(entries) // 2)
        if max(a, ii) < best:
            best, best_k = max(a, ii), k
    if not best_k:
        return none
    eligible = [e for e, r in rows.items() if e[0] != last and r[-1] < best_k]

    def split(share: int):
        lane_b = set(eligible[:min(len(eligible), share)])
        return (tuple(e for e in entries if e not in lane_b),
                tuple(e for e in entries if e in lane_b))

    if jac_cycles is not None and block in jac_cycles:
        pa, pb = split(-(-len(entries) // 3))
        if 2 * n * max(-(-len(pa) // 2), len(pb)) <= jac_cycles[block]:
            return pa, pb, best_k, True
    return (*split(len(entries) // 2), best_k, False)


def gram_lanes(program, block: int, lanes: int, jac_ii: dict | None,
               jac_cycles: dict | None = None
               ) -> tuple[tuple[tuple[int, int], ...], tuple[tuple[int, int], ...], int]:
    """(lane A's entries, lane B's entries, K) of :func:`gram_config`."""
    return gram_config(program, block, lanes, jac_ii, jac_cycles)[:3]


def hgc_operators(program, lanes: int, jac_ii: dict | None = None,
                  jac_cycles: dict | None = None) -> list[tuple[int, tuple]]:
    """(block, operators) of each block type's HGC as accel.cpp.jinja's gram_entries binds
    them: its entries' loop at :func:`gram_ii`: lane A's ceil(m / II) multipliers and its
    tree's m - 1 adds with the gradient's add (the Gram's last row into G), ceil(m / II)
    adders; lane B's (:func:`gram_lanes`) K multipliers and K - 1 adders; paired
    (:func:`gram_config`, II 2), m + ceil(K / 2) multipliers and m + ceil((K - 1) / 2) adders
    (the finiteness check of the diagonal entries is a test of their exponent bits: no
    operator)."""
    out = []
    for i, b in enumerate(program.blocks):
        if not any(f.block == i for f in program.factors):
            continue
        m, ii = b.residual_dim, gram_ii(program, i, lanes)
        _, _, k, paired = gram_config(program, i, lanes, jac_ii, jac_cycles)
        if paired:  # II 2: two lane-A entries (2m products, 2m adds) and one lane-B entry
            out.append((i, (("add", m + -(-(k - 1) // 2)), ("mul", m + -(-k // 2)))))
            continue
        out.append((i, (("add", -(-m // ii) + max(0, k - 1)), ("mul", -(-m // ii) + k))))
    return out


def gram_depth(m: int, timing: dict, t_timing: dict | None = None) -> int:
    """Depth of one Gram entry of a block of m rows (accel.cpp.jinja's gram_entries): the
    multiply and the tree of ceil(log2 m) adds (L's latencies, ``timing``), at least the 6
    cycles of the gradient's address (the instance's tables, the factor's variable, its tangent
    offset: ROM reads one after another), then the gradient's add (T's adder, ``t_timing``;
    G read beside the tree) and the reads and writes: max(Lm + La ceil(log2 m), 6) + La(T) + 3.
    Lane B's shallower tree ends within it."""
    la = timing["acc"][0]
    lm = timing["acc"][1] - la
    t_la = (t_timing or timing)["acc"][0]
    tree = math.ceil(math.log2(m)) if m > 1 else 0
    return max(lm + la * tree, 6) + t_la + 3


def gram_steps(program, block: int, t_timing: dict, lanes: int = 32,
               jac_ii: dict | None = None, jac_cycles: dict | None = None) -> int:
    """Iterations of gram_entries' loop an instance of block ``block`` takes (its STEPS): the
    entries of its larger lane (:func:`gram_lanes`); with more than one instance at least
    m + 3 (the next instance's rows are read into the other bank in the first m, and a bank is
    read no sooner than 3 iterations after it is written) and at least the span of lane A's
    last-row entries (the += into G) plus the adder's latency and 3, so that two instances'
    += into one entry of G (two factors of one variable) are a whole add apart. Paired
    (:func:`gram_config`): lane A's entries two an iteration."""
    lane_a, lane_b, _, paired = gram_config(program, block, lanes, jac_ii, jac_cycles)
    return gram_steps_of(program.blocks[block],
                         sum(1 for f in program.factors if f.block == block), lane_a,
                         len(lane_b), t_timing, 2 if paired else 1)


def gram_third(program, block: int, lanes: int, jac_ii: dict | None,
               jac_cycles: dict | None = None) -> tuple | None:
    """A third entries lane for block ``block``'s Grams streamed beside the elimination with two
    cascades (fgc_cascades.h): (lane A's entries, lane B's, lane C's, K, K', c0), or None where
    :func:`gram_config` has no lane B, pairs its lanes, or three lanes are no faster. Two lanes
    are what the Gram source can put away a cycle: every entry goes into its stage lane and
    GRAM_B (LM's retries), two ports each (imu_window's 496 entries: 248 words an instance, over
    the datapath's II 233, and a region's two instances 496 cycles of the source). Lane C's
    entries go into two memories of their own (its stage lane, its GRAM_B), so three entries a
    word: each lane at most ceil(n / 3) entries (and m + 3), the HGC's loop ahead of the
    datapath (it waits for the rows) and the source catching up after a wait at three entries a
    cycle. Lane C is the longest run of packed positions c0 ... c0 + |C| - 1 whose entries only
    the first K' rows touch (never the last row: no += into G), so the grams process tells a
    lane-C entry by its position alone; lane B the first entries no row past K touches of the
    rest, lane A the rest (the last row's among them); K' + K the fewest multipliers."""
    two_a, two_b, _, paired = gram_config(program, block, lanes, jac_ii, jac_cycles)
    if paired or not two_b:
        return None
    b = program.blocks[block]
    rows = _gram_rows(b)
    keys = list(rows)
    n, m, last = len(keys), b.residual_dim, sum(b.variable_dims)
    steps = max(-(-n // 3), m + 3)
    if steps >= max(len(two_a), len(two_b)):
        return None
    best = None
    for kc in range(1, m):
        ok = [e[0] != last and rows[e][-1] < kc for e in keys] + [False]
        run, start = (0, 0), None
        for i, x in enumerate(ok):
            if x and start is None:
                start = i
            elif not x and start is not None:
                run = max(run, (i - start, -start))
                start = None
        nc, c0 = min(run[0], steps), -run[1]
        if nc < n - 2 * steps:
            continue
        lane_c = keys[c0:c0 + nc]
        need = max(0, n - steps - nc)
        for kb in range(1, m):
            lane_b = [e for e in keys[:c0] + keys[c0 + nc:] if e[0] != last and rows[e][-1] < kb]
            if len(lane_b) >= need:
                if best is None or kb + kc < best[0]:
                    chosen_b = set(lane_b[:need])
                    lane_a = tuple(e for e in keys[:c0] + keys[c0 + nc:] if e not in chosen_b)
                    best = (kb + kc, (lane_a, tuple(lane_b[:need]), tuple(lane_c), kb, kc, c0))
                break
    return best[1] if best else None


def gram_steps_of(b, count: int, lane_a, longest: int, t_timing: dict, per: int = 1) -> int:
    """:func:`gram_steps` of given lanes: lane A's entries ``per`` an iteration, the other lanes'
    ``longest`` entries, with ``count`` instances of block ``b``."""
    steps = max(-(-len(lane_a) // per), longest)
    if count <= 1:
        return steps
    last = sum(b.variable_dims)  # the last row of [A | b]'s Gram: b^T A, then b^T b
    g = [e // per for e, (p, q) in enumerate(lane_a) if p == last and q < last]
    span = g[-1] - g[0] if g else 0
    return max(steps, b.residual_dim + 3, span + t_timing["acc"][0] + 3)


def jacobian_ii(jacobian) -> dict[int, int]:
    """Block -> the II of its datapath's Jacobian loop, from the processes
    ``factor_<b>_jacobian`` (the factor_jacobian phase's)."""
    out = {}
    for proc in jacobian:
        head, _, tail = proc.name.partition("_")
        idx = tail.removesuffix("_jacobian")
        if head == "factor" and tail.endswith("_jacobian") and idx.isdigit() and proc.loops:
            out[int(idx)] = proc.loops[0].ii
    return out


def jacobian_cycles(jacobian) -> dict[int, int]:
    """Block -> the cycles of its datapath's Jacobian loop (processes ``factor_<b>_jacobian``),
    what :func:`gram_config` weighs the paired HGC against."""
    return {b: proc.cycles for b in jacobian_ii(jacobian) for proc in jacobian
            if proc.name == f"factor_{b}_jacobian"}


def hgc_loops(program, timing: dict, lanes: int = 32, t_timing: dict | None = None,
              jac_ii: dict | None = None, jac_cycles: dict | None = None) -> list[Process]:
    """Cholesky: linearize_all's HGC (reduce_<b>: instance 0's m whitened rows from
    evaluate_<b>'s stream, a row a cycle, into registers, then one pipelined loop over all
    instances (:func:`gram_steps` iterations each) of the Gram's structurally non-zero entries
    (:func:`gram_entries`, in one or two lanes: :func:`gram_lanes`) one every :func:`gram_ii`
    cycles, each the rows' products folded in a tree into GRAM and, for the last row (b^T A),
    added into the gradient G in the same iteration, the diagonal's checked finite there too
    (:func:`gram_depth`), the next instance's rows read alongside into the other bank), after
    G is zeroed (the first process). The structural zeros are never written: GRAM keeps its
    initial zeros there, so no pass clears it. ``timing``: L's kernel timing; ``t_timing``:
    T's (the gradient's adder), L's when omitted; ``jac_ii``, ``jac_cycles``:
    :func:`gram_config`'s (paired: II 2, one cycle deeper)."""
    t_timing = t_timing or timing
    n_t = sum(v.dim for v in program.variables)
    procs = [Process("zero_gradient", "hgc", (kernel_loop("zero", _ported(n_t), "fill",
                                                                timing),))]
    for i, b in enumerate(program.blocks):
        m, _, _, _ = _block_shape(b)
        n = sum(1 for f in program.factors if f.block == i)
        paired = gram_config(program, i, lanes, jac_ii, jac_cycles)[3]
        loops = [kernel_loop("rows", m, "move", timing) if n else Loop("rows", 0, 1, 2),
                 Loop("entries", n * gram_steps(program, i, t_timing, lanes, jac_ii, jac_cycles),
                      2 if paired else gram_ii(program, i, lanes),
                      gram_depth(m, timing, t_timing) + paired)]
        procs.append(Process(f"reduce_{i}", "hgc", tuple(loops)))
    return procs


def hgc_phases(program, timing: dict, lanes: int, jacobian: tuple[Process, ...],
               t_timing: dict | None = None, zero: bool = True) -> list[Phase]:
    """linearize_all as emitted for Cholesky: ``hgc`` (G zeroed), then per block type b the
    DATAFLOW region linearize_<b> as phase ``hgc_level<b>`` (group ``hgc``): its datapath's
    Jacobian-mode instance loop (``jacobian``'s process factor_<b>_jacobian: whitened rows into
    AB and, a stream word a row, to the HGC) alongside reduce_<b> (:func:`hgc_loops`), so the
    region takes the slower of the two plus the other's fill. ``zero`` False
    (units/lm_control.py's retire_step_test): no ``hgc`` phase, G zeroed by LM's copies."""
    procs = hgc_loops(program, timing, lanes, t_timing, jacobian_ii(jacobian),
                      jacobian_cycles(jacobian))
    jac = {p.name: p for p in jacobian}
    phases = [Phase("hgc", False, (procs[0],), linear=True)] if zero else []
    for i, reduce in enumerate(procs[1:]):
        region = tuple(p for p in (jac.get(f"factor_{i}_jacobian"), reduce) if p is not None)
        phases.append(Phase(f"hgc_level{i}", True, region, linear=True))
    return phases


def assemble_loops(tables: dict, s: int, timing: dict, grams: bool = True,
                   children: bool = True, odd: dict | None = None, par: int = 0) -> list[Loop]:
    """The loops that assemble step s's [H | g] into its lane of HA (fgc_eliminate.h), which is
    all zero (the source that streams a step into the cascade clears every word it reads, so
    no clearing pass): ``grams`` (cholesky_assemble_first, cholesky_assemble_adds) per
    factor its packed Gram's lower
    triangle and gradient row (d (d + 1) / 2 + d entries), the step's first factor stored, not
    added, two entries a cycle (``move``) after its column map is copied into registers
    (``move``, d), each further one a loop of ``+=`` into the table-addressed frontal matrix
    whose entries all go to different addresses (``scatter``: II 1); ``children``
    (cholesky_assemble_adds) per child its update matrix's upper triangle and reduced g
    (s (s + 1) / 2 + s), a ``scatter`` loop each; with ``odd`` (step -> its position's parity in
    the schedule) only the children of parity ``par`` (one NF lane's)."""
    loops = []
    fb = tables["STEP_FACTOR_BEGIN"]
    for e in range(fb[s], fb[s + 1]) if grams else ():
        fac = tables["STEP_FACTORS"][e]
        d = tables["FACTOR_COLMAP_BEGIN"][fac + 1] - tables["FACTOR_COLMAP_BEGIN"][fac]
        n = d * (d + 1) // 2 + d
        if e == fb[s]:  # the lane all zero: stored, two entries a cycle, after its column map
            loops += [kernel_loop("map", d, "move", timing),
                      kernel_loop("gram_first", -(-n // 2), "move", timing)]
        else:
            loops.append(kernel_loop("gram", n, "scatter", timing))
    cb = tables["STEP_CHILD_BEGIN"]
    for e in range(cb[s], cb[s + 1]) if children else ():
        c = tables["STEP_CHILDREN"][e]
        if odd is not None and odd[c] != par:
            continue
        sc = tables["STEP_W"][c] - tables["STEP_F"][c]
        loops.append(kernel_loop("child", sc * (sc + 1) // 2 + sc, "scatter", timing))
    return loops


def cpe_pairs(w: int) -> int:
    """The stream words (fgc_cpe.h's cpe_pair, two of a row each) of a step's w rows: row i's
    w + 1 - i words, two a word, rounded up (fgc_cpe.h's cpe_pairs)."""
    return (w + 2) * (w + 2) // 4 - 1


def first_gram_trip(tables: dict, s: int) -> int:
    """The iterations step ``s``'s first factor's Gram takes in fgc_eliminate.h's
    cholesky_source_first (0: none, or s < 0): its column map into registers (d iterations),
    three iterations before the first read, then its packed Gram (n = d (d + 1) / 2 + d
    entries) two entries a cycle: d + 3 + ceil(n / 2)."""
    fb = tables["STEP_FACTOR_BEGIN"]
    if s < 0 or fb[s] == fb[s + 1]:
        return 0
    fac = tables["STEP_FACTORS"][fb[s]]
    d = tables["FACTOR_COLMAP_BEGIN"][fac + 1] - tables["FACTOR_COLMAP_BEGIN"][fac]
    return d + 3 + -(-(d * (d + 1) // 2 + d) // 2)


def assembler_loops(tables: dict, s: int, nxt: int, timing: dict, odd: dict,
                    ops: OperatorTable | None = None, prev: int = -1) -> list[Loop]:
    """fgc_eliminate.h's cholesky_assembler beside step s's cascade (s at an even position or
    not: ``odd[s]``; s < 0: the pass before the first step's region, nothing streamed): one
    loop (cholesky_source_first, ``move``) that streams step s's words out of its lane two of
    a row a cycle (:func:`cpe_pairs`, each bank read and cleared) while step ``nxt``'s first
    factor's Gram is stored into the other lane (:func:`first_gram_trip`), trip the larger;
    then step ``nxt``'s further factor Grams and its children at positions of the other parity
    than s's (written before this region; :func:`assemble_loops` but the first factor's), none
    if nxt < 0; last step ``prev``'s pivot check (:func:`cpe_check_loops`; -1 none), which its
    cascade left in DPIV / RMAX: off the cascade's path."""
    pairs = cpe_pairs(tables["STEP_W"][s]) if s >= 0 else 0
    loops = [kernel_loop("source", max(pairs, first_gram_trip(tables, nxt)), "move", timing)]
    if nxt >= 0:
        par = 1 - odd[s] if s >= 0 else 0
        loops += [lp for lp in assemble_loops(tables, nxt, timing, odd=odd, par=par)
                  if lp.name not in ("map", "gram_first")]
    if prev >= 0:
        loops += cpe_check_loops(tables["STEP_F"][prev], ops, name=f"s{prev}")
    return loops


def elimination_phases(tables: dict, order: list[int], dims: dict, cpe: int,
                       ops: OperatorTable, timing: dict, lanes: int = 1,
                       check_beside: bool = False) -> list[Phase]:
    """cholesky_eliminate_all's phases (passes of one cholesky_overlap region, fgc_eliminate.h)
    on the steps ``order`` (the schedule's LEVEL_STEPS; ``dims``: step -> (frontal, separator)
    columns) with the step tables ``tables``: phase ``assemble`` (the assembler alone: each
    step's position parity (the NF lane its drain writes), the first step's Grams, then per step
    its children at positions of the other parity than its own, the step before among them)
    and per step t the region ``cholesky_level<t>``: the cascade on the step
    (:func:`cpe_step_loops`) beside the assembler (:func:`assembler_loops`: its words
    streamed out, the next step's Grams and its children of t's parity), the slower of the two
    plus the other's fill. ``check_beside`` (fgc_eliminate.h's FGC_CHECK_BESIDE): each step's
    pivot check not at its cascade's end but in the next region's assembler, and a last
    ``cholesky_level<steps>``, the assembler alone on the last step's check. A child that is
    no step of ``order`` (an on-chip window's τ, kept from before the window) counts as of
    parity 0: added with the first step's Grams, alone. The
    batch plan (:func:`_frontal`) and the stream's window model (plan/update.py) both price
    the elimination with it."""
    odd = {s: t % 2 for t, s in enumerate(order)}
    for e in range(len(tables["STEP_CHILDREN"])):
        odd.setdefault(tables["STEP_CHILDREN"][e], 0)
    first = [Process("assemble_first", "cpe", tuple(assembler_loops(
        tables, -1, order[0], timing, odd)))] if order else []
    phases = [Phase("assemble", False, (
        Process("lanes", "cpe", (kernel_loop("lanes", len(order), "fill", timing),)),
        *first, *(Process(f"assemble{s}", "cpe", tuple(assemble_loops(
            tables, s, timing, grams=False, odd=odd, par=1 - odd[s]))) for s in order)),
        linear=True)]
    for t, s in enumerate(order):
        nxt = order[t + 1] if t + 1 < len(order) else -1
        frontal, separator = dims[s]
        prev = order[t - 1] if t > 0 and check_beside else -1
        phases.append(Phase(f"cholesky_level{t}", True, (
            cascade_process(s, frontal, separator, cpe, ops, lanes, not check_beside),
            Process(f"assembler{s}", "cpe", tuple(assembler_loops(
                tables, s, nxt, timing, odd, ops, prev)))), linear=True))
    if order and check_beside:
        phases.append(Phase(f"cholesky_level{len(order)}", False, (Process(
            "check", "cpe", tuple(cpe_check_loops(dims[order[-1]][0], ops, f"s{order[-1]}"))),),
            linear=True))
    return phases


def beside_block(phases, program) -> int | None:
    """The block type whose HGC runs beside the elimination (accel.cpp.jinja's
    linearize_solve): the one with the longest ``hgc_level<b>`` region (the first of equals),
    if it has instances and every one of them is some step's factor; None otherwise."""
    cycles = {int(ph.name[len("hgc_level"):]): phase_cycles(ph) for ph in phases
              if ph.name.startswith("hgc_level")}
    if not cycles:
        return None
    big = max(sorted(cycles), key=lambda b: cycles[b])
    return big if any(f.block == big for f in program.factors) else None


def beside_layout(program, tables: dict, order: list[int], big: int) -> dict:
    """Where block ``big``'s streamed Grams go (accel.cpp.jinja's tables of the HGC beside the
    elimination): ``order`` (its factors in the order the elimination, LEVEL_STEPS ``order``,
    reaches their steps, each step's in STEP_FACTORS order: the stream's), ``factor_stage``
    (per factor its offset in a stage lane, -1 if not streamed), ``step_first`` /
    ``step_count`` (per step its first streamed instance in the stream and how many), ``nb``
    (a packed Gram's words, b^T b included: an entry the HGC may write, the assembly never
    reads), ``n_stage`` (a lane's words), ``max_per_step``."""
    fb, sf = tables["STEP_FACTOR_BEGIN"], tables["STEP_FACTORS"]
    cb = tables["FACTOR_COLMAP_BEGIN"]
    n_steps = len(order)
    facs = {s: [sf[e] for e in range(fb[s], fb[s + 1]) if program.factors[sf[e]].block == big]
            for s in order}
    stream = [f for s in order for f in facs[s]]
    if sorted(stream) != [i for i, f in enumerate(program.factors) if f.block == big]:
        raise PlanError(f"block {big}: not every instance is one step's factor (the HGC "
                        "beside the elimination streams each once)")
    d = cb[stream[0] + 1] - cb[stream[0]]
    nb = (d + 1) * (d + 2) // 2  # [A | b]'s packed lower triangle, b^T b included (as in GRAM)
    factor_stage = [-1] * len(program.factors)
    first, count = [0] * n_steps, [0] * n_steps
    k = 0
    for s in order:
        first[s], count[s] = k, len(facs[s])
        for j, f in enumerate(facs[s]):
            factor_stage[f] = j * nb
        k += len(facs[s])
    most = max(count)
    return {"order": stream, "factor_stage": factor_stage, "step_first": first,
            "step_count": count, "nb": nb, "n_stage": most * nb, "max_per_step": most}


def beside_region_layout(program, tables: dict, regions: list[tuple[int, int]], big: int
                         ) -> dict:
    """:func:`beside_layout` for two cascades (:func:`cascade_regions`): the stream follows the
    regions (each region's cascade 0 step's instances, then cascade 1's), and a stage lane holds
    a whole region's streamed Grams (fgc_cascades.h's cholesky_set_gram_source fills region
    r + 2's while the grams process reads region r + 1's), in two memories, one a cascade's
    step (so that the grams process reads both steps' first Grams side by side):
    ``step_first`` / ``step_count`` are per region, ``step_count0`` the cascade 0 step's
    instances of the region, ``factor_stage`` a factor's offset in its cascade's memory of its
    region's lane, ``n_stage`` (a memory's words) the most streamed Grams of a step."""
    order = [s for reg in regions for s in reg if s >= 0]
    lay = beside_layout(program, tables, order, big)
    nb = lay["nb"]
    first, count = [0] * len(regions), [0] * len(regions)
    factor_stage = list(lay["factor_stage"])
    at = {f: k for k, f in enumerate(lay["order"])}
    for r, reg in enumerate(regions):
        steps = [s for s in reg if s >= 0]
        first[r] = lay["step_first"][steps[0]]
        count[r] = sum(lay["step_count"][s] for s in steps)
    count0 = [lay["step_count"][reg[0]] if reg[0] >= 0 else 0 for reg in regions]
    for f, k in at.items():
        r = next(r for r in range(len(regions)) if first[r] <= k < first[r] + count[r])
        j = k - first[r]  # its place in the region; cascade 1's step's after cascade 0's
        factor_stage[f] = (j - count0[r] if j >= count0[r] else j) * nb
    return {**lay, "factor_stage": factor_stage, "step_first": first, "step_count": count,
            "step_count0": count0, "max_per_step": max(count)}


def _gram_source(key: int, lay: dict, relin: bool, steps: int, ii: int, timing: dict
                 ) -> tuple[tuple[Process, ...], int | None]:
    """The Gram source's process for step (one cascade) or region (two) ``key`` of ``lay``
    (:func:`beside_layout` / :func:`beside_region_layout`): its streamed Grams into a stage
    lane - a stream word every ``ii`` cycles (``steps`` an instance) on the first solve of a
    linearisation (``relin``), two words of GRAM_B a cycle on a retry - and the producer's
    instance it waits for (None on a retry); nothing if ``key`` has no streamed Grams."""
    n = lay["step_count"][key]
    if not n:
        return (), None
    loop = (Loop("stream", n * steps, ii, timing["move"][1]) if relin
            else kernel_loop("kept", -(-n * lay["nb"] // 2), "move", timing))
    return (Process(f"gram_source{key}", "cpe", (loop,)),), (
        lay["step_first"][key] + n - 1 if relin else None)


def beside_set_passes(tables: dict, order: list[int], dims: dict, cpe: int, ops: OperatorTable,
                      timing: dict, lay: dict, relin: bool, steps: int, ii: int, lanes: int = 1,
                      cond_banks: int = 1) -> list[tuple[Phase, int | None]]:
    """fgc_cascades.h's cholesky_eliminate_sets_beside, pass by pass (two cascades, the HGC
    beside the elimination): :func:`cascades_phases`' passes with, in each, the Gram source of
    the region two on (``lay``: :func:`beside_region_layout`) - first the source alone (region
    0's streamed Grams into stage lane 0), then the grams process alone on region 0 beside the
    source of region 1, then per region r its children added alone (``reassemble_level``) and
    its region (``recholesky_level<r>``) beside the source of region r + 2, last the committer
    alone. (The pass as a phase, the producer's instance its source waits for or None.)"""
    staged = frozenset(f for f, at in enumerate(lay["factor_stage"]) if at >= 0)
    base = cascades_phases(tables, order, dims, cpe, ops, timing, lanes, cond_banks, staged)
    n_regions = len(lay["step_count"])

    def source(r: int) -> tuple[tuple[Process, ...], int | None]:
        if r >= n_regions:
            return (), None
        return _gram_source(r, lay, relin, steps, ii, timing)

    procs, gate = source(0)
    passes: list[tuple[Phase, int | None]] = [
        (Phase("reassemble", False, procs, linear=True), gate)]
    j = 0
    for phase in base:
        if phase.name.startswith("assemble"):  # the grams alone, or children added alone
            src, gate = source(1) if phase.name == "assemble" else ((), None)
            passes.append((replace(phase, name=f"reassemble_level{j}",
                                   dataflow=phase.dataflow or bool(src),
                                   processes=phase.processes + src), gate))
            j += 1
            continue
        r = int(phase.name[len("cholesky_level"):])
        src, gate = source(r + 2) if r < n_regions else ((), None)
        passes.append((replace(phase, name=f"recholesky_level{r}",
                               dataflow=phase.dataflow or bool(src),
                               processes=phase.processes + src), gate))
    return passes


def beside_ready(count: int, jac: Loop, rows: int, steps: int, ii: int, depth: int) -> list[int]:
    """When the producer's instance k's Gram is complete, cycles after linearize_solve starts
    (fgc_cycles.h's ready_chain): its entries start k II_jac + the datapath's depth + the rows'
    loop (``rows`` cycles) after, or ``steps`` iterations of the entries loop (II ``ii``) after
    the instance before's, whichever is later, and end (steps - 1) ii + ``depth`` later."""
    out, prev = [], 0
    for k in range(count):
        start = k * jac.ii + jac.depth + rows
        if k > 0:
            start = max(start, prev + steps * ii)
        out.append(start + (steps - 1) * ii + depth)
        prev = start
    return out


def beside_passes(tables: dict, order: list[int], dims: dict, cpe: int, ops: OperatorTable,
                  timing: dict, lay: dict, relin: bool, steps: int, ii: int, lanes: int = 1,
                  check_beside: bool = False) -> list[tuple[Phase, int | None]]:
    """fgc_eliminate.h's cholesky_eliminate_beside, pass by pass: (the pass as a phase, the
    producer's instance its Gram source waits for or None). Phase ``reassemble`` (the lanes'
    parity loop), then the source alone (the first step's streamed Grams into stage lane 0), the
    first step's assembly beside the source of the second, and as :func:`elimination_phases`'
    passes (the assembler alone adding children: ``reassemble_level<j>``; a step's region:
    ``recholesky_level<t>``) with, beside the
    region of step t, the source of step t + 2; with ``check_beside`` the assembler of step
    t's region checks step t - 1's pivots and a last pass the last step's alone
    (:func:`elimination_phases`'), else each step's check ends its cascade. The
    source (``relin``: the first solve of a linearisation) takes a stream word every ``ii``
    cycles (``steps`` an instance) or (a retry) two words of GRAM_B a cycle."""
    odd = {s: t % 2 for t, s in enumerate(order)}
    for e in range(len(tables["STEP_CHILDREN"])):
        odd.setdefault(tables["STEP_CHILDREN"][e], 0)

    def source(t: int) -> tuple[tuple[Process, ...], int | None]:
        if t >= len(order):
            return (), None
        return _gram_source(order[t], lay, relin, steps, ii, timing)

    passes: list[tuple[Phase, int | None]] = [(Phase("reassemble", False, (
        Process("lanes", "cpe", (kernel_loop("lanes", len(order), "fill", timing),)),),
        linear=True), None)]
    j = 0

    def alone(procs, gate):
        nonlocal j
        passes.append((Phase(f"reassemble_level{j}", True, procs, linear=True), gate))
        j += 1

    alone(*source(0))
    src, gate = source(1)
    first = (Process("assemble_first", "cpe", tuple(assembler_loops(
        tables, -1, order[0], timing, odd))),) if order else ()
    alone(src + first, gate)
    for t, s in enumerate(order):
        alone((Process(f"assemble{s}", "cpe", tuple(assemble_loops(
            tables, s, timing, grams=False, odd=odd, par=1 - odd[s]))),), None)
        nxt = order[t + 1] if t + 1 < len(order) else -1
        frontal, separator = dims[s]
        src, gate = source(t + 2)
        prev = order[t - 1] if t > 0 and check_beside else -1
        passes.append((Phase(f"recholesky_level{t}", True, (
            *src,
            Process(f"assembler{s}", "cpe", tuple(assembler_loops(tables, s, nxt, timing, odd,
                                                                  ops, prev))),
            cascade_process(s, frontal, separator, cpe, ops, lanes, not check_beside)),
            linear=True), gate))
    if order and check_beside:  # the last step's pivot check, the assembler alone
        passes.append((Phase(f"recholesky_level{len(order)}", False, (Process(
            "check", "cpe", tuple(cpe_check_loops(dims[order[-1]][0], ops,
                                                  f"s{order[-1]}"))),), linear=True), None))
    return passes


def beside_cycles(producer: int, ready: list[int], passes, move_depth: int) -> tuple[int, int]:
    """linearize_solve's cycles (fgc_cycles.h's beside_total): the later of the producer's end
    (``producer``, its region's cycles, or its last instance's ``ready``, if later) and the
    consumer's, its ``passes`` one after another,
    a pass whose source waits for instance k ending no earlier than ``move_depth`` after
    ``ready[k]``; and the cycles the consumer waited in all."""
    t = waited = 0
    # the producer's region: its slower process plus the other's fill, but no sooner than its
    # last Gram (reduce_<b> starts only after the datapath's first rows, so where it is the
    # slower process the fill rule under-prices it)
    producer = max([producer, *ready])
    for phase, gate in passes:
        t += phase_cycles(phase)
        if gate is not None and ready[gate] + move_depth > t:
            waited += ready[gate] + move_depth - t
            t = ready[gate] + move_depth
    return max(producer, t), waited


def cascade_regions(tables: dict, order: list[int]) -> list[tuple[int, int]]:
    """Two cascades (``unit_sets=2``): the steps ``order`` (LEVEL_STEPS) as regions of at most
    two independent steps, (cascade 0's step, cascade 1's), -1 for an idle cascade: consecutive
    steps of ``order`` go side by side unless the second is a parent of the first (on a
    two-ended chain the two ends alternate, so every region but the root's holds one step of
    each end). A step goes to the cascade that factored one of its children in the region
    before (its assembler streams that child's update matrix into the cascade: its words are
    read where the drain left them, no pass adds them), cascade 0 when neither did."""
    cb, kids = tables["STEP_CHILD_BEGIN"], tables["STEP_CHILDREN"]

    def children(s):
        return {kids[e] for e in range(cb[s], cb[s + 1])} if s >= 0 else set()

    regions: list[tuple[int, int]] = []
    t = 0
    while t < len(order):
        a = order[t]
        b = order[t + 1] if t + 1 < len(order) and a not in children(order[t + 1]) else -1
        prev = regions[-1] if regions else (-1, -1)

        def on(s, k, prev=prev):  # s's child was factored by cascade k in the region before
            return s >= 0 and prev[k] >= 0 and prev[k] in children(s)

        swap = (on(a, 1) or on(b, 0)) and not (on(a, 0) or on(b, 1))
        regions.append((b, a) if swap else (a, b))
        t += 2 if b >= 0 else 1
    return regions


def cascade_children(tables: dict, regions: list[tuple[int, int]]
                     ) -> dict[int, tuple[int, tuple[int, ...]]]:
    """Step -> (its streamed child or -1, its children added alone) with two cascades
    (:func:`cascade_regions`): a child its own cascade factored in the region just before is
    streamed (its update matrix added to the step's words as the source streams them into the
    cascade, fgc_cascades.h's cholesky_set_source: that NF lane is the source's to read); any
    other (the other cascade's, or older) is added in a pass of its own before the step's
    region (its NF lane may be another process's in the region)."""
    where = {s: (r, k) for r, reg in enumerate(regions) for k, s in enumerate(reg) if s >= 0}
    cb, kids = tables["STEP_CHILD_BEGIN"], tables["STEP_CHILDREN"]
    out = {}
    for s, (r, k) in where.items():
        streamed, alone = -1, []
        for e in range(cb[s], cb[s + 1]):
            c = kids[e]
            if where[c] == (r - 1, k):
                streamed = c
            else:
                alone.append(c)
        out[s] = (streamed, tuple(alone))
    return out


def _child_loop(tables: dict, c: int, timing: dict) -> Loop:
    sc = tables["STEP_W"][c] - tables["STEP_F"][c]
    return kernel_loop("child", sc * (sc + 1) // 2 + sc, "scatter", timing)


def cond_pairs(tables: dict, s: int) -> int:
    """COND's aligned word pairs (2 g, 2 g + 1) step ``s``'s conditional touches (0 for -1):
    fgc_cascades.h's cholesky_set_cond_pairs."""
    if s < 0:
        return 0
    c0, n = tables["STEP_COND_OFF"][s], tables["STEP_F"][s] * (tables["STEP_W"][s] + 1)
    return (c0 + n - 1) // 2 - c0 // 2 + 1


def cascades_phases(tables: dict, order: list[int], dims: dict, cpe: int,
                    ops: OperatorTable, timing: dict, lanes: int = 1,
                    cond_banks: int = 1, staged: frozenset = frozenset()) -> list[Phase]:
    """cholesky_eliminate_sets' phases (fgc_cascades.h, two cascades), passes of its one
    cholesky_sets region: phase ``assemble`` (the grams process alone: the first region's
    steps' Grams), then per region r of :func:`cascade_regions` (after a phase
    ``assemble_level<r>`` when a step of it has children added alone, :func:`cascade_children`:
    a scatter loop each) the region ``cholesky_level<r>``:

    - per cascade its step's ``cpe_step`` rounds (:func:`cpe_step_loops` but its check);
    - the source: the streamed children's separator maps into registers (``move``, trip the
      larger separator), then both steps' words, two of a row a cycle each (trip the larger
      step's :func:`cpe_pairs`; ``move``, or ``scatter`` with a streamed child's words added);
    - the grams process: the next region's steps' Grams into the other lanes, both first
      factors' column maps in one loop (``move``, trip the wider), then
      :func:`assemble_loops` but the maps, step after step; where both steps' first factors
      are ``staged`` (the HGC beside the elimination streams them into a stage lane, a memory
      per cascade's step) both first Grams side by side in one loop, two entries of each a
      cycle (``move``, trip the larger's pairs: fgc_cascades.h's cholesky_set_firsts), then
      the further factors step after step;
    - the committer: the region before's conditionals from CONDBUF into COND, two words a
      cycle, each step's pivot check after its copy (:func:`cpe_check_loops`: off the
      cascade's path); with COND cyclic over ``cond_banks`` > 1 (back-substitution's width:
      its four ports and more), both conditionals in one loop, an aligned pair of each a cycle
      (trip the larger step's pairs, :func:`cond_pairs`), then the two checks
      (fgc_cascades.h's cholesky_set_commit_both);

    last ``cholesky_level<regions>``: the committer alone on the last region's."""
    regions = cascade_regions(tables, order)
    kids = cascade_children(tables, regions)
    sw, sf = tables["STEP_W"], tables["STEP_F"]

    def first_width(s):  # the width of step s's first factor (0: none)
        fb, cb = tables["STEP_FACTOR_BEGIN"], tables["FACTOR_COLMAP_BEGIN"]
        if s < 0 or fb[s] == fb[s + 1]:
            return 0
        fac = tables["STEP_FACTORS"][fb[s]]
        return cb[fac + 1] - cb[fac]

    def first_factor(s):  # step s's first factor (-1: none)
        fb = tables["STEP_FACTOR_BEGIN"]
        return tables["STEP_FACTORS"][fb[s]] if s >= 0 and fb[s] < fb[s + 1] else -1

    def grams(reg):  # both first factors' column maps in one loop, then step after step
        maps = kernel_loop("map", max(first_width(s) for s in reg), "move", timing)
        if all(first_factor(s) in staged for s in reg):  # both first Grams side by side
            pairs = max(-(-(first_width(s) * (first_width(s) + 3) // 2) // 2) for s in reg)
            return (maps, kernel_loop("gram_firsts", pairs, "move", timing),
                    *(lp for s in reg
                      for lp in assemble_loops(tables, s, timing, children=False)
                      if lp.name not in ("map", "gram_first")))
        return (maps, *(lp for s in reg if s >= 0
                        for lp in assemble_loops(tables, s, timing, children=False)
                        if lp.name != "map"))

    def commit(reg):  # each conditional copied, then its pivots checked (cpe_check)
        if cond_banks > 1:  # both copied at once, then both checked
            trip = max(cond_pairs(tables, s) for s in reg)
            return (kernel_loop("cond" + "_".join(str(s) for s in reg if s >= 0), trip, "move",
                                timing),
                    *(lp for s in reg if s >= 0 for lp in cpe_check_loops(sf[s], ops,
                                                                          name=f"s{s}")))
        return tuple(lp for s in reg if s >= 0 for lp in (
            kernel_loop(f"cond{s}", -(-sf[s] * (sw[s] + 1) // 2), "move", timing),
            *cpe_check_loops(sf[s], ops, name=f"s{s}")))

    phases = [Phase("assemble", False, (Process("grams", "cpe", grams(regions[0])),)
                    if regions else (), linear=True)]
    for r, reg in enumerate(regions):
        alone = [(s, c) for s in reg if s >= 0 for c in kids[s][1]]
        if alone:
            phases.append(Phase(f"assemble_level{r}", False, tuple(
                Process(f"alone{s}_{c}", "cpe", (_child_loop(tables, c, timing),))
                for s, c in alone), linear=True))
        procs = []
        for s in reg:
            if s >= 0:
                # the two cascades start together on the source's words: a cascade's fill (what
                # it adds beside the slower one) is its feed's depth, La + 2 (the round's depth
                # is in its cycles), the trip-0 loop that heads its loops
                frontal, separator = dims[s]
                procs.append(Process(f"cascade{s}", "cpe", (
                    Loop(f"s{s}_fill", 0, 1, ops.add.latency + 2),
                    *cpe_step_loops(frontal, separator, cpe, ops, name=f"s{s}",
                                    lanes=lanes)[:-2])))
        streamed = [kids[s][0] for s in reg if s >= 0 and kids[s][0] >= 0]
        source = [kernel_loop("inv", max(sw[c] - sf[c] for c in streamed), "move", timing)
                  ] if streamed else []
        source.append(kernel_loop("source", max(cpe_pairs(sw[s]) for s in reg if s >= 0),
                                  "scatter" if streamed else "move", timing))
        procs.append(Process(f"source{r}", "cpe", tuple(source)))
        if r + 1 < len(regions):
            procs.append(Process(f"grams{r}", "cpe", grams(regions[r + 1])))
        if r > 0:
            procs.append(Process(f"committer{r}", "cpe", commit(regions[r - 1])))
        phases.append(Phase(f"cholesky_level{r}", True, tuple(procs), linear=True))
    if regions:
        phases.append(Phase(f"cholesky_level{len(regions)}", False, (Process(
            "committer", "cpe", commit(regions[-1])),), linear=True))
    return phases


def hessian_envelope(program) -> list[int]:
    """For each column j of H (variables in the Program's order), its lowest structurally
    non-zero row: H's envelope, which the Cholesky factor fills and does not leave."""
    start, k = {}, 0
    for v in program.variables:
        start[v.key] = k
        k += v.dim
    n = k
    dims = {v.key: v.dim for v in program.variables}
    first = list(range(n))  # first non-zero column of each row
    for f in program.factors:
        lo = min(start[key] for key in f.keys)
        for key in f.keys:
            for i in range(start[key], start[key] + dims[key]):
                first[i] = min(first[i], lo)
    lowest = list(range(n))
    for i, fi in enumerate(first):
        for j in range(fi, i + 1):
            lowest[j] = max(lowest[j], i)
    return lowest


def build(ctx) -> None:
    """The HGC unit and phase, the #CPE cascade, and (as emitted) the frontal steps' assembly,
    factorisation and store, or (what-if) one whole-matrix factorisation."""
    program, opts, ops = ctx.program, ctx.opts, ctx.les
    n = program.storage.columns
    c = opts.cpe
    # HGC: H = JᵀJ, g = Jᵀr over each instance's dense block rows × columns
    macs = 0
    for f in program.factors:
        b = program.blocks[f.block]
        cols = sum(b.variable_dims)
        macs += b.residual_dim * (cols * (cols + 1) // 2 + cols)
    if opts.hessian_storage == "frontal":  # as emitted: reduce_<b>'s loops (hgc_loops)
        # one Gram unit per block type (the template instance its reduce_<b> calls)
        # the datapaths' Jacobian pass becomes part of linearize_<b>'s regions (evaluate_<b>
        # alongside its HGC): its phase is replaced, in place, by hgc_phases
        at = next(k for k, (_, ph) in enumerate(ctx.phases) if ph.name == "factor_jacobian")
        slot, jacobian = ctx.phases[at]
        jac_ii = jacobian_ii(jacobian.processes)
        jac_cycles = jacobian_cycles(jacobian.processes)
        for i, unit_ops in hgc_operators(program, opts.hgc_lanes, jac_ii, jac_cycles):
            ctx.units.append(Unit(f"hgc_{i}", f"Hessian/gradient of block {i}", 1, unit_ops))
        from fgc_backends.hls.units.lm_control import retire_step_test
        ctx.phases[at:at + 1] = [(slot, ph) for ph in hgc_phases(
            program, ctx.les_timing, opts.hgc_lanes, jacobian.processes, ctx.timing,
            zero=not retire_step_test(program, opts))]
        for i, b in enumerate(program.blocks):  # the row stream (a row a word) and registers
            m, _, padded, _ = _block_shape(b)
            ctx.memories.append(Memory(f"gram_rows_{i}", m * padded, ops.word_bits, 1))
    else:
        ctx.units.append(Unit("hgc", "Hessian/gradient accumulation", opts.hgc_lanes,
                              (("add", 1), ("mul", 1))))
        ctx.add_phase("solve", Phase("hgc", False, (Process("hgc", "hgc", (
            Loop("macs", math.ceil(macs / opts.hgc_lanes), 1,
                 ops.mul.latency + ops.add.latency),)),), linear=True))
    # a CPE as fgc_cpe.h's loops bind it: its tap's loop divides (1 / d), its Update loop
    # multiplies twice and subtracts per lane (STREAM_WORDS words a cycle), at II 1
    lanes = opts.cascade_lanes if opts.hessian_storage == "frontal" else 1
    ctx.units.append(Unit("cpe", "Cholesky process element: tap (1 / d) + Update", c,
                          (("add", lanes), ("mul", 2 * lanes), ("div", 1))))
    if opts.hessian_storage == "frontal":
        _frontal(ctx)
        return
    # what-if designs (not emitted): the whole [H | g] factored as one matrix, dense or by its
    # envelope ("blocked", paper B's choice), through one cascade
    for i in range(c):
        ctx.channels.append(Channel(f"cpe_fifo{i}", "stream", n, ops.word_bits,
                                    "cholesky_in" if i == 0 else f"cpe{i - 1}", f"cpe{i}"))
    lowest = hessian_envelope(program) if opts.hessian_storage == "blocked" else [n - 1] * n
    rounds = []
    for r in range(math.ceil(n / c)):
        m = n - r * c
        words = sum(lowest[j] - j + 1 for j in range(r * c, n)) + m
        waits = sum(cpe_wait(p, lowest[p], ops) for p in range(r * c, min(n, r * c + c)))
        rounds.append(Loop(f"round{r}", words + 1, 1,
                           cpe_round_depth(min(c, m), c, ops, waits)))
    ctx.add_phase("solve", Phase("cholesky", True, (Process("cascade", "cpe", tuple(rounds)),),
                                 linear=True))
    ctx.add_phase("solve", Phase("cholesky_scalar", False, (Process("scale_and_check", "cpe", (
        Loop("scale", n, 1, ops.mul.latency + ops.div.latency + 2),
        Loop("pivot_check", n, 1, ops.mul.latency + 2))),), linear=True))
    ctx.memories.append(Memory("hessian", sum(lo - j + 1 for j, lo in enumerate(lowest)) + n,
                               ops.word_bits, max(1, c // 4)))


def cascades_of(program, opts) -> int:
    """Cholesky cascades (``unit_sets``: 1 unless set; 2 factors two independent steps side by
    side, :func:`cascades_phases`); more than 2 is an error, and a schedule of one step has
    one."""
    sets = 1 if opts.unit_sets is None else int(opts.unit_sets)
    if sets > 2:
        from fgc_backends.hls.config import HlsConfigError
        raise HlsConfigError(f"Cholesky: unit_sets={sets}: the design has one or two cascades "
                             "(unit_sets 1 or 2)")
    return max(1, min(sets, len(program.schedule.steps)))


def _beside(ctx, big: int, order: list[int], dims: dict) -> None:
    """The HGC beside the elimination (accel.cpp.jinja's linearize_solve, fgc_eliminate.h's
    cholesky_eliminate_beside): block ``big``'s region hgc_level<big> leaves the linearisation;
    phase ``hgc_beside`` (once an iteration) is the producer (that region's loops, the
    instances in step order) beside the first solve's elimination with its Gram source
    (:func:`beside_cycles` on :func:`beside_passes`), and LM's retries re-solve from GRAM_B
    (phases ``reassemble`` / ``recholesky_level<t>``, per rejection). Memories: the two stage
    lanes, GRAM_B and the Gram stream (a step's words). Two cascades (:func:`cascades_of`):
    fgc_cascades.h's cholesky_eliminate_sets_beside, the instances in region order, a stage lane
    and the stream's depth a region's (:func:`beside_region_layout`,
    :func:`beside_set_passes`)."""
    program, ops, tables, timing = ctx.program, ctx.les, ctx.tables, ctx.les_timing
    at = next(k for k, (_, ph) in enumerate(ctx.phases) if ph.name == f"hgc_level{big}")
    slot, region = ctx.phases[at]
    procs = {p.name: p for p in region.processes}
    jac = procs[f"factor_{big}_jacobian"].loops[0]
    rows, entries = procs[f"reduce_{big}"].loops[:2]
    if cascades_of(program, ctx.opts) == 2:
        lay = beside_region_layout(program, tables, cascade_regions(tables, order), big)
        passes = beside_set_passes
    else:
        lay = beside_layout(program, tables, order, big)
        passes = beside_passes
    lanes = ctx.opts.cascade_lanes
    banks = {"cond_banks": ctx.opts.backsub_lanes} if passes is beside_set_passes else {}
    # two cascades: a third entries lane (gram_third) where the first solve is faster by it
    third = None
    if passes is beside_set_passes and ctx.opts.hgc_third_lane:
        third = gram_third(program, big, ctx.opts.hgc_lanes, jacobian_ii(region.processes),
                           jacobian_cycles(region.processes))
    best = None
    for lane3 in (None, third) if third else (None,):
        reg = region
        if lane3 is not None:
            steps3 = gram_steps_of(program.blocks[big], len(lay["order"]), lane3[0],
                                   max(len(lane3[1]), len(lane3[2])), ctx.timing)
            reg = replace(region, processes=tuple(replace(p, loops=(rows, replace(
                entries, trip=len(lay["order"]) * steps3))) if p.name == f"reduce_{big}"
                else p for p in region.processes))
        red = next(p for p in reg.processes if p.name == f"reduce_{big}").loops[1]
        steps = red.trip // len(lay["order"])
        ready = beside_ready(len(lay["order"]), jac, rows.cycles, steps, red.ii, red.depth)
        # one cascade: each step's pivot check where the first solve is faster (check_beside)
        for extra in ({},) if passes is beside_set_passes else ({}, {"check_beside": True}):
            first = passes(tables, order, dims, ctx.opts.cpe, ops, timing, lay, True, steps,
                           red.ii, lanes, **banks, **extra)
            cycles, _ = beside_cycles(phase_cycles(reg), ready, first, timing["move"][1])
            if best is None or cycles < best[0]:
                best = (cycles, extra, lane3, reg, steps)
    cycles, extra, third, region, steps = best
    banks = {**banks, **extra}
    if third is not None:  # lane C's K' multipliers and its tree's K' - 1 adders, lane B's K
        m, kb, kc = program.blocks[big].residual_dim, third[3], third[4]
        hgc = next(i for i, u in enumerate(ctx.units) if u.name == f"hgc_{big}")
        ctx.units[hgc] = replace(ctx.units[hgc], operators=(("add", m + kb + kc - 2),
                                                          ("mul", m + kb + kc)))
    # the producer's region stays in the plan for the record (per "beside": priced inside
    # hgc_beside, not on its own)
    ctx.phases[at:at + 1] = [(slot, Phase("hgc_beside", False, (Process(
        f"linearize_solve_{big}", "cpe", (Loop("region", 1, 1, cycles),)),), linear=True)),
        (slot, replace(region, name="hgc_producer", per="beside"))]
    for phase, _ in passes(tables, order, dims, ctx.opts.cpe, ops, timing, lay, False, steps,
                           entries.ii, lanes, **banks):
        ctx.add_phase("solve", replace(phase, per="rejection"))
    _, lane_b, _, paired = gram_config(program, big, ctx.opts.hgc_lanes,
                                       jacobian_ii(region.processes),
                                       jacobian_cycles(region.processes))
    slots = (2 if paired else 1) + (1 if lane_b else 0)  # accel.cpp.jinja's GramWord
    # two lanes; with two cascades each lane a memory per cascade's step
    per_lane = 2 if passes is beside_set_passes else 1
    ctx.memories.append(Memory("stage", 2 * per_lane * lay["n_stage"], ops.word_bits, per_lane))
    ctx.memories.append(Memory("gram_kept", len(lay["order"]) * lay["nb"], ops.word_bits, 1))
    if third is not None:  # lane C's own stage lanes and GRAM_B (emitter: stage_c marks it)
        slots += 1
        nc = len(third[2])
        ctx.memories.append(Memory("stage_c", 2 * per_lane * lay["n_stage"] // lay["nb"] * nc,
                                   ops.word_bits, per_lane))
        ctx.memories.append(Memory("gram_kept_c", len(lay["order"]) * nc, ops.word_bits, 1))
    ctx.channels.append(Channel("grams", "stream", lay["max_per_step"] * steps,
                                slots * ops.word_bits, f"reduce_{big}", "gram_source"))


def _frontal(ctx) -> None:
    """The emitted multifrontal Cholesky: per elimination step its frontal [H | g] streamed from
    its lane of HA into fgc_cpe.h's cpe_step (feed -> #CPE taps and CPEs -> drain per round of
    #CPE pivots), whose drain writes the conditional into COND and the update matrix into its NF
    lane, while the assembler fills the other HA lane with the next step's Grams and children
    (fgc_eliminate.h's cholesky_overlap; back-substitution step by step is
    :mod:`fgc_backends.hls.units.backsub`'s). Two cascades (:func:`cascades_of`): each with its
    own CPEs, feed and drain, assembler (two lanes of HA, streaming its step's streamed child
    in: two more adders), NF lanes and CONDBUF lanes, and a committer that copies the
    conditionals into COND beside the next region (fgc_cascades.h's cholesky_sets region)."""
    program, ops, c = ctx.program, ctx.les, ctx.opts.cpe
    sets = cascades_of(program, ctx.opts)
    lanes = ctx.opts.cascade_lanes  # fgc_cpe.h's STREAM_WORDS: words a stream word of the cascade
    sizes = ctx.sizes
    cols = sizes["MAX_W"] + 1
    # cpe_round's streams: link[0 ... #CPE - 1] (feed -> tap 0, CPE K -> tap K + 1), tail[K]
    # (CPE K -> drain, when K holds the round's last pivot), tapped[K] (tap K -> CPE K, deep
    # enough for the tap never to stall while its CPE waits for r) and recip[K] (r = 1 / d,
    # tap K -> CPE K); per cascade
    for k in range(sets):
        pre = "cpe_" if k == 0 else f"cpe{k}_"  # the first cascade's keep their names

        def cpe(i, pre=pre):
            return f"{pre[:-1]}{i}" if pre == "cpe_" else f"{pre}{i}"

        for i in range(c):
            ctx.channels.append(Channel(f"{pre}link{i}", "stream", sizes["MAX_W"],
                                        lanes * ops.word_bits,
                                        f"{pre}feed" if i == 0 else cpe(i - 1), f"{pre}tap{i}"))
        for i in range(c):
            ctx.channels.append(Channel(f"{pre}tail{i}", "stream", 2,  # the drain never stalls
                                        lanes * ops.word_bits, cpe(i), f"{pre}drain"))
            ctx.channels.append(Channel(f"{pre}tapped{i}", "stream", cols + ops.div.latency + 2,
                                        lanes * ops.word_bits, f"{pre}tap{i}", cpe(i)))
            ctx.channels.append(Channel(f"{pre}recip{i}", "stream", 2, ops.word_bits,
                                        f"{pre}tap{i}", cpe(i)))
    # a CPE per cascade (build's "cpe" unit counts one cascade's)
    if sets > 1:
        ctx.units.append(Unit("cpe_set1", "the second cascade's process elements", c,
                              (("add", lanes), ("mul", 2 * lanes), ("div", 1))))
    # the feed's adder (mu on the diagonal), the singularity scale's multiplier and divider and
    # the check's divider (the smallest pivot over the scale): one operator of each a loop or
    # statement (cpe_step's sequential code); two cascades: a feed each, one check (the
    # committer's, fgc_cascades.h: one copy of cholesky_set_commit_one)
    ctx.units.append(Unit("cpe_step", "cascade feed (+ mu) and the pivot check", 1,
                          (("add", sets), ("mul", 1), ("div", 2))))
    # fgc_eliminate.h's assembly: the further factors' and the children's entries added
    # through one pipelined HA += loop at II 1 (cholesky_assemble_adds, one call site: the
    # assembler's, which also takes the first step's Grams in a region with no step to factor):
    # one adder; the first factor is stored. Two cascades: the grams process's adder, the
    # alone pass's, and the source's four (a streamed child's word added to each of the two
    # words of a row it streams a cycle into each cascade)
    ctx.units.append(Unit("assemble", "the step's [H | g] from Grams and update matrices", 1,
                          (("add", 1 if sets == 1 else 6),)))
    tables, timing = ctx.tables, ctx.les_timing
    order = [tables["LEVEL_STEPS"][i] for i in range(len(program.schedule.steps))]
    dims = {st.index: (st.frontal_dim, st.separator_dim) for st in program.schedule.steps}
    big = (beside_block([ph for _, ph in ctx.phases], program)
           if ctx.opts.hgc_beside and ctx.les.word_bits == ctx.ops.word_bits
           else None)
    if big is not None:
        _beside(ctx, big, order, dims)
    elif sets == 1:  # each step's pivot check where the elimination is faster (check_beside)
        phases = min((elimination_phases(tables, order, dims, c, ops, timing, lanes, beside)
                      for beside in (False, True)),
                     key=lambda phs: sum(phase_cycles(ph) for ph in phs))
    else:
        phases = cascades_phases(tables, order, dims, c, ops, timing, lanes,
                                 ctx.opts.backsub_lanes)
    for phase in phases if big is None else ():
        ctx.add_phase("solve", phase)
    # cholesky_overlap's stream, a pair of words wide, deep enough that the assembler (a pair a
    # cycle) never waits for the feed (a word a cycle): half a step's pairs and the feed's start
    mw = sizes["MAX_W"]
    for k in range(sets):
        ctx.channels.append(Channel("frontal" if k == 0 else f"frontal{k}", "stream",
                                    mw * (mw + 4) // 8 + ops.add.latency + 8, 2 * ops.word_bits,
                                    "cholesky_assembler" if sets == 1 else "cholesky_set_source",
                                    "cpe_feed" if k == 0 else f"cpe{k}_feed"))
    # accel.cpp.jinja's GRAM and HF (the frontal matrix of one step at a time) and cpe_step's
    # trailing-matrix buffer (the rows a round leaves for the next, copied back into HF); per
    # cascade two HA lanes, two NF lanes, HF and the trailing buffer (and two CONDBUF lanes)
    ctx.memories.append(Memory("gram", sizes["N_GRAM"], ops.word_bits, 1))
    # HA (fgc_eliminate.h) or HA0 / HA1 (fgc_cascades.h): two lanes of two column banks each,
    # four memories a cascade
    ctx.memories.append(Memory("assembly", 2 * sets * sizes["MAX_W"] * cols, ops.word_bits,
                               4 * sets))
    for lane in range(1, 2 * sets):  # NF's further lanes (solver_memories: the first)
        ctx.memories.append(Memory(f"nf_lane{lane}", sizes["N_NF"], ops.word_bits, 1))
    for k in range(sets):
        ctx.memories.append(Memory("frontal" if k == 0 else f"frontal{k}",
                                   sizes["MAX_W"] * cols, ops.word_bits, 1))
        ctx.memories.append(Memory("trailing" if k == 0 else f"trailing{k}",
                                   sizes["MAX_W"] * cols, ops.word_bits, 1))
    if sets > 1:  # CONDBUF
        ctx.memories.append(Memory("condbuf", 2 * sets * sizes["MAX_F"] * cols, ops.word_bits,
                                   1))
    # DPIV / RMAX (each step's pivots and rows' largest |h|, checked beside the next region:
    # two cascades, or one with its check beside, check_beside), two lanes a cascade
    if sets > 1 or any(p.name == "check" for _, ph in ctx.phases for p in ph.processes):
        ctx.memories.append(Memory("pivots", 2 * 2 * sets * sizes["MAX_F"], ops.word_bits, 1))
    solver_memories(sizes, ops, ctx.memories)


SPEC = UnitSpec(
    name="cholesky", role="HGC and the cascade of #CPE Cholesky process elements",
    linear_solver=True,
    build=build, phases=("hgc", "assemble", "cholesky", "cholesky_scalar", "hgc_beside",
                         "hgc_producer", "reassemble", "recholesky"),
    header="fgc_cpe.h",
    constants=(("CPE", "#CPE process elements (PlanOptions.cpe)"),
               ("MAX_W", "widest frontal matrix")),
    printed_by="accel.cpp.jinja: eliminate -> fgc_cpe.h cpe_step",
    applies=lambda program, options: program.solver.linear == "cholesky")

