"""The Householder QR unit sets (paper A): per set one Evaluate unit and n_u Update units
around ``qr_reflection``'s DATAFLOW region (``include/fgc_qr.h``), each elimination step
stacked into the set's banks and committed to COND / NF by the kernel. ``PlanOptions.qr_unit
= "stream"`` puts :mod:`fgc_backends.hls.units.qr_stream`'s stages in the sets instead (the
same stacking, commit and memories around them)."""

from __future__ import annotations

import math

import numpy as np

from fgc_backends.cost.operators import OperatorTable
from fgc_backends.cost.structure import stacked_pattern
from fgc_backends.hls.plan.binding import BoundLoop, bound_unit
from fgc_backends.hls.plan.cost import phase_cycles
from fgc_backends.hls.plan.loops import _assign, _ported, _region_cycles, kernel_loop
from fgc_backends.hls.plan.model import PORTS, Channel, Loop, Memory, Phase, PlanError, Process
from fgc_backends.hls.plan.options import QR_ROWS  # fgc_qr.h's Update units: rows a cycle
from fgc_backends.hls.units.memories import solver_memories
from fgc_backends.hls.units.spec import UnitSpec


def active_rows(pattern, rhs=None) -> tuple[int, int, int, list[int]]:
    """A QR step's shape and the active rows of each reflection as the units meet them:
    ``pattern`` (rows × (f + s) structural non-zeros) with the right-hand side added (``rhs``:
    the rows whose right-hand side can be non-zero; None: every row's), rows, cols = w + 1,
    k = min(rows, cols), and per reflection j < k the count of rows j ... that are non-zero in
    column j after the fill of the reflections before it (row j always among them; 0: the
    column is zero and skipped)."""
    return reflection_rows(pattern, rhs)[:4]


def reflection_rows(pattern, rhs=None) -> tuple[int, int, int, list[int], list[int]]:
    """:func:`active_rows`, and per reflection j < k the rows the Evaluate keeps of column j + 1
    for its update pass (fgc_qr.h's qr_evaluate): row j, row j + 1, reflection j's active rows
    and the rows j ... non-zero in column j + 1 before it (0 where j + 1 = cols)."""
    return reflection_lanes(pattern, rhs)[:5]


def reflection_lanes(pattern, rhs=None) -> tuple[int, int, int, list[int], list[int], list[int]]:
    """:func:`reflection_rows`, and per reflection j < k how many of its active rows below the
    pivot are even rows (the rest are odd): the two lanes of the Update units two rows a cycle
    (fgc_qr.h with FGC_QR_TWO_ROWS)."""
    pattern = np.asarray(pattern, dtype=bool)
    side = (np.ones((len(pattern), 1), dtype=bool) if rhs is None
            else np.asarray(rhs, dtype=bool).reshape(len(pattern), 1))
    nz = np.hstack([pattern, side])
    rows, cols = nz.shape
    k = min(rows, cols)
    active, kept, even = [], [], []
    for j in range(k):
        rows_j = [i for i in range(j, rows) if nz[i, j]]
        act = sorted(set(rows_j) | {j}) if rows_j else []
        kept.append(len({i for i in range(j, rows) if nz[i, j + 1]} | set(act) | {j, j + 1})
                    if j + 1 < cols else 0)
        even.append(sum(1 for i in act if i > j and i % 2 == 0))
        if not rows_j:
            active.append(0)  # all zero: skipped
            continue
        union = nz[act, j + 1:].any(axis=0)
        nz[np.ix_(act, range(j + 1, cols))] = union
        nz[act, j] = False
        nz[j, j] = True
        active.append(len(act))
    return rows, cols, k, active, kept, even


def qr_unit_loops(pattern, frontal: int, units: int, ops: OperatorTable,
                  partials: int | None = None, name: str = "s", qr_rows: int = 1,
                  rhs=None) -> list[Loop]:
    """The loops of ``qr_step`` (backends/hls/include/fgc_qr.h) on one step, as it executes them.

    ``pattern``: the structural rows × (f + s) non-zeros of the stacked matrix (the right-hand
    side is added here: ``rhs``, the rows whose right-hand side can be non-zero, None: every
    row's); a structural non-zero is taken as non-zero in value. Returns one
    ``Loop`` (trip 1) per DATAFLOW region ``qr_reflection`` j = -1 ... k - 1 (k = min(rows,
    w + 1)), whose depth is the region's cycles (slowest process plus the others' fill, and no
    less than the Evaluate's end, which reads its column as the Update unit streams it and the
    vector as the broadcast does, then waits for v_0 and tau: the same loops and rule as the
    header's FGC_CYCLES / FGC_WAIT counters), then the pivot check. The Evaluate applies
    reflection j to the next pivot column, so its unit does no more than the others.
    ``partials`` is the header's CFG::PARTIALS (default: the adder latency, II 1).
    ``qr_rows`` 2: the Update units two rows a cycle (FGC_QR_TWO_ROWS): the vector in two lanes
    by row parity, the broadcast a pair a cycle, ``dot_axpy`` q iterations a column (q the
    longer lane with the pivot, at least 2) and its pair's products summed before the partial.
    """
    if qr_rows not in QR_ROWS:
        raise PlanError(f"qr_rows {qr_rows!r}: expected one of {QR_ROWS}")
    la, lm, ld, ls = ops.add.latency, ops.mul.latency, ops.div.latency, ops.sqrt.latency
    p = partials if partials is not None else la
    rows, cols, k, active, kept, even = reflection_lanes(pattern, rhs)
    tree = math.ceil(math.log2(p)) if p > 1 else 0
    tree1 = math.ceil(math.log2(p + 1))  # the fold of the P partials and the pivot's term
    out = []
    for j in range(-1, k):
        n = active[j] if j >= 0 else 0
        below = max(n - 1, 0)
        if qr_rows == 2:
            # the lanes: ne / no words below the pivot on even / odd rows, the pivot last in
            # lane j mod 2; the broadcast's header and max(ne, no) pairs; a column q iterations
            ne = even[j] if n > 1 else 0
            no = below - ne
            words = max(ne, no)
            q = max(ne + (j % 2 == 0), no + (j % 2 == 1), 2)
            bcast = 1 + words
            dot_lat = lm + 2 * la
        else:
            words, q, bcast, dot_lat = below, n, max(n, 1), lm + la
        # the broadcast (index 0) streams the vector, qr_finish (1) computes v_0, tau, R_jj
        procs = [[Loop("vector", bcast, 1, 2)],
                 [Loop("read", 2, 1, 1), Loop("v0", 1, 1, ls + la if n else 1),
                  Loop("tau", 1, 1, lm + ld if n else 1)]]
        waits = []
        col = j + 1
        for u in range(units):
            # the unit's first column right of j; the next pivot column if it is j + 1 < k
            c0 = j + 1 + (u - (j + 1)) % units
            next_here = c0 == j + 1 and c0 < k
            # the unit's other columns right of j
            lb = c0 // units + (1 if next_here else 0)
            r = (cols - 1 - u) // units - lb + 1 if c0 < cols else 0
            loops = [Loop("header", 1, 1, 1)]
            if next_here:
                # the next pivot column streamed to the Evaluate (rows max(j, 0) ... rows - 1)
                # while the n - 1 words below the pivot arrive: before dot_axpy two rows a
                # cycle, the aligned pairs (2p, 2p + 1) from p = max(j, 0) // 2 (the bank is
                # two memories by row parity), else one
                pairs = (rows + 1) // 2 - max(j, 0) // 2
                loops.append(Loop("vector_column", pairs if r > 0 and n > 1 else
                                  rows - max(j, 0), 1, 2))
            elif not (r > 0 and n > 1):
                loops.append(Loop("vector", words, 1, 1))  # read, not needed here
            if r > 0 and n > 1:
                # dot_axpy: a column's dot product beside the update of the column before it;
                # a word's update lag = n - 1 + (its dot's multiply-add) + (the fold and scale)
                # iterations after its dot. Its first column takes the vector as the broadcast
                # streams it (unless the column loop read it), v_0 in iteration n - 1 (the
                # pivot's word last) and tau at that column's fold, iteration n - 1 + Lm + La:
                # the loop ends no earlier than its remaining iterations and depth after each
                # (FGC_WAIT_AFTER)
                # (two rows a cycle: q iterations a column, the pair's sum La deeper)
                lag = q - 1 + dot_lat + (la * tree + lm)
                trip = q * r + lag
                waits.append((len(procs), len(loops), 1, "v0", trip - q))
                waits.append((len(procs), len(loops), 1, "tau", trip - q - dot_lat))
                loops.append(Loop("dot_axpy", trip, 1, lm + la))
            else:
                # v_0 (waiting for qr_finish's square root), then tau (its divide)
                waits.append((len(procs), len(loops), 1, "v0"))
                loops.append(Loop("pivot_word", 1, 1, 1))
                waits.append((len(procs), len(loops), 1, "tau"))
                loops.append(Loop("tail", 1, 1, 1))
                if r > 0 and j >= 0:
                    loops.append(Loop("negate_rows" if n == 1 else "rows_out", r, 1, 1))
            procs.append(loops)
        if col < k:
            # the Evaluate: the column as its unit streams it and the vector as the broadcast
            # does (v.x as they arrive), the pivot's term once v_0 is there, the scale once tau
            # is, then one pass over the rows it kept (reflection_rows) that updates the
            # column, sends row j's entry to the collector and sums the next vector's squares,
            # and their fold (the tail is the next
            # region's qr_finish); with no reflection to apply (n <= 1) one pass, the fold,
            # then qr_finish's words
            e = len(procs)
            span = rows - max(j, 0)
            waits += [(e, 1, 2 + col % units, "vector_column")]
            if n > 1:
                # two rows a cycle: the receive over the aligned pairs (the column's two
                # streams, its own copy of the vector by row parity; the pair's terms added
                # before the partial), the update pass over its kept rows two at a time (the
                # pair's squares added before the partial)
                pairs = (rows + 1) // 2 - max(j, 0) // 2
                waits += [(e, 2, 1, "v0"), (e, 4, 1, "tau")]
                procs.append([Loop("header", 1, 1, 1),
                              Loop("receive_dot", pairs, 1, lm + 2 * la),
                              Loop("pivot_term", 1, 1, lm), Loop("fold_dot", 1, 1, la * tree1),
                              Loop("tail", 2, 1, 1), Loop("scale", 1, 1, lm),
                              Loop("axpy_norm", (kept[j] + 1) // 2, 1, 2 * lm + 3 * la),
                              Loop("fold", 1, 1, la * tree)])
            else:
                waits += [(e, 3, 1, "v0"), (e, 4, 1, "tau")]
                procs.append([Loop("header", 1, 1, 1), Loop("receive_norm", span, 1, lm + la),
                              Loop("fold", 1, 1, la * tree), Loop("pivot_word", 1, 1, 1),
                              Loop("tail", 2, 1, 1)])
        # the collector: row j of R out (cond / update) and the running scale
        first = 0 if j < frontal else frontal  # rows out with their zeros left of the diagonal
        procs.append([Loop("header", 1, 1, 1)]
                     + ([Loop("row", cols - first, 1, 2)] if 0 <= j < k else []))
        out.append(Loop(f"{name}_reflection{j + 1}", 1, 1, _region_cycles(procs, tuple(waits))))
    out.append(Loop(f"{name}_pivot_check", frontal, 1, 2))
    return out


def householder_loops(partials: int, qr_rows: int = 1
                      ) -> tuple[tuple[BoundLoop, ...], tuple[BoundLoop, ...]]:
    """The operators of one unit set's Evaluate (qr_evaluate, qr_finish, and qr_pivot_check's
    threshold) and of one Update unit (qr_update<CFG, U>) as Vitis binds fgc_qr.h's text: each
    pipelined loop its own operators at its II (``dot_axpy`` at II 1: the dot's and the axpy's
    multiply-adds and a column's fold, ``fold_partials<P>``'s P - 1 adds and the scale's
    multiplier, in every iteration's schedule), the sequential code one operator of each kind
    it uses. qr_step's two parity call sites of qr_reflection share
    one instance (its ALLOCATION function limit=1), so each unit is one RTL copy.
    ``partials``: CFG::PARTIALS. ``qr_rows`` 2 (FGC_QR_TWO_ROWS): ``dot_axpy`` two rows an
    iteration, its dot's two products and their sum before the partial, its axpy's two
    multiply-adds: P + 3 adders and 5 multipliers."""
    p = partials
    # receive_dot and axpy_norm take two rows a cycle: two products and their sum before the
    # partial; two multiply-adds, two squares and their sum before the partial
    evaluate = (BoundLoop("receive_dot", (("add", 2), ("mul", 2)), 1),
                BoundLoop("receive_norm", (("add", 1), ("mul", 1)), 1),
                BoundLoop("axpy_norm", (("add", 4), ("mul", 4)), 1),
                BoundLoop("fold", (("add", p - 1),), 0),  # fold_partials<P>, sequential
                # the next pivot column's fold (fold_partials<P + 1>), its pivot term and scale
                BoundLoop("fold_dot", (("add", p),), 0),
                BoundLoop("pivot_term_scale", (("mul", 2),), 0),
                BoundLoop("qr_finish", (("add", 2), ("mul", 1), ("div", 1), ("sqrt", 1)), 0),
                # qr_pivot_check's threshold SINGULAR_EPS * scale, before its loop
                BoundLoop("pivot_check", (("mul", 1),), 0))
    update = ((BoundLoop("dot_axpy", (("add", p + 3), ("mul", 5)), 1),) if qr_rows == 2 else
              (BoundLoop("dot_axpy", (("add", p + 1), ("mul", 3)), 1),))
    return evaluate, update


def rows_in_banks(program, opts, tables: dict, root: bool = False
                  ) -> dict[int, tuple[int, int, int]]:
    """The factors whose rows the datapaths write straight into a unit set's banks (besides
    AB), ``factor -> (set, step, its first row in the step)``: under the one-step policy
    (``SolverConfig.one_step``: one linearisation, then one solve) with the Householder unit
    (its ``qr_step`` leaves the banks zero), the factors of the steps the solve's first
    stack takes, level 0's first ``sets`` steps, set u the u-th (``qr_eliminate_all``'s order).
    Their rows are at the step's rows where ``qr_stack_rows`` would put them, so that stack
    only advances past them. Empty otherwise (LM's retries stack from AB again; the stream
    unit's banks are not left zero). ``root`` (the root step in a wavefront inside lin_level,
    :func:`lin_wave`): the root's own factors too, as set ``sets`` (the root's stream to unit
    set 1, which stacks the root after its own step) at their rows in the root."""
    solver = program.solver
    if solver.linear != "qr" or not solver.one_step or opts.qr_unit != "householder":
        return {}
    sets = unit_sets_of(program, opts)
    lb = tables["LEVEL_BEGIN"]
    out = {}
    fb, cb = tables["STEP_FACTOR_BEGIN"], tables["FACTOR_COLMAP_BEGIN"]
    steps = list(tables["LEVEL_STEPS"][lb[0]:lb[1]][:sets])
    wave = wave_steps(program, opts) if root else None
    if wave is not None:
        steps.append(wave[2])
    for u, s in enumerate(steps):
        row = 0
        for e in range(fb[s], fb[s + 1]):
            fac = tables["STEP_FACTORS"][e]
            out[fac] = (u, s, row)
            words = tables["FACTOR_A_OFF"][fac + 1] - tables["FACTOR_A_OFF"][fac]
            row += words // (cb[fac + 1] - cb[fac] + 1)
    return out


def stack_loops(tables: dict, s: int, units: int, max_w: int, damped: bool,
                timing: dict, banks_zero: bool = True, in_place: bool = False,
                fed: int = -1, own: int = -1) -> list[Loop]:
    """fgc_eliminate.h's qr_stack of step s into its unit set's banks: unless ``banks_zero``
    (fgc_qr.h's qr_step leaves its banks zero: CFG::BANKS_ZERO; not fgc_qr_stream.h's) the
    rows zeroed (all n_u banks a cycle), then each factor's rows [A | b] (none when
    ``in_place``: the datapaths wrote them, :func:`rows_in_banks`) and each child's
    new-factor rows :data:`PORTS` words a cycle (but child ``fed``'s: the root step in a
    wavefront reads them from their set's stream, :func:`wave_loops`; nor child ``own``'s:
    lin_level's wave's set 1 takes them as its collector packed them, :func:`lin_wave_loops`),
    the damping rows' diagonal."""
    f, m = tables["STEP_F"][s], tables["STEP_ROWS"][s]
    local = -(-(max_w + 1) // units)
    loops = [] if banks_zero else [kernel_loop("zero", m * local, "fill", timing)]
    fb = tables["STEP_FACTOR_BEGIN"]
    for e in range(fb[s], fb[s + 1]):
        if in_place:
            break
        fac = tables["STEP_FACTORS"][e]
        words = tables["FACTOR_A_OFF"][fac + 1] - tables["FACTOR_A_OFF"][fac]
        loops.append(kernel_loop("factor_rows", _ported(words), "move", timing))
    cb = tables["STEP_CHILD_BEGIN"]
    for e in range(cb[s], cb[s + 1]):
        c = tables["STEP_CHILDREN"][e]
        if c in (fed, own):
            continue
        sc = tables["STEP_W"][c] - tables["STEP_F"][c]
        loops.append(kernel_loop("child_rows", _ported(tables["STEP_NF_ROWS"][c] * (sc + 1)),
                                 "move", timing))
    if damped:
        loops.append(kernel_loop("damping", f, "fill", timing))
    return loops


def commit_loops(tables: dict, s: int, timing: dict, cholesky: bool) -> list[Loop]:
    """A step's conditional into COND and its new factor (QR's commit(): STEP_NF_ROWS rows)
    or update matrix (Cholesky's store at the end of eliminate(): w - f rows) into NF,
    :data:`PORTS` words a cycle."""
    w, f = tables["STEP_W"][s], tables["STEP_F"][s]
    nf = w - f if cholesky else tables["STEP_NF_ROWS"][s]
    return [kernel_loop("cond", _ported(f * (w + 1)), "move", timing),
            kernel_loop("nf", _ported(nf * (w - f + 1)), "move", timing)]


def unit_sets_of(program, opts) -> int:
    """QR unit sets: the options' (default 2 for a two-ended chain, else 1), at most the widest
    level's steps."""
    sched = program.schedule
    widest = max(len(level) for level in sched.levels)
    sets = opts.unit_sets if opts.unit_sets is not None else (
        2 if sched.structure_class == "chain" and sched.ordering == "two-ended" else 1)
    return max(1, min(sets, widest))


def wave_steps(program, opts) -> tuple[int, int, int] | None:
    """``PlanOptions.root_wave``: the root step in a wavefront behind its children (issue 33
    item 2), ``(c0, c1, root)`` - the last level one step, ``root``, whose children are the two
    steps of the level before it, ``c0`` on unit set 0 and ``c1`` on unit set 1
    (``LEVEL_STEPS`` order). That level is one DATAFLOW region: set 0 runs c0, its collector
    streaming c0's passed rows (the new factor's) to set 1, which runs c1, commits it, stacks
    the root's own rows and c1's passed rows, and runs the root step, reading each of c0's rows
    before the root's first region that needs it (:func:`wave_entries`). None when the option is
    off; an ``FgcError`` naming why when the design cannot take it."""
    if not getattr(opts, "root_wave", False):
        return None
    sched = program.schedule
    why = None
    if program.solver.linear != "qr" or opts.qr_unit != "householder":
        why = "it needs the Householder QR unit (fgc_qr.h)"
    elif unit_sets_of(program, opts) != 2:
        why = "it needs two unit sets"
    elif len(sched.levels) < 2 or len(sched.levels[-1]) != 1 or len(sched.levels[-2]) != 2:
        why = (f"the schedule's last level must be one root step after a level of two steps "
               f"(levels {[list(lv) for lv in sched.levels]})")
    else:
        c0, c1 = sched.levels[-2]
        root = sched.levels[-1][0]
        if sorted(sched.steps[root].children) != sorted((c0, c1)):
            why = f"the root step {root}'s children are not the level before it ({c0}, {c1})"
        elif sched.steps[c0].new_factor_rows < 1:
            why = f"step {c0} passes no rows to the root"
    if why is not None:
        raise PlanError(f"root_wave (the root step in a wavefront behind its children): {why}")
    return c0, c1, root


def lin_wave(program, opts) -> tuple[int, int, int] | None:
    """The root step in a wavefront INSIDE lin_level (``PlanOptions.root_wave`` under the
    one-step policy, where level 0's two unit sets reflect their steps beside the
    linearisation, :func:`rows_in_banks`): :func:`wave_steps`' ``(c0, c1, root)`` when the
    wave's children are level 0's two steps (the schedule's two levels), None when the design
    runs the wave as the qr_level region (no lin_level) or has no wave. Unit set 0's process of
    lin_level then reflects c0, its collector streaming c0's passed rows to set 1 and its words
    to the commit process (:func:`wave_commit_loops`, no commit loop after its last region);
    set 1's fills its banks with c1's rows, reflects c1, takes the root's own rows from their
    stream (the datapaths send them as they write them), stacks c1's passed rows from its
    UPDBUF, and reflects the root reading c0's passed rows as set 0 finishes them
    (:func:`lin_wave_loops`), the root's conditional into CONDBUF1 after c1's (twice the
    words)."""
    wave = wave_steps(program, opts)
    if wave is None or not rows_in_banks(program, opts, _tables_of(program)):
        return None
    if len(program.schedule.levels) != 2:
        raise PlanError(f"root_wave under the one-step policy (the wave inside lin_level): the "
                        f"root's children must be level 0's steps, the schedule has "
                        f"{len(program.schedule.levels)} levels")
    return wave


PASS_NONE = 255  # fgc_qr.h's QR_PASS_NONE: an empty slot of a qr_pass stream word
COMMIT_PAIR = 2  # fgc_qr.h's qr_pair: words of one row a lin_level commit stream word


def wave_colmap(tables: dict, c0: int, root: int) -> list[int]:
    """Per word q of a passed row of step ``c0`` (its s separator words, then its right-hand
    side) the root's column it lands in."""
    sc = tables["STEP_W"][c0] - tables["STEP_F"][c0]
    mb = tables["STEP_SEPMAP_BEGIN"][c0]
    return [tables["STEP_SEPMAP"][mb + q] for q in range(sc)] + [tables["STEP_W"][root]]


def pass_pack(tables: dict, c0: int, root: int, units: int) -> list[int]:
    """How step ``c0``'s collector packs a passed row into ``qr_pass`` stream words of
    2 * ``units`` slots (fgc_qr.h's qr_pass_word): per word q in order, ``slot | local << 8 |
    out << 16``, the slot 2u + h of its root column's bank u (h: the bank's first or second
    word in this stream word), its local column in the bank, and out = 1 where the stream word
    goes after q (the row's last word, or the next word's bank has both its slots taken). Every
    row packs alike (the same columns), so that the root's set writes a stream word into its
    banks in one cycle, each bank at most two words (two ports a memory) at fixed banks."""
    cols = wave_colmap(tables, c0, root)
    out, used = [], [0] * units
    for q, t in enumerate(cols):
        u = t % units
        if used[u] == 2:  # (not reached: the word before went out)
            raise PlanError(f"root_wave: passed word {q} of step {c0} finds bank {u} full")
        slot = 2 * u + used[u]
        used[u] += 1
        last = q == len(cols) - 1 or used[cols[q + 1] % units] == 2
        out.append(slot | (t // units) << 8 | int(last) << 16)
        if last:
            used = [0] * units
    return out


def pass_words(tables: dict, c0: int, root: int, units: int) -> int:
    """Stream words of one passed row of step ``c0`` on ``qr_pass`` (:func:`pass_pack`: each as
    the root's banks take it; fgc_qr.h's qr_collect writes them, qr_feed_row writes each into
    the banks in one cycle): 1 when no bank holds more than two of the row's columns."""
    return sum(pk >> 16 for pk in pass_pack(tables, c0, root, units))


def pass_channel(tables: dict, c0: int, root: int, units: int, word_bits: int) -> Channel:
    """The wave's ``qr_pass`` stream (set 0's collector to set 1's root): every passed row of
    step ``c0`` (set 0 never waits for set 1), a stream word 2 * ``units`` slots of a word and
    its 8-bit local column (fgc_qr.h's qr_pass_word)."""
    return Channel("qr_pass", "stream",
                   tables["STEP_NF_ROWS"][c0] * pass_words(tables, c0, root, units),
                   2 * units * (word_bits + 8), "qr_set0", "qr_set1")


def _row_pairs(tables: dict, s: int, nf: bool) -> int:
    """Stream words of step ``s``'s conditional (f rows of w + 1 words) and, where ``nf``, its
    new factor (STEP_NF_ROWS rows of s + 1) a pair of one row's words a stream word (fgc_qr.h's
    qr_collect on lin_level's commit streams; a row of odd length ends on a half pair)."""
    w, f = tables["STEP_W"][s], tables["STEP_F"][s]
    half = -(-(w + 1) // COMMIT_PAIR) * f
    return half + (tables["STEP_NF_ROWS"][s] * -(-(w - f + 1) // COMMIT_PAIR) if nf else 0)


def commit_pair_words(tables: dict, c1: int, root: int) -> int:
    """Stream words on lin_level's ``qr_commit1`` (the wave's set 1 to the commit process): step
    ``c1``'s and the root's conditionals (:func:`_row_pairs`; c1's passed rows went into the
    root from its buffer). The stream's depth: every pair (set 1 never waits for the commit
    process, which reads set 0's words first)."""
    return _row_pairs(tables, c1, False) + _row_pairs(tables, root, False)


def wave_commit_loops(tables: dict, wave: tuple[int, int, int],
                      timing: dict) -> tuple[Loop, ...]:
    """lin_level's commit process (accel.cpp.jinja's qr_commit_wave, fgc_eliminate.h's
    qr_commit_pairs), a loop a step, two words a cycle: the words the wave's set 0's collector
    streams as it writes its buffers (step c0's conditional, f rows of w + 1, and new factor,
    STEP_NF_ROWS rows of s + 1) into COND and NF, then step c1's and the root's conditionals as
    set 1's collector wrote them into COND - the three steps' commits, no loop after the region
    (:func:`commit_loops`' words). When it ends: :func:`wave_commit_end`."""
    c0, c1, root = wave
    return (kernel_loop("pairs", _row_pairs(tables, c0, True), "move", timing),
            kernel_loop("pairs", _row_pairs(tables, c1, False), "move", timing),
            kernel_loop("pairs", _row_pairs(tables, root, False), "move", timing))


def wave_commit_end(loops: tuple[Loop, ...], end0: int, end1: int) -> int:
    """The cycle of lin_level's region at which its commit process (:func:`wave_commit_loops`'
    three loops, one after another from the region's start) ends: step c0's no earlier than its
    depth after set 0's step ends (``end0``: its last pair comes as its last passed row is
    written, before then - an upper bound), the root's no earlier than its depth after set 1's
    (``end1``: the root's last conditional row comes in its region f - 1, before its last one),
    as fgc_cycles.h's FGC_WAIT counts each. 0 when no loop runs."""
    clock, pending = 0, None
    for lp, wait in zip(loops, (end0, None, end1), strict=True):
        if wait is not None:
            pending = max(pending or 0, wait)
        if lp.trip <= 0:
            continue
        clock += lp.cycles
        if pending is not None:
            clock = max(clock, pending + lp.depth)
            pending = None
    return clock


def _tables_of(program) -> dict:
    from fgc_backends.hls.plan.loops import _tables

    return _tables(program)


def lin_wave_loops(tables: dict, timing: dict, units: int, max_w: int, damped: bool,
                   steps: tuple[int, int, int], loops: dict, start0: int, start1: int,
                   root_fill: Loop, root_ready: int) -> tuple[Loop, ...]:
    """Unit set 1's process of lin_level after its fill (:func:`lin_wave`), as it runs: step
    c1's regions (``loops[c1]``; its result stays in the set's buffers, the root's conditional
    goes after it), the root's own rows from their stream
    (``root_fill``: a word a cycle, ending no earlier than its depth after ``root_ready``, the
    region's cycle at which the datapath loop that sends their last words ends), the root's
    stack of c1's passed rows (as the set's collector packed them, :func:`pass_pack`: a stream
    word a cycle) and the damping rows, then the root's regions, before each the
    reads of c0's passed rows it needs (:func:`wave_entries`), a read ending no earlier than its
    depth after set 0's region that wrote the row ends (set 0's clock ``loops[c0]`` from its
    start ``start0``; set 1's from ``start1``, both cycles of the region). A wait is a loop
    ``wave_wait`` of the cycles it holds, as fgc_cycles.h's FGC_WAVE_WAIT and FGC_WAVE_WAIT_ON
    count them inside set 1's FGC_COLLAPSE span."""
    c0, c1, root = steps
    out = list(loops[c1])
    clock = sum(lp.cycles for lp in out)
    if root_fill.trip > 0:
        end = max(clock + root_fill.cycles, root_ready - start1 + root_fill.depth)
        if end > clock + root_fill.cycles:
            out.append(Loop("wave_wait", 1, 1, end - clock - root_fill.cycles))
        out.append(root_fill)
        clock = end
    # step c1's passed rows as its collector packed them, a stream word a cycle
    # (:func:`pass_pack`), then the rest of the root's stack (c0's rows come by qr_pass)
    trip = tables["STEP_NF_ROWS"][c1] * pass_words(tables, c1, root, units)
    stack = ([kernel_loop("child_rows", trip, "move", timing)] if trip > 0 else []) + \
        stack_loops(tables, root, units, max_w, damped, timing, in_place=True, fed=c0, own=c1)
    out += stack
    clock += sum(lp.cycles for lp in stack)
    return tuple(out) + _root_regions(tables, timing, c0, root, loops, clock,
                                      start0 - start1, units)


def wave_entries(tables: dict, c0: int, root: int) -> list[int]:
    """Per passed row i of step ``c0`` (its new factor's, STEP_NF_ROWS[c0]) the root's region
    (reflection j = -1 ... k - 1) before which the root's set reads it into its banks: row i
    sits at the root's row p (after the root's own factor rows and the children before c0) and
    is zero left of its first separator column's place in the root (STEP_SEPMAP); the region
    whose Evaluate first reads it (the column before that, or row p's pivot region) needs it,
    and the rows come in order, so a row is read no later than the one after it needs."""
    nf = tables["STEP_NF_ROWS"][c0]
    sc = tables["STEP_W"][c0] - tables["STEP_F"][c0]
    mb = tables["STEP_SEPMAP_BEGIN"][c0]
    cols = [tables["STEP_SEPMAP"][mb + q] for q in range(sc)] + [tables["STEP_W"][root]]
    rows = tables["STEP_ROWS"][root]
    k = min(rows, tables["STEP_W"][root] + 1)
    row0 = _own_rows(tables, root)
    for e in range(tables["STEP_CHILD_BEGIN"][root], tables["STEP_CHILD_BEGIN"][root + 1]):
        c = tables["STEP_CHILDREN"][e]
        if c == c0:
            break
        row0 += tables["STEP_NF_ROWS"][c]
    need = [min(min(cols[i:]), row0 + i) - 1 for i in range(nf)]
    out = [0] * nf
    low = k - 1
    for i in range(nf - 1, -1, -1):
        low = min(low, need[i])
        out[i] = max(-1, low)
    return out


def root_bank_parity_words(tables: dict, root: int) -> tuple[int, int]:
    """The stream words of the root's own factor rows by row parity, ``(even, odd)``: each
    datapath word (:data:`PORTS` values of [A | b] in AB's order, each instance's whole
    words: units/datapath.py's bank_fill_words) splits into its values on even stack rows
    (lin_level's ``bank_root``) and on odd ones (``bank_root1``), so unit set 1 reads one
    word of each a cycle and writes each into its banks' memories of that parity (two writes
    a memory a cycle, its two ports): the root's fill takes the larger count, about half the
    words. Each is its stream's depth: every word, so the datapaths never wait for unit set 1
    (it reads them after its own step)."""
    a, cb = tables["FACTOR_A_OFF"], tables["FACTOR_COLMAP_BEGIN"]
    counts = [0, 0]
    row0 = 0
    for e in range(tables["STEP_FACTOR_BEGIN"][root], tables["STEP_FACTOR_BEGIN"][root + 1]):
        fac = tables["STEP_FACTORS"][e]
        words, stride = a[fac + 1] - a[fac], cb[fac + 1] - cb[fac] + 1
        for k in range(0, words, PORTS):
            for par in {(row0 + (k + h) // stride) % 2 for h in range(PORTS) if k + h < words}:
                counts[par] += 1
        row0 += words // stride
    return counts[0], counts[1]


def _own_rows(tables: dict, s: int) -> int:
    """Rows of step s's own factors (its first rows in the stack)."""
    rows = 0
    cb = tables["FACTOR_COLMAP_BEGIN"]
    for e in range(tables["STEP_FACTOR_BEGIN"][s], tables["STEP_FACTOR_BEGIN"][s + 1]):
        fac = tables["STEP_FACTORS"][e]
        words = tables["FACTOR_A_OFF"][fac + 1] - tables["FACTOR_A_OFF"][fac]
        rows += words // (cb[fac + 1] - cb[fac] + 1)
    return rows


def wave_loops(tables: dict, timing: dict, units: int, max_w: int, damped: bool,
               steps: tuple[int, int, int], loops: dict) -> tuple[Loop, ...]:
    """Unit set 1's process of the wave region (:func:`wave_steps`), as it runs: step c1's
    regions (``loops[c1]``, :func:`qr_unit_loops`), its commit, the root's stack without c0's
    rows, then the root's regions (``loops[root]``), before each the reads of c0's passed rows
    it needs (:func:`wave_entries`): one loop of s + 1 words a row (II 1, depth 2), ending no
    earlier than its depth after c0's region that wrote the row (reflection f + i's, on set 0's
    clock ``loops[c0]``; ``wave_wait``: the cycles the read waits past its own), as
    fgc_cycles.h's FGC_WAVE_WAIT counts it."""
    c0, c1, root = steps
    out = list(loops[c1]) + commit_loops(tables, c1, timing, False) + stack_loops(
        tables, root, units, max_w, damped, timing, fed=c0)
    clock = sum(lp.cycles for lp in out)
    return tuple(out) + _root_regions(tables, timing, c0, root, loops, clock, 0, units)


def _root_regions(tables: dict, timing: dict, c0: int, root: int, loops: dict, clock: int,
                  offset: int, units: int) -> tuple[Loop, ...]:
    """The root's regions (``loops[root]``) on unit set 1 from ``clock``, before each the reads
    of step ``c0``'s passed rows it needs (:func:`wave_entries`): one loop of
    :func:`pass_words` stream words a row, each as the banks take it (II 1, depth 2), ending
    no earlier than its depth after c0's region that wrote the row (reflection f + i's on set
    0's clock ``loops[c0]``, which starts ``offset`` cycles after set 1's; ``wave_wait``: the cycles
    the read waits past its own), then the pivot check."""
    out = []
    ends, t = [], offset
    for lp in loops[c0]:
        t += lp.cycles
        ends.append(t)
    f0 = tables["STEP_F"][c0]
    entry = kernel_loop("wave_row", pass_words(tables, c0, root, units), "move", timing)
    when = wave_entries(tables, c0, root)
    regions = list(loops[root])
    nxt = 0
    for idx, j in enumerate(range(-1, len(regions) - 2)):
        while nxt < len(when) and when[nxt] <= j:
            end = max(clock + entry.cycles, ends[f0 + 1 + nxt] + entry.depth)
            if end > clock + entry.cycles:
                out.append(Loop("wave_wait", 1, 1, end - clock - entry.cycles))
            out.append(entry)
            clock = end
            nxt += 1
        out.append(regions[idx])
        clock += regions[idx].cycles
    out.append(regions[-1])  # the pivot check
    return tuple(out)


def build(ctx) -> None:
    """The unit sets, their streams, per level the stack, the steps' regions and the commit,
    and the sets' memories (accel.cpp.jinja's WORK<s>, CONDBUF<s>, UPDBUF<s>)."""
    program, opts = ctx.program, ctx.opts
    sched = program.schedule
    sets = ctx.shared["sets"] = unit_sets_of(program, opts)
    damping = program.solver.method == "lm"
    patterns = {st.index: stacked_pattern(program, st, damping) for st in sched.steps}
    max_rows = ctx.sizes["MAX_ROWS"]
    if opts.qr_unit == "stream":
        from fgc_backends.hls.units import qr_stream
        by_index = qr_stream.build_sets(ctx, sets, patterns)
    elif opts.qr_unit == "householder":
        by_index = _householder_sets(ctx, sets, patterns, max_rows)
    else:
        raise PlanError(f"qr_unit {opts.qr_unit!r}: expected householder or stream")
    _levels(ctx, sets, by_index, damping)


def _householder_sets(ctx, sets, patterns, max_rows) -> dict:
    """fgc_qr.h's unit sets (units, streams) and each step's regions."""
    opts, ops, sched = ctx.opts, ctx.les, ctx.program.schedule
    evaluate, update = householder_loops(ops.add.latency, opts.qr_rows)
    for s in range(sets):
        ctx.units.append(bound_unit(f"qr{s}_evaluate", "Householder vector of a column",
                                    evaluate, 1, ops))
        ctx.units.append(bound_unit(f"qr{s}_update", "apply the reflector to a column",
                                    update, opts.units, ops))
        # the network of one reflection (include/fgc_qr.h's qr_reflection): broadcast streams
        # the vector below the pivot to each Update unit while qr_finish computes v_0, tau and
        # R_jj from the norm and the pivot and streams v_0 and tau to each unit (R_jj to
        # collect);
        # the unit holding the next column streams it to Evaluate (which applies the
        # reflection to it), each unit its entries of R's row to collect; Evaluate writes one
        # of the vector's and one of the norm's two buffers, which the next region's broadcast
        # and qr_finish read
        channels = ctx.channels
        for u in range(opts.units):  # (two rows a cycle: a pair of words a cycle)
            channels.append(Channel(f"qr{s}_v{u}", "stream", 2 * ops.add.latency,
                                    opts.qr_rows * (ops.word_bits + 32), f"qr{s}_broadcast",
                                    f"qr{s}_update{u}"))
        for u in range(opts.units):
            channels.append(Channel(f"qr{s}_t{u}", "stream", 2, ops.word_bits + 32,
                                    f"qr{s}_finish", f"qr{s}_update{u}"))
        channels.append(Channel(f"qr{s}_r", "stream", 1, ops.word_bits,
                                f"qr{s}_finish", f"qr{s}_collect"))
        for u in range(opts.units):
            # the next pivot column, a stream per row parity (its unit sends two rows a cycle)
            for parity in ("even", "odd"):
                channels.append(Channel(f"qr{s}_col{u}_{parity}", "stream", (max_rows + 1) // 2,
                                        ops.word_bits, f"qr{s}_update{u}", f"qr{s}_evaluate"))
            channels.append(Channel(f"qr{s}_row{u}", "stream", 2, ops.word_bits,
                                    f"qr{s}_update{u}", f"qr{s}_collect"))
        # the vector's header to the Evaluate (it keeps the words itself, qr<s>_evec), its
        # copies of v_0, tau, R_jj, and its entry of row j to collect
        channels.append(Channel(f"qr{s}_ve", "stream", 2, ops.word_bits + 32,
                                f"qr{s}_broadcast", f"qr{s}_evaluate"))
        channels.append(Channel(f"qr{s}_te", "stream", 3, ops.word_bits + 32,
                                f"qr{s}_finish", f"qr{s}_evaluate"))
        channels.append(Channel(f"qr{s}_e", "stream", 2, ops.word_bits,
                                f"qr{s}_evaluate", f"qr{s}_collect"))
        # (two rows a cycle: the words by row parity, MAX_ROWS + 3 slots)
        channels.append(Channel(f"qr{s}_vbuf", "pingpong", max_rows + 1 + 2 * (opts.qr_rows - 1),
                                ops.word_bits + 32,
                                f"qr{s}_evaluate", f"qr{s}_broadcast"))
        channels.append(Channel(f"qr{s}_hbuf", "pingpong", 2, ops.word_bits + 32,
                                f"qr{s}_evaluate", f"qr{s}_finish"))
    # per step: the regions of fgc_qr.h's qr_step (Evaluate of column k+1 overlaps the Update
    # of column k in region k) and its store, one process per step
    return {st.index: Process(f"qr_step{st.index}", "qr_update", tuple(qr_unit_loops(
        patterns[st.index], st.frontal_dim, opts.units, ops, name=f"s{st.index}",
        qr_rows=opts.qr_rows)))
        for st in sched.steps}


def _levels(ctx, sets, by_index, damping) -> None:
    """Per level the stack, the steps on the unit sets and the commit; the sets' memories."""
    opts, ops, sched = ctx.opts, ctx.les, ctx.program.schedule
    tables, timing = ctx.tables, ctx.les_timing
    max_w = ctx.sizes["MAX_W"]
    banked = rows_in_banks(ctx.program, opts, tables)
    wave = wave_steps(ctx.program, opts)
    if wave is not None and lin_wave(ctx.program, opts) is not None:
        # the wave inside lin_level (the emitted kernel's one-step solve): the solve's levels
        # as without it (the update model's qr_beside_linearize takes the region with the
        # root inside), its two streams to unit set 1
        c0, c1, root = wave
        ctx.channels.append(pass_channel(tables, c0, root, opts.units, ops.word_bits))
        # step c1's passed rows packed as the root's banks take them, set 1's collector to set 1
        # itself (accel.cpp.jinja's `own`: every word, read after its step)
        own = pass_channel(tables, c1, root, opts.units, ops.word_bits)
        ctx.channels.append(Channel("qr_own", "stream", own.depth, own.width, "qr_set1",
                                    "qr_set1"))
        # step c0's words from set 0's collector to the commit process (wave_commit_loops),
        # two of a row a stream word
        ctx.channels.append(Channel("qr_commit", "stream", 2, COMMIT_PAIR * ops.word_bits,
                                    "qr_set0", "qr_commit_wave"))
        # step c1's and the root's conditionals from set 1's collector, two words a stream
        # word, every pair held (commit_pair_words)
        ctx.channels.append(Channel("qr_commit1", "stream", commit_pair_words(tables, c1, root),
                                    COMMIT_PAIR * ops.word_bits, "qr_set1", "qr_commit_wave"))
        # the root's own rows by row parity (root_bank_parity_words), a stream each
        for name, words in zip(("bank_root", "bank_root1"), root_bank_parity_words(tables, root),
                               strict=True):
            ctx.channels.append(Channel(name, "stream", max(1, words), 2 * ops.word_bits + 64,
                                        "datapaths", "qr_set1"))
        wave = None
    for li, level in enumerate(sched.levels):
        if wave is not None and li == len(sched.levels) - 1:
            break  # the root ran in the level before's region (wave_loops)
        # eliminate_all: each step stacked into its unit set's banks (√μ once per solve
        # first, when damping: Gauss-Newton stacks no damping row), the level's steps on the
        # unit sets side by side, each result committed
        stack = [Process("root_mu", "qr_stack", (kernel_loop("root_mu", 1, "root", timing),))] \
            if li == 0 and damping else []
        # (level 0's first steps: their factors' rows already in the banks, rows_in_banks)
        stack += [Process(f"stack{i}", "qr_stack", tuple(stack_loops(
            tables, i, opts.units, max_w, damping, timing, opts.qr_unit != "stream",
            li == 0 and k < sets and bool(banked))))
            for k, i in enumerate(level)]
        ctx.add_phase("solve", Phase(f"qr_stack_level{li}", False, tuple(stack), linear=True))
        # eliminate_all hands a level's steps to the unit sets `sets` at a time, in level
        # order: each chunk a DATAFLOW region of its sets side by side, the chunks one after
        # another
        chunks = [_assign([by_index[i] for i in level[c:c + sets]], sets, "qr", li)
                  for c in range(0, len(level), sets)]
        if wave is not None and li == len(sched.levels) - 2:
            c0, c1, root = wave
            loops = {i: by_index[i].loops for i in wave}
            chunks = [(Process(f"qr{li}_set0", "set0", loops[c0]),
                       Process(f"qr{li}_set1", "set1", wave_loops(
                           tables, timing, opts.units, max_w, damping, wave, loops)))]
            level = (c0, root)  # committed after the region (c1 in set 1's process)
            ctx.channels.append(pass_channel(tables, c0, root, opts.units, ops.word_bits))
        if len(chunks) == 1:
            ctx.add_phase("solve", Phase(f"qr_level{li}", True, chunks[0], linear=True))
        else:
            ctx.add_phase("solve", Phase(f"qr_level{li}", False, tuple(
                Process(f"qr{li}_chunk{c}", "qr_sets", (Loop(
                    f"qr{li}_chunk{c}", 1, 1, phase_cycles(Phase("chunk", True, procs))),))
                for c, procs in enumerate(chunks)), linear=True))
        ctx.add_phase("solve", Phase(f"qr_commit_level{li}", False, tuple(
            Process(f"commit{i}", "qr_commit", tuple(commit_loops(tables, i, timing, False)))
            for i in level), linear=True))
    sizes = ctx.sizes
    cols = sizes["MAX_W"] + 1
    local = -(-cols // opts.units)
    # fgc_qr.h's banks are two memories each by row parity (WORK<s>'s cyclic partition);
    # fgc_qr_stream.h's one
    parities = 1 if opts.qr_unit == "stream" else 2
    lin = lin_wave(ctx.program, opts) is not None
    for s in range(sets):  # accel.cpp.jinja's WORK<s>, CONDBUF<s>, UPDBUF<s>
        ctx.memories.append(Memory(f"qr{s}_work", opts.units * sizes["MAX_ROWS"] * local,
                                   ops.word_bits, parities * opts.units))
        # fgc_qr.h's evec: the Evaluate's copy of the vector by row, two memories by parity
        ctx.memories.append(Memory(f"qr{s}_evec", sizes["MAX_ROWS"], ops.word_bits, 2))
        # (lin_level's wave: set 1's holds the root's conditional after its own step's)
        ctx.memories.append(Memory(f"qr{s}_condbuf", (2 if lin and s == 1 else 1)
                                   * sizes["MAX_F"] * cols, ops.word_bits, 1))
        ctx.memories.append(Memory(f"qr{s}_updbuf", cols * cols, ops.word_bits, 1))
        if lin and s < 2:
            # lin_level's steps keep rows by structure (fgc_qr.h's qr_step_io with mask0): the
            # Evaluate's row patterns (msk, a row's cols bits, two memories by row parity)
            ctx.memories.append(Memory(f"qr{s}_keep_mask", sizes["MAX_ROWS"], cols, 2))
    if lin:
        # the emitter's pattern table (accel.cpp.jinja's QR_KEEP_MASK, a ROM): per update class
        # of the window (at most its slots + 1: emitter.py's _keep_context), the wave's three
        # steps' rows
        classes = len(ctx.program.schedule.clusters) + 1
        ctx.memories.append(Memory("qr_keep_table", classes * 3 * sizes["MAX_ROWS"], cols, 1))
    solver_memories(sizes, ops, ctx.memories)


SPEC = UnitSpec(
    linear_solver=True,
    name="qr", role="Householder QR unit sets: Evaluate + n_u Update units per set (paper A's, "
    "--qr-unit householder), or n_u streaming reflection stages (--qr-unit stream: "
    "fgc_qr_stream.h, priced by units/qr_stream.py)",
    build=build, phases=("qr_stack", "qr", "qr_commit"), header="fgc_qr.h",
    constants=(("UNITS", "n_u Update units (PlanOptions.units)"),
               ("PARTIALS", "interleaved partial sums of a dot product (the adder latency)"),
               ("MAX_ROWS", "rows of the widest stacked step"), ("MAX_W", "widest step")),
    printed_by="accel.cpp.jinja: eliminate_all -> fgc_eliminate.h qr_eliminate_all (QrSets: "
    "qr_stack, qr_level -> qr_set<s> -> fgc_qr.h qr_step or fgc_qr_stream.h qrs_step, "
    "qr_commit)",
    applies=lambda program, options: program.solver.linear == "qr")

