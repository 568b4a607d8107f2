"""A keyframe update of a stream priced on the accelerator plan (issue 19; model estimates).

The on-chip designs of a QR Program (``fgc_backends.hls.window``: the fixed-lag window, the
incremental plan with its kept Bayes net and batch kernel) are priced by their own
``WindowUpdateModel``. This module prices the path where no on-chip design is emitted (a
Cholesky Program: each window solved as a batch solve, the kept net on the host):
:class:`UpdateModel` prices what the simulator's update did (``fgc_sim_incremental``:
``solve_incremental`` / ``solve_fixed_lag``) as the emitted units would run it, with the loops,
IIs and depths of :mod:`fgc_backends.hls.plan` and its operator table:

- per LM iteration the update ran (linearisations; rejected trial steps and the start's cost
  pass are not priced, as :func:`~fgc_backends.hls.plan.plan_summary` prices a batch solve):
  every per-iteration phase of the batch plan, built with the plan's own loop constructors on
  the window (its block instances, its variables, its clusters' steps at their sizes,
  eliminated serially oldest first on one unit set: the simulator's order, root at the newest
  cluster; :meth:`UpdateModel.window_tables` gives the constructors the window's step and
  factor tables): the factor datapaths (Jacobian mode, then cost mode), QR's gradient pass over
  AB, the linear solver — QR: per step its stack (√μ first), ``qr_unit_loops`` on its stacked
  pattern (the window's factors, the previous step's new factor, the prior τ on the oldest
  cluster, √μ rows) and its commit; Cholesky: the HGC, each step's assembly, the cascade
  (``cpe_step_loops``), each step's store — back-substitution through the window with its
  copies, the state update of the window's variables per type and LM control over them; a
  window spanning the whole chain costs exactly ``plan_cost`` of the serially ordered batch
  Program;
- once per update: the store (the converged window eliminated once more without damping, its
  conditionals and new factors kept), the plan's per-call copies (``setup``: the keyframe's new
  initial values and data in, the changed estimate out) and, incremental mode,
  back-substitution through the kept conditionals (with its copies) and a state update of
  their variables;
- per rejected trial step, as the simulator's update record counts them (``rejected``): the
  linear solve again at the grown μ, the state update, the cost pass and the step test
  (:meth:`UpdateModel.trial_cycles`); per iteration with such a step at a finite cost
  (``noise_passes``) the plan's rounding-noise pass on the window; a record without the counts
  (the native and C-simulation streams') gets both as assumed terms counted zero times (their
  price in ``each``);
- a batch keyframe j: its iterations as full batch iterations, ``plan_cost`` of the Program of
  keyframes 0 … j (``batch_program(j)``; the stream's own Program at the last keyframe), plus
  the store and the setup.

Terms no emitted unit computes are listed apart and labelled *assumed*: τ's rows at x (A·J and
b − A·Log(x̄⁻¹x)), re-expressing the newest kept conditional at its parent's new estimate, the
Log maps of the kept back-substitution, the host → accelerator transfer of a keyframe's
measurements before the call (the top's copy-in is the ``setup`` term), the on-chip state kept
between calls and, when the record does not count them, rejected steps (none). ``latency_ms``
counts the plan's terms only; ``latency_with_assumed_ms`` adds the assumed ones.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import replace
from types import SimpleNamespace

import numpy as np

from fgc.errors import FgcError
from fgc.ir.program import Program
from fgc_backends.cost.structure import whitened_pattern
from fgc_backends.hls.plan import (
    AcceleratorPlan,
    Loop,
    Phase,
    PlanOptions,
    Process,
    build_plan,
    kernel_loop,
    kernel_timing,
    phase_cycles,
    phase_group,
    plan_cost,
    plan_sizes,
)
from fgc_backends.hls.plan.stream import Term, UpdatePrice
from fgc_backends.hls.units.backsub import (
    backsub_copies,
    backsub_loops,
    retire_region,
    root_in_commit,
    serial_slots,
)
from fgc_backends.hls.units.cholesky import elimination_phases, hgc_loops, hgc_phases
from fgc_backends.hls.units.datapath import linearize_region, small_blocks, trial_end, trial_loops
from fgc_backends.hls.units.lm_control import lm_control_phases, rounding_noise_loops, setup_phase
from fgc_backends.hls.units.qr import commit_loops, qr_unit_loops, stack_loops
from fgc_backends.hls.units.state_update import fed_by_backsub, retire_timing, retract_loops

NOT_EMITTED = ("a Cholesky design's on-chip incremental state is not emitted in C++ (the "
               "on-chip design, fgc_backends.hls.window, keeps the QR unit's conditionals): this "
               "HLS design solves each update's window as a batch solve and the kept Bayes net "
               "(conditionals, marginal prior, back-substitution) lives on the host; these are "
               "model estimates of the emitted units running the update")
MODES = ("incremental", "batch", "fixed-lag")


class UpdateModelError(FgcError):
    """An update the model cannot price (not a chain, a mode it does not know, a window
    outside the stream)."""


class UpdateModel:
    """The accelerator plan's price of each update of a stream over ``program``'s chain.

    ``options``: the plan's units (default ``PlanOptions.of(program)``: the Program's
    ``--units`` / ``--cpe``). ``batch_program(j)`` returns the batch Program of keyframes
    0 … j (needed for batch keyframes before the last). ``transfer_words_per_cycle``: the
    assumed host → accelerator rate. The window's linearisation runs before its elimination
    (the HGC beside the elimination is a batch design's: ``hgc_beside`` is off in the plan this
    model reads, so a window spanning the chain costs that plan)."""

    def __init__(self, program: Program, options: PlanOptions | None = None,
                 batch_program: Callable[[int], Program] | None = None,
                 transfer_words_per_cycle: int = 1):
        sched = program.schedule
        if sched.structure_class != "chain" or not sched.clusters:
            raise UpdateModelError(f"the update model needs a chain of keyframes; "
                                   f"{program.name!r} is {sched.structure_class}")
        if transfer_words_per_cycle < 1:
            raise UpdateModelError(f"transfer_words_per_cycle must be ≥ 1, got "
                                   f"{transfer_words_per_cycle}")
        self.program, self.batch_program = program, batch_program
        self.options = replace(options or PlanOptions.of(program), hgc_beside=False)
        self.plan = build_plan(program, self.options)
        self.ops = self.plan.ops  # the accelerator's scalar, and the linear solver's (plan's)
        self.les = self.plan.target.ops(self.options.precisions(program)[1])
        self.rate = transfer_words_per_cycle
        self.qr = program.solver.linear == "qr"
        self.damping = program.solver.method == "lm"
        self._batch_plans: dict[int, AcceleratorPlan] = {}
        self._window_phases: dict[tuple[int, int], tuple[Phase, ...]] = {}
        self._read_plan()
        self._read_chain()

    # -- what the batch plan already prices, per unit ------------------------------------------
    def _read_plan(self) -> None:
        from fgc_backends.cfamily.blocks import block_contexts
        from fgc_backends.hls.plan.loops import tree_latencies
        self._blocks = block_contexts(self.program, vector=False,  # what an instance gathers
                                      latencies=tree_latencies(self.plan.ops))
        self.factor_loop = {}  # (block, mode) -> the plan's instance loop (ii, depth)
        small = small_blocks(self.program)  # their shared datapath's one loop
        for mode in ("jacobian", "cost"):  # Cholesky: the Jacobian pass in the hgc regions
            for proc in (p for ph in self.plan.phases for p in ph.processes):
                unit = re.fullmatch(rf"factor_(\d+|small)_{mode}", proc.name)
                if unit is None:
                    continue
                for block in small if unit.group(1) == "small" else (int(unit.group(1)),):
                    self.factor_loop[block, mode] = proc.loops[0]
        # the plan's kernel loop timings (in the accelerator's scalar) and the emitted buffer
        # sizes (MAX_W: the stack's and the assembly's row stride)
        self.timing = kernel_timing(self.plan.ops)
        self.les_timing = kernel_timing(self.les)
        self.max_w = plan_sizes(self.program)["MAX_W"]

    def _read_chain(self) -> None:
        p = self.program
        self.clusters = p.schedule.clusters
        self.dims = {v.key: v.dim for v in p.variables}
        self.storage = {v.key: v.storage_dim for v in p.variables}
        cluster_of = {k: c for c, keys in enumerate(self.clusters) for k in keys}
        self.entry = [min(cluster_of[k] for k in f.keys) for f in p.factors]
        self.reach = [max(cluster_of[k] for k in f.keys) for f in p.factors]
        self.cdim = [sum(self.dims[k] for k in keys) for keys in self.clusters]
        # rows of the factor each cluster passes to the next (a child's new factor or, once the
        # cluster has left the window, the prior τ): the serial recurrence of the simulator's
        # stores, min(rows - f, s) as the schedule trims a partial QR
        self.tau_rows = []
        carried = 0
        for c, f in enumerate(self.cdim):
            rows = carried + sum(p.blocks[p.factors[i].block].residual_dim
                                 for i in range(len(p.factors))
                                 if self.entry[i] == c and self.reach[i] <= c + 1)
            s = self.cdim[c + 1] if c + 1 < len(self.cdim) else 0
            carried = max(0, min(rows - f, s))
            self.tau_rows.append(carried)

    # -- pricing -----------------------------------------------------------------------------
    def price(self, update) -> UpdatePrice:
        """The price of one update (a :class:`fgc.app.streaming.KeyframeResult` or any object
        with ``keyframe``, ``mode``, ``first`` and ``iterations``)."""
        j, first, mode = int(update.keyframe), int(update.first), str(update.mode)
        k = int(update.iterations)
        n = len(self.clusters)
        if mode not in MODES:
            raise UpdateModelError(f"update mode {mode!r}: the model prices {', '.join(MODES)}")
        if not 0 <= first <= j < n:
            raise UpdateModelError(f"keyframe {j} from {first}: outside the stream's {n} "
                                   "keyframes")
        if mode == "batch" and first != 0:
            raise UpdateModelError(f"keyframe {j}: a batch update re-eliminates every "
                                   f"keyframe, but this one starts at {first}")
        if k < 0:
            raise UpdateModelError(f"keyframe {j}: {k} iterations")
        terms = []
        if mode == "batch":
            terms.append(Term("batch_iteration", self.batch_iteration_cycles(j), k, False,
                              f"plan_cost of the batch Program of keyframes 0…{j}"))
        else:
            terms += self._iteration_terms(first, j, k)
        terms.append(Term("store", self._linear_cycles(first, j, damping=False), 1, False,
                          "the converged window eliminated once more without damping, its "
                          "conditionals and new factors kept (serial, oldest first)"))
        if mode == "incremental" and first > 0:
            terms += self._kept_terms(first, j)
        terms.append(Term("setup", phase_cycles(self.setup_phase(first, j, mode)), 1, False,
                          "once per update (the plan's per-call copies): the keyframe's new "
                          "initial values and data in, the changed estimate out"))
        terms += self._rejection_terms(update, 0 if mode == "batch" else first, j, mode)
        terms += self._transfer_terms(first, j, mode)
        return UpdatePrice(j, mode, first, k, self.plan.clock_mhz, tuple(terms))

    def batch_iteration_cycles(self, j: int) -> int:
        """One batch iteration of keyframes 0 … j: ``plan_cost(build_plan(P_j))``."""
        return plan_cost(self._batch_plan(j)).cycles

    def _batch_plan(self, j: int) -> AcceleratorPlan:
        """The plan of the batch Program of keyframes 0 … j (the stream's own at the last)."""
        if j not in self._batch_plans:
            if j == len(self.clusters) - 1:
                program = self.program
            elif self.batch_program is None:
                raise UpdateModelError(f"keyframe {j}: a batch update before the last keyframe "
                                       "needs batch_program (the Program of its keyframes)")
            else:
                program = self.batch_program(j)
            self._batch_plans[j] = build_plan(program, self.options)
        return self._batch_plans[j]

    def window_iteration_phases(self, first: int, last: int) -> tuple[Phase, ...]:
        """One LM iteration of the window first … last as the plan's phases, in the plan's
        order, built with the plan's own loop constructors on the window (its block instances,
        its variables, its clusters' steps eliminated serially oldest first): the Jacobian
        pass, QR's gradient pass (Cholesky's comes with the HGC), the linear solver (stack, QR
        step and commit per cluster; or HGC, assembly, cascade and store), back-substitution
        with its copies, the state update per variable type, the cost pass and LM control.
        τ's relinearisation is not among them (an assumed term). Built once per window (an
        update prices its iterations and its rejected trials from them)."""
        if (first, last) not in self._window_phases:
            self._window_phases[first, last] = self._build_window_phases(first, last)
        return self._window_phases[first, last]

    def _build_window_phases(self, first: int, last: int) -> tuple[Phase, ...]:
        inst = self._instances(first, last)
        view = self._view(first, last, inst)
        jacobian = self._factor_phase("jacobian", inst)
        phases = [jacobian]
        if self.qr:  # the datapaths beside the gradient, one region (as emitted)
            phases = [linearize_region(view, self.timing, list(jacobian.processes))]
            phases += self._linear_phases(first, last, self.damping, inst)
        else:  # the Jacobian pass runs alongside the HGC, a region per block type (as emitted)
            phases = hgc_phases(view, self.les_timing, self.options.hgc_lanes,
                                jacobian.processes, self.timing)
            phases += [ph for ph in self._linear_phases(first, last, self.damping, inst)
                       if ph.name != "hgc"]
        if not fed_by_backsub(self.program, self.options):  # else beside back-substitution
            phases.append(self._factor_phase("cost", inst))
        phases += self._lm_phases(view.variables)
        return tuple(phases)

    def setup_phase(self, first: int, last: int, mode: str) -> Phase:
        """The plan's once-per-call copies (its ``setup`` phase: x in, the data in, x out) for
        one update: the keyframe's new variables' initial values and its new factors' data in
        (the rest of the state and data stays on chip), and out the estimate the update
        changed (fixed-lag: the window's variables; incremental and batch: every keyframe's
        up to this one, as back-substitution through the kept conditionals changes them)."""
        from fgc_backends.cfamily.tables import factor_data_words

        p = self.program
        new = [i for i in range(len(p.factors)) if self.reach[i] == last]
        data = sum(factor_data_words(p, p.factors[i].block) for i in new)
        x_in = sum(self.storage[k] for k in self.clusters[last])
        out_from = first if mode == "fixed-lag" else 0
        x_out = sum(self.storage[k] for c in range(out_from, last + 1) for k in self.clusters[c])
        return setup_phase(x_in, data, x_out, self.timing)

    def rounding_noise_phase(self, first: int, last: int) -> Phase:
        """The plan's per-rejection rounding-noise pass on the window's variables and block
        instances."""
        inst = self._instances(first, last)
        return Phase("rounding_noise", False, tuple(rounding_noise_loops(
            self._view(first, last, inst), self.timing)), per="rejection")

    # -- the terms ----------------------------------------------------------------------------
    def _iteration_terms(self, first, last, k) -> list[Term]:
        out = []
        for ph in self.window_iteration_phases(first, last):
            out.append(Term(f"iteration:{ph.name}", phase_cycles(ph), k, False,
                            "per LM iteration, the plan's loops on the window"))
        if first > 0:
            out.append(Term("iteration:prior_rows", self._prior_rows_cycles(first), k, True,
                            "assumed: τ's rows at x (A·J, b − A·Log(x̄⁻¹x)) for the Jacobian "
                            "and the cost pass on one multiply-add lane plus a state-update "
                            "pass for the Log; no emitted unit computes them"))
        return out

    def _rejection_terms(self, update, first, last, mode) -> list[Term]:
        """LM's rejected trial steps, as the update record counts them (``rejected``: trial
        steps retracted, costed and not accepted; ``noise_passes``: iterations in which one was
        rejected at a finite cost, when the kernel works out the rounding-noise band). A record
        without the counts (the native and C-simulation streams') gets both assumed zero."""
        trial = self.trial_cycles(first, last, mode)
        noise = phase_cycles(self.rounding_noise_phase(first, last))
        rejected = getattr(update, "rejected", None)
        passes = getattr(update, "noise_passes", None)
        if rejected is None or passes is None:
            return [Term("rejected_trial", trial, 0, True,
                         f"assumed: no rejected trial step (the update record does not count "
                         f"them); each would add a re-solve at the grown μ, the state update, "
                         f"the cost pass and the step test, {trial} cycles"),
                    Term("rounding_noise", noise, 0, True,
                         f"assumed: no rounding-noise pass (the update record does not count "
                         f"rejected steps); each would add the plan's pass on the window, "
                         f"{noise} cycles")]
        rejected, passes = int(rejected), int(passes)
        if rejected < 0 or not 0 <= passes <= rejected:
            raise UpdateModelError(f"keyframe {update.keyframe}: {rejected} rejected steps with "
                                   f"{passes} rounding-noise passes")
        return [Term("rejected_trial", trial, rejected, False,
                     "per rejected trial step the update reports: the linear solve again at the "
                     "grown μ (the Jacobians and gradient are kept), the state update, the cost "
                     "pass and LM control's step test"),
                Term("rounding_noise", noise, passes, False,
                     "per iteration with a rejected step at a finite cost: the plan's "
                     "rounding-noise pass on the window (the band is worked out once)")]

    def trial_cycles(self, first: int, last: int, mode: str) -> int:
        """One rejected trial step as the kernel runs it (``try_steps``): the per-iteration
        phases without the Jacobian pass, the gradient / HGC and LM control's per-linearisation
        and per-accept loops (``lm_iteration``, ``lm_accept``): the linear solve, the state
        update, the cost pass and the step test with its decision (``lm_control``). A batch
        keyframe: the batch Program's own plan; otherwise the window's phases."""
        if mode == "batch":
            phases = [ph for ph in self._batch_plan(last).phases if ph.per == "iteration"]
        else:
            phases = list(self.window_iteration_phases(first, last))
        # kept from the linearisation: the Jacobian pass, the gradient / HGC and LM control's
        # once-per-linearisation loops; nothing accepted: no copy of the trial x
        kept = ("factor_jacobian", "gradient", "hgc", "lm_iteration", "lm_accept")
        return sum(phase_cycles(ph) for ph in phases if phase_group(ph.name) not in kept)

    def _kept_terms(self, first, last) -> list[Term]:
        """Back-substitution through the kept conditionals first − 1 … 0 (plan), with the
        re-expression of the newest at its parent's new estimate and each parent's Log
        (assumed)."""
        loops = []
        for c in range(first - 1, -1, -1):
            f, sep = self.cdim[c], self.cdim[c + 1]
            before, after = backsub_copies({"STEP_W": [f + sep], "STEP_F": [f]}, 0,
                                           self.les_timing, self.les)
            loops += before + backsub_loops(f, sep, self.les, name=f"kept{c}") + after
        keys = {k for c in range(first) for k in self.clusters[c]}
        loops += retract_loops([v for v in self.program.variables if v.key in keys],
                               self.plan.ops, self.plan.options.state_allocation)
        kept = Process("kept_backsub", "backsub", tuple(loops))
        f, s = self.cdim[first - 1], self.cdim[first]
        la, lm = self.les.add.latency, self.les.mul.latency
        reexpress = (Loop("reexpress", f * s * s + f * s, 1, lm + la).cycles
                     + self._retract(len(self.clusters[first]), "log").cycles)
        logs = sum(self._retract(len(self.clusters[c + 1]), "log").cycles for c in range(first))
        return [Term("kept_backsub", kept.cycles, 1, False,
                     f"back-substitution through the {first} kept conditionals (cond_backsub "
                     "with its copies) and the state update of their variables"),
                Term("kept_reexpress", reexpress, 1, True,
                     "assumed: the newest kept conditional re-expressed at its parent's new "
                     "estimate (S·J, d − S·Log) on one multiply-add lane, the Log as a "
                     "state-update pass"),
                Term("kept_logs", logs, 1, True,
                     "assumed: Log(x̄⁻¹x) of each kept conditional's parent, each priced as a "
                     "state-update pass (the design has no Log unit)")]

    def _transfer_terms(self, first, last, mode) -> list[Term]:
        from fgc_backends.cfamily.tables import factor_data_words

        p = self.program
        new = [i for i in range(len(p.factors)) if self.reach[i] == last]
        words = (sum(factor_data_words(p, p.factors[i].block) for i in new)
                 + sum(self.storage[k] for k in self.clusters[last]))
        # after the update: every cluster's conditional [R | S | d] (fixed-lag: the window's)
        held = range(first, last + 1) if mode == "fixed-lag" else range(last + 1)
        conds = sum(self.cdim[c] * (self.cdim[c] + (self.cdim[c + 1] if c < last else 0) + 1)
                    for c in held)
        state = sum(self.storage[k] for c in range(last + 1) for k in self.clusters[c])
        taus = sum(self.tau_rows[c] * (self.cdim[c + 1] + 1) for c in held if c < last)
        return [Term("transfer", math.ceil(words / self.rate), 1, True,
                     f"assumed: host → accelerator, the keyframe's {words} words (its new "
                     f"factors' data and initial values) at {self.rate} word(s) a cycle, "
                     "before the call (the top's copy-in is the setup term)"),
                Term("on_chip_state", 0, 1, True,
                     f"assumed: the state ({state} words), the conditionals ({conds}) and the "
                     f"factors passed up ({taus}) stay on chip between calls, no cycles")]

    # -- pieces --------------------------------------------------------------------------------
    def _instances(self, first, last) -> list[int]:
        return [i for i in range(len(self.program.factors))
                if self.entry[i] >= first and self.reach[i] <= last]

    def _factor_phase(self, mode, instances) -> Phase:
        procs = []
        small = small_blocks(self.program)
        for b in range(len(self.program.blocks)):
            if b in small[1:]:
                continue  # in the first small block type's shared loop
            loop = self.factor_loop[b, mode]
            blocks = small if b in small else (b,)
            count = sum(1 for i in instances if self.program.factors[i].block in blocks)
            name = "factor_small" if b in small else f"factor_{b}"
            procs.append(Process(f"{name}_{mode}", name, (
                Loop(loop.name, count, loop.ii, loop.depth),)))
        return Phase(f"factor_{mode}", False, tuple(procs))

    def _view(self, first, last, instances) -> SimpleNamespace:
        """The window as the plan's loop constructors read a Program: its variables (cluster
        order), the block types and its block instances."""
        p = self.program
        keys = {k for c in range(first, last + 1) for k in self.clusters[c]}
        return SimpleNamespace(variables=[v for v in p.variables if v.key in keys],
                               blocks=p.blocks, factors=[p.factors[i] for i in instances],
                               solver=p.solver)

    def _retract(self, variables, name) -> Loop:
        return kernel_loop(name, variables, "retract", self.timing)

    def _lm_phases(self, variables) -> tuple[Phase, ...]:
        """LM control (the plan's two phases) over the window's δ and x."""
        n_x = sum(v.storage_dim for v in variables)
        n_t = sum(v.dim for v in variables)
        return lm_control_phases(n_t, n_x, self.timing)

    def _linear_cycles(self, first, last, damping) -> int:
        return sum(phase_cycles(ph) for ph in self._linear_phases(first, last, damping))

    def window_tables(self, first, last) -> dict:
        """The emitted step and factor tables the plan's loop constructors read, for the window
        eliminated serially oldest first: step ``c - first`` is cluster c (frontal: its
        variables; separator: cluster c + 1's, none at the newest), its factors the window's
        block instances entering at c, its child step c − 1; at the oldest cluster of a window
        that starts after 0 the child is τ, the factor passed up from cluster first − 1 (an
        extra step at the end of the tables, ``tau_rows`` rows over cluster first). Row counts
        follow the tables' rule (``build_tables``: the damped rows count when the solver
        damps)."""
        p = self.program
        width = len(range(first, last + 1))
        inst = self._instances(first, last)
        f = [self.cdim[c] for c in range(first, last + 1)]
        w = [self.cdim[c] + (self.cdim[c + 1] if c < last else 0) for c in range(first, last + 1)]
        factors_of = [[n for n, i in enumerate(inst) if self.entry[i] == c]
                      for c in range(first, last + 1)]
        a_words = [p.blocks[p.factors[i].block].residual_dim
                   * (1 + sum(p.blocks[p.factors[i].block].variable_dims)) for i in inst]
        d = [sum(p.blocks[p.factors[i].block].variable_dims) for i in inst]
        children = [[s - 1] if s > 0 else ([width] if first > 0 else []) for s in range(width)]
        # τ as the oldest step's child (QR: tau_rows rows over cluster first; Cholesky: its
        # Hessian over cluster first, an update matrix)
        nf_rows = [0] * width + ([self.tau_rows[first - 1] if self.qr else self.cdim[first]]
                                 if first > 0 else [])
        for s in range(width):
            rows = (sum(p.blocks[p.factors[inst[n]].block].residual_dim for n in factors_of[s])
                    + sum(nf_rows[c] for c in children[s]) + f[s] * self.damping)
            nf_rows[s] = max(0, min(rows, w[s]) - f[s]) if self.qr else w[s] - f[s]
        if first > 0:
            f.append(self.cdim[first - 1])
            w.append(self.cdim[first - 1] + self.cdim[first])
        rows_of = [sum(p.blocks[p.factors[inst[n]].block].residual_dim for n in factors_of[s])
                   + sum(nf_rows[c] for c in children[s]) + f[s] * self.damping
                   for s in range(width)]
        return {"STEP_F": f, "STEP_W": w, "STEP_ROWS": rows_of, "STEP_NF_ROWS": nf_rows,
                "STEP_FACTOR_BEGIN": _offsets([len(x) for x in factors_of]),
                "STEP_FACTORS": [n for x in factors_of for n in x],
                "STEP_CHILD_BEGIN": _offsets([len(x) for x in children]),
                "STEP_CHILDREN": [c for x in children for c in x],
                "FACTOR_A_OFF": _offsets(a_words), "FACTOR_COLMAP_BEGIN": _offsets(d)}

    def _linear_phases(self, first, last, damping, instances=None) -> list[Phase]:
        """The window's linear solver as the plan's phases, one step per cluster, oldest first
        (the simulator's order; the serial schedule's levels): QR: per step its stack (√μ
        first, when damping), its ``qr_step`` and its commit; Cholesky: the HGC (``hgc_loops``
        over the window's instances), each step's assembly, the cascade, each step's store;
        then back-substitution newest first with its copies."""
        tables = self.window_tables(first, last)
        lt = self.les_timing
        inst = self._instances(first, last)
        steps = range(last - first + 1)
        phases = []
        if self.qr:
            for s in steps:
                c = first + s
                stack = [Process("root_mu", "qr_stack", (kernel_loop("root_mu", 1, "root", lt),))] \
                    if s == 0 and damping else []
                stack.append(Process(f"stack{s}", "qr_stack", tuple(stack_loops(
                    tables, s, self.options.units, self.max_w, damping, lt))))
                phases.append(Phase(f"qr_stack_level{s}", False, tuple(stack), linear=True))
                loops = qr_unit_loops(self.step_pattern(first, last, c, damping), self.cdim[c],
                                      self.options.units, self.les, name=f"s{c}",
                                      qr_rows=self.options.qr_rows)
                phases.append(Phase(f"qr_level{s}", True, (
                    Process(f"qr{s}_set0", "set0", tuple(loops)),), linear=True))
                phases.append(Phase(f"qr_commit_level{s}", False, (Process(
                    f"commit{s}", "qr_commit", tuple(commit_loops(tables, s, lt, False))),),
                    linear=True))
        else:
            view = self._view(first, last, inst)
            phases.append(Phase("hgc", False,
                                tuple(hgc_loops(view, lt, self.options.hgc_lanes, self.timing, {
                                    b: loop.ii for (b, mode), loop in self.factor_loop.items()
                                    if mode == "jacobian"})), linear=True))
            # as the batch plan's: the assembly beside the cascade (cholesky_overlap), the
            # window's clusters serially oldest first
            dims = {s: (self.cdim[first + s], self.cdim[first + s + 1] if first + s < last else 0)
                    for s in steps}
            # each step's pivot check where the kernel runs it (the batch plan's choice: its
            # last pass a process "check" when beside the next step, fgc_eliminate.h)
            beside = any(p.name == "check" for ph in self.plan.phases for p in ph.processes)
            phases += elimination_phases(tables, list(steps), dims, self.options.cpe, self.les, lt,
                                         self.options.cascade_lanes, beside)
        # back-substitution step by step, the state update fed by it beside (fgc_backsub.h's
        # back_substitute: backsub_retire retracts each cluster's variables as it is solved)
        # (the plan's slots on this serial chain: units/backsub.py's serial_slots)
        unit = "backsub" if self.qr else "trisolve"
        sizes, counts = [], []
        for s in reversed(steps):
            c = first + s
            sizes.append((self.cdim[c], self.cdim[c + 1] if c < last else 0))
            counts.append(len(self.clusters[c]))
        slots, sent = serial_slots(sizes, self.les, lt,
                                   root_in_commit(self.program, self.options),
                                   self.options.backsub_lanes)
        keys = {k for c in range(first, last + 1) for k in self.clusters[c]}
        ii, depth = retire_timing([v for v in self.program.variables if v.key in keys],
                                  self.plan.ops, max(self.cdim[first + s] for s in steps),
                                  self.plan.options.state_allocation)
        var_end: list[int] = []
        region = retire_region(slots, sent, counts, ii, depth, var_end)
        a = sum(lp.cycles for loops in slots for lp in loops)
        # with ``instances``: the cost at X_TRIAL beside them (back_substitute's trial_cost),
        # the window's instances fed its variables in the order they are retired
        cost = region
        if instances is not None and fed_by_backsub(self.program, self.options):
            order = [k for s in reversed(steps) for k in self.clusters[first + s]]
            from fgc_backends.hls.units.backsub import COLUMN_LANES
            slot = self.options.backsub_lanes != COLUMN_LANES  # (the plan's trial_var_end)
            loops = self._trial_loops(order, instances, var_end if slot else None)
            index = {v.key: i for i, v in enumerate(self.program.variables)}
            # (in two processes where that ends sooner: units/datapath.py's slot_split_loops)
            pos = {index[k]: i for i, k in enumerate(order)} \
                if any(lp.proc == 1 for lp in loops) else None
            cost = max(region, trial_end(loops, var_end, pos))
        phases.append(Phase("backsub", False, (
            Process("backsub_slots", unit, tuple(lp for loops in slots for lp in loops)),
            Process("backsub_retire", "state_update", (Loop("retire_tail", 1, 1, region - a),)
                    if region > a else ()),
            Process("trial_cost", "factor_cost", (Loop("cost_tail", 1, 1, cost - region),)
                    if cost > region else ())), linear=True))
        return phases

    def _trial_loops(self, keys, instances, var_end=None):
        """trial_cost's loops (units.datapath's trial_loops) for the window's ``instances``,
        its variables retired in the order of ``keys`` (``var_end``: when each is, which
        orders the loops and may split them in two processes, as the plan's slot design):
        each datapath's cost-mode loop as the plan's."""
        from fgc_backends.hls.plan.loops import _tables
        p = self.program
        index = {v.key: i for i, v in enumerate(p.variables)}
        small = small_blocks(p)
        from fgc_backends.hls.units.datapath import instance_accesses
        costs, accesses, data = {}, {}, {}
        for b in range(len(p.blocks)):
            if b in small[1:]:
                continue
            members = small if b in small else (b,)
            key = "small" if b in small else b
            loop = self.factor_loop[b, "cost"]
            costs[key] = ([i for i in instances if p.factors[i].block in members], loop.ii,
                          loop.depth)
            accesses[key] = sum(self._blocks[m].n_x_in for m in members)
            data[key] = max(instance_accesses(self._blocks[m], "cost")[1][0] for m in members)
        return trial_loops(p, [index[k] for k in keys], costs,
                           max(v.storage_dim for v in p.variables), accesses, var_end,
                           _tables(p) if var_end is not None else None, data)

    def step_pattern(self, first, last, c, damping) -> np.ndarray:
        """Structural rows × (frontal + separator) non-zeros of the window's step for cluster c:
        whitened rows of the block instances entering at c, then the factor passed up from
        cluster c − 1 (the previous step's new factor, or τ at the window's oldest cluster),
        upper trapezoidal over cluster c, then with ``damping`` √μ rows on the frontal columns
        (the row order of ``stacked_pattern``, which the emitted tables follow)."""
        p = self.program
        keys = list(self.clusters[c]) + (list(self.clusters[c + 1]) if c < last else [])
        col, start = {}, 0
        for key in keys:
            col[key] = start
            start += self.dims[key]
        width, f = start, self.cdim[c]
        rows = []
        for i in range(len(p.factors)):
            if self.entry[i] != c or self.reach[i] > last:
                continue
            spec = p.factors[i]
            blk = p.blocks[spec.block]
            out = np.zeros((blk.residual_dim, width), dtype=bool)
            for key, mask in zip(spec.keys, whitened_pattern(blk), strict=True):
                out[:, col[key]:col[key] + self.dims[key]] |= mask
            rows.append(out)
        if c > 0:  # a child's new factor (c > first) or τ (c == first > 0)
            carried = self.tau_rows[c - 1]
            block = np.zeros((carried, width), dtype=bool)
            for i in range(carried):
                block[i, i:f] = True
            rows.append(block)
        if damping:
            rows.append(np.eye(f, width, dtype=bool))
        return np.vstack(rows) if rows else np.zeros((0, width), dtype=bool)

    def _prior_rows_cycles(self, first) -> int:
        rows, n = self.tau_rows[first - 1], self.cdim[first]
        la, lm = self.ops.add.latency, self.ops.mul.latency
        mac = Loop("prior_rows", rows * n * (n + 1), 1, lm + la)
        log = self._retract(len(self.clusters[first]), "log")
        return 2 * (mac.cycles + log.cycles)  # the Jacobian pass and the cost pass


def _offsets(sizes) -> list[int]:
    out = [0]
    for n in sizes:
        out.append(out[-1] + n)
    return out
