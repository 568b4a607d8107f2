"""The accelerator plan: typed hardware for one Program and unit options, and its cost.

:func:`build_plan` turns a :class:`fgc.ir.program.Program` and :class:`PlanOptions` (n_u Update
units,
#CPE, QR unit sets, operator ALLOCATION limits) into an :class:`AcceleratorPlan`: units with their
allocated operators, memories, channels and *phases* of processes made of loops (trip count, II,
depth, all derived from :mod:`fgc_backends.cost.operators`). :func:`plan_cost` is nothing but the
arithmetic of that plan:

- a loop takes ``(trip - 1) * ii + depth`` cycles (0 when ``trip == 0``), repeated ``repeat``
  times; a process runs its loops one after another;
- a dataflow phase (processes overlapping through channels) takes its slowest process plus the
  fill of the others (their first-item depth); a sequential phase sums its processes;
- one LM/GN iteration runs the phases one after another;
- resources are the units' allocated operators × instances + memories as placed (BRAM36 from
  words × width and banks, BRAM18 granularity; small memories in LUTRAM).

The HLS emitter prints this plan (accel.cpp.jinja): its units are the emitted processes, its
channels the emitted streams (:func:`process_network`), its factor-datapath operators the
``ALLOCATION`` limits and its instance-loop IIs the ``PIPELINE`` IIs (docs/hls.md). Options the
emitter does not build (raw Jacobian storage, a whole-matrix dense or blocked Hessian) are
what-if designs for the design space: :func:`emitted_options` says which.

The QR and Cholesky timings follow the fixed unit headers the design calls
(backends/hls/include/fgc_qr.h, fgc_cpe.h): :func:`qr_unit_loops` and :func:`cpe_round_depth`
price the loops those headers execute and count under FGC_COUNT_CYCLES. The stacked matrix's
structure (which rows each Householder reflection touches) is read from the sim cost model's
``stacked_pattern``, a data source only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from fgc.errors import FgcError
from fgc.ir.program import Program
from fgc_backends.cost.operators import OperatorTable, table
from fgc_backends.cost.target import DEFAULT, DEFAULT_PART, capacity

# the default device (cost/target.py); PlanOptions.part selects the fit verdict's
PART = DEFAULT.name
PART_DSP, PART_BRAM36, PART_LUT, PART_FF = DEFAULT.dsp, DEFAULT.bram36, DEFAULT.lut, DEFAULT.ff
BRAM18_BITS = 18 * 1024
PORTS = 2  # words a cycle a copy moves through a memory's two ports (accel.cpp.jinja's PORTS)
LUTRAM_MAX_BITS = 1024  # memories up to this size go to LUTRAM / registers (design)

# default ALLOCATION limits of the factor datapath, per kernel operator kind (design: the sim
# model's factor pool, so both models share one datapath size)
DEFAULT_ALLOCATION = (("add", 16), ("mul", 24), ("div", 4), ("sqrt", 2), ("trig", 2),
                      ("special", 2))
# default ALLOCATION limits of the state update's datapath per variable type (design: it runs
# once per trial step over the variables, so it is kept small; a Pose3 retraction at these
# limits takes a variable every 36 cycles, set by its special functions)
STATE_ALLOCATION = (("add", 4), ("mul", 6), ("div", 1), ("sqrt", 1), ("trig", 2), ("special", 1))


ALLOCATION_SCALING = ("instances", "uniform")
JACOBIAN_STORAGE = ("whitened", "raw")
HESSIAN_STORAGE = ("frontal", "dense", "blocked")


class PlanError(FgcError):
    """The plan cannot be built for these options."""


@dataclass(frozen=True)
class PlanOptions:
    units: int = 4  # n_u Update units per QR unit set
    cpe: int = 20  # Cholesky process elements
    unit_sets: int | None = None  # QR unit sets: None = 2 for two-ended chains, else 1
    allocation: tuple[tuple[str, int], ...] = DEFAULT_ALLOCATION
    # how a block type's datapath gets its share of ``allocation``: "instances" (default): the
    # heaviest type (most operations × instances) gets the limits, every other type
    # ⌈limit × min(1, n / n_heaviest)⌉ (at least 1) for its n instances, so a prior evaluated
    # once a linearisation does not hold the IMU datapath's operators (the factor_jacobian
    # phase runs the types one after another; a few-instance type's loop is short whatever
    # its II); "uniform": every type gets the whole limit (capped by its own operation counts
    # in both rules)
    allocation_scaling: str = "instances"
    state_allocation: tuple[tuple[str, int], ...] = STATE_ALLOCATION  # retract_<k>'s limits
    hgc_lanes: int = 16  # multiply-accumulate lanes of the Hessian/gradient unit
    # "whitened": each factor's A = W·J and b = -W·r, dense, as the factor datapath leaves them;
    # "raw": the papers' choice - the unwhitened Jacobians' structurally non-zero entries (0 and
    # ±1 entries are not stored), the residual and W's parameters, whitened while stacking
    # (a "whiten_stack" phase of multiply-accumulates before the linear solver)
    jacobian_storage: str = "whitened"
    # Cholesky: "frontal" (emitted): each elimination step's frontal [H | g] through the cascade
    # in turn (multifrontal); what-if, not emitted: "dense", the whole lower triangle of [H | g]
    # as one matrix; "blocked", only H's envelope in chain (variable) order - Cholesky fills no
    # entry outside it - and the cascade streams only that
    hessian_storage: str = "frontal"
    # the precisions the design computes in (operator table, word width): None = the Program's
    # (SolverConfig.precision, and its les_precision for the linear solver); an HLS design
    # emitted in another scalar than the Program's sets them (for_config)
    precision: str | None = None
    les_precision: str | None = None
    # the FPGA part whose device capacities the fit verdict uses (cost/target.py; an HLS
    # design's HlsConfig.part, which run_hls.tcl names)
    part: str = DEFAULT_PART

    @classmethod
    def of(cls, program: Program, **changes) -> PlanOptions:
        base = dict(units=program.solver.units, cpe=program.solver.cpe)
        base.update(changes)
        return cls(**base)

    @classmethod
    def for_config(cls, config, program: Program, **changes) -> PlanOptions:
        """The options of the design an HLS config emits for ``program``: the Program's n_u
        and #CPE, the config's unit sets, and the operators of the scalar types it emits
        (``HlsConfig.scalar_cxx`` for the whole accelerator, ``linear_cxx`` for the linear
        solver), not the Program's precision: a float design of a float64 Program is priced in
        float32 operators."""
        base = dict(unit_sets=config.unit_sets, precision=scalar_precision(config.scalar_cxx),
                    les_precision=scalar_precision(config.linear_cxx), part=config.part)
        if getattr(config, "allocation", None):  # the config's limits over the defaults
            base["allocation"] = tuple({**dict(DEFAULT_ALLOCATION),
                                        **dict(config.allocation)}.items())
        base.update(changes)
        return cls.of(program, **base)


def scalar_precision(scalar_cxx: str) -> str:
    """The operator-table precision of an emitted C++ scalar type."""
    if scalar_cxx == "float":
        return "float32"
    if scalar_cxx == "double":
        return "float64"
    raise PlanError(f"no operator table for the scalar type {scalar_cxx!r} (float32 and float64 "
                    "only: fgc has no fixed-point operator table)")


@dataclass(frozen=True)
class Loop:
    name: str
    trip: int
    ii: int
    depth: int
    repeat: int = 1

    @property
    def cycles(self) -> int:
        return self.repeat * ((self.trip - 1) * self.ii + self.depth if self.trip > 0 else 0)


@dataclass(frozen=True)
class Process:
    name: str
    unit: str
    loops: tuple[Loop, ...]

    @property
    def cycles(self) -> int:
        return sum(lp.cycles for lp in self.loops)

    @property
    def fill(self) -> int:
        return self.loops[0].depth if self.loops else 0


PHASE_PER = ("iteration", "call", "rejection")


@dataclass(frozen=True)
class Phase:
    name: str
    dataflow: bool
    processes: tuple[Process, ...]
    linear: bool = False  # part of the linear-equation solver
    # how often it runs: "iteration" (once an iteration: in Cost.cycles), "call" (once per
    # accelerator call: the top's copies in and out), "rejection" (when a trial step does not
    # lower the cost: the rounding-noise pass); the last two are in Cost.other_cycles
    per: str = "iteration"


@dataclass(frozen=True)
class Unit:
    name: str
    role: str
    instances: int
    operators: tuple[tuple[str, int], ...]  # kind -> allocated instances in one unit
    extra_dsp: int = 0


@dataclass(frozen=True)
class Memory:
    name: str
    words: int
    width: int
    banks: int

    @property
    def bram18(self) -> int:
        if self.words * self.width <= LUTRAM_MAX_BITS:
            return 0
        per_bank = math.ceil(self.words / self.banks)
        # a BRAM18 is 512 × 36 or 1024 × 18 (wider words use several side by side)
        width_blocks = math.ceil(self.width / 36)
        return self.banks * width_blocks * math.ceil(per_bank / 512)

    @property
    def kind(self) -> str:
        return "lutram" if self.bram18 == 0 else "bram"


@dataclass(frozen=True)
class Channel:
    name: str
    kind: str  # "stream" (FIFO), or "pingpong" (two buffers: region j writes one while it reads
    # the other, which region j - 1 wrote; the next region swaps them)
    depth: int
    width: int
    producer: str
    consumer: str


@dataclass(frozen=True)
class AcceleratorPlan:
    program: str
    linear: str
    precision: str
    clock_mhz: float
    options: PlanOptions
    units: tuple[Unit, ...]
    memories: tuple[Memory, ...]
    channels: tuple[Channel, ...]
    phases: tuple[Phase, ...]
    ops: OperatorTable = field(repr=False)

    def unit(self, name: str) -> Unit:
        return next(u for u in self.units if u.name == name)


@dataclass(frozen=True)
class Cost:
    cycles: int  # one iteration
    phase_cycles: tuple[tuple[str, int], ...]
    linear_cycles: int
    dsp: int
    lut: int
    ff: int
    bram36: float
    clock_mhz: float
    fits: bool
    over: tuple[str, ...]  # resources over the part's capacity
    dsp_by_unit: tuple[tuple[str, int], ...] = ()  # (unit, DSP of all its instances)
    words: int = 0  # words the plan's memories hold (channels not counted)
    other_cycles: tuple[tuple[str, int], ...] = ()  # phases not run every iteration (Phase.per)

    @property
    def latency_ms(self) -> float:
        return self.cycles / (self.clock_mhz * 1e3)


# --------------------------------------------------------------------------------------------
# loops from the operator table
# --------------------------------------------------------------------------------------------


def dot_loop(name: str, length: int, ops: OperatorTable, partials: int | None = None,
             repeat: int = 1) -> Loop:
    """A pipelined dot product: k interleaved partial sums give II = ceil(La / k); the depth
    holds one multiply, one add and the ⌈log₂ k⌉-level tree folding the partial sums."""
    la, lm = ops.add.latency, ops.mul.latency
    k = max(1, min(length, partials if partials is not None else la))
    tree = math.ceil(math.log2(k)) if k > 1 else 0
    return Loop(name, length, math.ceil(la / k), lm + la * (1 + tree), repeat)


def _region_cycles(processes: list[list[Loop]],
                   waits: tuple[tuple[int, int, int, str], ...] = ()) -> int:
    """A DATAFLOW region as :func:`phase_cycles` prices it: its slowest process plus the fill of
    the others (the depth of their first loop that runs); processes with no running loop are
    absent (fgc_cycles.h's ``total``). ``waits``: (process, loop, on process, loop name suffix):
    that loop of the process (or, if it does not run, the process's next one that does) reads
    the stream the other's first such loop writes, as it comes, so it ends no earlier than its
    depth after that loop; each process's loops follow one another, in the region's order, and
    the region takes no less than any process's last loop's end (fgc_cycles.h's FGC_WAIT)."""
    procs = [(sum(lp.cycles for lp in loops), next((lp.depth for lp in loops if lp.trip > 0), 0))
             for loops in processes if any(lp.trip > 0 for lp in loops)]
    if not procs:
        return 0
    slow = max(range(len(procs)), key=lambda i: procs[i][0])
    total = procs[slow][0] + sum(fill for i, (_, fill) in enumerate(procs) if i != slow)
    if not waits:
        return total
    ends: dict[tuple[int, int], int] = {}
    for p, loops in enumerate(processes):
        clock, pending = 0, None
        for li, lp in enumerate(loops):
            for wp, wl, q, suffix in waits:
                if (wp, wl) != (p, li):
                    continue
                at = next((ends[q, x] for x, lq in enumerate(processes[q])
                           if lq.name.endswith(suffix) and (q, x) in ends), None)
                if at is not None:
                    pending = at if pending is None else max(pending, at)
            if lp.trip <= 0:
                continue
            end = clock + lp.cycles
            if pending is not None:
                end, pending = max(end, pending + lp.depth), None
            clock = ends[p, li] = end
            total = max(total, end)
    return total


def qr_unit_loops(pattern, frontal: int, units: int, ops: OperatorTable,
                  partials: int | None = None, name: str = "s") -> list[Loop]:
    """The loops of ``qr_step`` (backends/hls/include/fgc_qr.h) on one step, as it executes them.

    ``pattern``: the structural rows × (f + s) non-zeros of the stacked matrix (the right-hand
    side, dense, is added here); a structural non-zero is taken as non-zero in value. Returns one
    ``Loop`` (trip 1) per DATAFLOW region ``qr_reflection`` j = -1 ... k - 1 (k = min(rows,
    w + 1)), whose depth is the region's cycles (slowest process plus the others' fill, and no
    less than the Evaluate's end, which reads its column as the Update unit streams it: the same
    loops and rule as the header's FGC_CYCLES / FGC_WAIT counters), then the pivot check.
    ``partials`` is the header's CFG::PARTIALS (default: the adder latency, II 1).
    """
    import numpy as np

    la, lm, ld, ls = ops.add.latency, ops.mul.latency, ops.div.latency, ops.sqrt.latency
    p = partials if partials is not None else la
    nz = np.hstack([np.asarray(pattern, dtype=bool),
                    np.ones((len(pattern), 1), dtype=bool)])
    rows, cols = nz.shape
    k = min(rows, cols)

    # the active rows of each column as the units meet them (the fill of earlier reflections)
    active = []
    for j in range(k):
        rows_j = [i for i in range(j, rows) if nz[i, j]]
        if not rows_j:
            active.append(0)  # all zero: skipped
            continue
        act = sorted(set(rows_j) | {j})
        union = nz[act, j + 1:].any(axis=0)
        nz[np.ix_(act, range(j + 1, cols))] = union
        nz[act, j] = False
        nz[j, j] = True
        active.append(len(act))
    tree = math.ceil(math.log2(p)) if p > 1 else 0
    tree1 = math.ceil(math.log2(p + 1))  # the fold of the P partials and the pivot's term
    out = []
    for j in range(-1, k):
        n = active[j] if j >= 0 else 0
        # the broadcast (index 0) streams the vector, qr_finish (1) computes v_0, tau, R_jj
        procs = [[Loop("vector", max(n, 1), 1, 2)],
                 [Loop("read", 2, 1, 1), Loop("v0", 1, 1, ls + la if n else 1),
                  Loop("tau", 1, 1, lm + ld if n else 1)]]
        waits = []
        for u in range(units):
            # the unit's first column right of j; the next pivot column if it is j + 1 < k
            c0 = j + 1 + (u - (j + 1)) % units
            next_here = c0 == j + 1 and c0 < k
            fused = n > 1 and next_here
            # the n - 1 words below the pivot (the next pivot column's dot over them), then v_0
            # (waiting for qr_finish's square root: its term is one more leaf of the fold's
            # tree), then tau and R_jj (waiting for qr_finish's divide)
            below = max(n - 1, 0)
            loops = [Loop("header", 1, 1, 1),
                     Loop("vector_dot", below, 1, lm + la) if fused else
                     Loop("vector", below, 1, 1)]
            waits.append((len(procs), len(loops), 1, "v0"))
            if fused:
                loops += [Loop("pivot_term", 1, 1, lm), Loop("fold", 1, 1, la * tree1)]
            else:
                loops.append(Loop("pivot_word", 1, 1, 1))
            waits.append((len(procs), len(loops), 1, "tau"))
            loops.append(Loop("tail", 2, 1, 1))
            if n > 0 and j >= 0 and j % units == u:
                loops.append(Loop("pivot_column", n, 1, 1))
            if next_here:  # updated and streamed to the Evaluate first
                if n > 1:
                    loops += [Loop("scale", 1, 1, lm),
                              Loop("axpy_next_column", rows - j, 1, lm + la)]
                else:
                    if n == 1:
                        loops.append(Loop("negate", 1, 1, 1))
                    loops.append(Loop("next_column", rows - c0, 1, 1))
                if j >= 0:
                    loops.append(Loop("row_out", 1, 1, 1))
            # the unit's other columns right of j, through the flattened loops
            lb = c0 // units + (1 if next_here else 0)
            r = (cols - 1 - u) // units - lb + 1 if c0 < cols else 0
            if r > 0 and n > 1:
                loops += [Loop("dots", n * r, 1, lm + la), Loop("fold_scale", r, 1, la * tree + lm),
                          Loop("axpys", n * r, 1, lm + la)]
            elif r > 0 and j >= 0:
                loops.append(Loop("negate_rows" if n == 1 else "rows_out", r, 1, 1))
            procs.append(loops)
        col = j + 1
        if col < k:
            # the Evaluate starts when the unit holding the column streams it; the squares are
            # summed as the column arrives, then folded (the tail is the next region's qr_finish)
            waits.append((len(procs), 0, 2 + col % units, "next_column"))
            procs.append([Loop("receive_norm", rows - col, 1, lm + la),
                          Loop("fold", 1, 1, la * tree)])
        # the collector: row j of R out (cond / update) and the running scale
        first = 0 if j < frontal else frontal  # rows out with their zeros left of the diagonal
        procs.append([Loop("header", 1, 1, 1)]
                     + ([Loop("row", cols - first, 1, 2)] if 0 <= j < k else []))
        out.append(Loop(f"{name}_reflection{j + 1}", 1, 1, _region_cycles(procs, tuple(waits))))
    out.append(Loop(f"{name}_pivot_check", frontal, 1, 2))
    return out


def cpe_round_depth(active: int, cpe: int, ops: OperatorTable) -> int:
    """Depth of one ``cpe_round`` (backends/hls/include/fgc_cpe.h) as a loop of trip = its words
    at II 1: the region's slowest process is a CPE with a pivot (words + 1 words, its latency
    Ls + Ld + Lm + La deep), the others add their fill: each other CPE with a pivot its latency,
    each idle CPE 1, the feed and the drain 2 each; + 1 for the status word."""
    cpe_depth = ops.sqrt.latency + ops.div.latency + ops.mul.latency + ops.add.latency
    return active * cpe_depth + (cpe - active) + 2 + 2 + 1


def cpe_step_loops(frontal: int, separator: int, cpe: int, ops: OperatorTable,
                   name: str = "s") -> list[Loop]:
    """The loops of ``cpe_step`` (backends/hls/include/fgc_cpe.h) on one step's [H | g] of f
    frontal and s separator columns, as the csim counters count them: mu on the diagonal, one
    ``Loop`` per round (trip = its words at II 1, depth :func:`cpe_round_depth`), the copy of
    [H | g] when f = 0, the pivot check. The whole matrix as one step (f = n, s = 0) is what the
    Cholesky phase of :func:`build_plan` prices; a multifrontal design sums this over its steps."""
    w = frontal + separator
    loops = [Loop(f"{name}_damping", frontal, 1, ops.add.latency)]
    for r, p0 in enumerate(range(0, frontal, cpe)):
        m = w - p0
        loops.append(Loop(f"{name}_round{r}", m * (m + 1) // 2 + m, 1,
                          cpe_round_depth(min(cpe, frontal - p0), cpe, ops)))
    if frontal == 0:
        loops.append(Loop(f"{name}_no_pivots", w * (w + 1) // 2 + w, 1, 1))
    loops.append(Loop(f"{name}_pivot_check", frontal, 1, 2))
    return loops


def kernel_timing(ops: OperatorTable) -> dict[str, tuple[int, int]]:
    """(II, depth) of each kind of loop the emitted kernel runs around the units
    (accel.cpp.jinja prints these numbers into its FGC_CYCLES counters, so plan and count share
    them; what is counted is how often each loop runs and its trip count at run time):

    - ``move``: one word read and written a cycle (II 1, depth 2); ``fill``: one word written
      a cycle (II 1, depth 1);
    - ``acc``: a sum of products into one accumulator: the recurrence through the adder sets
      II = add latency, depth multiply + add (interleaved into partial sums by
      :func:`kernel_dot`); ``acc2``: a term through two multiply-adds before its sum (the
      rounding-noise pass's terms), depth 2 (multiply + add);
    - ``scatter``: ``+=`` into a table-addressed memory where every iteration of the loop has
      its own address (II 1, depth read + add + write);
    - ``max``: a running maximum (compare and select: II = compare latency, depth + 2 for the
      read and |·|; into partial maxima by :func:`kernel_dot`, LM control's gradient maximum);
    - ``root``: one square root (√μ); ``decision``: LM control's scalar decision (gain ratio
      divide, two multiplies, two adds, a compare); ``retract``: one variable a cycle through a
      retraction-sized datapath (square root, divide, sin/cos, four multiply-adds deep), what
      the update model assumes for a Log pass (the emitted state update is priced per type by
      :func:`retract_datapath`).
    """
    la, lm, lc = ops.add.latency, ops.mul.latency, ops.compare.latency
    return {"move": (1, 2), "fill": (1, 1), "acc": (la, lm + la), "acc2": (la, 2 * (lm + la)),
            "scatter": (1, la + 2), "max": (lc, lc + 2),
            "root": (1, ops.sqrt.latency), "div": (ops.div.latency, ops.div.latency),
            "decision": (1, ops.div.latency + 2 * lm + 2 * la + lc),
            "retract": (1, ops.sqrt.latency + ops.div.latency + ops.sincos.latency
                        + 4 * (lm + la))}


def kernel_loop(name: str, trip: int, kind: str, timing: dict, repeat: int = 1) -> Loop:
    """A loop of the kernel's own code (not a unit's) with ``trip`` iterations of kind ``kind``
    (move, acc, retract, …): its II and depth from ``timing`` (:func:`kernel_timing`)."""
    ii, depth = timing[kind]
    return Loop(name, trip, ii, depth, repeat)


def kernel_dot(name: str, length: int, timing: dict, repeat: int = 1, kind: str = "acc",
               lead: int = 0) -> Loop:
    """A kernel loop summing ``length`` terms into the adder latency's interleaved partial sums
    (accel.cpp.jinja's T_PARTIALS / L_PARTIALS), priced by the dot-product rule
    (:func:`dot_loop`) with the latencies of ``timing`` (:func:`kernel_timing`).

    ``kind`` is the recurrence the partials break: ``"acc"`` (a sum: the adder's latency, the
    multiply ahead of it) or ``"max"`` (a running maximum into partial maxima: the compare's
    latency, the read and |·| ahead of it, the fold a tree of compares); ``lead``: latency
    ahead of the multiply (the step test's g + μδ)."""
    ii, depth = timing[kind]
    k = max(1, min(length, ii))
    return Loop(name, length, math.ceil(ii / k), lead + (depth - ii) + ii * (1 + _ceil_log2(k)),
                repeat)


def _ported(words: int) -> int:
    """Iterations of a copy of ``words`` words at :data:`PORTS` words a cycle."""
    return -(-words // PORTS)


def _ceil_log2(n: int) -> int:
    """⌈log₂ n⌉ (0 for n ≤ 1): the adds of a tree folding n sums (fgc_cycles.h's ceil_log2)."""
    return math.ceil(math.log2(n)) if n > 1 else 0


def _block_shape(block) -> tuple[int, int, int, object]:
    """(m, d, padded row stride, Gram tiles) of a block type as the emitted kernel lays it out
    (fgc_backends.cfamily.blocks' pattern: rows padded to whole TILEs)."""
    from fgc.ir.codes import NOISE_CODES
    from fgc_backends.cfamily.sparsity import block_pattern

    kinds = tuple(NOISE_CODES[m.noise_kind] for m in block.members)
    pattern = block_pattern(block, kinds, f"block {block.name!r}")
    return block.residual_dim, sum(block.variable_dims), pattern.padded, pattern.tiles()


def _tables(program) -> dict:
    """The emitted constant tables by name (the same arrays the kernel steps through)."""
    from fgc_backends.cfamily.tables import build_tables
    t = build_tables(program, damped=program.solver.method == "lm",
                     cholesky=program.solver.linear == "cholesky")
    return {a.name: a.values for a in t.arrays}


def gradient_loops(program, timing: dict) -> list[Process]:
    """QR: linearize_all's gradient pass over AB (reduce_<b>: per instance its rows loaded,
    :data:`PORTS` words a cycle, the column map, A^T b a row a cycle into the adder latency's
    interleaved partial sums of every column (a dot product of m terms, :func:`kernel_dot`),
    the finiteness check's tree over the padded columns, the scatter into G at II 1), after G
    is zeroed."""
    la = timing["acc"][0]
    n_t = sum(v.dim for v in program.variables)
    procs = [Process("zero_gradient", "gradient", (kernel_loop("zero", n_t, "fill", timing),))]
    for i, b in enumerate(program.blocks):
        m, d, padded, _ = _block_shape(b)
        n = sum(1 for f in program.factors if f.block == i)
        procs.append(Process(f"reduce_{i}", "gradient", (
            kernel_loop("load", _ported(m * padded), "move", timing, n),
            kernel_loop("columns", d, "fill", timing, n),
            kernel_dot("rows", m, timing, n),
            Loop("check", 1, 1, la * _ceil_log2(padded), n),
            kernel_loop("scatter", d, "scatter", timing, n))))
    return procs


def hgc_loops(program, timing: dict) -> list[Process]:
    """Cholesky: linearize_all's HGC over AB (reduce_<b>: per instance its rows loaded,
    :data:`PORTS` words a cycle, the column map, its packed Gram in GRAM zeroed, the Gram
    panels - one row of a panel a cycle into the adder latency's interleaved partial sums of
    TILE x (tiles TILE) entries, a dot product of its rows (:func:`kernel_dot`) - each panel's
    lower-triangle entries out into GRAM (folded, a word a cycle), the gradient scatter from
    GRAM (II 1) and the finiteness check over the diagonal (interleaved partial sums: the
    dot-product rule)), after G is zeroed."""
    from fgc_backends.cfamily.sparsity import TILE

    n_t = sum(v.dim for v in program.variables)
    procs = [Process("zero_gradient", "hgc", (kernel_loop("zero", n_t, "fill", timing),))]
    for i, b in enumerate(program.blocks):
        m, d, padded, tiles = _block_shape(b)
        n = sum(1 for f in program.factors if f.block == i)
        cols = d + 1
        loops = [kernel_loop("load", _ported(m * padded), "move", timing, n),
                 kernel_loop("columns", d, "fill", timing, n),
                 kernel_loop("zero_gram", cols * (cols + 1) // 2, "fill", timing, n)]
        for k in range(tiles.count):
            rows, wide = tiles.table[5 * k + 3], tiles.table[5 * k + 4]
            loops += [kernel_dot("panel", rows, timing, n),
                      kernel_loop("panel_out", TILE * wide * TILE, "fill", timing, n)]
        loops += [kernel_loop("scatter", d, "scatter", timing, n),
                  kernel_dot("check", cols, timing, n)]
        procs.append(Process(f"reduce_{i}", "hgc", tuple(loops)))
    return procs


def stack_loops(tables: dict, s: int, units: int, max_w: int, damped: bool,
                timing: dict) -> list[Loop]:
    """accel.cpp.jinja's stack() of step s into its unit set's banks: the rows zeroed (all
    n_u banks a cycle), each factor's rows [A | b] and each child's new-factor rows
    :data:`PORTS` words a cycle, the damping rows' diagonal."""
    f, m = tables["STEP_F"][s], tables["STEP_ROWS"][s]
    local = -(-(max_w + 1) // units)
    loops = [kernel_loop("zero", m * local, "fill", timing)]
    fb = tables["STEP_FACTOR_BEGIN"]
    for e in range(fb[s], fb[s + 1]):
        fac = tables["STEP_FACTORS"][e]
        words = tables["FACTOR_A_OFF"][fac + 1] - tables["FACTOR_A_OFF"][fac]
        loops.append(kernel_loop("factor_rows", _ported(words), "move", timing))
    cb = tables["STEP_CHILD_BEGIN"]
    for e in range(cb[s], cb[s + 1]):
        c = tables["STEP_CHILDREN"][e]
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


def assemble_loops(tables: dict, s: int, max_w: int, timing: dict) -> list[Loop]:
    """Cholesky's eliminate(): step s's [H | g] zeroed (MAX_W + 1 words a row, a word a cycle),
    then per factor its packed Gram's lower triangle and gradient row (d (d + 1) / 2 + d
    entries), per child its update matrix's upper triangle and reduced g (s (s + 1) / 2 + s),
    each one loop of ``+=`` into the table-addressed frontal matrix whose entries all go to
    different addresses (``scatter``: II 1)."""
    w = tables["STEP_W"][s]
    loops = [kernel_loop("zero", w * (max_w + 1), "fill", timing)]
    fb = tables["STEP_FACTOR_BEGIN"]
    for e in range(fb[s], fb[s + 1]):
        fac = tables["STEP_FACTORS"][e]
        d = tables["FACTOR_COLMAP_BEGIN"][fac + 1] - tables["FACTOR_COLMAP_BEGIN"][fac]
        loops.append(kernel_loop("gram", d * (d + 1) // 2 + d, "scatter", timing))
    cb = tables["STEP_CHILD_BEGIN"]
    for e in range(cb[s], cb[s + 1]):
        c = tables["STEP_CHILDREN"][e]
        sc = tables["STEP_W"][c] - tables["STEP_F"][c]
        loops.append(kernel_loop("child", sc * (sc + 1) // 2 + sc, "scatter", timing))
    return loops


def backsub_copies(tables: dict, s: int, timing: dict) -> tuple[list[Loop], list[Loop]]:
    """back_substitute()'s copies around cond_backsub for step s alone on one unit (one unit
    set, :data:`PORTS` words a cycle): the conditional from COND and the separator's solution
    in; the frontal solution out."""
    w, f = tables["STEP_W"][s], tables["STEP_F"][s]
    return ([kernel_loop("cond_in", _ported(f * (w + 1)), "move", timing),
             kernel_loop("separator_in", _ported(w - f), "move", timing)],
            [kernel_loop("solution_out", _ported(f), "move", timing)])


def rounding_noise_loops(program, timing: dict) -> list[Process]:
    """rounding_noise_all(): each variable's largest storage entry, then per instance its rows
    loaded (:data:`PORTS` words a cycle), the column scales, the rows' moved terms (a row a
    cycle, its TILE partial sums unrolled) and their sum (TILE rows a step into TILE partial
    sums)."""
    from fgc_backends.cfamily.sparsity import TILE

    la, lm = timing["acc"][0], timing["acc"][1] - timing["acc"][0]
    procs = [Process("variable_scale", "lm_control", tuple(
        kernel_loop("scale", v.storage_dim, "max", timing) for v in program.variables))]
    for i, b in enumerate(program.blocks):
        m, _, padded, _ = _block_shape(b)
        n = sum(1 for f in program.factors if f.block == i)
        row_depth = 2 * lm + la * (padded // TILE + 2)
        procs.append(Process(f"noise_{i}", "lm_control", (
            kernel_loop("load", _ported(m * padded), "move", timing, n),
            kernel_loop("scales", padded, "fill", timing, n),
            Loop("rows", m, 1, row_depth, n),
            kernel_loop("terms", -(-m // TILE), "acc2", timing, n))))
    return procs


def _sim_table(ops: OperatorTable):
    from fgc_backends.cost.params import OperatorCost
    from fgc_backends.cost.params import OperatorTable as SimTable

    def c(o):
        return OperatorCost(latency=o.latency, dsp=o.dsp, lut=o.lut, ff=o.ff, ii=o.ii)

    return SimTable(word_bits=ops.word_bits, add=c(ops.add), mul=c(ops.mul), div=c(ops.div),
                    sqrt=c(ops.sqrt), trig=c(ops.sincos), special=c(ops.special))


# --------------------------------------------------------------------------------------------
# the plan
# --------------------------------------------------------------------------------------------


def build_plan(program: Program, options: PlanOptions | None = None) -> AcceleratorPlan:
    """The accelerator plan of ``program`` with ``options`` (default: the Program's solver)."""
    from fgc_backends.cost.kernels import critical_path

    opts = options or PlanOptions.of(program)
    for name in ("units", "cpe", "hgc_lanes"):
        if int(getattr(opts, name)) < 1:
            raise PlanError(f"plan option {name} must be ≥ 1, got {getattr(opts, name)}")
    for name, allowed in (("jacobian_storage", JACOBIAN_STORAGE),
                          ("hessian_storage", HESSIAN_STORAGE),
                          ("allocation_scaling", ALLOCATION_SCALING)):
        if getattr(opts, name) not in allowed:
            raise PlanError(f"plan option {name} must be one of {', '.join(allowed)}, "
                            f"got {getattr(opts, name)!r}")
    alloc = dict(opts.allocation)
    for kind, n in (*alloc.items(), *opts.state_allocation):
        if n < 1:
            raise PlanError(f"ALLOCATION limit of {kind} must be ≥ 1, got {n}")
    precision = opts.precision or program.solver.precision
    les_precision = opts.les_precision or (program.solver.les_precision if opts.precision is None
                                           else precision)
    ops = table(precision)
    les = table(les_precision)
    sim_ops = _sim_table(ops)
    units, memories, channels, phases = [], [], [], []

    # factor datapath: one per block type, shared by the Jacobian and the cost mode
    jac, cost = [], []
    whiten_macs = 0
    n_of = [sum(1 for f in program.factors if f.block == i) for i in range(len(program.blocks))]
    work = [n * sum(b.ops_after.values()) for n, b in zip(n_of, program.blocks, strict=True)]
    heaviest = n_of[max(range(len(work)), key=work.__getitem__)] if work else 1
    for i, b in enumerate(program.blocks):
        name = f"factor_{i}"
        instances = n_of[i]
        used = {k: max(b.ops_after.get(k, 0), b.ops_cost.get(k, 0)) for k in alloc}
        share = {k: alloc[k] if opts.allocation_scaling == "uniform"
                 else max(1, math.ceil(alloc[k] * min(1.0, instances / heaviest)))
                 for k in alloc}
        allocated = tuple((k, min(share[k], n)) for k, n in used.items() if n > 0)
        units.append(Unit(name, f"factor datapath of block {b.name!r} (both modes)", 1,
                          allocated))
        for mode, counts, text, out in (("jacobian", b.ops_after, b.kernel, jac),
                                        ("cost", b.ops_cost, b.cost_kernel, cost)):
            issue = max([1] + [math.ceil(counts.get(k, 0) * ops.op(k).ii / n)
                               for k, n in allocated])
            ii = issue
            if mode == "cost":  # the emitted cost_of_<b> sums the instances' costs in order (the
                ii = max(ii, ops.add.latency)  # simulator's): a recurrence through the adder
            # one evaluation ends no earlier than its critical path, nor before the allocated
            # operators have issued all its operations (a lower bound of the schedule's depth)
            depth = max(critical_path(text, sim_ops), issue)
            out.append(Process(f"{name}_{mode}", name,
                               (Loop(f"{name}_{mode}_instances", instances, ii, depth),)))
        if opts.jacobian_storage == "raw":
            words = raw_jacobian_words(b) * instances
            whiten_macs += whitening_macs(b) * instances
        else:
            words = b.residual_dim * (1 + sum(b.variable_dims)) * instances
        memories.append(Memory(f"ab_{i}", words, ops.word_bits, 1))
    # the emitted instance loops (evaluate_<b>, cost_of_<b>) run one block type after another
    phases.append(Phase("factor_jacobian", False, tuple(jac)))
    timing = kernel_timing(ops)
    if program.solver.linear == "qr":  # Cholesky's gradient comes with the HGC (_cholesky)
        phases.append(Phase("gradient", False, tuple(gradient_loops(program, timing))))
    if opts.jacobian_storage == "raw":
        # whitening while stacking: W·[J | -r] of each instance, one multiply-accumulate a
        # cycle in each of n_u lanes, before the solver reads the rows
        units.append(Unit("whiten", "W·[J | -r] while stacking the raw Jacobians", opts.units,
                          (("add", 1), ("mul", 1))))
        phases.append(Phase("whiten_stack", False, (Process("whiten", "whiten", (
            Loop("macs", math.ceil(whiten_macs / opts.units), 1,
                 ops.mul.latency + ops.add.latency),)),), linear=True))

    if program.solver.linear == "qr":
        _qr(program, opts, les, units, memories, channels, phases)
    else:
        _cholesky(program, opts, les, units, memories, channels, phases)

    # state update: one retract datapath per variable type (ALLOCATION: state_allocation's
    # limits), its variables pipelined through it, type by type (retract_all's loop per kind)
    for k, name in enumerate(_type_counts(program.variables)):
        units.append(Unit(f"state_update_{k}", f"retract x ⊕ δ of {name}", 1,
                          retract_datapath(name, ops, opts.state_allocation)[0]))
    phases.append(state_update_phase(program.variables, ops, opts.state_allocation))
    phases.append(Phase("factor_cost", False, tuple(cost)))
    n_x = sum(v.storage_dim for v in program.variables)
    n_t = sum(v.dim for v in program.variables)
    # LM control (optimize / try_steps): the gradient's largest entry, |x|, the step test over
    # δ (|δ|² and the predicted decrease), the scalar decision, the accepted x copied back
    # (the step test at II 1 starts three multiplies and three adds a cycle: μδ, δ·δ,
    # δ·(g + μδ); g + μδ and the two partial sums)
    units.append(Unit("lm_control", "gain ratio, μ update, stopping rules", 1,
                      (("add", 3), ("mul", 3), ("div", 1), ("compare", 1))))
    phases += lm_control_phases(n_t, n_x, timing)
    # once per call: the top's copies of x and the data in and x out
    phases.append(setup_phase(n_x, _sizes(program)["N_DATA"], n_x, timing))
    # when a trial step does not lower the cost: the rounding-noise band from AB
    phases.append(Phase("rounding_noise", False, tuple(rounding_noise_loops(program, timing)),
                        per="rejection"))
    memories.append(Memory("state", n_x, ops.word_bits, 1))  # X
    memories.append(Memory("state_trial", n_x, ops.word_bits, 1))  # X_TRIAL
    memories.append(Memory("gradient_delta", 2 * n_t, ops.word_bits, 2))  # G, DELTA
    memories.append(Memory("data", _sizes(program)["N_DATA"], ops.word_bits, 1))  # DATA_BUF
    return AcceleratorPlan(program.name, program.solver.linear, precision,
                           program.solver.clock_mhz, opts, tuple(units), tuple(memories),
                           tuple(channels), tuple(phases), ops)


def _qr(program, opts, ops, units, memories, channels, phases):
    from fgc_backends.cost.structure import stacked_pattern

    sched = program.schedule
    widest = max(len(level) for level in sched.levels)
    sets = opts.unit_sets if opts.unit_sets is not None else (
        2 if sched.structure_class == "chain" and sched.ordering == "two-ended" else 1)
    sets = max(1, min(sets, widest))
    damping = program.solver.method == "lm"
    patterns = {st.index: stacked_pattern(program, st, damping) for st in sched.steps}
    max_rows = _sizes(program)["MAX_ROWS"]
    for s in range(sets):
        units.append(Unit(f"qr{s}_evaluate", "Householder vector of a column", 1,
                          (("add", 2), ("mul", 2), ("div", 1), ("sqrt", 1))))
        units.append(Unit(f"qr{s}_update", "apply the reflector to a column", opts.units,
                          (("add", 1), ("mul", 1))))
        # the network of one reflection (include/fgc_qr.h's qr_reflection): broadcast streams
        # the vector below the pivot to each Update unit while qr_finish computes v_0, tau and
        # R_jj from the norm and the pivot and streams them to each unit (R_jj also to collect);
        # each unit streams the next column (its owner's) to Evaluate and its entries of R's
        # row to collect; Evaluate writes one of the vector's and one of the norm's two
        # buffers, which the next region's broadcast and qr_finish read
        for u in range(opts.units):
            channels.append(Channel(f"qr{s}_v{u}", "stream", 2 * ops.add.latency,
                                    ops.word_bits + 32, f"qr{s}_broadcast", f"qr{s}_update{u}"))
        for u in range(opts.units):
            channels.append(Channel(f"qr{s}_t{u}", "stream", 3, ops.word_bits + 32,
                                    f"qr{s}_finish", f"qr{s}_update{u}"))
        channels.append(Channel(f"qr{s}_r", "stream", 1, ops.word_bits,
                                f"qr{s}_finish", f"qr{s}_collect"))
        for u in range(opts.units):
            channels.append(Channel(f"qr{s}_col{u}", "stream", max_rows, ops.word_bits,
                                    f"qr{s}_update{u}", f"qr{s}_evaluate"))
            channels.append(Channel(f"qr{s}_row{u}", "stream", 2, ops.word_bits,
                                    f"qr{s}_update{u}", f"qr{s}_collect"))
        channels.append(Channel(f"qr{s}_vbuf", "pingpong", max_rows + 1, ops.word_bits + 32,
                                f"qr{s}_evaluate", f"qr{s}_broadcast"))
        channels.append(Channel(f"qr{s}_hbuf", "pingpong", 2, ops.word_bits + 32,
                                f"qr{s}_evaluate", f"qr{s}_finish"))
    # per step: the regions of fgc_qr.h's qr_step (Evaluate of column k+1 overlaps the Update
    # of column k in region k) and its store, one process per step
    step_proc = []
    for st in sched.steps:
        pattern = patterns[st.index]
        loops = qr_unit_loops(pattern, st.frontal_dim, opts.units, ops, name=f"s{st.index}")
        step_proc.append((st, Process(f"qr_step{st.index}", "qr_update", tuple(loops))))
    tables = _tables(program)
    timing = kernel_timing(ops)
    max_w = _sizes(program)["MAX_W"]
    for li, level in enumerate(sched.levels):
        # eliminate_all: each step stacked into its unit set's banks (√μ once per solve
        # first), the level's steps on the unit sets side by side, each result committed
        stack = [Process("root_mu", "qr_stack", (kernel_loop("root_mu", 1, "root", timing),))] \
            if li == 0 else []
        stack += [Process(f"stack{i}", "qr_stack", tuple(stack_loops(
            tables, i, opts.units, max_w, damping, timing))) for i in level]
        phases.append(Phase(f"qr_stack_level{li}", False, tuple(stack), linear=True))
        # eliminate_all hands a level's steps to the unit sets `sets` at a time, in level
        # order: each chunk a DATAFLOW region of its sets side by side, the chunks one after
        # another
        by_index = {st.index: p for st, p in step_proc}
        chunks = [_assign([by_index[i] for i in level[c:c + sets]], sets, "qr", li)
                  for c in range(0, len(level), sets)]
        if len(chunks) == 1:
            phases.append(Phase(f"qr_level{li}", True, chunks[0], linear=True))
        else:
            phases.append(Phase(f"qr_level{li}", False, tuple(
                Process(f"qr{li}_chunk{c}", "qr_sets", (Loop(
                    f"qr{li}_chunk{c}", 1, 1, phase_cycles(Phase("chunk", True, procs))),))
                for c, procs in enumerate(chunks)), linear=True))
        phases.append(Phase(f"qr_commit_level{li}", False, tuple(
            Process(f"commit{i}", "qr_commit", tuple(commit_loops(tables, i, timing, False)))
            for i in level), linear=True))
    _backsub_phases(program, ops, phases, "backsub", sets)
    for s in range(sets):
        units.append(Unit(f"qr{s}_backsub", "back-substitution (cond_backsub)", 1,
                          (("add", 1), ("mul", 2))))
    sizes = _sizes(program)
    cols = sizes["MAX_W"] + 1
    local = -(-cols // opts.units)
    for s in range(sets):  # accel.cpp.jinja's WORK<s>, CONDBUF<s>, UPDBUF<s>
        memories.append(Memory(f"qr{s}_work", opts.units * sizes["MAX_ROWS"] * local,
                               ops.word_bits, opts.units))
        memories.append(Memory(f"qr{s}_condbuf", sizes["MAX_F"] * cols, ops.word_bits, 1))
        memories.append(Memory(f"qr{s}_updbuf", cols * cols, ops.word_bits, 1))
    _solver_memories(sizes, ops, memories)


def backsub_loops(frontal: int, separator: int, ops: OperatorTable,
                  name: str = "bs") -> list[Loop]:
    """The loops of ``cond_backsub`` (backends/hls/include/fgc_backsub.h) on one conditional of
    f frontal and s separator columns, as its csim counters count them: the rows' partial sums
    zeroed (all PARTIALS banks a cycle), the separator's share S xs of every row in one loop
    (trip f s, II 1: consecutive iterations hit different rows, PARTIALS = the add latency
    interleaved sums per row, multiply-add deep), each row's partial sums folded and subtracted
    from d (trip f, II 1, La (1 + ⌈log₂ PARTIALS⌉) deep), the f reciprocals of the diagonal, then
    column by column (last first) one multiply and the column above the pivot (trip r, II 1,
    multiply-add deep)."""
    la, lm = ops.add.latency, ops.mul.latency
    tree = math.ceil(math.log2(la)) if la > 1 else 0
    loops = [Loop(f"{name}_zero", frontal, 1, 1),
             Loop(f"{name}_separator", frontal * separator, 1, lm + la),
             Loop(f"{name}_fold", frontal, 1, la * (1 + tree))]
    if frontal:
        loops.append(Loop(f"{name}_reciprocals", frontal, 1, ops.div.latency))
    for r in range(frontal - 1, -1, -1):
        loops.append(Loop(f"{name}_solve{r}", 1, 1, lm))
        if r:
            loops.append(Loop(f"{name}_column{r}", r, 1, lm + la))
    return loops


def backsub_chunk_loops(tables: dict, steps, ops: OperatorTable, timing: dict,
                        sets: int) -> list[Loop]:
    """back_substitute() on ``steps`` (at most ``sets``: one chunk of a level, one step per unit
    set): their conditionals and separator solutions copied in side by side (the memories' two
    ports shared out: ``max(1, PORTS // sets)`` words of each step an iteration at II
    ⌈sets / PORTS⌉), the ``backsub_level`` DATAFLOW region (one ``cond_backsub`` process per
    unit set: the slowest plus the others' fill), the frontal solutions out side by side."""
    per, ii = max(1, PORTS // sets), -(-sets // PORTS)
    sizes = [(tables["STEP_F"][s], tables["STEP_W"][s]) for s in steps]
    region = _region_cycles([backsub_loops(f, w - f, ops, name=f"bs{s}")
                             for s, (f, w) in zip(steps, sizes, strict=True)])
    _, depth = timing["move"]

    def copy(name, words):
        return Loop(name, -(-max(words) // per), ii, depth)

    return [copy("cond_in", [f * (w + 1) for f, w in sizes]),
            copy("separator_in", [w - f for f, w in sizes]),
            Loop("backsub_level", 1, 1, region),
            copy("solution_out", [f for f, _ in sizes])]


def _backsub_phases(program, ops, phases, unit, sets: int = 1) -> None:
    """The emitted back_substitute: levels root first, each level's steps (LEVEL_STEPS order)
    ``sets`` at a time through the ``backsub_level`` region (:func:`backsub_chunk_loops`)."""
    tables, timing = _tables(program), kernel_timing(ops)
    begin, order = tables["LEVEL_BEGIN"], tables["LEVEL_STEPS"]
    for li in range(len(begin) - 2, -1, -1):
        procs = []
        for i in range(begin[li], begin[li + 1], sets):
            chunk = order[i:min(i + sets, begin[li + 1])]
            procs.append(Process("backsub_" + "_".join(f"step{s}" for s in chunk), unit,
                                 tuple(backsub_chunk_loops(tables, chunk, ops, timing, sets))))
        phases.append(Phase(f"backsub_level{len(begin) - 2 - li}", False, tuple(procs),
                            linear=True))


def _solver_memories(sizes, ops, memories) -> None:
    """The linear solver's stores: conditionals (R | d) and the factors passed to parents."""
    memories.append(Memory("cond", sizes["N_COND"], ops.word_bits, 1))
    memories.append(Memory("nf", sizes["N_NF"], ops.word_bits, 1))


def _type_counts(variables) -> dict[str, int]:
    """Variables per type, in first-seen order (retract_all's kinds)."""
    kinds: dict[str, int] = {}
    for v in variables:
        kinds[v.type_name] = kinds.get(v.type_name, 0) + 1
    return kinds


def retract_datapath(type_name: str, ops: OperatorTable,
                     allocation=STATE_ALLOCATION) -> tuple[tuple[tuple[str, int], ...], int, int]:
    """The state-update datapath of one variable type as emitted (accel.cpp.jinja's
    retract_<k>, its ALLOCATION limits): (allocated operators, II, depth). Operators per kind:
    the retraction's count, at most the ``allocation`` limit (the factor datapaths' rule,
    ``PlanOptions.state_allocation``'s limits); II:
    max over kinds of ⌈count × op II / allocated⌉; depth: the retraction's critical path."""
    from fgc.ir.program import KernelText
    from fgc_backends.cfamily.retract import retract_kernel, variable_class
    from fgc_backends.cost.kernels import critical_path

    kernel = retract_kernel(variable_class(type_name))
    counts = kernel.op_counts()
    alloc = dict(allocation)
    allocated = tuple((k, min(alloc[k], n)) for k, n in counts.items() if n > 0 and k in alloc)
    ii = max([1] + [math.ceil(counts[k] * ops.op(k).ii / n) for k, n in allocated])
    return allocated, ii, critical_path(KernelText.of(kernel), _sim_table(ops))


def retract_loops(variables, ops: OperatorTable,
                  allocation=STATE_ALLOCATION) -> tuple[Loop, ...]:
    """retract_all's loops over ``variables`` (VariableSpecs): one pipelined loop per variable
    type, in first-seen order, at its datapath's II and depth (:func:`retract_datapath`)."""
    loops = []
    for k, (name, n) in enumerate(_type_counts(variables).items()):
        _, ii, depth = retract_datapath(name, ops, allocation)
        loops.append(Loop(f"kind{k}", n, ii, depth))
    return tuple(loops)


def state_update_phase(variables, ops: OperatorTable, allocation=STATE_ALLOCATION) -> Phase:
    """The state update as emitted (retract_all) over ``variables``."""
    return Phase("state_update", False, (Process("retract", "state_update",
                                                 retract_loops(variables, ops, allocation)),))


def lm_control_phases(n_t: int, n_x: int, timing: dict) -> tuple[Phase, ...]:
    """LM control as emitted (optimize / try_steps) over ``n_t`` tangent and ``n_x`` storage
    words, in three phases by how often their loops run: ``lm_iteration`` once per
    linearisation (the gradient's largest entry; |x|, at the top of try_steps), ``lm_control``
    once per linear solve (the step test over δ, the scalar decision) and ``lm_accept`` once
    per accepted step (x_trial copied into x). A plan iteration has one of each; an LM retry
    adds a solve, not an iteration, and the last iteration of a run often accepts nothing. The
    gradient maximum is partial maxima and the sums (|x|², ‖δ‖² and δᵀ(g + μδ)) interleaved
    partial sums, all PIPELINEd at II 1 and priced by the dot-product rule
    (:func:`kernel_dot`); the step test's terms pass a multiply and an add (g + μδ) before
    their product."""
    lead = timing["acc"][1]  # μδ, then g + μδ
    return (Phase("lm_iteration", False, (Process("iterate", "lm_control", (
                kernel_dot("gradient_max", n_t, timing, kind="max"),
                kernel_dot("x_norm", n_x, timing))),)),
            Phase("lm_control", False, (Process("decide", "lm_control", (
                kernel_dot("step_test", n_t, timing, lead=lead),
                kernel_loop("decision", 1, "decision", timing))),)),
            Phase("lm_accept", False, (Process("accept", "lm_control", (
                kernel_loop("accept", n_x, "move", timing),)),)))


def setup_phase(x_in: int, data_in: int, x_out: int, timing: dict) -> Phase:
    """The top's copies once per call: ``x_in`` state words and ``data_in`` data words in,
    ``x_out`` state words out."""
    return Phase("setup", False, (Process("top", "lm_control", (
        kernel_loop("x_in", x_in, "move", timing), kernel_loop("data_in", data_in, "move", timing),
        kernel_loop("x_out", x_out, "move", timing))),), per="call")


def plan_sizes(program) -> dict:
    """The emitted kernel's sizes (MAX_W, N_DATA, …) as the C++ tables define them."""
    return _sizes(program)


def _sizes(program) -> dict:
    """The emitted tables' sizes (MAX_ROWS, MAX_W, ...): the unit headers' CFG constants."""
    from fgc_backends.cfamily.tables import build_tables
    t = build_tables(program, damped=program.solver.method == "lm",
                     cholesky=program.solver.linear == "cholesky")
    return dict(t.constants)


def _assign(procs, sets, tag, li):
    """Independent steps on ``sets`` unit sets, longest first (one process per set that has
    a step)."""
    loads = [[] for _ in range(sets)]
    for p in sorted(procs, key=lambda p: -p.cycles):
        i = min(range(sets), key=lambda j: sum(q.cycles for q in loads[j]))
        loads[i].append(p)
    return tuple(Process(f"{tag}{li}_set{i}", f"set{i}",
                         tuple(lp for q in group for lp in q.loops))
                 for i, group in enumerate(loads) if any(q.loops for q in group))


def _cholesky(program, opts, ops, units, memories, channels, phases):
    n = program.storage.columns
    c = opts.cpe
    # HGC: H = JᵀJ, g = Jᵀr over each instance's dense block rows × columns
    macs = 0
    for f in program.factors:
        b = program.blocks[f.block]
        cols = sum(b.variable_dims)
        macs += b.residual_dim * (cols * (cols + 1) // 2 + cols)
    units.append(Unit("hgc", "Hessian/gradient accumulation", opts.hgc_lanes,
                      (("add", 1), ("mul", 1))))
    if opts.hessian_storage == "frontal":  # as emitted: reduce_<b>'s loops (hgc_loops)
        phases.append(Phase("hgc", False, tuple(hgc_loops(program, kernel_timing(ops))),
                            linear=True))
    else:
        phases.append(Phase("hgc", False, (Process("hgc", "hgc", (
            Loop("macs", math.ceil(macs / opts.hgc_lanes), 1,
                 ops.mul.latency + ops.add.latency),)),), linear=True))
    units.append(Unit("cpe", "Cholesky process element: Evaluate + Update", c,
                      (("add", 1), ("mul", 1), ("div", 1), ("sqrt", 1)), extra_dsp=1))
    if opts.hessian_storage == "frontal":
        _cholesky_frontal(program, opts, ops, units, memories, channels, phases)
        return
    # what-if designs (not emitted): the whole [H | g] factored as one matrix, dense or by its
    # envelope ("blocked", paper B's choice), through one cascade
    for i in range(c):
        channels.append(Channel(f"cpe_fifo{i}", "stream", n, ops.word_bits,
                                "cholesky_in" if i == 0 else f"cpe{i - 1}", f"cpe{i}"))
    lowest = hessian_envelope(program) if opts.hessian_storage == "blocked" else [n - 1] * n
    rounds = []
    for r in range(math.ceil(n / c)):
        m = n - r * c
        words = sum(lowest[j] - j + 1 for j in range(r * c, n)) + m
        rounds.append(Loop(f"round{r}", words, 1, cpe_round_depth(min(c, m), c, ops)))
    phases.append(Phase("cholesky", True, (Process("cascade", "cpe", tuple(rounds)),),
                        linear=True))
    phases.append(Phase("cholesky_scalar", False, (Process("damping_and_check", "cpe", (
        Loop("damping", n, 1, ops.add.latency), Loop("pivot_check", n, 1, 2))),), linear=True))
    units.append(Unit("trisolve", "Lᵀδ = z (Lz = g runs in the cascade)", 1,
                      (("add", 1), ("mul", 1), ("div", 1))))
    solve = dot_loop("rows", n, ops)
    phases.append(Phase("trisolve", False, (Process("backward", "trisolve", (
        Loop("rows", n, max(1, math.ceil(n / 2)), solve.depth + ops.div.latency),)),),
        linear=True))
    memories.append(Memory("hessian", sum(lo - j + 1 for j, lo in enumerate(lowest)) + n,
                           ops.word_bits, max(1, c // 4)))


def _cholesky_frontal(program, opts, ops, units, memories, channels, phases):
    """The emitted multifrontal Cholesky: per elimination step (one after another) its frontal
    [H | g] through fgc_cpe.h's cpe_step (feed -> #CPE CPEs -> drain per round of #CPE pivots),
    then back-substitution step by step (cond_backsub)."""
    c = opts.cpe
    sizes = _sizes(program)
    for i in range(c + 1):
        channels.append(Channel(f"cpe_link{i}", "stream", sizes["MAX_W"], ops.word_bits,
                                "cpe_feed" if i == 0 else f"cpe{i - 1}",
                                f"cpe{i}" if i < c else "cpe_drain"))
    loops = []
    for st in program.schedule.steps:
        loops += cpe_step_loops(st.frontal_dim, st.separator_dim, c, ops, name=f"s{st.index}")
    tables, timing = _tables(program), kernel_timing(ops)
    # eliminate(s): [H | g] assembled from GRAM and the children's update matrices, the
    # cascade, the conditional and update matrix stored into COND / NF
    phases.append(Phase("assemble", False, tuple(
        Process(f"assemble{st.index}", "cpe", tuple(assemble_loops(
            tables, st.index, sizes["MAX_W"], timing))) for st in program.schedule.steps),
        linear=True))
    phases.append(Phase("cholesky", False, (Process("cascade", "cpe", tuple(loops)),),
                        linear=True))
    phases.append(Phase("store", False, tuple(
        Process(f"store{st.index}", "cpe", tuple(commit_loops(tables, st.index, timing, True)))
        for st in program.schedule.steps), linear=True))
    units.append(Unit("trisolve", "back-substitution (cond_backsub; Lz = g rides the cascade)",
                      1, (("add", 1), ("mul", 1), ("div", 1))))
    _backsub_phases(program, ops, phases, "trisolve")
    cols = sizes["MAX_W"] + 1
    # accel.cpp.jinja's GRAM, HF, CONDBUF, UPDBUF (the frontal matrix of one step at a time) and
    # cpe_step's second trailing-matrix buffer Hb (the rounds alternate between HF and Hb)
    memories.append(Memory("gram", sizes["N_GRAM"], ops.word_bits, 1))
    memories.append(Memory("frontal", sizes["MAX_W"] * cols, ops.word_bits, 1))
    memories.append(Memory("frontal_b", sizes["MAX_W"] * cols, ops.word_bits, 1))
    memories.append(Memory("condbuf", sizes["MAX_F"] * cols, ops.word_bits, 1))
    memories.append(Memory("updbuf", sizes["MAX_W"] * cols, ops.word_bits, 1))
    _solver_memories(sizes, ops, memories)


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


# --------------------------------------------------------------------------------------------
# the cost: the plan's arithmetic
# --------------------------------------------------------------------------------------------


def phase_cycles(phase: Phase) -> int:
    if not phase.processes:
        return 0
    lat = [p.cycles for p in phase.processes]
    if not phase.dataflow:
        return sum(lat)
    slow = max(range(len(lat)), key=lambda i: lat[i])
    return lat[slow] + sum(p.fill for i, p in enumerate(phase.processes) if i != slow)


def plan_cost(plan: AcceleratorPlan) -> Cost:
    per = tuple((ph.name, phase_cycles(ph)) for ph in plan.phases if ph.per == "iteration")
    other = tuple((ph.name, phase_cycles(ph)) for ph in plan.phases if ph.per != "iteration")
    cycles = sum(c for _, c in per)
    linear = sum(phase_cycles(ph) for ph in plan.phases if ph.linear and ph.per == "iteration")
    lut = ff = 0
    by_unit = []
    for u in plan.units:
        unit_dsp = u.instances * u.extra_dsp
        for kind, n in u.operators:
            o = plan.ops.op(kind)
            unit_dsp += u.instances * n * o.dsp
            lut += u.instances * n * o.lut
            ff += u.instances * n * o.ff
        by_unit.append((u.name, unit_dsp))
    dsp = sum(d for _, d in by_unit)
    channel_mems = tuple(Memory(ch.name, ch.depth * (2 if ch.kind == "pingpong" else 1), ch.width,
                                2 if ch.kind == "pingpong" else 1) for ch in plan.channels)
    bram36 = sum(m.bram18 for m in plan.memories + channel_mems) / 2
    device = capacity(plan.options.part)
    over = tuple(name for name, used, cap in (("DSP", dsp, device.dsp),
                                              ("BRAM36", bram36, device.bram36),
                                              ("LUT", lut, device.lut), ("FF", ff, device.ff))
                 if used > cap)
    return Cost(cycles, per, linear, dsp, lut, ff, bram36, plan.clock_mhz, not over, over,
                tuple(by_unit), sum(m.words for m in plan.memories), other)


def plan_power_w(cost: Cost) -> float:
    """Power of a plan's design, W: not modelled by the plan itself. This applies the sim cost
    model's approach (``backends/cost/resources.power_w``: static power plus per-DSP, LUT,
    FF and BRAM36 dynamic power, linear in the clock; coefficients fitted to paper B's three
    Vivado estimates) to the plan's resources."""
    from fgc_backends.cost.params import CostParams

    params = CostParams()
    dynamic_mw = (cost.dsp * params.power_dsp_mw + cost.lut * params.power_lut_mw
                  + cost.ff * params.power_ff_mw + cost.bram36 * params.power_bram_mw)
    return params.power_static_w + dynamic_mw * 1e-3 * cost.clock_mhz / params.power_reference_mhz


def phase_groups(cost: Cost) -> tuple[tuple[str, int], ...]:
    """Per-iteration cycles of the plan's phases with their level number dropped (``qr_level3``
    and ``qr_level4`` add up under ``qr``), in first-seen order."""
    groups: dict[str, int] = {}
    for name, cycles in cost.phase_cycles:
        key = phase_group(name)
        groups[key] = groups.get(key, 0) + cycles
    return tuple(groups.items())


def plan_summary(program: Program, iterations: int, options: PlanOptions | None = None) -> dict:
    """What ``fgc simulate`` / ``fgc report`` print as hardware figures, all from
    ``plan_cost(build_plan(program, options))``: ``iterations`` × one iteration's cycles by
    phase group, latency, resources and their share of the part's device (``options.part``,
    default the xc7z045), memory words, and power /
    energy (:func:`plan_power_w`: the sim model's power approach on the plan's resources)."""
    plan = build_plan(program, options)
    c = plan_cost(plan)
    k = max(1, int(iterations))
    device = capacity(plan.options.part)
    caps = {"dsp": device.dsp, "bram": device.bram36, "lut": device.lut, "ff": device.ff}
    res = {"dsp": c.dsp, "bram": c.bram36, "lut": c.lut, "ff": c.ff}
    power = plan_power_w(c)
    latency_ms = k * c.latency_ms
    return {"source": "accelerator plan (fgc_backends.hls.plan: plan_cost of build_plan)",
            "device": device.name, "part": plan.options.part, "clock_mhz": c.clock_mhz,
            "iterations": k,
            "cycles": k * c.cycles, "iteration_cycles": c.cycles, "latency_ms": latency_ms,
            "linear_cycles": k * c.linear_cycles,
            "cycles_by_unit": {name: k * cyc for name, cyc in phase_groups(c)},
            "resources": res, "utilization": {key: res[key] / caps[key] for key in caps},
            "fits": c.fits, "memory_words": c.words, "power_w": power,
            "energy_mj": power * latency_ms}


# --------------------------------------------------------------------------------------------
# the emitted process network
# --------------------------------------------------------------------------------------------


EMITTED = {"jacobian_storage": ("whitened",), "hessian_storage": ("frontal",)}


def emitted_options(options: PlanOptions) -> list[str]:
    """The options of ``options`` the HLS emitter does not build (what-if designs), as text."""
    return [f"{k}={getattr(options, k)!r}" for k, ok in EMITTED.items()
            if getattr(options, k) not in ok]


def unit_sets(plan: AcceleratorPlan) -> int:
    """QR unit sets of ``plan`` (0 for Cholesky)."""
    return sum(1 for u in plan.units if u.name.endswith("_evaluate"))


def backsub_units(plan: AcceleratorPlan) -> int:
    """Back-substitution units of ``plan``: one per QR unit set, one for Cholesky (the
    emitted ``backsub_set<u>`` processes of back_substitute's ``backsub_level`` region)."""
    return max(1, unit_sets(plan))


def process_network(plan: AcceleratorPlan) -> tuple[tuple[str, ...], tuple[Channel, ...]]:
    """The dataflow processes and streams the emitter prints for ``plan``: the linear solver's
    (the unit headers' regions: per QR unit set broadcast, qr_finish, n_u Update units,
    Evaluate and collect; for Cholesky the feed, the #CPE process elements and the drain),
    then back-substitution's (the kernel's ``backsub_level`` region: one ``backsub_set<u>``
    per unit, :func:`backsub_units`, side by side). Streams are the plan's stream channels;
    the back-substitution units have none (each reads its own conditional and separator
    buffers and writes its own frontal buffer, the region's arguments: nothing passes from
    one unit to another)."""
    if plan.linear == "qr":
        procs = tuple(p for s in range(unit_sets(plan)) for p in (
            f"qr{s}_broadcast", f"qr{s}_finish",
            *(f"qr{s}_update{u}" for u in range(plan.options.units)),
            f"qr{s}_evaluate", f"qr{s}_collect"))
    else:
        procs = ("cpe_feed", *(f"cpe{i}" for i in range(plan.options.cpe)), "cpe_drain")
    procs += tuple(f"backsub_set{u}" for u in range(backsub_units(plan)))
    return procs, tuple(ch for ch in plan.channels if ch.kind == "stream")


# the plan phase group (a phase's name without its level number) -> the run event (FGC_EVENT in
# accel.cpp.jinja) that executes it once: how a counting C simulation's phases are priced
# (bench/bench_cycles.py) and how the on-chip stream's model counts a call's phases
# (fgc_backends.hls.window)
PHASE_TRIGGER = {"setup": "call", "factor_jacobian": "linearize", "gradient": "linearize",
                 "hgc": "linearize", "qr_stack": "solve", "qr": "solve", "qr_commit": "solve",
                 "backsub": "solve", "assemble": "solve", "cholesky": "solve", "store": "solve",
                 "lm_control": "solve", "lm_iteration": "linearize", "lm_accept": "accept",
                 "state_update": "retract", "factor_cost": "cost", "rounding_noise": "noise"}


def phase_group(name: str) -> str:
    """A plan phase's group: its name without the level number (qr_level3 -> qr)."""
    head, _, tail = name.rpartition("_level")
    return head if head and tail.isdigit() else name


def plan_groups(plan: AcceleratorPlan) -> dict[str, int]:
    """Per phase group of ``plan`` the cycles of one execution of its per-iteration and
    per-rejection phases."""
    group: dict[str, int] = {}
    for ph in plan.phases:
        if ph.per in ("iteration", "rejection"):
            g = phase_group(ph.name)
            group[g] = group.get(g, 0) + phase_cycles(ph)
    return group
