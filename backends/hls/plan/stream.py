"""The price of a stream's updates on the on-chip design (issue 31: one pricer).

The on-chip stream (:mod:`fgc_backends.hls.window`: the fixed-lag window, or the incremental
plan's window with its kept Bayes net and batch kernel) is one design: the window kernel's plan,
the batch kernel's units and memories beside it and the stream section's memories
(:meth:`WindowUpdateModel.design_plan`). Its price is that plan's: the stream section's own loops
(the keyframe's words in, the shift, the marginalisation but its QR step, the kept net's
re-expression, store and walk, the batch kernel's copies, the window out) are phases of the design
plan run once per update (``Phase.per == "stream"``), and each update's QR steps on the rows
non-zero in that update are the plan's QR phases on that update's stacked patterns; every figure
is :func:`~fgc_backends.hls.plan.plan_cost` of a phase of the design, composed per update by how
often the update ran it (:meth:`WindowUpdateModel.price`). The layouts say which words move and
which rows are zero; this module prices them. :class:`Term` and :class:`UpdatePrice` are the
priced record both stream models return (:mod:`fgc_backends.hls.plan.update` prices the host-kept
path of a Cholesky design).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, replace

import numpy as np

from fgc_backends.cost.structure import entering_blocks, stacked_pattern, step_columns
from fgc_backends.hls.plan.cost import merge_plans, phase_cycles, plan_cost
from fgc_backends.hls.plan.loops import _assign, _tables, kernel_loop, kernel_timing, plan_sizes
from fgc_backends.hls.plan.model import Loop, Phase, PlanError, Process, Unit
from fgc_backends.hls.plan.report import PHASE_TRIGGER, plan_groups, unit_sets
from fgc_backends.hls.units.memories import stream_memories
from fgc_backends.hls.units.qr import (
    commit_loops,
    lin_wave,
    lin_wave_loops,
    qr_unit_loops,
    stack_loops,
    wave_commit_loops,
    wave_loops,
    wave_steps,
)

STREAM_SOURCE = ("accelerator plan of the emitted on-chip fixed-lag window "
                 "(fgc_backends.hls.plan.stream; model estimate)")


@dataclass(frozen=True)
class Term:
    """One priced part of an update: ``cycles`` in all (``each`` × ``times``), ``assumed`` when no
    emitted unit computes it (then ``text`` says what is assumed)."""

    name: str
    each: int
    times: int
    assumed: bool
    text: str

    @property
    def cycles(self) -> int:
        return self.each * self.times


@dataclass(frozen=True)
class UpdatePrice:
    """A keyframe update's model price: its terms, the plan's total and the assumed extras."""

    keyframe: int
    mode: str
    first: int
    iterations: int
    clock_mhz: float
    terms: tuple[Term, ...]
    source: str = ("accelerator plan update model (fgc_backends.hls.plan.update; model estimate; "
                   "incremental mode not emitted)")

    @property
    def window(self) -> int:
        """Clusters the update re-eliminated."""
        return self.keyframe - self.first + 1

    @property
    def cycles(self) -> int:
        """The plan's terms (assumed terms excluded)."""
        return sum(t.cycles for t in self.terms if not t.assumed)

    @property
    def assumed_cycles(self) -> int:
        return sum(t.cycles for t in self.terms if t.assumed)

    @property
    def latency_ms(self) -> float:
        return self.cycles / (self.clock_mhz * 1e3)

    @property
    def assumed_ms(self) -> float:
        return self.assumed_cycles / (self.clock_mhz * 1e3)

    @property
    def latency_with_assumed_ms(self) -> float:
        return (self.cycles + self.assumed_cycles) / (self.clock_mhz * 1e3)

    def term(self, name: str) -> Term:
        for t in self.terms:
            if t.name == name:
                return t
        raise KeyError(name)

    def as_dict(self) -> dict:
        return {"source": self.source,
                "keyframe": self.keyframe, "mode": self.mode, "first": self.first,
                "window": self.window, "iterations": self.iterations,
                "cycles": self.cycles, "latency_ms": self.latency_ms,
                "assumed_cycles": self.assumed_cycles,
                "latency_with_assumed_ms": self.latency_with_assumed_ms,
                "terms": [{"name": t.name, "cycles": t.cycles, "each": t.each, "times": t.times,
                           "assumed": t.assumed, "text": t.text} for t in self.terms]}


# The stream section's own loops as fgc_stream.h writes them: per pipelined loop its operations
# an iteration (each an operator at II 1; MV_II / L_ACC_II loops hold one of each too), the
# sequential code one operator of each kind it uses.
WRITE_TAU_OPS = (("add", 1), ("mul", 3), ("div", 1))  # sign (×), the mean's columns (−= ×),
# ÷ and the singularity threshold (×) in sequential code
KEPT_MATVEC_OPS = (("add", 1), ("mul", 1))  # kept_matvec: + ×
# kept_task with reexpress and kept_walk INLINE: reexpress's vector_difference and difference
# (− × ÷ each), d_update (−), sj_column and sj_vector (+ × each); kept_walk's rhs (−) and
# column (−= ×); the sequential code's + × ÷ (the vector directions' differences, R's divides)
KEPT_TASK_OPS = (("add", 8), ("mul", 5), ("div", 3))
KEPT_SCALE_OPS = (("mul", 1), ("div", 1))  # kept_conditional: 1 / R_ii, each word × it
ARITHMETIC = ("add", "mul", "div")


# the kept net's datapath module (accel.cpp.jinja's keyframe_pass: its Log and retraction of a
# keyframe, every helper INLINE in it): its ALLOCATION limits per arithmetic kind; each special
# function it calls (a sine, a cosine, an arctangent) one instance
KEPT_LIMITS = (("add", 2), ("mul", 2), ("div", 1), ("sqrt", 1))
_SPECIAL = {"sin": "sin", "cos": "cos", "tan": "tan", "atan2": "atan2", "atan": "atan",
            "asin": "asin", "acos": "acos"}


def _special_functions(kernel) -> set[str]:
    """The special functions a call of printed ``kernel`` reaches: its own trigonometric calls,
    its Lie coefficients' closed forms', so3_log's arctangent."""
    import sympy as sp

    from fgc.frontend.geometry import special
    from fgc_backends.cfamily.special import _closed_form_kernel

    names: set[str] = set()
    for expr in [e for _, e in kernel.assignments] + list(kernel.outputs):
        for node in sp.preorder_traversal(sp.sympify(expr)):
            if isinstance(node, special.LieCoefficient):
                names |= _special_functions(_closed_form_kernel(node.coeff_name))
            elif isinstance(node, special.SO3LogComponent):
                names.add("atan2")
            elif isinstance(node, sp.Function) and type(node).__name__ in _SPECIAL:
                names.add(_SPECIAL[type(node).__name__])
    return names


def _kept_kernels(layout):
    """Per variable of a keyframe that is not a vector its Log and retraction kernels; and how
    many tangent directions are a vector's (keyframe_pass's loops: one add each)."""
    from fgc_backends.cfamily.retract import local_kernel, retract_kernel, variable_class

    locals_, kf_vars = layout._kf_vars()
    name_of = {k.kind: k.type_name for k in locals_}
    kernels, flat = [], 0
    for v in kf_vars:
        if v["flat"]:
            flat += v["dim"]
            continue
        cls = variable_class(name_of[v["kind"]])
        kernels.append((local_kernel(cls), retract_kernel(cls)))
    return kernels, flat


def kept_datapath_ops(layout, ops=None) -> tuple[tuple[str, int], ...]:
    """The kept net's datapath as accel.cpp.jinja emits it: one module (keyframe_pass) for a
    keyframe's Log and its retraction, exclusive branches, every helper INLINE in it (the Log
    kernels, the retraction printed again, the special functions' ``kept_`` copies), sequential
    code under its ALLOCATION: per arithmetic kind the module's operations, at most
    :data:`KEPT_LIMITS`; each special function it calls one instance (a ``special``
    operator). ``ops`` is not read: the limits are the design's, whatever the table."""
    from fgc_backends.cfamily.printer import kernel_printed_ops
    from fgc_backends.hls.units.special_ops import helper_ops

    kernels, flat = _kept_kernels(layout)
    total: Counter = Counter({"add": flat})
    functions: set[str] = set()
    for pair in kernels:
        for kernel in pair:
            total.update({k: n for k, n in kernel_printed_ops(kernel) if k in dict(KEPT_LIMITS)})
            total.update(dict(helper_ops(kernel)))
            functions |= _special_functions(kernel)
    limits = dict(KEPT_LIMITS)
    out = {k: min(limits[k], total[k]) for k in limits if total[k]}
    if functions:
        out["special"] = len(functions)
    return tuple(sorted(out.items()))


def kept_pass_bound(layout, ops) -> int:
    """The cycles the kept datapath's ALLOCATION needs to issue one pass (a Log or a
    retraction of a keyframe): per kind ⌈operations one pass issues (each helper's exclusive
    branches sharing) × the operator's II / its limit⌉, the larger pass's."""
    import math

    from fgc_backends.cfamily.printer import kernel_printed_ops
    from fgc_backends.hls.units.special_ops import helper_ops

    kernels, flat = _kept_kernels(layout)
    limits = dict(KEPT_LIMITS)
    bound = 0
    for which in (0, 1):  # the Log pass, the retraction pass
        issued: Counter = Counter({"add": flat})
        for pair in kernels:
            issued.update({k: n for k, n in kernel_printed_ops(pair[which]) if k in limits})
            issued.update(dict(helper_ops(pair[which], exclusive=True)))
        bound = max([bound] + [math.ceil(n * ops.op(k).ii / limits[k])
                               for k, n in issued.items() if k in limits and n])
    return bound


def _stream_phase(name: str, *loops: Loop) -> Phase:
    """One of the stream section's sequential loop runs, once per update that runs it."""
    return Phase(f"stream_{name}", False, (Process(f"stream_{name}", "stream", tuple(loops)),),
                 per="stream")


def qr_solve_phases(t, zero: frozenset, damped: bool, sets: int, les, leaf=None,
                    unit: frozenset = frozenset(),
                    drop: frozenset = frozenset(), qr_rows: int = 1, opts=None
                    ) -> tuple[Phase, ...]:
    """The QR unit sets' DATAFLOW regions of one linear solve of template ``t`` (every level's,
    the plan's assignment of a level's steps to ``sets`` unit sets) with the rows of the
    ``zero`` template factors and, unless ``damped``, the √μ rows zero: the Evaluate unit skips
    a row that is zero in its column (fgc_qr.h), so these rows cost nothing. The ``unit``
    template factors (priors holding a slot under R = I at its linearisation point: their
    whitened rows are the identity) have one non-zero a row, on their own tangent direction.
    ``leaf``: that step alone on unit set 0, without the rows of the ``drop`` factor instances
    (not stacked: qr_eliminate_all's live leaf step). ``qr_rows``: the Update units' rows a
    cycle (PlanOptions.qr_rows). ``opts``: the design's ``PlanOptions`` (its ``qr_rows`` then);
    with ``root_wave`` the last two levels are one region (units/qr.py's ``wave_loops``: unit
    set 1's process holds its step's commit and the root's stack too)."""
    if opts is not None:
        qr_rows = opts.qr_rows
    procs = qr_step_processes(t, zero, damped, les, leaf, unit, drop, qr_rows)
    if leaf is not None:
        return (Phase("qr_leaf", True, (procs[leaf],), linear=True),)
    phases = []
    wave = wave_steps(t, opts) if opts is not None else None
    if wave is not None and lin_wave(t, opts) is not None:
        wave = None  # (the wave inside lin_level: the solve's levels as without it)
    levels = t.schedule.levels
    units = max(1, t.solver.units)
    for li, level in enumerate(levels):
        if wave is not None and li >= len(levels) - 2:
            tables = _tables(t)
            loops = {i: procs[i].loops for i in wave}
            phases.append(Phase(f"qr_level{li}_0", True, (
                Process(f"qr{li}_set0", "set0", loops[wave[0]]),
                Process(f"qr{li}_set1", "set1", wave_loops(
                    tables, kernel_timing(les), units, max(tables["STEP_W"]),
                    t.solver.method == "lm", wave, loops))), linear=True))
            break
        for c in range(0, len(level), sets):
            chunk = _assign([procs[i] for i in level[c:c + sets]], sets, "qr", li)
            phases.append(Phase(f"qr_level{li}_{c}", True, chunk, linear=True))
    return tuple(phases)


def qr_step_processes(t, zero: frozenset, damped: bool, les, leaf=None,
                      unit: frozenset = frozenset(),
                      drop: frozenset = frozenset(), qr_rows: int = 1) -> dict[int, Process]:
    """Per step of template ``t`` its Householder unit set's process (:func:`qr_solve_phases`'s
    steps; ``leaf``: that step's alone)."""
    units = max(1, t.solver.units)
    return {s: Process(f"qr_step{s}", "qr_update", tuple(qr_unit_loops(
        pattern, t.schedule.steps[s].frontal_dim, units, les, name=f"s{s}", qr_rows=qr_rows,
        rhs=rhs))) for s, (pattern, rhs) in step_patterns(t, zero, damped, leaf, unit,
                                                           drop).items()}


def step_patterns(t, zero: frozenset, damped: bool, leaf=None, unit: frozenset = frozenset(),
                  drop: frozenset = frozenset()) -> dict[int, tuple]:
    """Per step of template ``t`` (``leaf``: that step's alone) its stacked matrix's rows ×
    (f + s) structural non-zeros in this update and the rows whose right-hand side can be
    non-zero (:func:`~fgc_backends.hls.units.qr.qr_unit_loops`' ``pattern`` and ``rhs``): the
    ``zero`` factors' rows zero, the ``unit`` priors' the identity, the √μ rows zero unless
    ``damped``, a child's passed rows zero where its step leaves them so (``drop``: the leaf's
    factors not stacked)."""
    lm = t.solver.method == "lm"
    out, passed = {}, {}
    for st in t.schedule.steps:
        pattern = stacked_pattern(t, st, lm).copy()
        cols = step_columns(t, st)
        # the rows whose right-hand side can be non-zero: a zero row's is zero (a factor without
        # information, a child's zero passed row), and so are the √μ rows' and, at the slot's
        # reset value, a unit prior's (its residual 0)
        rhs = np.ones(len(pattern), dtype=bool)
        row = 0
        dropped = []
        for i in entering_blocks(t, st):
            spec = t.factors[i]
            block = t.blocks[spec.block]
            if i in drop and st.index == leaf:
                dropped += range(row, row + block.residual_dim)
            for member, ti in zip(block.members, spec.factors, strict=True):
                lo, hi = row + member.rows[0], row + member.rows[1]
                if ti in zero:
                    pattern[lo:hi] = False
                elif ti in unit:
                    own = [c for p in member.positions for c in cols[spec.keys[p]]]
                    if len(own) != hi - lo:
                        raise PlanError(f"internal error: a unit prior of {hi - lo} rows on "
                                        f"{len(own)} columns")
                    pattern[lo:hi] = False
                    pattern[np.arange(lo, hi), own] = True
                    rhs[lo:hi] = False
            row += block.residual_dim
        rhs[:row] &= pattern[:row].any(axis=1)  # a zero row's right-hand side: 0
        for child in st.children:  # a child's new factor: its rows that are zero in value
            for i, (zero_row, side) in enumerate(passed.get(child, ())):
                if zero_row:
                    pattern[row + i] = False
                rhs[row + i] = side
            row += t.schedule.steps[child].new_factor_rows
        if lm:
            rhs[pattern.shape[0] - st.frontal_dim:] = False  # [√μ I | 0]
            if not damped:
                pattern[pattern.shape[0] - st.frontal_dim:] = False
        passed[st.index] = list(zip(
            _zero_passed_rows(pattern, st.frontal_dim, st.new_factor_rows),
            _passed_rhs(pattern, rhs, st.frontal_dim, st.new_factor_rows), strict=True))
        if leaf is not None and st.index != leaf:
            continue
        if dropped:
            pattern = np.delete(pattern, dropped, axis=0)
            rhs = np.delete(rhs, dropped)
        out[st.index] = (pattern, rhs)
    return out


def _zero_passed_rows(pattern, frontal: int, passed: int) -> list[bool]:
    """Which of the ``passed`` rows of the new factor a step hands its parent are zero in value:
    the step's rows after QR (the fill rule of :func:`~fgc_backends.hls.units.qr.qr_unit_loops`:
    a reflection's active rows take the union of their patterns right of its column), rows
    ``frontal`` … ``frontal + passed - 1`` over the separator's columns. A window's held or not
    yet arrived slots pass such rows (no factor reaches their separator): the parent's
    Evaluate skips them."""
    nz = np.asarray(pattern, dtype=bool).copy()
    rows, cols = nz.shape
    _fill(nz, min(rows, cols))
    return [frontal + i >= rows or not nz[frontal + i, frontal:].any() for i in range(passed)]


def _fill(nz, pivots: int) -> None:
    """The QR fill rule on the boolean pattern ``nz``, in place, over its first ``pivots``
    columns: reflection j's active rows (non-zero in column j, and row j) take the union of
    their patterns right of column j, and leave only R's row j non-zero in it."""
    rows, cols = nz.shape
    for j in range(pivots):
        act = [i for i in range(j, rows) if nz[i, j]]
        if not act:
            continue
        act = sorted(set(act) | {j})
        nz[np.ix_(act, range(j + 1, cols))] = nz[act, j + 1:].any(axis=0)
        nz[act, j] = False
        nz[j, j] = True


def _passed_rhs(pattern, rhs, frontal: int, passed: int) -> list[bool]:
    """Which of the ``passed`` rows of the new factor a step hands its parent can have a
    non-zero right-hand side (``rhs``: the step's rows whose right-hand side can be non-zero):
    the fill rule of :func:`_zero_passed_rows` with the right-hand side as the last column."""
    nz = np.hstack([np.asarray(pattern, dtype=bool),
                    np.asarray(rhs, dtype=bool).reshape(len(pattern), 1)])
    rows, cols = nz.shape
    _fill(nz, min(rows, cols - 1))
    return [frontal + i < rows and bool(nz[frontal + i, -1]) for i in range(passed)]


def qr_solve_cycles(plan, t, zero: frozenset, damped: bool, sets: int, les, leaf=None,
                    unit: frozenset = frozenset(), drop: frozenset = frozenset()) -> int:
    """``plan_cost`` of ``plan`` (a design holding the QR unit sets) running
    :func:`qr_solve_phases` as its iteration (with the plan's options)."""
    return plan_cost(replace(plan, phases=qr_solve_phases(
        t, zero, damped, sets, les, leaf, unit, drop, opts=plan.options))).cycles


def _relinearize(ev: dict) -> int:
    """1 if the marginal (or a batch step's store) linearises the window (the chain) at its
    optimum again: LM took a step after its last linearisation (fgc_stream.h); counted, the
    ``relinearize`` event, else from the events: an accepted step in every iteration."""
    relin = ev.get("relinearize")
    if relin is None:
        relin = int(ev.get("accept", 0) >= ev.get("linearize", 0))
    return int(relin)


def _call_cost(plan) -> int:
    """The cost pass at X that LM control runs once per solve before its first linearisation
    (``cost_x``: the plan's per-call ``factor_cost`` phase, the "cost" event), 0 if none."""
    return sum(phase_cycles(ph) for ph in plan.phases
               if ph.name == "factor_cost" and ph.per == "call")


class WindowUpdateModel:
    """The price of each call of the on-chip window's design (``<name>_stream``): the
    accelerator plan of the emitted template (:func:`fgc_backends.hls.emitter.accel_plan`, the
    design ``config`` emits) for the solve's phases, each priced per execution times how often
    the update ran it, and the stream section's own loops as phases of the same design
    (:meth:`design_plan`), priced as accel.cpp.jinja counts them: the keyframe's words in, the
    shift, the marginalisation (a linearisation, slot 0's step on unit set 0 at μ = 0, τ's signs,
    mean and words) and the window out. Every figure is a model estimate of the emitted
    structure; :meth:`price` takes the update's event counts when a counting C simulation gives
    them, else derives them from its iterations (no rejected steps)."""

    def __init__(self, layout, config):
        from fgc_backends.hls.emitter import accel_plan, for_program

        self.layout = layout
        t = layout.template
        config = for_program(t, config).resolved(t, stream=True)  # one back-substitution lane
        if config.design.qr_unit != "householder":
            raise PlanError(f"the on-chip stream design's price is modelled on the Householder "
                            f"QR unit (its update's QR steps on the rows non-zero in that "
                            f"update); --qr-unit {config.design.qr_unit} is not")
        self.plan = plan = accel_plan(t, config)
        self.clock_mhz = plan.clock_mhz
        self.group = plan_groups(plan)
        self.cost_x = _call_cost(plan)
        self.les = plan.target.ops("float32" if config.linear_cxx == "float" else "float64")
        self._qr = {}
        self.sets = max(1, unit_sets(plan))
        if self.qr_cycles(frozenset(), True) != self.group["qr"]:
            raise PlanError("internal error: the stream model's QR steps are not the plan's")
        ctx = layout.context(config.linear_cxx, config.part)
        self.layout_marginal = ctx["marginal"]
        # the update's start (window.py's start_plan): the call's keyframe words as many an
        # iteration as the data port's beat holds (HlsConfig.data_width), DATA_BUF's banks
        self.data_words = config.data_words
        self.start_banks, self.start_rows, self.sweep_rows = layout.start_plan(self.data_words)
        # the one-step solve's linearisation once keyframe 0 has left: without the instances
        # that hold nothing from then on (units/datapath.py's solve_skip; lin_level's part 3)
        self._skip = frozenset()
        # (with root_wave, units/qr.py's lin_wave: the root on set 1 inside that region too)
        self._wave = lin_wave(t, self.plan.options)
        self._lin_sets = (self._lin_level_sets()
                          if self.layout_marginal and (self._wave is not None
                                                       or not self.plan.options.root_wave)
                          else None)
        self._lin_sets_live = (self._lin_level_sets(self._skip) if self._skip
                               else self._lin_sets)
        self._beside = {}
        # the one-step policy (SolverConfig.one_step): the step taken, the store is the
        # update's own factorisation (fgc_stream.h's took_step)
        self.one_step = t.solver.one_step
        # and the leaving keyframe's τ and kept conditional formed beside the update's
        # back-substitution, moved into place once the step is known taken (fgc_stream.h's
        # spec_tau_task / spec_keep_task, out_beside_commit)
        self.spec = layout.spec and not config.mixed
        self.batch = None
        if layout.batch is not None:  # the batch kernel of an incremental design with batch steps
            bplan = accel_plan(layout.batch.template, config)
            self.batch = {"layout": layout.batch, "plan": bplan, "group": plan_groups(bplan),
                          "sets": max(1, unit_sets(bplan)), "cost_x": _call_cost(bplan)}
        phases = self._stream_phases(kernel_timing(plan.ops), kernel_timing(self.les),
                                     layout.matvec_ii(config.linear_cxx, config.part))
        self._design = replace(self._merged(), phases=self.plan.phases + phases)
        self.stream = dict(plan_cost(self._design).other_cycles)

    def _lin_level_sets(self, skip: frozenset = frozenset()):
        """The unit sets that reflect level 0's first steps beside the one-step linearisation
        (accel.cpp.jinja's lin_level: the window's design with the rows straight into the
        banks, units/qr.py's ``rows_in_banks``): per set (its step, the datapath loop it waits
        on, its fill loop), or None when the design has no such sets; ``skip``: the instances
        not evaluated (their words not sent). Sets ``_skip`` (:func:`solve_skip`)."""
        from fgc_backends.hls.units.datapath import bank_fill_words, bank_ready_loops, solve_skip
        from fgc_backends.hls.units.qr import rows_in_banks

        t = self.layout.template
        tables = _tables(t)
        in_banks = rows_in_banks(t, self.plan.options, tables)
        if not in_banks:
            return None
        if not skip:
            self._skip = solve_skip(self.layout.leaf_skipped(), in_banks)
        steps = sorted({(u, s) for u, s, _ in in_banks.values()})
        fills = bank_fill_words(t, tables, in_banks, len(steps), skip)
        waits = bank_ready_loops(t, in_banks, len(steps), self.plan.options)
        move = kernel_timing(self.les)
        return [(s, waits[u], kernel_loop("fill", fills[u], "move", move))
                for u, s in steps]

    def _decide_only(self) -> bool:
        """Whether the plan's lm_control is the step test's scalars and the decision alone
        (units/lm_control.py's ``retire_test`` / ``in_retire``: the counted ``step_test``
        event's loops), so it runs once per tested step."""
        loops = {lp.name for ph in self.plan.phases if ph.name == "lm_control"
                 for p in ph.processes for lp in p.loops}
        return bool(loops) and loops <= {"step_scalars", "decision"}

    def solve_counts(self, live: bool) -> dict[int, int] | None:
        """The instances per block type the one-step solve's linearisation evaluates: all (None)
        but once keyframe 0 has left (``live``), then without :attr:`_skip` (lin_level's part 3)."""
        if not (live and self._skip):
            return None
        t = self.layout.template
        count = Counter(f.block for i, f in enumerate(t.factors) if i not in self._skip)
        return {i: count[i] for i in range(len(t.blocks))}

    def solve_linearize(self, live: bool) -> int:
        """The one-step solve's linearisation (factor_jacobian: the datapaths beside the
        gradient, :func:`~fgc_backends.hls.units.datapath.linearize_region`) at
        :meth:`solve_counts`: the plan's phase but once keyframe 0 has left."""
        from fgc_backends.hls.units.datapath import linearize_region

        counts = self.solve_counts(live)
        if counts is None:
            return self.group["factor_jacobian"]
        if "lin_live" not in self._beside:
            t = self.layout.template
            self._beside["lin_live"] = phase_cycles(linearize_region(
                t, kernel_timing(self.plan.ops), self._jac_at(Counter(counts)), counts))
        return self._beside["lin_live"]

    def beside_linearize(self, zero: frozenset, unit: frozenset = frozenset(),
                         solved: bool = True, live: bool = False) -> int:
        """The cycles the one-step update's linearisation and level 0's first steps save run
        as one region (lin_level) rather than one after the other: the region
        (:func:`~fgc_backends.hls.units.datapath.lin_level_cycles`) less the linearisation
        (factor_jacobian) and that level's region (its first ``sets`` steps, on the rows
        non-zero in this update: ``zero``, ``unit`` as :meth:`qr_cycles`). Not ``solved`` (the
        update stopped after its linearisation: no solve, no qr term): what the sets' steps
        add to the linearisation's region, ≥ 0. 0 when the design has no such sets. ``live``:
        keyframe 0 has left (:meth:`solve_counts`)."""
        from fgc_backends.hls.units.datapath import lin_level_cycles, lin_wave_region

        if not self._lin_sets:
            return 0
        counts = self.solve_counts(live)
        key = (zero, unit, counts is not None)
        if key not in self._beside:
            t = self.layout.template
            rows = self.plan.options.qr_rows
            procs = qr_step_processes(t, zero, True, self.les, unit=unit, qr_rows=rows)
            level = next(ph for ph in qr_solve_phases(t, zero, True, self.sets, self.les,
                                                      unit=unit, qr_rows=rows)
                         if ph.name == "qr_level0_0")
            lin = next(ph for ph in self.plan.phases if ph.name == "factor_jacobian")
            jac = ([p for p in lin.processes if p.name != "gradient"] if counts is None
                   else self._jac_at(Counter(counts)))
            sets = [(wait, fill, procs[s].cycles) for s, wait, fill in
                    (self._lin_sets if counts is None else self._lin_sets_live)]
            hidden = phase_cycles(level)
            if self._wave is None:
                region = lin_level_cycles(t, kernel_timing(self.plan.ops), jac, sets, counts)
            else:
                hide = self._wave_hidden(zero, unit)
                region = lin_wave_region(t, kernel_timing(self.plan.ops), jac, sets,
                                         self._wave_loops(procs), counts, wave_commit_loops(
                                             _tables(t), self._wave, kernel_timing(self.les)))
                hidden += hide
            self._beside[key] = (region - self.solve_linearize(counts is not None), hidden)
        added, level = self._beside[key]
        return added - level if solved else added

    def _wave_loops(self, procs: dict):
        """Set 1's process after its fill in lin_level with the root in a wavefront
        (units/qr.py's ``lin_wave_loops``), a function of set 0's and set 1's starts and the
        datapath loops' ends (units/datapath.py's ``lin_wave_region``)."""
        from fgc_backends.hls.units.datapath import bank_ready_loops
        from fgc_backends.hls.units.qr import root_bank_parity_words, rows_in_banks

        t = self.layout.template
        tables = _tables(t)
        c0, c1, root = self._wave
        wait = bank_ready_loops(t, rows_in_banks(t, self.plan.options, tables, root=True), 3,
                                self.plan.options)[2]
        fill = kernel_loop("root_fill", max(root_bank_parity_words(tables, root)), "move",
                           kernel_timing(self.les))
        loops = {i: procs[i].loops for i in self._wave}

        def run(start0: int, start1: int, ends: dict) -> tuple[Loop, ...]:
            return lin_wave_loops(tables, kernel_timing(self.les), max(1, t.solver.units),
                                  max(tables["STEP_W"]), t.solver.method == "lm", self._wave,
                                  loops, start0, start1, fill, ends[wait])
        return run

    def _wave_hidden(self, zero: frozenset, unit: frozenset) -> int:
        """What the solve no longer runs once the sets reflected the root inside lin_level:
        the root's level (its region on this update's non-zero rows), its stack (the plan's
        loops, moved into set 1's process) and the three steps' commits: step c0's (set 0's
        collector writes COND and NF as it writes its buffers: fgc_qr.h's COMMIT, no loop of its
        own), step c1's and the root's (set 1's collector streams their conditionals to the same
        process: qr_commit_cond; no one reads c1's passed rows from NF)."""
        t = self.layout.template
        c0, c1, root = self._wave
        rows = self.plan.options.qr_rows
        last = qr_solve_phases(t, zero, True, self.sets, self.les, unit=unit, qr_rows=rows)[-1]
        top = f"qr_stack_level{len(t.schedule.levels) - 1}"
        stack = next(p for ph in self.plan.phases if ph.name == top
                     for p in ph.processes if p.name == f"stack{root}")
        commits = {p.name: p for ph in self.plan.phases if ph.name.startswith("qr_commit_level")
                   for p in ph.processes}
        commit = sum(commits[f"commit{i}"].cycles for i in (c0, c1, root))
        return phase_cycles(last) + stack.cycles + commit

    def _stream_phases(self, kt: dict, lt: dict, mv_ii: int) -> tuple[Phase, ...]:
        """The stream section's loops (accel.cpp.jinja's stream top), one phase per part an
        update runs whole."""
        lay = self.layout
        n, kf = lay.kf_dim, lay.kf_words
        t = lay.template

        def move(name, words, repeat=1):
            return kernel_loop(name, words, "move", kt, repeat)

        out = [_stream_phase(f"keyframe_in{m}", move("x", kf), move("d", len(d)))
               for m, d in enumerate(lay.new_dest)]
        out += [_stream_phase(f"keyframe_data_in{m}", move("d", len(d)))
                for m, d in enumerate(lay.new_dest)]
        out += [_stream_phase("shift", move("x", len(lay.x_moves)),
                              move("d", len(lay.data_moves))),
                # the update's start region (fgc_stream.h's update_start): its moves on X
                # (start_x_task) and on DATA_BUF (start_data_task), each process's own loops
                _stream_phase("shift_x", move("x", len(lay.x_moves))),
                _stream_phase("shift_data", move("d", len(lay.data_moves))),
                # the window full: the shift's words and the keyframe's in one loop over
                # DATA_BUF's banks (window.py's _start_tables; start_data_task)
                _stream_phase("start_data", move("d", max(1, len(self.start_rows)))),
                _stream_phase("start_data_sweep", move("d", max(1, len(self.sweep_rows)))),
                _stream_phase("keyframe_x_in", move("x", kf)),
                _stream_phase("x_out", move("x", lay.n_x)),
                _stream_phase("x_out_kf", move("x", kf))]
        # tau: signed; its mean by columns, last first (per column x_r's divide, then its
        # update of the rows above at II 1); its words out
        mean = [lp for r in range(n - 1, -1, -1)
                for lp in (kernel_loop("divide", 1, "div", lt),
                           *((Loop("column", r, 1, lt["acc"][1]),) if r else ()))]
        write_tau = (kernel_loop("sign", n * (n + 1), "max", kt), *mean,
                     move("tau_out", kf + n + n * (n + 1) // 2 + 2))
        if lay.kept:  # the kept Bayes net's loops, as accel.cpp.jinja counts them
            # a Log or a retraction: the retraction-sized datapath's depth, or what its
            # ALLOCATION needs to issue a pass if that is longer
            one = kernel_loop("pass", 1, "retract", kt)
            one = replace(one, depth=max(one.depth, kept_pass_bound(lay, self.plan.ops)))
            matvec = Loop("matvec", n * n, mv_ii, lt["acc"][1])
            scatter = kernel_loop("scatter", n, "scatter", lt)
            columns = tuple(Loop("column", i, 1, lt["acc"][1]) for i in range(1, n))
            # four passes per direction of a variable that is not a vector, none for a vector's
            curved = sum(1 for w in lay.vector_words() if w < 0)
            vector_diff = Loop("vector_difference", n, 1, kt["div"][1] + 3 * kt["acc"][0],
                               n - curved)
            # a conditional kept: its pivots' reciprocals, then its rows scaled as they are
            # copied (kept_conditional; R unit-diagonal, so the walk divides by nothing)
            lmul = lt["acc"][1] - lt["acc"][0]
            keep_one = (kernel_loop("reciprocal", n, "div", lt),
                        Loop("cond", n * (2 * n + 1), kt["move"][0], kt["move"][1] + lmul))
            # the leaving keyframe's conditional kept beside tau (tau_and_keep's regions): its
            # reciprocals beside tau's sign loop, its rows scaled beside tau's tail
            out += [_stream_phase("keep_reciprocal", keep_one[0]),
                    _stream_phase("keep_scale", keep_one[1]),
                    _stream_phase("keep_points", move("x", kf))]
            out += [_stream_phase("kept_slot0", move("x", kf)),
                    _stream_phase("kept_reexpress", one, replace(one, repeat=4 * curved),
                                  Loop("difference", n, 1, kt["div"][1], curved), vector_diff,
                                  matvec, scatter,
                                  # per direction of a curved variable: its variable's
                                  # directions times the rows (J block-diagonal by variable)
                                  *(Loop("sj_column", dim * n, mv_ii, lt["acc"][1])
                                    for w, dim in zip(lay.vector_words(), lay.block_dims(),
                                                      strict=True) if w < 0),
                                  Loop("sj_vector", n, 1, lt["acc"][1], n - curved),
                                  move("s_out", n * n), move("x", kf)),
                    _stream_phase("kept_store", *keep_one, move("x", kf)),
                    _stream_phase("kept_walk_each", one, matvec, scatter, *columns, one,
                                  move("x", kf)),
                    _stream_phase("kept_walk_base", move("x", kf))]
        if self.layout_marginal:  # the marginalisation but its linearisation and QR step
            out += [self._leaf_linearize(False), self._leaf_linearize(True)]
            s = lay.leaf_step
            tables = _tables(t)
            stack = stack_loops(tables, s, max(1, t.solver.units), plan_sizes(t)["MAX_W"],
                                t.solver.method == "lm", kt)
            # once keyframe 0 has left (live): its factors that hold nothing are not stacked
            # (qr_stack_rows' skip: their rows loops not run; a zeroing, where the banks are
            # not left zero, over the rows left)
            mask, rows = lay.leaf_skip()
            live, k = [], 0
            for lp in stack:
                if lp.name == "zero":
                    live.append(replace(lp, trip=lp.trip // tables["STEP_ROWS"][s] * rows))
                elif lp.name == "factor_rows":
                    if not (mask >> k) & 1:
                        live.append(lp)
                    k += 1
                else:
                    live.append(lp)
            # write_tau reads slot 0's rows where the step left them (NF): no copy first
            tail = (*commit_loops(tables, s, kt, False), *write_tau)
            out += [_stream_phase("marginal", *stack, *tail),
                    _stream_phase("marginal_live", *live, *tail),
                    # the one-step policy: slots 0 and 1 copied before the solve; the step
                    # taken, the solve's own NF rows are τ (no stack, QR step or commit)
                    _stream_phase("lin_points", move("x", 2 * kf)),
                    _stream_phase("marginal_reused", *write_tau),
                    # tau's sign loop, then its mean and words: tau_and_keep's processes
                    # beside the keep's
                    _stream_phase("tau_sign", write_tau[0]),
                    _stream_phase("tau_tail", *write_tau[1:]),
                    # the window's marginal: tau's mean beside its words but the mean's
                    # (tau_beside_keep's processes), the mean's words after that region
                    _stream_phase("tau_mean", *mean),
                    _stream_phase("tau_words", move("tau_words", kf + n * (n + 1) // 2 + 2)),
                    _stream_phase("tau_mean_out", move("tau_mean_out", n))]
            if self.spec:
                # the one-step update's marginal beside its back-substitution, two processes
                # beside each other (spec_tau_task: τ signed, its mean, its words into TAU_BUF;
                # spec_keep_task: the conditional's points, reciprocals and rows staged; each
                # its loops one after another), and once the step is known taken its words
                # moved two a cycle (out_beside_commit's tau_commit_task, keep_commit_task)
                if lay.kept:
                    out.append(_stream_phase("spec_keep", move("x", kf), *keep_one))
                out += [_stream_phase("spec_tau", *write_tau),
                        _stream_phase("tau_commit",
                                      move("tau_commit", (kf + n + n * (n + 1) // 2 + 2 + 1) // 2)),
                        _stream_phase("keep_commit", move("keep_commit", (n * n + 1) // 2))]
        if lay.sweep is not None:  # batch steps as sweeps: each keyframe kept as it came
            # (its words a beat of the data port a cycle: HlsConfig.data_width)
            out += [_stream_phase(f"sweep_store{m}", move("x", kf),
                                  move("d", -(-len(d) // self.data_words)))
                    for m, d in enumerate(lay.new_dest)]
            # (the window full: the call's words but the newest prior's tail, window.py kf_call)
            out.append(_stream_phase("sweep_store_full", move("x", kf),
                                     move("d", -(-len(lay.kf_call) // self.data_words))))
            out += [_stream_phase(f"sweep{j}_gather", move("x", j * kf)) for j in lay.sweep]
        if self.batch is not None:
            b = lay.batch
            words = n * (2 * n + 1)
            out += [_stream_phase(f"batch_in{c}", move("x", kf), move("d", len(d)))
                    for c, d in enumerate(b.new_dest)]
            # τ's linearisation point copied before the batch kernel's call
            out.append(_stream_phase("batch_tau_lin", move("x", kf)))
            for j in b.keyframes:
                out.append(_stream_phase(f"batch{j}_gather", move("x", (j + 1) * kf)))
                out.append(_stream_phase(f"batch{j}_out", move("x", (j + 1) * kf),
                                         move("x", j * words),
                                         *((move("x", n * (n + 1)),) if j >= lay.window
                                           else ()),
                                         move("x", (j + 1) * kf)))
                if j >= lay.window:
                    kept = j - lay.window + 1
                    out.append(_stream_phase(f"batch{j}_kept",
                                             *(replace(loop, repeat=kept) for loop in keep_one),
                                             move("x", kept * kf), *write_tau))
        return tuple(out)

    def _leaf_linearize(self, live: bool) -> Phase:
        """The marginal's linearisation (a sweep pass's, or a leaving keyframe's after LM moved):
        ``linearize_all(X, part)``, LM's instance on the instances whose rows slot 0's step
        stacks (:meth:`~fgc_backends.hls.window.WindowLayout.leaf_factors`; ``live``, part 2:
        less those that hold nothing once keyframe 0 has left, ``leaf_gone``) - the plan's
        factor_jacobian region (:func:`~fgc_backends.hls.units.datapath.linearize_region`: the
        datapaths beside the gradient) at those instance counts, G zeroed as always."""
        from fgc_backends.hls.units.datapath import linearize_region

        t = self.layout.template
        leaf = self.layout.leaf_factors()
        if live:
            leaf = leaf - self.layout.leaf_gone()
        count = Counter(f.block for i, f in enumerate(t.factors) if i in leaf)
        jac = self._jac_at(count)
        region = linearize_region(t, kernel_timing(self.plan.ops), jac,
                                  {i: count[i] for i in range(len(t.blocks))})
        return Phase("stream_leaf_linearize" + ("_live" if live else ""), False,
                     tuple(Process(f"leaf_{p.name}", p.unit, p.loops) for p in region.processes),
                     per="stream")

    def _jac_at(self, count: Counter) -> list[Process]:
        """The plan's factor_jacobian datapath processes (the gradient's left out) at ``count``
        instances per block type (the small ones' loop at their sum)."""
        from fgc_backends.hls.units.datapath import small_blocks

        small = sum(count[i] for i in small_blocks(self.layout.template))
        jac = []
        for ph in self.plan.phases:
            if ph.name != "factor_jacobian":
                continue
            for p in ph.processes:
                name = p.name
                if name == "gradient":  # the region's gradient: linearize_region's again
                    continue
                if name == "factor_small_jacobian":
                    loops = tuple(replace(lp, trip=small) for lp in p.loops)
                elif name.startswith("factor_") and name.endswith("_jacobian"):
                    n = count[int(name[len("factor_"):-len("_jacobian")])]
                    loops = tuple(replace(lp, trip=n) for lp in p.loops)
                else:
                    raise PlanError(f"internal error: the linearisation's process {name!r} "
                                    "has no leaf form")
                jac.append(Process(name, p.unit, loops))
        return jac

    def _merged(self):
        """The window kernel's plan, the batch kernel's units, memories and channels (a second
        accelerator of the same design, its names prefixed ``batch_``), the memories the
        stream section adds (:func:`fgc_backends.hls.units.memories.stream_memories`) and its
        units (:meth:`stream_units`)."""
        batch = self.batch
        n = self.layout.kf_dim
        merged = merge_plans(self.plan, batch["plan"] if batch is not None else None,
                             stream_memories(self.layout, self.plan.ops.word_bits,
                                             self.les.word_bits,
                                             n * (2 * n + 1) if batch is not None else 0,
                                             self.spec))
        # DATA_BUF in the update start's cyclic banks (fgc_stream.h's start_data_task)
        memories = tuple(replace(m, banks=max(m.banks, self.start_banks))
                         if m.name == "data" else m for m in merged.memories)
        return replace(merged, memories=memories, units=merged.units + self.stream_units())

    def stream_units(self) -> tuple[Unit, ...]:
        """The operators the stream section's own code instantiates (fgc_stream.h, every call
        site its own RTL copy unless an ALLOCATION shares it), names prefixed ``stream_``:
        write_tau per call site (the marginal's, a batch step's), the kept net's task
        (reexpress and kept_walk INLINE: one datapath module for the Log and the retraction,
        :func:`kept_datapath_ops`, one matrix-vector product, its loops). The window kernel's
        functions the stream calls again after LM (linearize_all, eliminate_all,
        back_substitute_at) share LM's instance (window_task's and batch_kernel_solve's
        ALLOCATION): no unit here - the marginal's QR step too, eliminate_all's on unit set 0
        (fgc_eliminate.h's qr_eliminate_all with a leaf)."""
        lay, units = self.layout, []
        tau_sites = int(bool(self.layout_marginal)) + int(self.batch is not None)
        if tau_sites:
            units.append(Unit("stream_write_tau", "tau signed, its mean and words (per call "
                              "site: the marginal's, a batch step's)", tau_sites,
                              WRITE_TAU_OPS))
        if self.spec:  # the window kernel's top instantiates these (window_task's
            # back_substitute region, spec_tau_task / spec_keep_task): its part, not the
            # stream section's
            units.append(Unit("spec_write_tau", "tau signed, its mean and words: the one-step "
                              "update's call site beside its back-substitution", 1,
                              WRITE_TAU_OPS))
            if lay.kept:
                units.append(Unit("spec_kept_scale", "the one-step update's staged kept "
                                  "conditional (spec_keep): its pivot reciprocals and rows "
                                  "scaled", 1, KEPT_SCALE_OPS))
        if lay.kept:
            units += [Unit("stream_kept_datapaths", "the kept net's Log and retraction "
                           "(keyframe_pass: one module, its ALLOCATION)", 1,
                           kept_datapath_ops(lay, self.plan.ops)),
                      Unit("stream_kept_matvec", "S times a vector (kept_matvec)", 1,
                           KEPT_MATVEC_OPS),
                      Unit("stream_kept_task", "the kept net's re-expression and walk: their "
                           "loops and sequential code", 1, KEPT_TASK_OPS),
                      Unit("stream_kept_scale", "a kept conditional's pivot reciprocals and "
                           "its rows scaled by them (kept_conditional, per call site: keep's, "
                           "a batch step's)", 1 + int(self.batch is not None),
                           KEPT_SCALE_OPS)]
        return tuple(units)

    def design_plan(self):
        """The whole on-chip design as one plan (:meth:`_merged`) with the stream section's
        phases (``per == "stream"``)."""
        return self._design

    # -- the QR units on the rows that are non-zero in this update -----------------------------
    def qr_cycles(self, zero: frozenset, damped: bool, leaf_only: bool = False,
                  unit: frozenset = frozenset(), live: bool = False) -> int:
        """The QR unit sets' cycles of one linear solve with the rows of the ``zero`` factors
        and, unless ``damped``, the √μ rows zero, the ``unit`` priors' rows the identity
        (:func:`qr_solve_phases`). ``leaf_only``: slot 0's step alone on unit set 0 (the
        marginalisation; ``live``: keyframe 0 has left, the step's factors that hold nothing
        from then on not stacked)."""
        key = (zero, damped, leaf_only, unit, live)
        if key not in self._qr:
            drop = self.layout.leaf_gone() if live and leaf_only else frozenset()
            self._qr[key] = qr_solve_cycles(self.plan, self.layout.template, zero, damped,
                                            self.sets, self.les,
                                            self.layout.leaf_step if leaf_only else None, unit,
                                            drop)
        return self._qr[key]

    def zero_factors(self, keyframe: int) -> frozenset:
        """The window's template factors with zero rows during keyframe ``keyframe``'s solve
        (:meth:`fgc_backends.hls.window.WindowLayout.zero_factors`)."""
        return self.layout.zero_factors(keyframe, self.layout_marginal)

    def resources(self) -> dict:
        """The whole on-chip design's DSP, BRAM36, LUT and FF (model estimates): ``plan_cost``
        of :meth:`design_plan`, its fit verdict on all four, and its parts (DSP, BRAM36): the
        window kernel, the batch kernel, the stream section (its units and memories)."""
        design = plan_cost(self._design)
        window = plan_cost(self.plan)
        # (the one-step update's τ and keep call sites, spec_*: the window top's)
        spec = {name: d for name, d in design.dsp_by_unit if name.startswith("spec_")}
        parts = {"window kernel": (window.dsp + sum(spec.values()), window.bram36)}
        units = {"window kernel": dict(window.dsp_by_unit) | spec}
        if self.batch is not None:
            bcost = plan_cost(self.batch["plan"])
            parts["batch kernel"] = (bcost.dsp, bcost.bram36)
            units["batch kernel"] = dict(bcost.dsp_by_unit)
        units["stream section"] = {name: d for name, d in design.dsp_by_unit
                                   if name.startswith("stream_")}
        section = sum(units["stream section"].values())
        parts["stream section"] = (section, design.bram36 - sum(b for _, b in parts.values()))
        # fits: every figure within the part (plan_cost's verdict: DSP, BRAM36, LUT, FF; a
        # design whose operators are bound to fabric trades DSP for LUT)
        return {"dsp": design.dsp, "bram36": design.bram36, "lut": design.lut, "ff": design.ff,
                "parts": parts, "units": units, "fits": design.fits, "over": design.over,
                "part": self.plan.options.part}

    def duplicated(self) -> dict:
        """What the design holds twice (model estimates, DSP by the plan): per unit kind (the
        factor datapaths, the gradient, the QR units, back-substitution, the state update, LM
        control) its DSP in the window kernel and in the batch kernel, which never run at once.
        Empty without a batch kernel."""
        if self.batch is None:
            return {}
        units = self.resources()["units"]

        def kind(name: str) -> str:
            for prefix, label in (("factor_", "factor datapaths"), ("qr", "QR units"),
                                  ("state_update", "state update")):
                if name.startswith(prefix):
                    return ("back-substitution" if name.endswith("_backsub") else label)
            return name.replace("_", " ")

        out: dict = {}
        for part in ("window kernel", "batch kernel"):
            for name, d in units[part].items():
                out.setdefault(kind(name), {"window kernel": 0, "batch kernel": 0})[part] += d
        return out

    def stale_after(self, keyframe: int) -> bool:
        """Whether the kept keyframes' estimates (X_KEPT) are stale after keyframe
        ``keyframe``'s update: an incremental update with kept keyframes re-expressed the
        newest kept conditional and walked nothing (fgc_stream.h's KEPT_STALE); a batch step
        leaves its own optimum there."""
        lay = self.layout
        if not lay.kept or keyframe < 0:
            return False
        if self.batch is not None and keyframe in self.batch["layout"].keyframes:
            return False
        return keyframe - lay.window > 0

    def _walks_first(self, keyframe: int, events: dict | None) -> bool:
        """Whether a batch step at ``keyframe`` (the batch kernel's or a sweep) walks the kept
        estimates before it starts from them: counted (the ``kept_walk`` event) where the
        update's ``events`` are given, else when the update before left them stale."""
        if events is not None:
            return bool(events.get("kept_walk", 0))
        return self.stale_after(keyframe - 1)

    def leaves_pending(self, keyframe: int) -> bool:
        """Whether keyframe ``keyframe``'s update leaves the newest kept conditional's
        re-expression pending for the next call's region (fgc_stream.h's KEPT_PENDING): an
        incremental update with kept keyframes; not a batch step (a sweep's conditionals hold its
        points, the batch kernel rebuilds the kept net)."""
        lay = self.layout
        if not lay.kept or keyframe - lay.window <= 0:
            return False
        if lay.sweep is not None and keyframe in lay.sweep:
            return False
        return self.batch is None or keyframe not in self.batch["layout"].keyframes

    def _pending(self, keyframe: int, events: dict | None) -> bool:
        """Whether the call at ``keyframe`` runs a re-expression the update before left pending:
        counted (the ``kept_reexpress`` event) where its ``events`` are given, else when the
        update before left one (no estimates asked for between them: op 3 would have run
        it)."""
        if events is not None:
            return bool(events.get("kept_reexpress", 0))
        return self.leaves_pending(keyframe - 1)

    def _pending_term(self) -> Term:
        return Term("kept_reexpress", self.stream["stream_kept_reexpress"], 1, False,
                    "the newest kept conditional's re-expression the update before left pending "
                    "(at its parent's estimate then): Log, its central-difference Jacobian (four "
                    "datapath passes per direction of a non-vector variable), S·Log and S·J")

    def _start_from_kept(self, keyframe: int, first: int, events: dict | None,
                         parent: str) -> list:
        """What a batch step at ``keyframe`` (a sweep, or the batch kernel's) runs before it
        starts from the kept estimates: a pending re-expression first, then the walk back
        through ``first`` - 1 kept conditionals when the update before left them stale
        (:meth:`_walks_first`; counted: the ``kept_reexpress`` and ``kept_walk`` events where
        the update's ``events`` are given), its first parent copied out of the kept memory
        (the term ``parent``)."""
        terms = []
        walk = self._walks_first(keyframe, events)
        if self._pending(keyframe, events):
            terms.append(self._pending_term())  # pass -1, before its walk
        if walk and first > 1:
            terms += [Term(parent, self.stream["stream_kept_slot0"], 1, False,
                           "the leaving keyframe's estimate copied out of the kept memory: "
                           "the walk's first parent"),
                      self._walk_term(first - 1, "the leaving keyframe")]
        return terms

    def _walk_term(self, first: int, parent: str) -> Term:
        st = self.stream
        return Term("kept_walk", st["stream_kept_walk_base"] + first * st["stream_kept_walk_each"],
                    1, False, f"the walk back through {first} kept conditionals from {parent}: "
                    "per keyframe a Log, S·Log, R⁻¹ by rows, a retraction")

    def price_estimates(self, keyframe: int, events: dict | None = None) -> UpdatePrice:
        """The price of asking for the kept keyframes' estimates after keyframe ``keyframe``'s
        update (``stream_call`` op 3, not part of an update): slot 0's estimate copied out,
        the walk back through the kept conditionals when they are stale (:meth:`stale_after`;
        counted: the ``kept_walk`` event), the estimates out a word a cycle."""
        lay, st = self.layout, self.stream
        first = max(0, keyframe - lay.window) if keyframe >= 0 else 0
        walk = (events.get("kept_walk", 0) if events is not None
                else int(self.stale_after(keyframe)))
        pending = (events.get("kept_reexpress", 0) if events is not None
                   else self.leaves_pending(keyframe))
        terms = [self._pending_term()] if pending else []
        if walk and first:
            terms += [Term("kept_slot0", st["stream_kept_slot0"], 1, False,
                           "slot 0's estimate copied out of X: the walk's first parent"),
                      self._walk_term(first, "slot 0")]
        if first:
            terms.append(Term("x_kept_out", first * lay.kf_words + 1, 1, False,
                              "the kept keyframes' estimates out, a word a cycle"))
        return UpdatePrice(keyframe, "estimates", first, 0, self.clock_mhz, tuple(terms),
                           STREAM_SOURCE)

    def _keep_beside_tau(self, times: int = 1, name: str = "keep_beside_tau") -> Term:
        """tau_and_keep's two regions (fgc_stream.h), their processes each on its own memories
        and operators: tau's sign loop beside the kept conditional's pivot reciprocals (and the
        call's reads of X: :meth:`_out_beside_sign`), then tau's mean (a → mean) beside its
        words but the mean's (after the kept points: the rows from NF, signed on the way, and
        the point → DATA_BUF) beside the conditional's rows scaled into kept memory, the
        mean's words after that region: in each region all but the longest hidden. A design
        without a kept net runs the keep's processes empty."""
        st = self.stream
        kept = self.layout.kept
        recip = st["stream_keep_reciprocal"] if kept else 0
        scale = st["stream_keep_scale"] if kept else 0
        points = st["stream_keep_points"] if kept else 0
        # the second region: tau's mean beside its words (but the mean's, after the kept
        # points) beside the rows scaled, then the mean's words; against tau's tail (mean,
        # words one after the other) and the keep (points, scale) counted whole
        second = max(st["stream_tau_mean"], points + st["stream_tau_words"], scale) \
            + st["stream_tau_mean_out"]
        hidden = (min(st["stream_tau_sign"], recip)
                  + st["stream_tau_tail"] + points + scale - second)
        return Term(name, -hidden, times, False,
                    "tau beside the leaving keyframe's conditional kept (two DATAFLOW regions: "
                    "its sign loop beside the pivots' reciprocals, its mean beside its other "
                    "words and the rows scaled, the mean's words after): all but the longest "
                    "of each region hidden")

    def _spec_cycles(self) -> int:
        """The one-step update's marginal beside its back-substitution: two processes beside
        each other (spec_tau_task: τ's sign, mean and words; spec_keep_task: the conditional's
        points, reciprocals and rows; each its loops one after another), the longer of the two."""
        st = self.stream
        return max(st["stream_spec_tau"], st.get("stream_spec_keep", 0))

    def _spec_over(self) -> int:
        """The cycles the one-step update's marginal (``_spec_cycles``) runs past the rest of
        the back_substitute region its processes are of (0 when they end first)."""
        return max(0, self._spec_cycles() - self.group["backsub"])

    def _spec_beside_backsub(self, name: str = "spec_beside_backsub") -> Term:
        """The one-step update's marginal as the last processes of its solve's back_substitute
        region (fgc_stream.h's spec_tau_task beside spec_keep_task): τ and the leaving
        keyframe's conditional formed from the solve's own factorisation (NF and LIN01;
        KEEP_COND and LIN01K) beside the slots, the state update and the cost at X_TRIAL, no
        memory or operator of theirs or of each other's. Against the
        terms marginal (τ) and kept_store (the conditional) counted whole, all of it hidden
        but what runs past the region's other processes."""
        st = self.stream
        kept = st["stream_kept_store"] if self.layout.kept else 0
        hidden = st["stream_marginal_reused"] + kept - self._spec_over()
        return Term(name, -hidden, 1, False,
                    "τ and the leaving keyframe's conditional formed beside the update's "
                    "back-substitution (its region's last process; the one-step policy: the "
                    "solve's own factorisation is the store once the step is taken)")

    def _commit_terms(self, pending: bool) -> list:
        """The step taken: the speculation's words moved into place, two a cycle (τ's into
        slot 1's prior, the staged conditional into kept memory), beside the call's reads of X
        (the window out, the pending point): one DATAFLOW region (out_beside_commit), the
        longest of the three; x_out and kept_pending are counted whole."""
        st = self.stream
        tau = st["stream_tau_commit"]
        keep = st["stream_keep_commit"] if self.layout.kept else 0
        out = st["stream_x_out"] + (st["stream_kept_slot0"] if pending else 0)
        terms = [Term("tau_commit", tau, 1, False, "τ's words from TAU_BUF into slot 1's "
                      "prior, two a cycle")]
        if self.layout.kept:
            terms.append(Term("keep_commit", keep, 1, False, "the staged conditional (R, S, "
                              "d, its points) into kept memory, two words of each a cycle"))
        terms.append(Term("out_beside_commit", -(tau + keep + out - max(tau, keep, out)), 1,
                          False, "the window out (and the pending point) read out of X beside "
                          "the two moves (one DATAFLOW region): all but the longest hidden"))
        return terms

    def _start_hidden(self, m: int, shift: bool, leave: bool, points: bool,
                      row: bool = False) -> int:
        """The cycles update_start (fgc_stream.h) hides: its two processes, the moves on X (the
        leaving keyframe's estimate out where ``leave``, the shift's variables where ``shift``,
        the keyframe's storage into slot ``m``, slots 0 and 1 copied where ``points``) and the
        moves on DATA_BUF (the shift's words, the keyframe's words), share no memory and no
        operator: the region takes the longer, the shorter is hidden. Priced against the terms
        that count each move whole (keyframe_in, shift, leave, lin_points); ``row``: a sweep
        pass's keyframe from its row (:meth:`_banked`)."""
        st = self.stream
        x = (st["stream_x_out_kf"] if leave else 0) + (st["stream_shift_x"] if shift else 0) \
            + st["stream_keyframe_x_in"] + (st["stream_lin_points"] if points else 0)
        data = (st["stream_start_data_sweep" if row else "stream_start_data"] if shift
                else st[f"stream_keyframe_data_in{m}"])
        return min(x, data)

    def _banked(self, row: bool = False) -> int:
        """The cycles the update's start saves on DATA_BUF with the window full
        (start_data_task): the shift's words and then the keyframe's, a word a cycle through
        one bank's two ports (the terms shift and keyframe_in count them so), against one loop
        over DATA_BUF's banks that takes a read and a write of each an iteration and the
        keyframe's words one an iteration (window.py's _start_tables); ``row``: a sweep pass,
        its keyframe from its row of SWEEP_WORDS two words an iteration."""
        st, last = self.stream, self.layout.size - 1
        return st["stream_shift_data"] + st[f"stream_keyframe_data_in{last}"] \
            - st["stream_start_data_sweep" if row else "stream_start_data"]

    def _banked_term(self, times: int = 1, name: str = "start_banks", row: bool = False) -> Term:
        lay = self.layout
        rows = self.sweep_rows if row else self.start_rows
        per = "two" if row else ("one" if self.data_words == 1
                                 else f"up to {self.data_words}, a beat of the data port")
        return Term(name, -self._banked(row), times, False,
                    f"the shift's {len(lay.data_moves)} data words, the newest prior's "
                    f"{len(lay.kf_zero)} zeroed and the keyframe's "
                    f"{len(lay.kf_call)} ({per} an iteration) in "
                    f"{len(rows)} iterations over DATA_BUF's {self.start_banks} banks, not one "
                    "after the other through one")

    def _start_term(self, m: int, shift: bool, leave: bool, points: bool,
                    name: str = "start_beside", row: bool = False) -> Term:
        return Term(name, -self._start_hidden(m, shift, leave, points, row), 1, False,
                    "the update's start (one DATAFLOW region): the moves on X (leave, the "
                    "shift's variables, the keyframe's storage, the points) beside those on "
                    "DATA_BUF (the shift's and the keyframe's words), the shorter hidden")

    def _out_beside_sign(self, pending: bool) -> Term:
        """The call's reads of X (fgc_stream.h's out_task: slot 0's new estimate for the pending
        re-expression where ``pending``, the window's storage out) as a third process of
        tau_and_keep's first region, beside tau's sign loop and the kept conditional's
        reciprocals: X is final once the window's region is over, and neither of the others
        reads it. The region takes the longest of the three; against the terms x_out and
        kept_pending counted whole, the reads hide behind the longer of the other two."""
        st = self.stream
        out = st["stream_x_out"] + (st["stream_kept_slot0"] if pending else 0)
        first = max(st["stream_tau_sign"],
                    st["stream_keep_reciprocal"] if self.layout.kept else 0)
        return Term("out_beside_sign", -min(out, first), 1, False,
                    "the window out (and the pending point) read out of X beside τ's sign loop "
                    "(tau_and_keep's first region): the shorter hidden")

    def _sweep_terms(self, j: int) -> list:
        """A batch step at keyframe j as a sweep through the window (fgc_stream.h's
        ``FGC_STREAM_SWEEP``), but its last pass (keyframe j's update, priced as one): keyframes
        0 … j − 1's estimates gathered, each keyframe in again (and the shift once the window is
        full), and per keyframe c ≥ W that leaves the window before j: the window linearised at
        the estimates, slot 0's QR step at μ = 0 with τ written (beside the kept task's empty
        walk) and its conditional kept."""
        lay, st, w = self.layout, self.stream, self.layout.window
        moves = sum(st[f"stream_keyframe_in{min(c, w)}"] + (st["stream_shift"] if c >= lay.size
                                                               else 0) for c in range(j))
        # each pass's start region: its moves on X beside its words (the points copied on the
        # passes with the window full, c >= w)
        hidden = sum(self._start_hidden(min(c, w), c >= lay.size, False, c >= w, True)
                     for c in range(j))
        terms = [Term("sweep_gather", st[f"stream_sweep{j}_gather"], 1, False,
                      f"keyframes 0 … {j - 1}'s estimates into their rows (the sweep's points)"),
                 Term("sweep_in", moves, 1, False,
                      f"keyframes 0 … {j - 1} into the window again, one a pass (and the shift "
                      "once it is full)"),
                 Term("sweep_start_beside", -hidden, 1, False,
                      "each pass's start region: its moves on X (the shift's variables, the "
                      "keyframe's storage, the points) beside its words, the shorter hidden")]
        shifted = sum(1 for c in range(j) if c >= lay.size)
        if shifted:
            terms.append(self._banked_term(shifted, "sweep_start_banks", True))
        steps = range(w, j)
        if not steps:
            return terms
        # (pass c >= size: keyframe 0 has left, its priors neither linearised nor stacked)
        linearize = sum(st["stream_leaf_linearize" + ("_live" if c >= lay.size else "")]
                        for c in steps)
        marginal = sum(st["stream_marginal_live" if c >= lay.size else "stream_marginal"]
                       + self.qr_cycles(self.zero_factors(c), False, leaf_only=True,
                                        live=c >= lay.size)
                       for c in steps)
        terms += [Term("sweep_linearize", linearize, 1, False,
                       f"{len(steps)} sweep passes with the window full: slot 0's step's "
                       "factors linearised at the estimates (LM's instance on its leaf "
                       "instances)"),
                  Term("sweep_points", st["stream_lin_points"], len(steps), False,
                       "slots 0 and 1 copied"),
                  Term("sweep_marginal", marginal, 1, False,
                       f"keyframes 0 … {j - w - 1} leave: slot 0's QR step at μ = 0 on unit set "
                       "0, τ's signs, mean and words (the marginal's region, its kept task "
                       "empty)"),
                  Term("sweep_keep", st["stream_kept_store"], len(steps), False,
                       "each leaving keyframe's conditional and points kept"),
                  self._keep_beside_tau(len(steps), "sweep_keep_beside_tau")]
        return terms

    def _batch_terms(self, j: int, ev: dict) -> list:
        """A batch step's terms, as accel.cpp.jinja's batch_step and the batch kernel's
        batch_solve count them."""
        batch, lay, st = self.batch, self.layout, self.stream
        b, group = batch["layout"], batch["group"]
        zero, unit = b.zero_factors(j), b.unit_factors(j)
        qr_damped = qr_solve_cycles(batch["plan"], b.template, zero, True, batch["sets"],
                                    self.les, unit=unit)
        qr_store = qr_solve_cycles(batch["plan"], b.template, zero, False, batch["sets"],
                                   self.les, unit=unit)
        terms = [Term("batch_gather", st[f"stream_batch{j}_gather"], 2, False,
                      f"keyframes 0 … {j}'s estimates to the batch kernel (gathered, copied in)"),
                 Term("batch_tau_lin", st["stream_batch_tau_lin"], 1, False,
                      "τ's linearisation point (the batch kernel's start) copied before its "
                      "call")]
        if ev.get("cost", 0) and batch["cost_x"]:
            terms.append(Term("batch_cost_x", batch["cost_x"], ev["cost"], False,
                              "the batch kernel's cost pass at X before LM's first "
                              "linearisation"))
        for g in sorted(group):
            trigger = PHASE_TRIGGER.get(g)
            times = ev.get(trigger, 0) if trigger else 0
            if times:
                each = qr_damped if g == "qr" else group[g]
                terms.append(Term(f"batch_{g}", each, times, False,
                                  f"the batch kernel's {g} phase, once per {trigger}"))
        if not self.reuses(ev):
            relin = _relinearize(ev)
            store = (relin * (group["factor_jacobian"] + group.get("gradient", 0))
                     + group["qr_stack"]
                     + qr_store + group["qr_commit"])
            terms.append(Term("batch_store", store, 1, False,
                              f"keyframes 0 … {j} " + ("linearised at the optimum and " if relin
                                                       else "") + "eliminated serially at μ = 0 "
                              "(their conditionals and the factors they pass)"))
        terms.append(Term("batch_out", st[f"stream_batch{j}_out"], 1, False,
                          "the optimum, the conditionals and τ out of the batch kernel, the "
                          "optimum scattered to the kept memory and the window"))
        if j >= lay.window:
            terms.append(Term("batch_kept", st[f"stream_batch{j}_kept"], 1, False,
                              f"the kept net rebuilt: keyframes 0 … {j - lay.window}'s "
                              "conditionals and points, τ written for the next window"))
        return terms

    @staticmethod
    def events_of(iterations: int, rejected: int = 0, noise: int = 0,
                  status: str = "converged") -> dict:
        """The solve's event counts from its iterations: each iteration a linearisation, a
        solve (and its back-substitution, the cost at X_TRIAL beside it: none fails), a
        retraction and (but the last, which converged) an accepted step; the start's cost pass
        (at X: ``cost``); ``rejected`` trial steps add a solve, a back-substitution and a
        retraction each. (LM then stopped where it last linearised: a leaving keyframe's
        marginal reuses those rows, no ``relinearize``.) ``status`` "max_iterations" (the
        one-step policy: a Gauss-Newton step an update, k_max = 1): the last iteration took
        its step too, so every iteration accepted one and the marginal (a batch step's store)
        linearises again at the new estimate (:func:`_relinearize`)."""
        k = int(iterations)
        last = status == "max_iterations"
        return {"linearize": k, "solve": k + rejected, "backsub": k + rejected,
                "retract": k + rejected, "cost": 1, "accept": k if last else max(0, k - 1),
                "noise": noise}

    def reuses(self, ev: dict) -> bool:
        """Whether the update's store is its own solve's factorisation: the one-step policy
        with the step taken (an accepted step; fgc_stream.h's ``took_step``)."""
        return self.one_step and ev.get("accept", 0) >= 1

    def price(self, keyframe: int, iterations: int, events: dict | None = None,
              status: str = "converged"):
        """The :class:`UpdatePrice` of keyframe ``keyframe``'s call (``status``: the update's,
        for :meth:`events_of` when no ``events`` are given)."""
        lay, st = self.layout, self.stream
        m = min(keyframe, lay.size - 1)
        first = max(0, keyframe - lay.window)
        ev = dict(events) if events is not None else self.events_of(iterations, status=status)
        words = len(lay.kf_call) if keyframe >= lay.size else len(lay.new_dest[m])
        zeroed = (f", the other {len(lay.kf_zero)} zero (its prior's tail: the start's)"
                  if keyframe >= lay.size else "")
        terms = [Term("keyframe_in", st[f"stream_keyframe_in{m}"], 1, False,
                      f"keyframe {keyframe}'s storage and {words} data words in "
                      f"(slot {m}{zeroed})")]
        if keyframe >= lay.size:
            terms.append(Term("shift", st["stream_shift"], 1, False,
                              "every slot down one: its variables, its factors' words, τ"))
        sweep = lay.sweep is not None and keyframe in lay.sweep
        if keyframe >= lay.size:  # (a sweep's last pass reads its keyframe from its row too)
            terms.append(self._banked_term(row=sweep))
        if lay.sweep is not None:
            if keyframe >= lay.size:
                terms.append(Term("leave", st["stream_x_out_kf"], 1, False,
                                  "the leaving keyframe's estimate into the kept memory"))
            if sweep:
                # kept as it came before the sweep's passes (which read it back); an update that
                # is not a sweep keeps it as update_start moves it into the window (no cycles)
                store = ("stream_sweep_store_full" if keyframe >= lay.size
                         else f"stream_sweep_store{m}")
                terms.append(Term("sweep_store", st[store], 1, False,
                                  "the keyframe's storage and words kept as they came (the "
                                  "sweep brings them in again)"))
                # the sweep starts from the kept estimates (pass -1)
                terms += self._start_from_kept(keyframe, first, ev if events is not None
                                               else None, "kept_walk_parent")
                terms += self._sweep_terms(keyframe)
        batch = self.batch
        batch_step = batch is not None and keyframe in batch["layout"].keyframes
        # the update's start region: the leave in it but before a sweep or a batch step (they
        # read it back first); the points copied but on a batch step
        terms.append(self._start_term(
            m, keyframe >= lay.size,
            keyframe >= lay.size and (lay.sweep is not None or batch is not None)
            and not sweep and not batch_step, not batch_step, row=sweep))
        if batch is not None:
            if keyframe >= lay.size:
                terms.append(Term("leave", st["stream_x_out_kf"], 1, False,
                                  "the leaving keyframe's estimate into the kept memory"))
            if keyframe < batch["layout"].size:
                terms.append(Term("batch_in", st[f"stream_batch_in{keyframe}"], 1, False,
                                  "the keyframe's words into the batch kernel's slot"))
            if keyframe in batch["layout"].keyframes:
                if lay.kept:  # the batch kernel starts from the kept estimates
                    terms += self._start_from_kept(keyframe, max(0, keyframe - lay.window),
                                                   ev if events is not None else None,
                                                   "kept_slot0")
                terms += self._batch_terms(keyframe, ev)
                terms.append(Term("x_out", st["stream_x_out"], 1, False,
                                  "the window's storage out"))
                return UpdatePrice(keyframe, "batch", 0, int(iterations), self.clock_mhz,
                                   tuple(terms), STREAM_SOURCE)
        zero, unit = self.zero_factors(keyframe), lay.unit_factors(keyframe)
        # the window's process of the update's region (fgc_stream.h's window_task): the solve,
        # the relinearisation, the marginal; lin_points is copied before the region
        window = []
        for g in sorted(self.group):
            trigger = PHASE_TRIGGER.get(g)
            if trigger is None:
                continue
            times = ev.get(trigger, 0)
            if g == "lm_control" and "call" in ev and self._decide_only():
                # the step test's scalars and the decision run where the step is tested
                # (fgc_lm_units.h's lm_step_sums' step_test event): not after a solve that
                # stopped on its gradient (fgc_lm.h's FGC_LM_GRADIENT_IN_SOLVE). Events the C
                # simulation counted (they hold its call; one that did not happen is absent)
                times = ev.get("step_test", 0)
            each = (self.qr_cycles(zero, True, unit=unit) if g == "qr"
                    else self.solve_linearize(keyframe >= lay.size) if g == "factor_jacobian"
                    else self.group[g])
            if times:
                window.append(Term(g, each, times, False,
                                   f"the window's {g} phase, once per {trigger}" + (
                                       " (on its rows non-zero in this update)" if g == "qr"
                                       else "")))
        if self._lin_sets and ev.get("linearize", 0):
            # LM's one linearisation with level 0's first steps beside it (lin_level): the
            # solve's level 0 region is that region's sets, the stack took their results; an
            # update that stops before its solve still waits for the sets
            solved = ev.get("solve", 0) > 0
            window.append(Term("qr_beside_linearize",
                               self.beside_linearize(zero, unit, solved,
                                                     keyframe >= lay.size), 1, False,
                               "level 0's unit sets reflect their steps beside the "
                               "linearisation (one region), each from when its rows are in"
                               + ("" if solved else "; no solve took them")))
        if ev.get("cost", 0) and self.cost_x:
            window.append(Term("cost_x", self.cost_x, ev["cost"], False,
                               "the cost pass at X before LM's first linearisation"))
        terms.append(Term("lin_points", st["stream_lin_points"], 1, False,
                          "slots 0 and 1 copied before the solve (the one-step policy keeps a "
                          "leaving keyframe's conditional and τ there)"))
        if m == lay.window and self.layout_marginal and self.reuses(ev):
            window.append(Term("marginal", st["stream_marginal_reused"], 1, False,
                               "keyframe leaving: the one-step solve's slot 0 step is the store "
                               "(its rows at μ = 0, at the update's start): τ's signs, mean and "
                               "words"))
        elif m == lay.window and self.layout_marginal:
            # the window's rows at its optimum: computed again only if LM took a step after its
            # last linearisation (fgc_stream.h's window_task, by LM's own linearisation
            # instance; counted: the "relinearize" event)
            relin = _relinearize(ev)
            live = keyframe >= lay.size  # keyframe 0 has left: its priors are not linearised
            if relin:
                window.append(Term("relinearize", st["stream_leaf_linearize"
                                                      + ("_live" if live else "")], relin, False,
                                   "keyframe leaving: slot 0's step's factors linearised at "
                                   "the optimum (LM moved after its last linearisation)"))
            window.append(Term("marginal", st["stream_marginal_live" if live else "stream_marginal"]
                               + self.qr_cycles(zero, False, leaf_only=True, live=live), 1, False,
                               "keyframe leaving: slot 0's QR step at μ = 0 on unit set 0 (LM's), "
                               "τ's signs, mean and words"))
        terms += window
        leaving = m == lay.window and self.layout_marginal
        # the one-step update's marginal formed beside its back-substitution, the step taken
        spec = leaving and self.spec and self.reuses(ev)
        if lay.kept:
            # the re-expression the update before left pending runs beside this update's
            # window process (one DATAFLOW region, no memory between them): the update waits for
            # the longer of the two (a sweep ran it in its pass -1, above); tau's sign, mean and
            # words (the marginal term's write_tau) run after that region (tau_and_keep)
            if not sweep and self._pending(keyframe, ev if events is not None else None):
                kept = self._pending_term()
                solve = sum(t.cycles for t in window) - (st["stream_marginal_reused"]
                                                         if leaving else 0) \
                    + (self._spec_over() if spec else 0)
                terms += [kept, Term("overlap", -min(kept.cycles, solve),
                                     1, False, "the pending re-expression beside the window's "
                                     "solve and marginal (one DATAFLOW region): the shorter of "
                                     "the two is hidden behind the longer")]
            if leaving:
                terms += [Term("kept_store", st["stream_kept_store"], 1, False,
                               f"keyframe {first}'s conditional (R | S | d) and its "
                               "linearisation points kept"),
                          self._spec_beside_backsub() if spec else self._keep_beside_tau()]
            if first > 0 and not sweep:
                # this update's own re-expression (keyframe first - 1's conditional at slot 0's
                # new estimate) is left for the next call's region: its point copied out of X;
                # the kept keyframes' estimates are walked when asked for (price_estimates) or
                # by the next batch step
                terms.append(Term("kept_pending", st["stream_kept_slot0"], 1, False,
                                  f"slot 0's new estimate copied out of X: keyframe {first - 1}'s "
                                  "kept conditional re-expressed there in the next call's region"))
        elif leaving:  # the fixed-lag window: tau_and_keep's keep processes empty
            terms.append(self._spec_beside_backsub("tau_beside_backsub") if spec
                         else self._keep_beside_tau(name="tau_beside"))
        terms.append(Term("x_out", st["stream_x_out"], 1, False, "the window's storage out"))
        if self.spec and ev.get("accept", 0) and "lm_accept" in self.group:
            # the one-step policy's step taken stays in X_TRIAL (the kernel's X_HELD): the call's
            # reads of X after the window's region take its words and write them into X a word
            # a cycle (fgc_stream.h's out_task, stream_call's end), no copy of its own
            terms.append(Term("accept_in_out", -self.group["lm_accept"], ev["accept"], False,
                              "the step taken moved into X as the window out reads it (from "
                              "X_TRIAL, a word a cycle): LM's copy of x_trial not run"))
        if spec:
            terms += self._commit_terms(lay.kept and first > 0 and not sweep)
        elif leaving:
            terms.append(self._out_beside_sign(lay.kept and first > 0 and not sweep))
        if sweep:
            return UpdatePrice(keyframe, "batch", 0, int(iterations), self.clock_mhz,
                               tuple(terms), STREAM_SOURCE)
        return UpdatePrice(keyframe, "incremental" if lay.kept else "fixed-lag", first,
                           int(iterations),
                           self.clock_mhz, tuple(terms), STREAM_SOURCE)

