"""The factor datapath: one pipelined datapath per block type, shared by the Jacobian mode
(``evaluate_<b>``) and the cost mode (``cost_of_<b>``), under the options' ``ALLOCATION``
limits; the gradient pass over AB (QR) and, as a what-if design, whitening raw Jacobians while
stacking. Kernel code of accel.cpp.jinja (no static header)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from fgc.ir.codes import NOISE_CODES
from fgc_backends.cost.kernels import critical_path
from fgc_backends.hls.plan.binding import BoundLoop, bound_unit, loop_ii
from fgc_backends.hls.plan.loops import (
    _block_shape,
    _ceil_log2,
    _ported,
    _sim_table,
    kernel_dot,
    kernel_loop,
)
from fgc_backends.hls.plan.model import PORTS, Loop, Memory, Phase, Process, Unit
from fgc_backends.hls.units.spec import UnitSpec
from fgc_backends.hls.units.special_ops import issued_counts, printed_counts


def cost_in_linearization(program) -> bool:
    """Whether the linearisation gives LM its cost at X (fgc_lm.h's FGC_LM_COST_IN_LINEARIZE,
    no separate cost pass before the first linearisation), half the sum over the instances of
    ‖b‖² = ‖W r‖², when no member has a robust loss (its rows are reweighted, its cost ρ(·) is
    not their square; a robust member keeps the cost pass at X). QR: the gradient pass forms
    every column of [A | b]ᵀ b, the right-hand side's own among them, one more column out of
    the scatter. Cholesky: each instance's Gram holds bᵀb, its last diagonal entry, which the
    HGC's gradient adder (bᵀA into G) adds into a running sum in its own iteration: no cycle
    more."""
    return not any(m.robust for b in program.blocks for m in b.members)


def reduce_loops(block, timing: dict, cost_column: int) -> tuple[Loop, Loop, Loop]:
    """QR: one instance of ``block`` in reduce_all (accel.cpp.jinja's reduce_instance): its
    column map, A^T b PORTS columns of a row a cycle as the datapath's stream brings them (b's
    group first, so no right-hand-side pass) into the adder latency's interleaved partial sums
    (a dot product of m × padded / PORTS terms, :func:`kernel_dot`; the finiteness check rides
    along), the scatter into G at II 1, folding each column's partial sums on the way (a
    ⌈log₂ T_PARTIALS⌉-level tree in its depth); ``cost_column`` 1 with the cost in the
    linearisation (:func:`cost_in_linearization`): the right-hand side's column too, ‖b‖²
    into the cost's sum (one iteration more)."""
    la = timing["acc"][0]  # T_PARTIALS: the adder's latency
    m, d, padded, _ = _block_shape(block)
    return (kernel_loop("columns", d, "fill", timing),
            kernel_dot("rows", m * (padded // PORTS), timing),
            Loop("scatter", d + cost_column, timing["scatter"][0],
                 timing["scatter"][1] + la * _ceil_log2(la)))


def gradient_loops(program, timing: dict) -> list[Process]:
    """QR: reduce_all's loops per block type (G zeroed, then per instance
    :func:`reduce_loops`), each block type's as if alone; what the linearisation costs with
    them beside the datapaths is :func:`linearize_region`'s."""
    n_t = sum(v.dim for v in program.variables)
    bb = int(program.solver.linear == "qr" and cost_in_linearization(program))
    procs = [Process("zero_gradient", "gradient", (kernel_loop("zero", _ported(n_t), "fill",
                                                                timing),))]
    for i, b in enumerate(program.blocks):
        n = sum(1 for f in program.factors if f.block == i)
        procs.append(Process(f"reduce_{i}", "gradient", tuple(
            replace(lp, repeat=n) for lp in reduce_loops(b, timing, bb))))
    return procs


def linearize_region(program, timing: dict, jac: list[Process],
                     counts: dict[int, int] | None = None) -> Phase:
    """QR's linearisation as accel.cpp.jinja emits it: one DATAFLOW region (``linearize_rows``)
    of two processes, the datapaths one after another (``jac``: the factor_<b>_jacobian /
    factor_small_jacobian processes in the emitted order, their trips the instances evaluated)
    writing each instance's rows into AB and to a stream, and reduce_all (G zeroed, then per
    instance in the same order :func:`reduce_loops`) reading it. A block type's first
    instance's rows loop ends no earlier than the rows loop's depth after the datapath loop of
    its block type (the small ones: of factor_small's loop) ends - the stream's last word
    comes then (conservative: the earlier instances' words of a loop come sooner). The region
    takes what fgc_cycles.h's region rule gives: the slower process plus the other's fill, and
    no less than where either process's clock ends. Priced as the phase factor_jacobian: the
    datapaths, then one loop ``beside_datapaths`` of what the gradient adds after them
    (0 when it keeps up). ``counts``: instances per block type (default: all)."""
    c = _linearize_clocks(program, timing, jac, counts)
    e_sum, g_sum, g_clock, zero = c["e_sum"], c["g_sum"], c["g_clock"], c["zero"]
    # the slower process (the datapaths' on a tie: their records come first) plus the other's fill
    region = g_sum + c["e_fill"] if g_sum > e_sum else e_sum + (zero.depth if zero.trip > 0 else 0)
    region = max(region, e_sum, g_clock)
    return Phase("factor_jacobian", False, tuple(jac) + (Process(
        "gradient", "gradient", (Loop("beside_datapaths", 1, 1, region - e_sum),)),))


def _linearize_clocks(program, timing: dict, jac: list[Process],
                      counts: dict[int, int] | None) -> dict:
    """The clocks of :func:`linearize_region`'s two processes: where each datapath loop ends
    (``e_ends``, by name), the datapaths' sum and first depth, the gradient's clock and sum, its
    zeroing loop."""
    small = small_blocks(program)
    if counts is None:
        counts = {i: sum(1 for f in program.factors if f.block == i)
                  for i in range(len(program.blocks))}
    bb = int(cost_in_linearization(program))
    n_t = sum(v.dim for v in program.variables)
    zero = kernel_loop("zero", _ported(n_t), "fill", timing)
    # per datapath loop (emitted order) its block types' instances, in the stream's order
    groups = []
    for p in jac:
        if p.name == "factor_small_jacobian":
            groups.append([i for i in small for _ in range(counts.get(i, 0))])
        else:
            i = int(p.name[len("factor_"):-len("_jacobian")])
            groups.append([i] * counts.get(i, 0))
    shapes = {i: reduce_loops(b, timing, bb) for i, b in enumerate(program.blocks)}
    e_clock, e_ends = 0, []
    for p in jac:
        e_clock += p.cycles
        e_ends.append(e_clock)
    g_clock, g_sum = zero.cycles, zero.cycles
    for p, inst, end in zip(jac, groups, e_ends, strict=True):
        for k, i in enumerate(inst):
            columns, rows, scatter = shapes[i]
            g_clock += columns.cycles
            done = g_clock + rows.cycles
            if k == 0 and any(lp.trip > 0 for lp in p.loops):
                done = max(done, end + rows.depth)
            g_clock = done + scatter.cycles
            g_sum += columns.cycles + rows.cycles + scatter.cycles
    return {"e_ends": {p.name: end for p, end in zip(jac, e_ends, strict=True)},
            "e_sum": e_clock,
            "e_fill": next((lp.depth for p in jac for lp in p.loops if lp.trip > 0), 0),
            "g_clock": g_clock, "g_sum": g_sum, "zero": zero}


def lin_level_cycles(program, timing: dict, jac: list[Process],
                     sets: list[tuple[str, Loop, int]],
                     counts: dict[int, int] | None = None,
                     beside: tuple[Loop, ...] = ()) -> int:
    """The window's one-step linearisation with level 0's unit sets beside it (accel.cpp.jinja's
    lin_level, one DATAFLOW region): :func:`linearize_region`'s two processes and one per unit
    set, ``sets``: (the datapath loop after which its step's rows are all sent,
    :func:`bank_ready_loops`; its fill loop, the words from its stream into its banks at a word
    a cycle; its step's cycles, the plan's QR process of that step). A set's fill ends no
    earlier than its depth after that datapath loop ends (the stream's last word comes then),
    its step follows. The region takes what fgc_cycles.h's region rule gives: the slowest
    process plus the others' fills (each's first loop's depth), and no less than where any
    process's clock ends. ``counts``: instances per block type (default: all; the one-step
    solve's once keyframe 0 has left: :func:`solve_skip`). ``beside``: the loops of one more
    process of the region, from its start (the wave's commit of set 0's step, units/qr.py's
    ``wave_commit_loops``)."""
    c = _linearize_clocks(program, timing, jac, counts)
    zero = c["zero"]
    totals = [c["e_sum"], c["g_sum"]] + [fill.cycles + step for _, fill, step in sets]
    firsts = [c["e_fill"], zero.depth if zero.trip > 0 else 0] + [fill.depth for _, fill, _ in sets]
    run = [lp for lp in beside if lp.trip > 0]
    if run:
        totals.append(sum(lp.cycles for lp in run))
        firsts.append(run[0].depth)
    slowest = max(range(len(totals)), key=lambda k: (totals[k], -k))
    region = totals[slowest] + sum(f for k, f in enumerate(firsts) if k != slowest)
    ends = [c["e_sum"], c["g_clock"]] + [
        max(fill.cycles, c["e_ends"][wait] + fill.depth) + step for wait, fill, step in sets]
    return max(region, *ends, *totals[len(totals) - len(run):])


def lin_wave_region(program, timing: dict, jac: list[Process],
                    sets: list[tuple[str, Loop, int]], wave,
                    counts: dict[int, int] | None = None,
                    commit: tuple[Loop, ...] = ()) -> int:
    """:func:`lin_level_cycles` with the root step in a wavefront inside the region
    (units/qr.py's ``lin_wave``; ``sets``' set 0 its QR step, whose collector commits it as it
    writes it; its rows are final at its QR step's region ends): set
    1's step is its whole process after its fill (``wave(start0, start1, ready)``: units/qr.py's
    ``lin_wave_loops`` from set 0's and set 1's starts, the cycles of the region at which their
    fills end, and the end of each datapath loop, ``ready``), the rest as lin_level_cycles.
    ``counts``: instances per block type (default: all), as lin_level_cycles. ``commit``: the
    loops of the process that writes set 0's step into COND and NF as its collector streams it,
    then set 1's two conditionals (units/qr.py's ``wave_commit_loops``; from the region's start,
    its last words no earlier than set 0's step ends and its pairs no earlier than set 1's, as
    fgc_cycles.h's FGC_WAIT counts them: units/qr.py's ``wave_commit_end``)."""
    from fgc_backends.hls.units.qr import wave_commit_end

    c = _linearize_clocks(program, timing, jac, counts)
    starts = [max(fill.cycles, c["e_ends"][w] + fill.depth) for w, fill, _ in sets]
    span = sum(lp.cycles for lp in wave(starts[0], starts[1], c["e_ends"]))
    region = lin_level_cycles(program, timing, jac, [sets[0], (sets[1][0], sets[1][1], span)],
                              counts, commit)
    if not commit:
        return region
    ends = (starts[0] + sets[0][2] if sets[0][1].trip > 0 else 0,
            starts[1] + span if sets[1][1].trip > 0 else 0)
    return max(region, wave_commit_end(commit, *ends))


def datapath_order(program, opts=None) -> list[int]:
    """The datapath loops of ``linearize_rows`` / ``lin_level`` in the emitted order
    (accel.cpp.jinja's evaluate_all and reduce_all: the gradient reads the stream in the
    datapaths' order), each by its block type, the small block types' one loop by the first of
    them: the block types' order, but with the root step in a wavefront inside lin_level
    (units/qr.py's ``lin_wave``, set 1 reflects its step and then the root: set 1 is the
    region's path) the loops that send rows to set 1's step first, then those that send rows
    to set 0's, then those that send only the root's own rows (set 1 reads them after its
    step), then the rest, each group in the block types' order (a stable sort; a loop that
    sends rows to several goes with the first): set 1 starts as soon as its own loops end,
    not after set 0's. (The root's rows before set 0's: set 0 starts later and its passed rows,
    which the root reads, come later: keyframe 14 of paper A's pick 8,902 cycles against
    8,486.) ``opts`` None: the block types' order."""
    small = small_blocks(program)
    order = [i for i in range(len(program.blocks)) if i not in small or i == small[0]]
    if opts is None:
        return order
    from fgc_backends.hls.units.qr import _tables_of, lin_wave, rows_in_banks

    if lin_wave(program, opts) is None:
        return order
    in_banks = rows_in_banks(program, opts, _tables_of(program), root=True)
    sets: dict[int, set[int]] = {}
    for f, (u, _, _) in in_banks.items():
        b = program.factors[f].block
        sets.setdefault(small[0] if b in small else b, set()).add(u)

    rank = {1: 0, 0: 1, 2: 2}  # set 1's step, then set 0's, then the root's rows, then none
    return sorted(order, key=lambda i: min((rank[u] for u in sets.get(i, ())), default=3))


def datapath_loop_names(program, opts=None) -> list[str]:
    """The datapath loops of ``linearize_rows`` / ``lin_level`` in the emitted order
    (:func:`datapath_order`): a block type's own ``factor_<b>_jacobian``, the small block
    types' one ``factor_small_jacobian`` where the first of them stands."""
    small = small_blocks(program)
    return [f"factor_{i}_jacobian" if i not in small else "factor_small_jacobian"
            for i in datapath_order(program, opts)]


def bank_fill_words(program, tables: dict, in_banks: dict, sets: int,
                    skip: frozenset = frozenset()) -> list[int]:
    """Per unit set, the stream words of its step's factor rows the datapaths send it (each
    instance's m × (d + 1) words of [A | b], :data:`PORTS` a word: accel.cpp.jinja's BankWord),
    the trip of its fill loop in lin_level (units/qr.py's ``rows_in_banks``: ``in_banks``);
    ``skip``: instances not evaluated (:func:`solve_skip`), their words not sent."""
    a = tables["FACTOR_A_OFF"]
    return [sum(_ported(a[f + 1] - a[f]) for f, (u, _, _) in in_banks.items()
                if u == s and f not in skip)
            for s in range(sets)]


def solve_skip(gone: frozenset, in_banks: dict) -> frozenset:
    """The factor instances the window's one-step linearisation (lin_level, accel.cpp.jinja's
    part 3) does not evaluate once keyframe 0 has left the window: those of the leaf step that
    hold nothing from then on (``gone``: :meth:`~fgc_backends.hls.window.WindowLayout.leaf_gone`,
    every member's rows zero at every keyframe from then on - keyframe 0's priors), when every
    one of them sends its rows into a unit set's banks (``in_banks``, units/qr.py's
    ``rows_in_banks``). Their rows are zero, so skipping them changes no result: the banks'
    rows stay zero (qr_step leaves them so), the gradient and the cost gain nothing from them,
    and AB's rows of them are read by no one - the solve's stack takes that set's step as
    reflected (PRESOLVED), the marginal's live stack leaves them out (LEAF_SKIP). Empty
    otherwise (a gone instance whose rows a stack would read from AB)."""
    if not gone or not in_banks or not all(f in in_banks for f in gone):
        return frozenset()
    return frozenset(gone)


def bank_ready_loops(program, in_banks: dict, sets: int, opts=None) -> list[str]:
    """Per unit set, the datapath loop (emitted order, :func:`datapath_loop_names` under
    ``opts``) after which the datapaths have sent every row of its step: the last that
    evaluates one of its factors (the small datapath's loop as a whole: conservative for its
    earlier instances)."""
    names = datapath_loop_names(program, opts)
    small = small_blocks(program)
    out = []
    for s in range(sets):
        loops = {f"factor_{b}_jacobian" if b not in small else "factor_small_jacobian"
                 for f, (u, _, _) in in_banks.items() if u == s
                 for b in (program.factors[f].block,)}
        out.append(max(loops, key=names.index))
    return out


def raw_jacobian_words(b) -> int:
    """Words of one instance of block ``b`` stored raw: the residual, the Jacobians' entries
    that are not structurally 0 or ±1 (``derive``'s structure codes "x") and the members'
    whitening parameters."""
    entries = sum(code == "x" for blk in b.structure for row in blk for code in row)
    return b.residual_dim + entries + sum(m.noise_params for m in b.members)


def whitening_macs(b) -> int:
    """Multiply-accumulates whitening one instance of block ``b`` while stacking: for each
    member, each column of [J | -r] and each whitened row i, the rows r the member's W mixes
    into i (r ≥ i for a full upper-triangular W, r = i otherwise) whose raw entry is not a
    structural zero."""
    cols = [[blk[r][j] for r in range(b.residual_dim)] for blk in b.structure
            for j in range(len(blk[0]) if blk else 0)]
    cols.append(["x"] * b.residual_dim)  # the residual column
    macs = 0
    for m in b.members:
        r0, r1 = m.rows
        for col in cols:
            nz = [col[r] != "0" for r in range(r0, r1)]
            if m.noise_kind == "full":
                macs += sum(sum(nz[i:]) for i in range(len(nz)))
            else:
                macs += sum(nz)
    return macs


# RTL instances of the cost pass: LM control's two cost hooks (total_cost(X), total_cost(X_TRIAL))
# share one total_cost (fgc_lm.h: the hooks and try_steps INLINE into optimize, whose ALLOCATION
# function instances=total_cost limit=1 binds both calls to it; was 2, every cost datapath twice)
COST_CALL_SITES = 1

# A block type is *small* when its two kernels (Jacobian and cost mode) hold at most this many
# operations together, none of them trig or special, and no member has a robust loss: the
# priors and GPS factors of a navigation graph (6 to 43 operations). With two or more small
# block types, each mode of theirs is one time-multiplexed datapath (factor_small): one
# pipelined loop over all their instances whose body branches on the instance's block type,
# every branch in one function under one ALLOCATION, so the exclusive branches share its
# operators (Vitis binds per function and pipelined loop, UG1399) instead of each block type
# keeping its own. A larger datapath (an IMU factor) keeps its own loop and II.
SMALL_OPS = 64


def small_blocks(program) -> tuple[int, ...]:
    """The block types that share the factor_small datapath (:data:`SMALL_OPS`), or () when
    fewer than two qualify (nothing to share). A Cholesky design shares none: there every block
    type's datapath streams its whitened rows to its own HGC in one DATAFLOW region
    (``linearize_<b>``), which a time-multiplexed datapath over several block types would have
    to feed to several HGCs (not built)."""
    if program.solver.linear == "cholesky":
        return ()
    small = tuple(i for i, b in enumerate(program.blocks)
                  if sum(b.ops_after.values()) + sum(b.ops_cost.values()) <= SMALL_OPS
                  and not any(b.ops_after.get(k, 0) or b.ops_cost.get(k, 0)
                              for k in ("trig", "special"))
                  and not any(m.robust for m in b.members))
    return small if len(small) > 1 else ()


def _merged(*parts: dict) -> dict[str, int]:
    out: dict[str, int] = {}
    for part in parts:
        for k, n in part.items():
            if n:
                out[k] = out.get(k, 0) + n
    return out


def small_branch_ops(program, blocks, mode: str) -> list[dict[str, int]]:
    """Per small block type (:func:`small_blocks`), the operations of its branch of the shared
    ``mode`` function (``evaluate_small_one`` / ``cost_small_one``): its kernel in that mode and
    the instance's own operations (whitening; the members' cost sum), all under the shared
    ALLOCATION. ``blocks``: the Program's block contexts."""
    out = []
    for i in small_blocks(program):
        b, bc = program.blocks[i], blocks[i]
        if mode == "jacobian":
            out.append(_merged(printed_counts(b, "jacobian"), whitening_ops(bc)))
        else:  # robust_ops less the running total's add, which is the loop's own
            own = robust_ops(bc)
            out.append(_merged(printed_counts(b, "cost"), {**own, "add": own["add"] - 1}))
    return out


def small_allocation(program, blocks, opts, mode: str, table
                     ) -> tuple[tuple[tuple[str, int], ...], int, int]:
    """The shared ``mode`` function's ``ALLOCATION`` limits, its loop's II and the cycles the
    largest branch takes to issue its operations on them. The II is at
    least what the global memories' ports allow with every branch's accesses counted (the
    text's sum, as the second reader reads it: an upper bound for exclusive branches) and, in
    cost mode, the running total's adder latency; per kind the limit is what the largest branch
    needs to issue its operations in that II (exclusive branches share them), at most the
    options' limit (the II then grows to what those limits issue)."""
    alloc = dict(opts.allocation)
    branches = small_branch_ops(program, blocks, mode)
    accesses: dict[int, int] = {}
    from fgc_backends.hls.plan.loops import _tables
    in_banks = banked_blocks(program, opts, _tables(program)) if mode == "jacobian" else ()
    for i in small_blocks(program):
        for a, (n, _) in enumerate(instance_accesses(blocks[i], mode,
                                                     program.solver.linear == "qr",
                                                     i in in_banks)):
            accesses[a] = accesses.get(a, 0) + n
    ii = loop_ii((n, 1) for n in accesses.values())
    if mode == "cost":  # the running total, in instance order: through the adder
        ii = max(ii, table.add.latency)
    need: dict[str, int] = {}
    for ops in branches:
        for k, n in ops.items():
            need[k] = max(need.get(k, 0), math.ceil(n * table.op(k).ii / ii))
    limits = tuple(sorted((k, min(n, alloc.get(k, n))) for k, n in need.items() if n))
    issue = max([1] + [math.ceil(ops[k] * table.op(k).ii / n) for k, n in limits
                       for ops in branches if ops.get(k)])
    return limits, max(ii, issue), issue


def factor_allocation(program, opts) -> list[tuple[tuple[str, int], ...]]:
    """Per block type the ``ALLOCATION`` limits its ``factor_<b>`` function is emitted with:
    the options' limits (scaled by the block's share of the work, ``allocation_scaling``), at
    most what the datapath uses in either mode."""
    alloc = dict(opts.allocation)
    n_of = [sum(1 for f in program.factors if f.block == i) for i in range(len(program.blocks))]
    printed = [(printed_counts(b, "jacobian"), printed_counts(b, "cost")) for b in program.blocks]
    work = [n * sum(jac.values()) for n, (jac, _) in zip(n_of, printed, strict=True)]
    heaviest = n_of[max(range(len(work)), key=work.__getitem__)] if work else 1
    out = []
    for i, (jac, cost) in enumerate(printed):
        used = {k: max(jac.get(k, 0), cost.get(k, 0)) for k in alloc}
        share = {k: alloc[k] if opts.allocation_scaling == "uniform"
                 else max(1, math.ceil(alloc[k] * min(1.0, n_of[i] / heaviest)))
                 for k in alloc}
        out.append(tuple((k, min(share[k], n)) for k, n in used.items() if n > 0))
    return out


def mode_issue(b, limits, mode: str, ops) -> tuple[tuple[tuple[str, int], ...], int]:
    """(the ``ALLOCATION`` limits of block ``b``'s ``mode`` function, :func:`mode_allocation`;
    the II they allow: what an evaluation issues through them, a special function's exclusive
    branches sharing the allocated operators, units/special_ops.py's issued_counts)."""
    allocated = mode_allocation(limits, printed_counts(b, mode))
    issued = issued_counts(b, mode)
    return allocated, max([1] + [math.ceil(issued.get(k, 0) * ops.op(k).ii / n)
                                 for k, n in allocated])


def mode_allocation(limits, counts: dict) -> tuple[tuple[str, int], ...]:
    """The ``ALLOCATION`` limits of one mode's function (``factor_<b>``: the Jacobian's counts,
    ``factor_cost_<b>``: the cost's): the block's ``limits`` (:func:`factor_allocation`), at
    most that mode's operations."""
    return tuple((k, min(n, counts.get(k, 0))) for k, n in limits if counts.get(k, 0) > 0)


def whitening_ops(bc) -> dict[str, int]:
    """The operations of one ``evaluate_<b>`` iteration outside ``factor_<b>`` (its ALLOCATION
    does not reach them), as accel.cpp.jinja prints them for block context ``bc``
    (``fgc_backends.cfamily.blocks.BlockContext``): per member ``whiten`` (full noise: row i's
    leading product for every row, then R_ij times row j for the dense rows j > i; otherwise one
    product an entry), its ``whiten_tail`` (an add per constant entry, a multiply-add per
    right-hand side) and, for a member with a robust loss (``MemberSpec.robust``), ``reweight``
    (‖e‖², two square roots, the weight's divides, the rows scaled)."""
    s, ops = bc.padded, {"add": 0, "mul": 0, "div": 0, "sqrt": 0}
    for m in bc.members:
        r, d = m.rows, m.dense
        if m.kind == NOISE_CODES["full"]:
            ops["mul"] += r * s + s * d * (d - 1) // 2
            ops["add"] += s * d * (d - 1) // 2
        else:
            ops["mul"] += r * s
        for _, _, _, entries in m.tail:
            ops["add"] += len(entries) + 1
            ops["mul"] += 1
        if not m.robust:  # no reweight call printed
            continue
        ops["add"] += r + 1  # reweight: the squared norm, k² + e²
        ops["mul"] += r + 3 + r * s
        ops["div"] += 2
        ops["sqrt"] += 2
    return ops


def robust_ops(bc) -> dict[str, int]:
    """The operations of one ``cost_of_<b>`` iteration outside ``factor_<b>``: per member its
    sum and, with a robust loss (``MemberSpec.robust``), ``robust_loss`` (its Huber and Cauchy
    branches both built), then the total's."""
    nm, nr = len(bc.members), sum(m.robust for m in bc.members)
    ops = {"add": nm + nr + 1, "mul": 9 * nr, "div": nr, "sqrt": nr, "special": nr}
    return {k: n for k, n in ops.items() if n}


def instance_accesses(bc, mode: str, grad_stream: bool = False,
                      banked: bool = False) -> list[tuple[int, int]]:
    """(accesses, banks) of one instance to each global memory the Jacobian (``mode``
    "jacobian") or cost loop touches: X (the variables' storage), DATA_BUF (its measurements
    and noise parameters, two robust words a member) and, in Jacobian mode, AB (its whitened
    rows, m × (d + 1) words). None of them is partitioned (one bank, two ports). A member
    without a robust loss reads no robust words. ``grad_stream`` (QR, Jacobian mode): the
    rows go to the gradient's stream too, m × padded / PORTS words, one a cycle (counted as
    m × padded accesses of one two-port bank: the same cycles). ``banked`` (units/qr.py's
    rows_in_banks: the block's instances of level 0's first steps): the rows into a unit
    set's banks too, m × (d + 1) words through a run-time bank index (t % n_u), counted as
    one two-port memory's accesses, as AB's."""
    data = sum(m.meas_words + m.n_params + 2 * m.robust for m in bc.members)
    out = [(bc.n_x_in, 1), (data, 1)]
    if mode == "jacobian":
        out.append((bc.m * bc.stride, 1))
        if grad_stream:
            out.append((bc.m * bc.padded, 1))
        if banked:
            out.append((bc.m * bc.stride, 1))
    return out


def banked_blocks(program, opts, tables) -> frozenset[int]:
    """The block types with an instance whose rows go straight into a unit set's banks
    (units/qr.py's rows_in_banks)."""
    from fgc_backends.hls.units.qr import rows_in_banks

    banked = rows_in_banks(program, opts, tables, root=True)  # (and the wave's root rows)
    return frozenset(f.block for i, f in enumerate(program.factors) if i in banked)


def build(ctx) -> None:
    """Per block type a datapath unit and its AB memory; the factor_jacobian and factor_cost
    phases (the emitted instance loops run one block type after another); QR's gradient pass;
    raw Jacobians' whitening (what-if).

    Each instance loop runs at the II its allocated operators and its memories allow (the
    larger: :func:`~fgc_backends.hls.plan.binding.loop_ii`); the unit's operators are what
    Vitis binds (:mod:`fgc_backends.hls.plan.binding`): both call sites of ``factor_<b>``
    (Jacobian and cost loop) under its ``ALLOCATION``, plus each loop's own operations outside
    it (whitening, robust weights) at the loop's II."""
    program, opts, ops = ctx.program, ctx.opts, ctx.ops
    sim_ops = _sim_table(ops)
    jac, cost = [], []
    whiten_macs = 0
    allocations = factor_allocation(program, opts)
    small = small_blocks(program)
    # the column design: trial_cost's loops at the IIs that keep up with its retire
    banked = trial_banked(program, opts)
    chosen = keep_up_ii(ctx, allocations, small) if banked else {}
    in_banks = banked_blocks(program, opts, ctx.tables)
    for i, (b, bc) in enumerate(zip(program.blocks, ctx.blocks, strict=True)):
        if opts.jacobian_storage == "raw":
            words = raw_jacobian_words(b) * len(bc.instances)
            whiten_macs += whitening_macs(b) * len(bc.instances)
        else:
            words = b.residual_dim * (1 + sum(b.variable_dims)) * len(bc.instances)
        ctx.memories.append(Memory(f"ab_{i}", words, ops.word_bits, 1))
        if i in small:
            if i == small[0]:
                _small_datapath(ctx, small, jac, cost)
            continue
        name = f"factor_{i}"
        instances = len(bc.instances)
        bound = []
        for mode, text, out, own in (
                ("jacobian", b.kernel, jac, whitening_ops(bc)),
                ("cost", b.cost_kernel, cost, robust_ops(bc))):
            counts = printed_counts(b, mode)  # as printed, the special functions' bodies in
            allocated, issue = mode_issue(b, allocations[i], mode, ops)
            if mode == "cost" and banked:  # factor_cost_<b>'s one call site: trial_cost's
                ii = chosen[i]  # loop, gather_trial_<b> from DATA_BUF's two banks
            else:
                ii = max(issue, loop_ii(instance_accesses(bc, mode,
                                                          program.solver.linear == "qr",
                                                          i in in_banks and mode == "jacobian")))
            if mode == "cost":  # the emitted cost_of_<b> sums the instances' costs in order (the
                ii = max(ii, ops.add.latency)  # simulator's): a recurrence through the adder
            # one evaluation ends no earlier than its critical path, nor before the allocated
            # operators have issued all its operations (a lower bound of the schedule's depth)
            depth = max(critical_path(text, sim_ops), issue)
            out.append(Process(f"{name}_{mode}", name,
                               (Loop(f"{name}_{mode}_instances", instances, ii, depth),)))
            # factor_<b> / factor_cost_<b> under its ALLOCATION at this call site, and the
            # loop's own operations
            # (the cost loop once per total_cost instance: LM control's cost at X and at
            # X_TRIAL share one, COST_CALL_SITES)
            copies = COST_CALL_SITES if mode == "cost" else 1
            # (the emitter prints every limit: operation instances for the arithmetic,
            # function instances for trig and special, which Vitis honours alike)
            factor = BoundLoop(f"{name}_{mode}", tuple(counts.items()), ii, allocated, copies)
            bound.append(factor.instances(ops))
            # the loop's own operations: pipelined cores (robust_loss's log1p an hls_math
            # function, not the rolled Horner unit the table's "special" II describes)
            bound.append(BoundLoop(f"{name}_{mode}_own", tuple(own.items()), ii, (),
                                   copies).instances())
        operators: dict[str, int] = {}
        for part in bound:
            for k, n in part.items():
                operators[k] = operators.get(k, 0) + n
        ctx.units.append(Unit(name, f"factor datapath of block {b.name!r} (its Jacobian and "
                              "cost call sites, whitening, robust weights)", 1,
                              tuple(sorted(operators.items()))))
    if program.solver.linear == "qr":  # Cholesky's gradient comes with the HGC (units.cholesky)
        # the datapaths beside the gradient, one region (linearize_region), in the emitted
        # order (datapath_order: with the root in a wavefront, set 1's loops first)
        names = datapath_loop_names(program, opts)
        jac.sort(key=lambda p: names.index(p.name))
        ctx.add_phase("linearize", linearize_region(program, ctx.timing, jac))
        # accumulate, one module for every block type (reduce_all's ALLOCATION function
        # limit=1, reduce_<b> INLINE, the sizes run-time): PORTS multiply-adds a cycle (a word
        # of the datapaths' stream), then a column a cycle through the fold of its T_PARTIALS
        # partial sums and the add into G
        la = ops.add.latency
        # the stream between them (linearize_rows' FIFO): the largest instance's words, PORTS
        # values each; its BRAM priced as a memory (the plan's stream channels are the linear
        # solver's network, process_network's)
        words = max(bc.m * bc.padded // PORTS for bc in ctx.blocks)
        # (a word PORTS scalars side by side: PORTS banks of `words` scalars, the same BRAM)
        ctx.memories.append(Memory("gradient_rows", words * PORTS, ops.word_bits, PORTS))
        ctx.units.append(bound_unit("gradient", "A^T b, PORTS columns a cycle from the "
                                    "datapaths' stream, one module for every block type",
                                    [BoundLoop("accumulate", (("add", PORTS), ("mul", PORTS)), 1),
                                     BoundLoop("scatter", (("add", la),), 1)], table=ops))
    else:
        ctx.add_phase("linearize", Phase("factor_jacobian", False, tuple(jac)))
    if opts.jacobian_storage == "raw":
        # whitening while stacking: W·[J | -r] of each instance, one multiply-accumulate a
        # cycle in each of n_u lanes, before the solver reads the rows
        ctx.units.append(Unit("whiten", "W·[J | -r] while stacking the raw Jacobians",
                              opts.units, (("add", 1), ("mul", 1))))
        ctx.add_phase("linearize", Phase("whiten_stack", False, (Process("whiten", "whiten", (
            Loop("macs", math.ceil(whiten_macs / opts.units), 1,
                 ops.mul.latency + ops.add.latency),)),), linear=True))
    ctx.shared["cost_loops"] = cost_loops(cost)
    from fgc_backends.hls.units.state_update import fed_by_backsub, retire_timing
    if not fed_by_backsub(program, opts):  # what-if whole-matrix Cholesky: a pass of its own
        ctx.add_phase("cost", Phase("factor_cost", False, tuple(cost)))
        return
    # the cost at X_TRIAL: back_substitute's trial_cost process (units.backsub prices the
    # region); the cost at X, once per call: the same region with no solve, backsub_retire
    # sending X's variables a retire II apart
    loops = trial_state(ctx)
    ctx.shared["trial_loops"] = loops
    from fgc_backends.hls.units.lm_control import retire_step_test
    ii, depth = retire_timing(program.variables, ops, ctx.sizes["MAX_F"],
                              opts.state_allocation,
                              retire_step_test(program, opts))
    var_end = [j * ii + depth for j in range(len(program.variables))]
    pos = trial_positions(program, ctx.tables) if any(lp.proc == 1 for lp in loops) else None
    end = max(var_end[-1:] + [trial_end(loops, var_end, pos)])
    # (each datapath's cost-mode loop kept as a process of no cycles: trip 0, its II and
    # depth what trial_cost's loop for it starts from, cost_loops)
    idle = tuple(Process(p.name, p.unit, (replace(p.loops[0], trip=0),)) for p in cost)
    # (none when the linearisation gives the cost at X: cost_in_linearization)
    at_x = 0 if cost_in_linearization(program) else 1
    ctx.add_phase("cost", Phase("factor_cost", False, (Process("trial_cost", "factor_cost", (
        Loop("cost_at_x", at_x, 1, end),)),) + idle, per="call"))
    # the process's copy of the retired state, and the stream of retired variables
    ctx.memories.append(Memory("trial_state", sum(v.storage_dim for v in program.variables),
                               ops.word_bits, 1))
    if any(lp.feed for lp in loops):  # the slot design's trial_cost_b (slot_split_loops): its
        # running total's adder (its loops' `total +=`: a process of its own, not shared with
        # trial_cost's; the sum of the two totals is LM control's, after the region)
        ctx.units.append(Unit("trial_cost_b", "the second cost process's running total", 1,
                              (("add", 1),)))
    if any(lp.proc == 1 for lp in loops):  # trial_cost_b: its copies of the state and data
        ctx.memories.append(Memory("trial_state_b", sum(v.storage_dim
                                                        for v in program.variables),
                                   ops.word_bits, 1))
        # (the column design's gathers read it as DATA_BUF, cyclic 2; the slot design's
        # gather_b_<b> as one bank)
        ctx.memories.append(Memory("data_b", trial_b_data(program, loops, ctx.tables)[1],
                                   ops.word_bits,
                                   1 if any(lp.feed for lp in loops) else TRIAL_DATA_BANKS))


def _small_datapath(ctx, small: tuple[int, ...], jac: list, cost: list) -> None:
    """The factor_small unit (:data:`SMALL_OPS`): per mode one pipelined loop over the small
    block types' instances (in block order), one branch a block type in one function under
    :func:`small_allocation`. Its II: the most any branch needs to issue on those operators,
    and the ports of the global memories (:func:`small_allocation`); its depth the deepest
    branch's critical path or the largest branch's issue time."""
    program, opts, ops = ctx.program, ctx.opts, ctx.ops
    sim_ops = _sim_table(ops)
    count = sum(len(ctx.blocks[i].instances) for i in small)
    operators: dict[str, int] = {}
    for mode, out in (("jacobian", jac), ("cost", cost)):
        branches = small_branch_ops(program, ctx.blocks, mode)
        allocated, ii, issue = small_allocation(program, ctx.blocks, opts, mode, ops)
        # an instance ends no earlier than its branch's critical path, nor before the shared
        # operators have issued the largest branch's operations
        depth = max([issue] + [critical_path(program.blocks[i].kernel if mode == "jacobian"
                                             else program.blocks[i].cost_kernel, sim_ops)
                               for i in small])
        out.append(Process(f"factor_small_{mode}", "factor_small",
                           (Loop(f"factor_small_{mode}_instances", count, ii, depth),)))
        copies = COST_CALL_SITES if mode == "cost" else 1
        shared = BoundLoop(f"factor_small_{mode}", tuple(_merged(*branches).items()), ii,
                           allocated, copies)
        own = BoundLoop(f"factor_small_{mode}_own", (("add", 1),) if mode == "cost" else (),
                        ii, (), copies)
        for part in (shared.instances(ops), own.instances()):
            for k, n in part.items():
                operators[k] = operators.get(k, 0) + n
    names = ", ".join(repr(program.blocks[i].name) for i in small)
    ctx.units.append(Unit("factor_small", f"one time-multiplexed factor datapath of the small "
                          f"block types {names} (both modes)", 1,
                          tuple(sorted(operators.items()))))


SPEC = UnitSpec(
    name="datapath", role="factor datapaths (Jacobian and cost modes) and the gradient pass",
    build=build, phases=("factor_jacobian", "whiten_stack", "factor_cost"),
    constants=(("ALLOCATION", "per block type: operator limits (PlanOptions.allocation)"),),
    printed_by="accel.cpp.jinja: evaluate_<b>, cost_of_<b>, reduce_<b>")



# ---- the cost pass beside back-substitution (issue 33): back_substitute's third process,
# trial_cost (accel.cpp.jinja), downstream of backsub_retire's stream of retired variables

@dataclass(frozen=True)
class TrialLoop:
    """One loop of trial_cost: a block type's cost datapath (``key`` its index, or "small":
    the shared small datapath) over ``entries`` in the order they can run, each (factor
    instance, or -1 for an entry that only takes variables; the variables it takes from the
    stream first, in back-substitution's order), at most ``k`` taken an entry; ``ii`` and
    ``depth`` of the emitted loop."""
    key: int | str
    entries: tuple[tuple[int, tuple[int, ...]], ...]
    k: int
    ii: int
    depth: int
    proc: int = 0  # 0: trial_cost; 1: trial_cost_b (split_trial_loops)
    # cycles its process spends before this loop on trial_cost_b's data words (the slot design
    # in two processes, slot_split_loops: trial_cost sends them, trial_cost_b takes them in)
    feed: int = 0
    # a fused loop (slot_split_loops): the datapaths whose instances it costs, one an entry
    # (exclusive branches on the entry's block type: one pipeline, no drain between them);
    # ``key`` then names them ("0_3")
    fused: tuple[int, ...] = ()

    @property
    def name(self) -> str:
        return f"cost_{self.key}"


def trial_loops(program, retire_vars, costs: dict, max_storage: int, accesses: dict,
                var_end: list[int] | None = None,
                tables: dict | None = None, data: dict | None = None) -> tuple[TrialLoop, ...]:
    """trial_cost's loops, in the order the process runs them: per cost datapath (``costs``:
    key -> (instances, cost-mode II, depth), a block type's own or the small types' shared
    one; ``accesses[key]``: the x words an instance gathers) its instances in the order their
    last variable is retired (back-substitution's ``retire_vars``); the datapath with the most
    work (instances x II) first, so the later loops find their variables already taken.
    Before an instance, the entry takes from the stream every variable retired up to its
    last one not yet taken, at most its datapath's widest instance's variable count an entry
    (more: entries of their own before it, no instance); what no instance needed is taken by
    entries at the end of the last loop. Each entry's II: the datapath's cost-mode II, and the
    process's copy of the state (one memory, :data:`PORTS` words a cycle) written k ×
    ``max_storage`` words and read the instance's x words an entry; depth: the datapath's,
    plus the taken words' write and read (2) where it takes any.

    ``var_end`` (the slot design's, units/backsub.py's slot_retire: when each retired variable
    is in the stream): the loops one after another drain between them, so a loop whose
    instances wait on the last variables is better run last; the datapaths are also tried in
    the order their last instance is ready (``ready_order``, the most work first among equals),
    and that order is kept if it ends sooner (:func:`trial_end`), else the one above. With
    ``tables`` too, the cost pass in two processes (:func:`slot_split_loops`) where that ends
    sooner still; with ``data`` too (key -> the data words an instance reads), a process's block
    datapaths may run as one loop there (:func:`_fuse`)."""
    order = work_order(costs)
    base = _ordered_loops(program, retire_vars, costs, max_storage, accesses, order)
    if var_end is None:
        return base
    ready = _ordered_loops(program, retire_vars, costs, max_storage, accesses,
                           ready_order(program, retire_vars, costs))
    one = ready if trial_end(ready, var_end) < trial_end(base, var_end) else base
    if tables is None:
        return one
    two = slot_split_loops(program, retire_vars, costs, max_storage, accesses, var_end, tables,
                           data)
    pos = {v: i for i, v in enumerate(retire_vars)}
    if two and trial_end(two, var_end, pos) < trial_end(one, var_end):
        return two
    return one


# trial_cost_b's data words in the slot design: trial_cost reads them out of DATA_BUF and sends
# them on a stream at its start (a pipelined loop, II 1: the read and the write, depth 2),
# trial_cost_b writes them into DATA_B (the read and the write, a cycle behind: depth 3)
FEED_SEND_DEPTH, FEED_TAKE_DEPTH = 2, 3


def slot_split_loops(program, retire_vars, costs: dict, max_storage: int, accesses: dict,
                     var_end: list[int], tables: dict,
                     data: dict | None = None) -> tuple[TrialLoop, ...] | None:
    """The slot design's cost pass in two processes: ``trial_cost`` and ``trial_cost_b`` side by
    side, each fed the retired variables its instances read on a stream of its own
    (TRIAL_SEND), each its loops one after another in the better of the most-work and the
    ready order (:func:`trial_loops`). The shared small datapath stays in ``trial_cost`` (it
    reads DATA_BUF); ``trial_cost_b`` reads its instances' data lines from ``DATA_B``, its own
    copy, which ``trial_cost`` fills at its start through a stream (every stream move writes
    DATA_BUF: no second copy is kept there): :data:`FEED_SEND_DEPTH` / :data:`FEED_TAKE_DEPTH`
    cycles past the words (:func:`trial_b_data`'s span). Every split of the datapaths with a
    datapath in each process is priced (:func:`trial_end`); the one that ends first (the
    first of equals, in the order of the keys), or None with fewer than two datapaths."""
    keys = sorted(c for c in costs if c != "small")
    pos = {v: i for i, v in enumerate(retire_vars)}
    best, best_end = None, None
    for mask in range(1, 1 << len(keys)):
        second = [keys[i] for i in range(len(keys)) if mask >> i & 1]
        first = [c for c in costs if c not in second]
        if not any(costs[c][0] for c in first) or not any(costs[c][0] for c in second):
            continue  # (a process with no instance)
        out: list[TrialLoop] = []
        for q, group in enumerate((first, second)):
            sub = {c: costs[c] for c in group}
            needed = {i for c in group for f in sub[c][0] for i in _factor_vars(program, f)}
            mine = [v for v in retire_vars if v in needed]
            orders = [work_order(sub), ready_order(program, mine, sub)]
            # the block datapaths fused into one loop (:func:`_ordered_loops`), the small one
            # before or after it: no drain between them (last: kept only where that ends sooner)
            fused = tuple(sorted(c for c in group if c != "small" and sub[c][0]))
            if len(fused) > 1 and data is not None:
                rest = [c for c in group if c != "small" and c not in fused]
                tail = ["small"] if "small" in group else []
                orders += [tail + [fused] + rest, [fused] + rest + tail] if tail \
                    else [[fused] + rest]
            cands = [[replace(lp, proc=q) for lp in _ordered_loops(
                program, mine, sub, max_storage, accesses, o, data)] for o in orders]
            out += min(cands, key=lambda ls: _process_end(ls, var_end, pos))
        _, words = trial_b_data(program, out, tables)
        i0 = next(i for i, lp in enumerate(out) if lp.proc == 0)
        i1 = next(i for i, lp in enumerate(out) if lp.proc == 1)
        out[i0] = replace(out[i0], feed=words - 1 + FEED_SEND_DEPTH)
        out[i1] = replace(out[i1], feed=words - 1 + FEED_TAKE_DEPTH)
        end = trial_end(tuple(out), var_end, pos)
        if best_end is None or end < best_end:
            best, best_end = tuple(out), end
    return best


def ready_order(program, retire_vars, costs: dict) -> list:
    """The cost datapaths by when their last instance is ready (the retire position of its
    last variable), the most work (instances x II) first among equals."""
    pos = {v: i for i, v in enumerate(retire_vars)}
    index = {v.key: i for i, v in enumerate(program.variables)}
    last = {c: max((max(pos[index[k]] for k in program.factors[f].keys) for f in costs[c][0]),
                   default=-1) for c in costs}  # (-1: a datapath with no instance here)
    return sorted(costs, key=lambda c: (last[c], *_work_key(costs, c)))


def _work_key(costs: dict, c) -> tuple:
    """The most work first (instances x cost-mode II), the small types' shared datapath first
    among equals, then by block."""
    return -len(costs[c][0]) * costs[c][1], -1 if c == "small" else c


def work_order(costs: dict) -> list:
    """The cost datapaths, the most work first (:func:`_work_key`)."""
    return sorted(costs, key=lambda c: _work_key(costs, c))


def _fuse(costs: dict, accesses: dict, keys: tuple[int, ...],
          data: dict) -> tuple[str, tuple, int]:
    """A fused loop's key, its (instances, II, depth) and its x words an entry: the block
    datapaths ``keys`` in one pipelined loop, an entry costing one instance through its
    block's datapath (exclusive branches): the instances of all, the largest depth, and an II
    no less than any datapath's nor than the data memory's :data:`PORTS` allow for every
    branch's reads (``data``: the words an instance reads; the branches' reads counted as one
    iteration's, as the second reader counts them); the x words every branch reads."""
    ii = max([costs[c][1] for c in keys] + [loop_ii([(sum(data[c] for c in keys), 1)])])
    return ("_".join(str(c) for c in keys),
            ([f for c in keys for f in costs[c][0]], ii, max(costs[c][2] for c in keys)),
            sum(accesses[c] for c in keys))


def _ordered_loops(program, retire_vars, costs: dict, max_storage: int, accesses: dict,
                   order: list, data: dict | None = None) -> tuple[TrialLoop, ...]:
    """:func:`trial_loops`' loops with the datapaths in ``order``; an element that is a tuple
    of block datapaths is one fused loop over their instances, in the order they are ready
    (:func:`_fuse`)."""
    pos = {v: i for i, v in enumerate(retire_vars)}
    index = {v.key: i for i, v in enumerate(program.variables)}
    fused = {}
    for c in order:
        if isinstance(c, tuple):
            key, cost, words = _fuse(costs, accesses, c, data)
            costs, accesses = {**costs, key: cost}, {**accesses, key: words}
            fused[key] = c
    order = ["_".join(str(k) for k in c) if isinstance(c, tuple) else c for c in order]
    taken = 0
    plans = []
    for c in order:
        instances, _, _ = costs[c]
        cap = max([1] + [len(program.factors[f].keys) for f in instances])
        ready = sorted((max(pos[index[k]] for k in program.factors[f].keys), f)
                       for f in instances)
        entries = []
        for last, f in ready:
            need = list(retire_vars[taken:last + 1])
            taken = max(taken, last + 1)
            while len(need) > cap:
                entries.append((-1, tuple(need[:cap])))
                need = need[cap:]
            entries.append((f, tuple(need)))
        plans.append([c, entries, cap])
    rest = list(retire_vars[taken:])
    while rest and plans:
        cap = plans[-1][2]
        plans[-1][1].append((-1, tuple(rest[:cap])))
        rest = rest[cap:]
    out = []
    for c, entries, _ in plans:
        k = max([0] + [len(v) for _, v in entries])
        _, ii, depth = costs[c]
        ii = max(ii, loop_ii([(k * max_storage + accesses[c], 1)]))
        out.append(TrialLoop(c, tuple(entries), k, ii, depth + (2 if k else 0),
                             fused=fused.get(c, ())))
    return tuple(out)


def trial_end(loops: tuple[TrialLoop, ...], var_end: list[int],
              pos: dict[int, int] | None = None) -> int:
    """When trial_cost ends: its loops one after another, an entry its loop's II after the
    one before (a loop's first when the loop before has drained), and no earlier than the
    end of the retire iteration that sends the last variable it takes (``var_end``: per
    retired variable, in order, when its words are in the stream); it ends its depth after
    its last entry (fgc_cycles.h's outer group, its third process). Split loops
    (:func:`split_trial_loops`, ``pos``: a variable's position in the retire order): each
    process so, side by side; the later end."""
    if pos is not None:
        return max(_process_end([lp for lp in loops if lp.proc == q], var_end, pos)
                   for q in (0, 1))
    return _process_end(loops, var_end)


def _process_end(loops, var_end: list[int], pos: dict[int, int] | None = None) -> int:
    """One trial-cost process's end (:func:`trial_end`), a variable it takes ready when the
    retire iteration at its position ``pos`` ends; without ``pos`` the process takes every
    retired variable in the retire order (the last taken is the count taken so far)."""
    free, taken = 0, 0
    for lp in loops:
        free += lp.feed  # (trial_cost_b's data words first: slot_split_loops)
        issue = None
        for _, taking in lp.entries:
            at = free if issue is None else issue + lp.ii
            if taking:
                taken += len(taking)
                last = taken - 1 if pos is None else max(pos[v] for v in taking)
                at = max(at, var_end[last])
            issue = at
            free = at + lp.depth
    return free


def split_trial_loops(program, retire_vars, costs: dict, max_storage: int,
                      accesses: dict) -> tuple[TrialLoop, ...]:
    """trial_cost in two processes (the column design's LM, units/lm_control.py's
    retire_step_test): ``trial_cost`` runs the datapath with the most work (instances x II),
    ``trial_cost_b`` the others one after another, each fed by a stream of its own
    (accel.cpp.jinja's TRIAL_SEND: the retire sends a variable to the processes whose
    instances read it, in retire order), so the small loops, whose variables the chain's leaves
    hold and the retire sends last, run beside the big loop's last instances instead of after
    them. Each process's loops as :func:`trial_loops` on the variables it is sent; the second
    reads its instances' data from ``DATA_B``, its own copy of their lines (:func:`trial_b_data`:
    no memory is read by two processes of the region). Not split where a later datapath is the
    shared small one (it reads DATA_BUF)."""
    order = work_order(costs)
    if "small" in order[1:]:  # (the shared small datapath reads DATA_BUF: not split)
        return trial_loops(program, retire_vars, costs, max_storage, accesses)
    out: list[TrialLoop] = []
    for q, keys in enumerate((order[:1], order[1:])):
        if not keys:
            continue
        needed = {i for c in keys for f in costs[c][0] for i in _factor_vars(program, f)}
        mine = [v for v in retire_vars if v in needed]
        out += [replace(lp, proc=q) for lp in trial_loops(
            program, mine, {c: costs[c] for c in keys}, max_storage, accesses)]
    return tuple(out)


def _factor_vars(program, f: int) -> list[int]:
    index = {v.key: i for i, v in enumerate(program.variables)}
    return [index[k] for k in program.factors[f].keys]


def cost_loops(processes) -> dict:
    """The cost-mode instance loop of each datapath (key: its block type, or "small"), from
    its ``factor_<b>_cost`` / ``factor_small_cost`` process."""
    return {("small" if p.name.startswith("factor_small") else int(p.name.split("_")[1])):
            p.loops[0] for p in processes}


TRIAL_DATA_BANKS = 2  # DATA_BUF cyclic 2 (trial_cost's ARRAY_PARTITION; gather_trial_<b>)


def trial_banked(program, opts) -> bool:
    """True when trial_cost reads DATA_BUF cyclic :data:`TRIAL_DATA_BANKS` through
    ``gather_trial_<b>`` (:func:`keep_up_ii`): back-substitution by columns (``backsub_lanes``
    4), whose two ends and retire feed it faster than the slots (where the cost pass keeps
    up at one bank's ports, and faster loops would only cost operators)."""
    from fgc_backends.hls.units.backsub import COLUMN_LANES
    from fgc_backends.hls.units.state_update import fed_by_backsub
    return fed_by_backsub(program, opts) and opts.backsub_lanes == COLUMN_LANES


def keep_up_ii(ctx, allocations, small) -> dict[int, int]:
    """The column design's cost-mode II per block type with a datapath of its own: the
    largest II at which trial_cost still ends when it would with every such loop at its
    fastest, the retire feeding it as the column region's (``units.backsub.column_retire``):
    a loop that waits on the retire's variables anyway is given fewer operators
    (factor_cost_<b>'s ALLOCATION is bound at this II). Its fastest: the cost-mode operators'
    issue II, the running total's adder, DATA_BUF's two banks (:func:`trial_data_ii`), and no
    more trig or special function instances (12 and 17 DSP each) than the one-bank II binds
    (imu_window N = 50: the IMU cost's 6 special functions on one instance, II 72, not 57: 22
    DSP fewer for 137 cycles an iteration). Never slower than one bank's ports (the slot
    designs' II). Blocks with the most work (instances x II) first."""
    from fgc_backends.hls.units.backsub import column_chain, column_retire
    program, opts, ops, blocks = ctx.program, ctx.opts, ctx.ops, ctx.blocks
    sim_ops = _sim_table(ops)
    loops, slow = {}, {}
    for i, b in enumerate(program.blocks):
        if i in small:
            continue
        allocated, issue = mode_issue(b, allocations[i], "cost", ops)
        slow[i] = max(issue, ops.add.latency, loop_ii(instance_accesses(blocks[i], "cost")))
        # no more function instances (trig, special: 12 and 17 DSP each) than at one bank's II
        issued, floor = issued_counts(b, "cost"), 1
        for kind, limit in allocated:
            if kind in ("trig", "special") and issued.get(kind):
                work = issued[kind] * ops.op(kind).ii
                floor = max(floor, math.ceil(work / min(limit, math.ceil(work / slow[i]))))
        fast = min(slow[i], max(issue, ops.add.latency, trial_data_ii(blocks[i]), floor))
        loops[i] = Loop(f"factor_{i}_cost_instances", len(blocks[i].instances), fast,
                        max(critical_path(b.cost_kernel, sim_ops), issue))
    if small:
        _, ii, issue = small_allocation(program, blocks, opts, "cost", ops)
        loops["small"] = Loop("factor_small_cost_instances", 0, ii, max(
            [issue] + [critical_path(program.blocks[i].cost_kernel, sim_ops) for i in small]))

    if isinstance(column_chain(ctx.tables), str):  # refused by name (units.backsub)
        return slow
    _, _, var_end = column_retire(ctx)

    split = trial_split(program, opts)
    pos = trial_positions(program, ctx.tables) if split else None

    def end(trial) -> int:
        return trial_end(trial_plan(program, blocks, trial, ctx.tables, split), var_end, pos)

    target = end(loops)
    for i in sorted(slow, key=lambda i: (-loops[i].trip * loops[i].ii, i)):
        lo, hi = loops[i].ii, slow[i]
        while lo < hi:  # the largest II that keeps the end (the end grows with the II)
            mid = (lo + hi + 1) // 2
            if end({**loops, i: replace(loops[i], ii=mid)}) <= target:
                lo = mid
            else:
                hi = mid - 1
        loops[i] = replace(loops[i], ii=lo)
    return {i: loops[i].ii for i in slow}


def trial_span(bc) -> dict:
    """``gather_trial_<b>``'s reads of DATA_BUF (accel.cpp.jinja): ``lo``, the members' first
    data word in the line (measurements or noise parameters), and ``words``, from there to the
    last one plus one (read from the even address below the line, 2 h + lo + i: an odd line's
    words start one further on); 0 words if the block reads none."""
    regions = [(m.meas_data, m.meas_words) for m in bc.members if m.meas_words]
    regions += [(m.noise_data, m.n_params) for m in bc.members if m.n_params]
    if not regions:
        return {"lo": 0, "words": 0}
    lo = min(a for a, _ in regions)
    return {"lo": lo, "words": max(a + n for a, n in regions) - lo + 1}


def trial_data_ii(bc) -> int:
    """The II DATA_BUF's ports allow ``gather_trial_<b>`` and its robust words: DATA_BUF
    cyclic :data:`TRIAL_DATA_BANKS`, the gather's :func:`trial_span` words read at 2 h + c
    (h = its line / 2, c a constant: each read's bank known), so they take the banks' 4
    ports; each robust word's read (at FACTOR_DATA_OFF[f] + c, its bank not known) a port of
    every bank."""
    robust = sum(2 * m.robust for m in bc.members)
    return max(1, math.ceil((trial_span(bc)["words"] + TRIAL_DATA_BANKS * robust)
                            / (2 * TRIAL_DATA_BANKS)))


def trial_plan(program, blocks, loops: dict, tables: dict,
               split: bool = False, var_end: list[int] | None = None) -> tuple[TrialLoop, ...]:
    """trial_cost's loops for ``program`` (``blocks``: its block contexts; ``loops``: each
    datapath's cost-mode loop, :func:`cost_loops`; ``tables``: the emitted tables); ``split``:
    in two processes (:func:`split_trial_loops`); else ``var_end`` (the slot design's,
    :func:`trial_var_end`) chooses the loops' order (:func:`trial_loops`)."""
    from fgc_backends.hls.units.backsub import retire_solved
    from fgc_backends.hls.units.state_update import retire_order
    variables, _ = retire_order(program, retire_solved(tables))
    costs, accesses, data = {}, {}, {}
    small = small_blocks(program)
    for key, loop in loops.items():
        members = small if key == "small" else (key,)
        costs[key] = ([f for i in members for f in blocks[i].instances], loop.ii, loop.depth)
        accesses[key] = sum(blocks[i].n_x_in for i in members)
        data[key] = max(instance_accesses(blocks[i], "cost")[1][0] for i in members)
    width = max(v.storage_dim for v in program.variables)
    if split:
        return split_trial_loops(program, variables, costs, width, accesses)
    return trial_loops(program, variables, costs, width, accesses, var_end, tables, data)


def trial_var_end(ctx) -> list[int] | None:
    """When each retired variable reaches trial_cost in the slot design (units/backsub.py's
    slot_retire), which orders its loops; None for back-substitution by columns (its cost
    pass split in two: :func:`split_trial_loops`) or a design whose solve does not feed it."""
    from fgc_backends.hls.units.backsub import COLUMN_LANES, slot_retire
    from fgc_backends.hls.units.state_update import fed_by_backsub
    if not fed_by_backsub(ctx.program, ctx.opts) or ctx.opts.backsub_lanes == COLUMN_LANES:
        return None
    return slot_retire(ctx)[2]


def trial_b_data(program, loops, tables: dict) -> tuple[int, int]:
    """(first word, words) of ``DATA_B``: DATA_BUF's words from the even word at or below the
    first line of trial_cost_b's instances to the end of its last (the top's data copy writes
    them there too); (0, 0) without a second process."""
    off = tables["FACTOR_DATA_OFF"]
    fs = [f for lp in loops if lp.proc == 1 for f, _ in lp.entries if f >= 0]
    if not fs:
        return 0, 0
    lo = min(off[f] for f in fs) & ~1
    return lo, max(off[f + 1] for f in fs) - lo


def trial_positions(program, tables: dict) -> dict[int, int]:
    """Each variable's position in the retire order (back_substitute's RETIRE_VARS)."""
    from fgc_backends.hls.units.backsub import retire_solved
    from fgc_backends.hls.units.state_update import retire_order
    variables, _ = retire_order(program, retire_solved(tables))
    return {v: i for i, v in enumerate(variables)}


def trial_split(program, opts) -> bool:
    """Whether trial_cost runs in two processes (:func:`split_trial_loops`): the column
    design's LM (units/lm_control.py's retire_step_test)."""
    from fgc_backends.hls.units.lm_control import retire_step_test
    return retire_step_test(program, opts)


def trial_state(ctx) -> tuple[TrialLoop, ...]:
    """trial_cost's loops for the plan being built (``ctx``), from the cost-mode loops the
    datapath build left in ``ctx.shared["cost_loops"]``."""
    split = trial_split(ctx.program, ctx.opts)
    return trial_plan(ctx.program, ctx.blocks, ctx.shared["cost_loops"], ctx.tables, split,
                      None if split else trial_var_end(ctx))
