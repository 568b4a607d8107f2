"""The accelerator plan: typed hardware for one Program and unit options, and its cost.

:func:`build_plan` turns a :class:`fgc.program.Program` and :class:`PlanOptions` (n_u Update units,
#CPE, QR unit sets, operator ALLOCATION limits) into an :class:`AcceleratorPlan`: units with their
allocated operators, memories, channels and *phases* of processes made of loops (trip count, II,
depth, all derived from :mod:`fgc_backends.hls.operators`). :func:`plan_cost` is nothing but the
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
``ALLOCATION`` limits and its instance-loop IIs the ``PIPELINE`` IIs (docs/hls.md).

The QR sweep's structure (which rows and columns each Householder reflection touches) is read
from the sim cost model's structural simulation (``householder_sweep`` / ``stacked_pattern``), a
data source only; the timings here are this module's own.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from fgc.errors import FgcError
from fgc.program import Program

from .operators import OperatorTable, table

PART = "xc7z045"
PART_DSP, PART_BRAM36, PART_LUT, PART_FF = 900, 545, 218_600, 437_200
BRAM18_BITS = 18 * 1024
LUTRAM_MAX_BITS = 1024  # memories up to this size go to LUTRAM / registers (design)

# default ALLOCATION limits of the factor datapath, per kernel operator kind (design: the sim
# model's factor pool, so both models share one datapath size)
DEFAULT_ALLOCATION = (("add", 16), ("mul", 24), ("div", 4), ("sqrt", 2), ("trig", 2),
                      ("special", 2))


class PlanError(FgcError):
    """The plan cannot be built for these options."""


@dataclass(frozen=True)
class PlanOptions:
    units: int = 4  # n_u Update units per QR unit set
    cpe: int = 20  # Cholesky process elements
    unit_sets: int | None = None  # QR unit sets: None = 2 for two-ended chains, else 1
    allocation: tuple[tuple[str, int], ...] = DEFAULT_ALLOCATION
    hgc_lanes: int = 16  # multiply-accumulate lanes of the Hessian/gradient unit

    @classmethod
    def of(cls, program: Program, **changes) -> PlanOptions:
        base = dict(units=program.solver.units, cpe=program.solver.cpe)
        base.update(changes)
        return cls(**base)


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


@dataclass(frozen=True)
class Phase:
    name: str
    dataflow: bool
    processes: tuple[Process, ...]
    linear: bool = False  # part of the linear-equation solver


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
    kind: str  # "stream" (FIFO), "pingpong", or "buffer" (written by a region, read by the next)
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


def _sim_table(ops: OperatorTable):
    from fgc_backends.sim.cost.params import OperatorCost
    from fgc_backends.sim.cost.params import OperatorTable as SimTable

    def c(o):
        return OperatorCost(latency=o.latency, dsp=o.dsp, lut=o.lut, ff=o.ff, ii=o.ii)

    return SimTable(word_bits=ops.word_bits, add=c(ops.add), mul=c(ops.mul), div=c(ops.div),
                    sqrt=c(ops.sqrt), trig=c(ops.sincos), special=c(ops.special))


# --------------------------------------------------------------------------------------------
# the plan
# --------------------------------------------------------------------------------------------


def build_plan(program: Program, options: PlanOptions | None = None) -> AcceleratorPlan:
    """The accelerator plan of ``program`` with ``options`` (default: the Program's solver)."""
    from fgc_backends.sim.cost.kernels import critical_path

    opts = options or PlanOptions.of(program)
    for name in ("units", "cpe", "hgc_lanes"):
        if int(getattr(opts, name)) < 1:
            raise PlanError(f"plan option {name} must be ≥ 1, got {getattr(opts, name)}")
    alloc = dict(opts.allocation)
    for kind, n in alloc.items():
        if n < 1:
            raise PlanError(f"ALLOCATION limit of {kind} must be ≥ 1, got {n}")
    ops = table(program.solver.precision)
    les = table(program.solver.les_precision)
    sim_ops = _sim_table(ops)
    units, memories, channels, phases = [], [], [], []

    # factor datapath: one per block type, shared by the Jacobian and the cost mode
    jac, cost = [], []
    for i, b in enumerate(program.blocks):
        name = f"factor_{i}"
        used = {k: max(b.ops_after.get(k, 0), b.ops_cost.get(k, 0)) for k in alloc}
        allocated = tuple((k, min(alloc[k], n)) for k, n in used.items() if n > 0)
        units.append(Unit(name, f"factor datapath of block {b.name!r} (both modes)", 1,
                          allocated))
        instances = sum(1 for f in program.factors if f.block == i)
        for mode, counts, text, out in (("jacobian", b.ops_after, b.kernel, jac),
                                        ("cost", b.ops_cost, b.cost_kernel, cost)):
            ii = max([1] + [math.ceil(counts.get(k, 0) * ops.op(k).ii / n)
                            for k, n in allocated])
            if mode == "cost":  # the emitted cost_of_<b> sums the instances' costs in order (the
                ii = max(ii, ops.add.latency)  # simulator's): a recurrence through the adder
            depth = critical_path(text, sim_ops)
            out.append(Process(f"{name}_{mode}", name,
                               (Loop(f"{name}_{mode}_instances", instances, ii, depth),)))
        words = b.residual_dim * (1 + sum(b.variable_dims)) * instances
        memories.append(Memory(f"ab_{i}", words, ops.word_bits, 1))
    # the emitted instance loops (evaluate_<b>, cost_of_<b>) run one block type after another
    phases.append(Phase("factor_jacobian", False, tuple(jac)))

    if program.solver.linear == "qr":
        _qr(program, opts, les, units, memories, channels, phases)
    else:
        _cholesky(program, opts, les, units, memories, channels, phases)

    # state update: one retract per variable, pipelined one a cycle
    n_var = len(program.variables)
    retract_depth = (ops.sqrt.latency + ops.div.latency + ops.sincos.latency
                     + 4 * (ops.mul.latency + ops.add.latency))
    units.append(Unit("state_update", "retract x ⊕ δ", 1,
                      (("add", 3), ("mul", 4), ("sqrt", 1), ("div", 1), ("trig", 2))))
    phases.append(Phase("state_update", False, (
        Process("retract", "state_update", (Loop("variables", n_var, 1, retract_depth),)),)))
    phases.append(Phase("factor_cost", False, tuple(cost)))
    lm_depth = ops.div.latency + 2 * ops.mul.latency + 2 * ops.add.latency + ops.compare.latency
    units.append(Unit("lm_control", "gain ratio, μ update, stopping rules", 1,
                      (("add", 1), ("mul", 1), ("div", 1), ("compare", 1))))
    phases.append(Phase("lm_control", False, (
        Process("decide", "lm_control", (Loop("decision", 1, 1, lm_depth),)),)))
    n_x = sum(v.storage_dim for v in program.variables)
    n_t = sum(v.dim for v in program.variables)
    memories.append(Memory("state", n_x, ops.word_bits, 1))  # X
    memories.append(Memory("state_trial", n_x, ops.word_bits, 1))  # X_TRIAL
    memories.append(Memory("gradient_delta", 2 * n_t, ops.word_bits, 2))  # G, DELTA
    memories.append(Memory("data", _sizes(program)["N_DATA"], ops.word_bits, 1))  # DATA_BUF
    return AcceleratorPlan(program.name, program.solver.linear, program.solver.precision,
                           program.solver.clock_mhz, opts, tuple(units), tuple(memories),
                           tuple(channels), tuple(phases), ops)


def _qr(program, opts, ops, units, memories, channels, phases):
    from fgc_backends.sim.cost.qr import householder_sweep
    from fgc_backends.sim.cost.structure import stacked_pattern

    sched = program.schedule
    widest = max(len(level) for level in sched.levels)
    sets = opts.unit_sets if opts.unit_sets is not None else (
        2 if sched.structure_class == "chain" and sched.ordering == "two-ended" else 1)
    sets = max(1, min(sets, widest))
    damping = program.solver.method == "lm"
    max_rows = _sizes(program)["MAX_ROWS"]
    for s in range(sets):
        units.append(Unit(f"qr{s}_evaluate", "Householder vector of a column", 1,
                          (("add", 2), ("mul", 2), ("div", 1), ("sqrt", 1))))
        units.append(Unit(f"qr{s}_update", "apply the reflector to a column", opts.units,
                          (("add", 1), ("mul", 1))))
        # the emitted network of one reflection (include/fgc_qr.h's qr_reflection): broadcast
        # streams the reflector to each Update unit, every unit streams the next column (its
        # owner's) to Evaluate, which writes the reflector buffer the next region broadcasts
        for u in range(opts.units):
            channels.append(Channel(f"qr{s}_v{u}", "stream", 2 * ops.add.latency,
                                    ops.word_bits + 32, f"qr{s}_broadcast", f"qr{s}_update{u}"))
        for u in range(opts.units):
            channels.append(Channel(f"qr{s}_col{u}", "stream", max_rows, ops.word_bits,
                                    f"qr{s}_update{u}", f"qr{s}_evaluate"))
        channels.append(Channel(f"qr{s}_vbuf", "buffer", max_rows + 2, ops.word_bits + 32,
                                f"qr{s}_evaluate", f"qr{s}_broadcast"))
    # per step: Evaluate of column k+1 overlaps Update of column k -> one process per step
    step_proc = []
    for st in sched.steps:
        sweep = householder_sweep(stacked_pattern(program, st, damping),
                                  st.frontal_dim + st.new_factor_rows)
        loops = []
        for k, (rows, cols) in enumerate(sweep):
            ev = dot_loop(f"s{st.index}_evaluate{k}", rows, ops)
            ev_tail = ops.sqrt.latency + ops.add.latency + ops.mul.latency + ops.div.latency
            col = dot_loop(f"s{st.index}_update{k}", rows, ops)
            per_col = col.cycles + ops.mul.latency + rows + ops.mul.latency + ops.add.latency
            update = math.ceil(cols / opts.units) * per_col
            if k == 0:
                loops.append(Loop(ev.name, 1, 1, ev.cycles + ev_tail))
            nxt = sweep[k + 1][0] if k + 1 < len(sweep) else 0
            nxt_eval = dot_loop("next", nxt, ops).cycles + ev_tail if nxt else 0
            loops.append(Loop(f"s{st.index}_reflection{k}", 1, 1, max(update, nxt_eval)))
        step_proc.append((st, Process(f"qr_step{st.index}", "qr_update", tuple(loops))))
    for li, level in enumerate(sched.levels):
        procs = _assign([p for st, p in step_proc if st.index in level], sets, "qr", li)
        phases.append(Phase(f"qr_level{li}", True, procs, linear=True))
    _backsub_phases(program, ops, phases, "backsub")
    units.append(Unit("backsub", "back-substitution (cond_backsub)", 1,
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


def _backsub_phases(program, ops, phases, unit) -> None:
    """The emitted back_substitute: one cond_backsub per step, root first, one after another;
    each row bounded by its multiply-multiply-add chain or its stream of separator products."""
    sched = program.schedule
    chain = 2 * ops.mul.latency + ops.add.latency
    for li, level in enumerate(sched.back_substitution):
        procs = []
        for i in level:
            st = sched.steps[i]
            loops = [Loop(f"bs{i}_row{t}", 1, 1, max(d - t - 1 + p, chain))
                     for d, p in zip(st.frontal_dims, st.parent_dims, strict=True)
                     for t in range(d)]
            procs.append(Process(f"backsub_step{i}", unit, tuple(loops)))
        phases.append(Phase(f"backsub_level{li}", False, tuple(procs), linear=True))


def _solver_memories(sizes, ops, memories) -> None:
    """The linear solver's stores: conditionals (R | d) and the factors passed to parents."""
    memories.append(Memory("cond", sizes["N_COND"], ops.word_bits, 1))
    memories.append(Memory("nf", sizes["N_NF"], ops.word_bits, 1))


def _sizes(program) -> dict:
    """The emitted tables' sizes (MAX_ROWS, MAX_W, ...): the unit headers' CFG constants."""
    from .tables import build_tables
    t = build_tables(program, damped=program.solver.method == "lm",
                     cholesky=program.solver.linear == "cholesky")
    return dict(t.constants)


def _assign(procs, sets, tag, li):
    """Independent steps of one level on ``sets`` unit sets, longest first (one process/set)."""
    loads = [[] for _ in range(sets)]
    for p in sorted(procs, key=lambda p: -p.cycles):
        i = min(range(sets), key=lambda j: sum(q.cycles for q in loads[j]))
        loads[i].append(p)
    return tuple(Process(f"{tag}{li}_set{i}", f"set{i}",
                         tuple(lp for q in group for lp in q.loops))
                 for i, group in enumerate(loads) if any(q.loops for q in group))


def _cholesky(program, opts, ops, units, memories, channels, phases):
    c = opts.cpe
    # HGC: H = JᵀJ, g = Jᵀr over each instance's dense block rows × columns
    macs = 0
    for f in program.factors:
        b = program.blocks[f.block]
        cols = sum(b.variable_dims)
        macs += b.residual_dim * (cols * (cols + 1) // 2 + cols)
    units.append(Unit("hgc", "Hessian/gradient accumulation", opts.hgc_lanes,
                      (("add", 1), ("mul", 1))))
    phases.insert(1, Phase("hgc", False, (Process("hgc", "hgc", (
        Loop("macs", math.ceil(macs / opts.hgc_lanes), 1,
             ops.mul.latency + ops.add.latency),)),), linear=True))
    units.append(Unit("cpe", "Cholesky process element: Evaluate + Update", c,
                      (("add", 1), ("mul", 1), ("div", 1), ("sqrt", 1)), extra_dsp=1))
    # the emitted cascade (include/fgc_cpe.h's cpe_round): feed -> cpe0 -> ... -> drain
    for i in range(c + 1):
        channels.append(Channel(f"cpe_link{i}", "stream", _sizes(program)["MAX_W"],
                                ops.word_bits, "cpe_feed" if i == 0 else f"cpe{i - 1}",
                                f"cpe{i}" if i < c else "cpe_drain"))
    # per elimination step (one after another, as eliminate_all runs them), rounds of #CPE
    # pivots: round r streams the step's trailing m = w - r #CPE rows of [H | g] (upper
    # triangle + g: m (m + 1) / 2 + m words) through the cascade, one word a cycle
    cpe_depth = ops.sqrt.latency + ops.div.latency + ops.mul.latency + ops.add.latency
    rounds = []
    for st in program.schedule.steps:
        w, f = st.frontal_dim + st.separator_dim, st.frontal_dim
        for r in range(math.ceil(f / c)):
            m = w - r * c
            rounds.append(Loop(f"s{st.index}_round{r}", m * (m + 1) // 2 + m, 1,
                               c * cpe_depth))
    phases.append(Phase("cholesky", True, (Process("cascade", "cpe", tuple(rounds)),),
                        linear=True))
    units.append(Unit("trisolve", "back-substitution (cond_backsub; Lz = g rides the cascade)",
                      1, (("add", 1), ("mul", 1), ("div", 1))))
    _backsub_phases(program, ops, phases, "trisolve")
    sizes = _sizes(program)
    cols = sizes["MAX_W"] + 1
    # accel.cpp.jinja's GRAM, HF, CONDBUF, UPDBUF (the frontal matrix of one step at a time)
    memories.append(Memory("gram", sizes["N_GRAM"], ops.word_bits, 1))
    memories.append(Memory("frontal", sizes["MAX_W"] * cols, ops.word_bits, 1))
    memories.append(Memory("condbuf", sizes["MAX_F"] * cols, ops.word_bits, 1))
    memories.append(Memory("updbuf", sizes["MAX_W"] * cols, ops.word_bits, 1))
    _solver_memories(sizes, ops, memories)


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
    per = tuple((ph.name, phase_cycles(ph)) for ph in plan.phases)
    cycles = sum(c for _, c in per)
    linear = sum(phase_cycles(ph) for ph in plan.phases if ph.linear)
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
    channel_mems = tuple(Memory(ch.name, ch.depth, ch.width, 1) for ch in plan.channels)
    bram36 = sum(m.bram18 for m in plan.memories + channel_mems) / 2
    over = tuple(name for name, used, cap in (("DSP", dsp, PART_DSP),
                                              ("BRAM36", bram36, PART_BRAM36),
                                              ("LUT", lut, PART_LUT), ("FF", ff, PART_FF))
                 if used > cap)
    return Cost(cycles, per, linear, dsp, lut, ff, bram36, plan.clock_mhz, not over, over,
                tuple(by_unit))


# --------------------------------------------------------------------------------------------
# the emitted process network
# --------------------------------------------------------------------------------------------


def unit_sets(plan: AcceleratorPlan) -> int:
    """QR unit sets of ``plan`` (0 for Cholesky)."""
    return sum(1 for u in plan.units if u.name.endswith("_evaluate"))


def process_network(plan: AcceleratorPlan) -> tuple[tuple[str, ...], tuple[Channel, ...]]:
    """The dataflow processes and streams the emitter prints for ``plan``'s linear solver (the
    unit headers' regions): per QR unit set broadcast, n_u Update units and Evaluate; for
    Cholesky the feed, the #CPE process elements and the drain. Streams are the plan's stream
    channels."""
    if plan.linear == "qr":
        procs = tuple(p for s in range(unit_sets(plan)) for p in (
            f"qr{s}_broadcast", *(f"qr{s}_update{u}" for u in range(plan.options.units)),
            f"qr{s}_evaluate"))
    else:
        procs = ("cpe_feed", *(f"cpe{i}" for i in range(plan.options.cpe)), "cpe_drain")
    return procs, tuple(ch for ch in plan.channels if ch.kind == "stream")
