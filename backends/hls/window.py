"""The fixed-lag window on chip (issue 19): the accelerator keeps the window between calls and
takes one keyframe's measurements per call.

The design is the batch accelerator of a *template* window (:class:`~fgc.compiler.stream.
WindowTemplate`: the chain's first W + 1 keyframes, a ``MarginalPrior…`` factor on each) with a
second top function, ``<name>_stream`` (accel.cpp.jinja's stream section), that owns the
window's state in the accelerator's memories (``X``: the slots' variables, ``DATA_BUF``: every
factor's words, the marginal prior τ among them) and runs one update a call:

1. keyframe j enters slot m = min(j, W); once the window is full (j > W) every slot first moves
   down one (``stream_shift``: slot s takes slot s + 1's variables and the words of the factor one
   keyframe later, a factor without one there gets zero square-root information; slot 0's prior
   takes slot 1's, which is τ);
2. the call's inputs — keyframe j's initial storage and the words of the factors that end at it
   (``keyframe_words``: measurements and noise, a factor the stream lacks with zero square-root
   information) and of its slot's prior (its linearisation point, zero information) — are
   written to their slot (``stream_in``, the ``NEW_DEST`` table);
3. LM on the window (``optimize``, the batch design's units);
4. window full (m = W): keyframe j − W leaves. The window is linearised at its optimum and slot 0's
   elimination step is run once more at μ = 0 on unit set 0 (``marginalize``); the new factor it
   passes to slot 1 ([A | b], upper triangular: the QR unit's rows) becomes τ, signed to a
   positive diagonal, its mean A⁻¹b by back-substitution, written into slot 1's prior with slot 1's
   estimate as the linearisation point (a singular marginal is reported, not written).

This is the native stream's update (:class:`~fgc_backends.cfamily.stream.FixedLagDriver`) with
the host's window assembly and NumPy marginalisation replaced by the accelerator's own memories
and units; held slots during the first W updates keep their reset values under a unit prior, as
there. :class:`WindowLayout` computes the tables the stream section reads and the words of each
call; the host driver is :class:`fgc_backends.hls.streaming.OnChipFixedLagStream`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fgc.compiler.stream import WindowTemplate
from fgc.errors import FgcError
from fgc.ir.datafile import factor_words
from fgc_backends.hls.target import DEFAULT_PART

KEEP, ZERO = -1, -2  # shift codes besides a source word: keep the word, write zero
# DATA_BUF's cyclic partitions the update's start may take (its shift's and keyframe's words in
# one loop, fgc_stream.h's start_data_task): the fewest iterations, then the fewest banks; per
# keyframe words an iteration (the data port's words a beat: two, a 64-bit port of floats, can
# use eight banks)
START_BANKS = {1: (2, 4), 2: (2, 4, 8)}


class OnChipWindowError(FgcError):
    """The stream cannot run on the on-chip window (a Cholesky design, a slot whose
    elimination does not pass a whole prior to the next, a stream whose factors do not repeat
    keyframe by keyframe)."""


@dataclass(frozen=True)
class Member:
    """One factor of the template in the data buffer: template factor ``t`` (graph factors
    first, then the slots' priors), its words ``start`` … ``start + words``, its last
    ``noise`` words the noise parameters and the robust loss; ``slots``: its keyframes' slots
    (a prior: its slot); ``cells``: (slot, position) per variable (None for a prior)."""

    t: int
    start: int
    words: int
    noise: int
    slots: tuple[int, ...]
    cells: tuple | None
    kind: str
    prior: bool

    @property
    def hi(self) -> int:
        return max(self.slots)


class WindowLayout(WindowTemplate):
    """The template of a fixed-lag window of ``window`` keyframes (W + 1 slots) and the tables
    of its on-chip stream (module docstring)."""

    def __init__(self, graph, program, window: int, kept: bool = False, batch=None,
                 sweep=None):
        if isinstance(window, bool) or not isinstance(window, int) or window < 1:
            raise OnChipWindowError(f"the fixed-lag window must be a positive number of "
                                    f"keyframes, got {window!r}")
        super().__init__(graph, program, window + 1)
        first = set(program.schedule.clusters[0])
        if self.size > 1 and not any(set(st.frontals) == first
                                     for st in self.template.schedule.steps):
            # a short chain's two-ended schedule may eliminate slot 0 with its neighbour in one
            # step: the serial order gives it its own (its marginal is that step's new factor)
            super().__init__(graph, program, window + 1, ordering="serial")
        self.window = window
        # incremental mode: every keyframe that leaves the window is kept as its conditional
        self.kept = len(program.schedule.clusters) if kept else 0
        self.batch = batch  # the batch kernel's BatchLayout (incremental plans with batch steps)
        # or the batch steps as sweeps through this window (one set of units): their keyframes
        self.sweep = tuple(sweep) if sweep else None
        if self.sweep is not None and (batch is not None or not kept):
            raise OnChipWindowError("internal error: batch steps as sweeps need the kept net and "
                                    "no batch kernel")
        _check_qr(self.template, program)
        from fgc_backends.hls.plan import _tables

        tables = _tables(self.template)
        index = self._read_layout(tables)
        self._shift_tables()
        self._leaf(tables, index)

    def _read_layout(self, tables) -> dict:
        """Where each slot's variables and each factor's words lie in the template's memories:
        ``slot_x`` (slot s's storage words in cluster order: one keyframe's record order),
        ``members``, ``new_dest`` (per slot the data words a keyframe entering it brings: its
        factors ending there and its prior, ascending), the sizes. Returns each variable's
        index by key."""
        t = self.template
        x_off = tables["VAR_X_OFF"]
        index = {v.key: i for i, v in enumerate(t.variables)}
        clusters = self.program.schedule.clusters
        self.slot_x = []
        for s in range(self.size):
            words = []
            for k in clusters[s]:
                i = index[k]
                words += range(x_off[i], x_off[i + 1])
            self.slot_x.append(words)
        self.kf_words = len(self.slot_x[0])
        self.kf_dim = self.prior_types[0][1]
        self.members = self._members(tables["FACTOR_DATA_OFF"])
        self.n_x, self.n_data = x_off[-1], tables["FACTOR_DATA_OFF"][-1]
        self.new_dest = []
        for s in range(self.size):
            words = []
            for m in self.members:
                if m.hi == s:
                    words += range(m.start, m.start + m.words)
            self.new_dest.append(sorted(words))
        return index

    # -- where each factor's words lie -----------------------------------------------------
    def _members(self, data_off) -> list[Member]:
        t = self.template
        n_template = len(self.template_factors)
        out = []
        for spec, start in zip(t.factors, data_off, strict=False):
            block = t.blocks[spec.block]
            pos = start
            for member, ti in zip(block.members, spec.factors, strict=True):
                if ti < n_template:
                    f = self.template_factors[ti]
                    parts = factor_words(f.measured, f.noise, member)
                    kind, cells = self.signatures[ti]
                    slots = tuple(c for c, _ in cells)
                    prior = False
                else:
                    slot = ti - n_template
                    dim = self.prior_types[slot][1]
                    parts = [np.zeros(self.kf_words + dim), np.zeros(dim * (dim + 1) // 2),
                             np.zeros(2)]
                    kind, cells, slots, prior = "prior", None, (slot,), True
                words = sum(p.size for p in parts)
                out.append(Member(ti, pos, words, parts[-1].size + parts[-2].size, slots, cells,
                                  kind, prior))
                pos += words
        if pos_total(out) != data_off[-1]:
            raise OnChipWindowError("internal error: the template's factor words are not laid "
                                    "out as the data file's")
        return out

    def _shift_tables(self) -> None:
        last = self.size - 1
        x_shift = [KEEP] * self.n_x
        for s in range(last):
            for dst, src in zip(self.slot_x[s], self.slot_x[s + 1], strict=True):
                x_shift[dst] = src
        data_shift = [KEEP] * self.n_data
        by_cells = {(m.kind, m.cells): i for i, m in enumerate(self.members) if not m.prior}
        self.prior_of = {m.slots[0]: m for m in self.members if m.prior}
        # per member the member a shift moves into it (the same factor one keyframe on; a
        # prior: the next slot's), None for the newest slot's (the keyframe writes them) and a
        # factor with no counterpart one keyframe on
        self.next_member = [None] * len(self.members)
        for i, m in enumerate(self.members):
            if m.hi == last:
                continue
            if m.prior:
                self.next_member[i] = self.members.index(self.prior_of[m.slots[0] + 1])
            else:
                self.next_member[i] = by_cells.get((m.kind, tuple((c + 1, p)
                                                                   for c, p in m.cells)))
        for m, nxt in zip(self.members, self.next_member, strict=True):
            if m.hi == last:
                continue  # written by the keyframe that enters the newest slot
            source = None if nxt is None else self.members[nxt]
            if source is None:  # no such factor one keyframe on: zero square-root information
                for w in range(m.start + m.words - m.noise, m.start + m.words):
                    data_shift[w] = ZERO
                continue
            if source.words != m.words or source.noise != m.noise:
                raise OnChipWindowError(f"internal error: a {m.kind} factor is laid out in "
                                        f"{m.words} words on slots {m.slots} and "
                                        f"{source.words} one keyframe on")
            for k in range(m.words):
                data_shift[m.start + k] = source.start + k
        self.x_moves, self.data_moves = _moves(x_shift), _moves(data_shift)
        # the newest slot's prior after its point (its mean, square-root information and
        # robust words): zero on every call (a keyframe enters with no prior information,
        # _slot_words), so once the window is full the start writes them zero itself and the
        # call brings the other words (kf_call, in NEW_DEST's order); while the window fills
        # the call brings them all (the reset's priors are unit ones)
        prior = self.prior_of[last]
        self.kf_zero = list(range(prior.start + self.kf_words, prior.start + prior.words))
        zero = set(self.kf_zero)
        self.kf_call = [w for w in self.new_dest[last] if w not in zero]
        if len(self.kf_call) + len(zero) != len(self.new_dest[last]) or any(
                dst in zero for dst, _ in self.data_moves):
            raise OnChipWindowError("internal error: the newest slot's prior is not among its "
                                    "keyframe's words, or a shift writes it")
        self._start_tables()

    def _start_tables(self) -> None:
        """The update's start on DATA_BUF once the window is full (the shift, then the keyframe
        into the newest slot) as one loop over DATA_BUF in ``start_banks`` cyclic banks: per
        iteration each bank reads one word and writes one (its two ports), the written word
        read this iteration from any bank, one of the keyframe's next words or zero.
        ``start_rows``: the call's keyframe (its input read a word a cycle: one keyframe word
        an iteration); ``sweep_rows`` (batch steps as sweeps): a sweep pass's, its keyframe
        from its row of SWEEP_WORDS (two read ports: two an iteration). Per iteration per bank
        (word read or None, word written or None, its source: a bank, ``nb`` / ``nb + 1`` the
        iteration's first / second keyframe word, None zero). Checked against the moves one
        after another (:func:`_check_start`). :meth:`start_plan` gives the same for a ``data``
        port of two words a beat."""
        self._start_plans = {}
        self.start_banks, self.start_rows, self.sweep_rows = self.start_plan(1)

    def start_plan(self, words: int = 1) -> tuple[int, list, list]:
        """(banks, start rows, sweep rows) of the update's start (:meth:`_start_tables`) with
        the call's keyframe words ``words`` an iteration (the ``data`` port's words a beat,
        ``HlsConfig.data_words``): the banks of :data:`START_BANKS` for ``words`` with the
        fewest iterations, then the fewest banks; a sweep pass's rows (two words an iteration
        from SWEEP_WORDS) over the same banks."""
        if words in self._start_plans:
            return self._start_plans[words]
        if words not in START_BANKS:
            raise OnChipWindowError(f"internal error: the update's start takes 1 or 2 keyframe "
                                    f"words an iteration, not {words}")
        if self.size < 2:
            self._start_plans[words] = (1, [], [])
            return self._start_plans[words]
        # the shift's moves, then the newest prior's tail zeroed; the call's words
        moves, kf = self.start_moves(), self.kf_call
        best = None
        for nb in START_BANKS[words]:
            rows = _start_schedule(moves, kf, nb, words)
            if best is None or len(rows) < len(best[1]):
                best = (nb, rows)
        _check_start(moves, kf, self.n_data, *best)
        sweep = []
        if self.sweep is not None:
            sweep = _start_schedule(moves, kf, best[0], 2)
            _check_start(moves, kf, self.n_data, best[0], sweep)
        self._start_plans[words] = (*best, sweep)
        return self._start_plans[words]

    def start_moves(self) -> list[tuple[int, int]]:
        """The update start's moves on DATA_BUF once the window is full: the shift's, then the
        newest slot's prior tail zeroed (each after the shift's move that reads it)."""
        return list(self.data_moves) + [(w, ZERO) for w in self.kf_zero]

    def start_context(self, words: int = 1) -> dict:
        """accel.cpp.jinja's START_OPS (and START_OPS_SWEEP) tables (:meth:`_start_tables`):
        per iteration and bank one word, the row read (0: none), the row written plus one (0:
        none) and the written word's source, ``row_bits`` bits each but the source's (a bank,
        ``nb + q`` the iteration's q-th keyframe word, q < max(2, ``words``), ``nb + max(2,
        ``words``)`` zero); ``words``: the call's keyframe words an iteration (the ``data``
        port's words a beat)."""
        nb, start_rows, sweep_rows = self.start_plan(words)
        bits = max(1, ((self.n_data - 1) // nb + 1).bit_length())
        zero = nb + max(2, words)

        def ops(rows):
            return [(0 if r is None else r // nb) | (0 if w is None else w // nb + 1) << bits
                    | (zero if s is None else s) << 2 * bits
                    for row in rows for r, w, s in row]

        return {"banks": nb, "iterations": len(start_rows), "row_bits": bits,
                "ops": ops(start_rows), "sweep_iterations": len(sweep_rows),
                "sweep_ops": ops(sweep_rows), "words": words}

    def _leaf(self, tables, index) -> None:
        """The elimination step of slot 0: its frontal variables slot 0's, its separator slot
        1's in the prior's tangent order, passing at least a whole prior's rows."""
        t = self.template
        clusters = self.program.schedule.clusters
        self.leaf_step = None
        if self.size < 2:
            return
        self.leaf_step = s = _slot_step(t, clusters, tables, index, 0, self.size,
                                        "the marginal cannot be read off the QR unit")
        rows = tables["STEP_NF_ROWS"][s]
        if rows < self.kf_dim:
            raise OnChipWindowError(f"slot 0's elimination passes {rows} rows to slot 1, fewer "
                                    f"than its {self.kf_dim} tangent directions: the marginal "
                                    "prior would be singular")

    def leaf_factors(self) -> frozenset:
        """The template's factor instances whose rows slot 0's step stacks (the instances
        entering the leaf step): all a marginal needs linearised, since its step reads no other
        rows of AB (``linearize_all(X, true)``, fgc_stream.h's ``CFG::linearize``). Empty
        without a marginal."""
        from fgc_backends.cost.structure import entering_blocks

        if self.leaf_step is None:
            return frozenset()
        t = self.template
        return frozenset(entering_blocks(t, t.schedule.steps[self.leaf_step]))

    @property
    def spec(self) -> bool:
        """Whether the update forms the leaving keyframe's τ and kept conditional beside its
        back-substitution (the one-step policy: the store is the solve's own factorisation
        whenever its step is taken; fgc_stream.h's ``spec_tau_task`` and ``spec_keep_task``)."""
        return (self.leaf_step is not None and self.size == self.window + 1
                and self.template.solver.one_step)

    def leaf_gone(self) -> frozenset:
        """The leaf step's factor instances that hold nothing once keyframe 0 has left the
        window: every member's rows zero (:meth:`zero_factors`, τ written) at every keyframe
        from ``size`` on (keyframe 0's own priors, say). A marginal from then on neither
        linearises nor stacks them (``live``), so slot 0's step reflects only the rows that
        can be non-zero. Empty unless the rows left still cover the step's conditional and the
        factor it passes, and the stream reaches past the first marginal."""
        from fgc_backends.cost.structure import entering_blocks

        if self.leaf_step is None or self.size != self.window + 1:
            return frozenset()
        t = self.template
        st = t.schedule.steps[self.leaf_step]
        n_kf = len(self.program.schedule.clusters)
        if n_kf <= self.size:
            return frozenset()
        zero = [self.zero_factors(kf, True) for kf in range(self.size, n_kf)]
        gone = frozenset(i for i in entering_blocks(t, st)
                         if all(ti in z for z in zero for ti in t.factors[i].factors))
        rows = sum(t.blocks[t.factors[i].block].residual_dim for i in entering_blocks(t, st)
                   if i not in gone)
        rows += sum(t.schedule.steps[c].new_factor_rows for c in st.children)
        if rows < st.frontal_dim + st.new_factor_rows:
            return frozenset()
        return gone

    def leaf_skip(self) -> tuple[int, int]:
        """The leaf step's stack once keyframe 0 has left (:meth:`leaf_gone`): a mask of its
        factor list's entries left out (bit k: the k-th of STEP_FACTORS, the first 32) and the
        rows stacked."""
        t = self.template
        st = t.schedule.steps[self.leaf_step]
        gone = self.leaf_gone()
        from fgc_backends.hls.plan import _tables

        tables = _tables(t)
        fb = tables["STEP_FACTOR_BEGIN"]
        entries = tables["STEP_FACTORS"][fb[st.index]:fb[st.index + 1]]
        mask = 0
        rows = tables["STEP_ROWS"][st.index]
        for k, i in enumerate(entries):  # (factor instances, as qr_stack reads them)
            if k < 32 and i in gone:
                mask |= 1 << k
                rows -= t.blocks[t.factors[i].block].residual_dim
        return mask, rows

    def leaf_skipped(self) -> frozenset:
        """The factor instances the leaf step's live stack leaves out (:meth:`leaf_skip`'s
        mask: those of :meth:`leaf_gone` among the first 32 of its factor list)."""
        gone = self.leaf_gone()
        if not gone:
            return frozenset()
        from fgc_backends.hls.plan import _tables

        tables = _tables(self.template)
        st = self.template.schedule.steps[self.leaf_step]
        fb = tables["STEP_FACTOR_BEGIN"]
        entries = tables["STEP_FACTORS"][fb[st.index]:fb[st.index + 1]]
        return frozenset(i for k, i in enumerate(entries) if k < 32 and i in gone)

    # -- what the emitter places ---------------------------------------------------------------
    def context(self, linear_cxx: str, part: str = DEFAULT_PART, data_words: int = 1) -> dict:
        """The stream section's constants and tables (accel.h.jinja / accel.cpp.jinja);
        ``linear_cxx``: the linear solver's scalar (τ's singularity threshold); ``data_words``:
        the ``data`` port's words a beat (``HlsConfig.data_words``)."""
        return {"window": self.window, "slots": self.size, "kf_x": self.kf_words,
                "kf_t": self.kf_dim,
                "leaf_step": self.leaf_step if self.leaf_step is not None else 0,
                "marginal": self.leaf_step is not None and self.size == self.window + 1,
                "spec": self.spec,
                "prior1": self.prior_of[1].start if self.size > 1 else 0,
                # as_prior's 1e-12 in double; float's resolution is 1e-7
                "singular": "1e-12" if linear_cxx == "double" else "1e-5",
                "x_moves": [w for pair in self.x_moves for w in pair],
                "data_moves": [w for pair in self.data_moves for w in pair],
                "slot_x": [w for s in self.slot_x for w in s],
                "new_dest": [w for d in self.new_dest for w in d],
                "new_begin": self.new_begin(),
                "max_new": max(len(d) for d in self.new_dest),
                "full_words": len(self.kf_call),
                "start": self.start_context(data_words), "data_words": data_words,
                "role": "window", "in_x": self.n_x, "in_data": self.n_data,
                **self._kept_context(linear_cxx, part), **self._batch_context(),
                "sweep": None if self.sweep is None else {
                    "slots": self.sweep_slots,
                    "is_batch": [int(j in self.sweep) for j in range(self.kept)]}}

    @property
    def batch_keyframes(self) -> tuple[int, ...]:
        """The plan's batch steps, on the batch kernel or as sweeps (none: ())."""
        if self.sweep is not None:
            return self.sweep
        return self.batch.keyframes if self.batch is not None else ()

    @property
    def sweep_slots(self) -> int:
        """Keyframes the sweep design keeps as they came: 0 … the last batch step."""
        return max(self.sweep) + 1 if self.sweep else 0

    def _batch_context(self) -> dict:
        """What the window's stream top needs of the batch kernel: its names, sizes and the
        batch keyframes (a ROM flag per keyframe)."""
        b = self.batch
        if b is None:
            return {"batch": None}
        keyframes = set(b.keyframes)
        in_x = max(self.n_x, b.n_x)
        in_data = max(self.n_data, b.n_data, max(len(d) for d in self.new_dest)
                      + max(len(d) for d in b.new_dest))
        return {"in_x": in_x, "in_data": in_data,
                "batch": {"name": b.project, "slots": b.size, "n_x": b.n_x,
                          "n_data": b.n_data, "new_begin": b.new_begin(),
                          "is_batch": [int(j in keyframes) for j in range(self.kept)]}}

    def _kept_context(self, linear_cxx: str, part: str) -> dict:
        """The kept Bayes net's constants (incremental mode): the Log kernels, slot 0's
        variables by kind and offset, the re-expression's central-difference step."""
        if not self.kept:
            return {"kept": 0}
        from fgc_backends.cfamily.printer import HlsCodePrinter

        locals_, kf_vars = self._kf_vars()
        eps = np.finfo(np.float64 if linear_cxx == "double" else np.float32).eps
        return {"kept": self.kept, "locals": locals_, "kf_vars": kf_vars,
                "flat_s": self.vector_words(), "block_t": self.block_offsets(),
                "block_dim": self.block_dims(),
                "jacobian_step": HlsCodePrinter({}).literal(float(np.sqrt(eps) * 10)),
                "mv_ii": self.matvec_ii(linear_cxx, part)}

    def _kf_vars(self) -> tuple[list, list[dict]]:
        """The template's Log kernels and slot 0's variables (kind, vector or not, tangent
        dimension, storage and tangent offsets in the keyframe)."""
        from fgc_backends.cfamily.retract import local_kinds

        t = self.template
        locals_ = local_kinds(t)
        kind_of = {k.type_name: k for k in locals_}
        by_key = {v.key: v for v in t.variables}
        kf_vars, s_off, t_off = [], 0, 0
        for key in self.program.schedule.clusters[0]:
            v = by_key[key]
            k = kind_of[v.type_name]
            kf_vars.append({"kind": k.kind, "flat": k.flat, "dim": v.dim, "s": s_off,
                            "t": t_off})
            s_off += v.storage_dim
            t_off += v.dim
        return locals_, kf_vars

    def vector_words(self) -> list[int]:
        """Per tangent direction of a keyframe its storage word if its variable is a vector
        (retraction x + δ, Log b − a: the re-expression's central differences need no datapath
        pass for it, fgc_stream.h), else −1."""
        _, kf_vars = self._kf_vars()
        out = [-1] * self.kf_dim
        for v in kf_vars:
            if v["flat"]:
                for i in range(v["dim"]):
                    out[v["t"] + i] = v["s"] + i
        return out

    def block_offsets(self) -> list[int]:
        """Per tangent direction of a keyframe the first tangent direction of its variable: the
        Jacobian of a keyframe's Log is block-diagonal by variable (a variable's Log moves with
        its own directions only), so the re-expression's S·J column q sums over its variable's
        directions alone (fgc_stream.h; :meth:`block_dims` their count)."""
        _, kf_vars = self._kf_vars()
        return [v["t"] for v in kf_vars for _ in range(v["dim"])]

    def block_dims(self) -> list[int]:
        """Per tangent direction of a keyframe its variable's tangent dimension."""
        _, kf_vars = self._kf_vars()
        return [v["dim"] for v in kf_vars for _ in range(v["dim"])]

    def matvec_ii(self, linear_cxx: str, part: str = DEFAULT_PART) -> int:
        """The kept net's matrix-vector loop's II: a row's sum returns to the adder every
        KF_T iterations, so ceil(multiply-add depth of L / KF_T)."""
        from fgc_backends.hls.plan import kernel_timing
        from fgc_backends.hls.target import target_of

        ops = target_of(part, self.program.solver.clock_mhz).ops(
            "float32" if linear_cxx == "float" else "float64")
        depth = kernel_timing(ops)["acc"][1]
        return max(1, -(-depth // self.kf_dim))

    # -- the words of the calls ------------------------------------------------------------
    def reset_words(self, estimate: dict) -> tuple[np.ndarray, np.ndarray]:
        """The reset call's (x, data): the template's slots at ``estimate`` (keyframes 0 … W),
        every factor with zero square-root information, every prior a unit one at its slot's
        value (held)."""
        clusters = self.program.schedule.clusters
        x = np.zeros(self.n_x)
        for s in range(self.size):
            x[self.slot_x[s]] = np.concatenate([estimate[k] for k in clusters[s]])
        data = np.zeros(self.n_data)
        members = self._member_objects()
        for m in self.members:
            if m.prior:
                s = m.slots[0]
                words = np.concatenate([x[self.slot_x[s]], self._held[s]])
            else:
                words = self._zeroed(m.t, members[m.t])
            data[m.start:m.start + m.words] = words
        return x, data

    def new_begin(self) -> list[int]:
        """Where each slot's run of ``new_dest`` begins (and the last ends)."""
        return np.cumsum([0] + [len(d) for d in self.new_dest]).tolist()

    def keyframe_words(self, j: int, x_new: np.ndarray) -> tuple[int, np.ndarray]:
        """(slot, data words) of keyframe j's call (``x_new``: its initial storage, cluster
        order): its slot's factors and prior in ``NEW_DEST`` order."""
        m = min(j, self.size - 1)
        words = self._slot_words(m, j - m, x_new)
        if j >= self.size:  # the window full: the newest prior's tail is the start's (zero)
            keep = set(self.kf_call)
            words = words[[k for k, w in enumerate(self.new_dest[m]) if w in keep]]
        return m, words

    def _slot_words(self, m: int, first: int, x_new: np.ndarray) -> np.ndarray:
        """The data words a keyframe brings into slot m when slot 0 holds keyframe ``first``:
        the graph factor of each factor ending at m (zero square-root information where the
        stream has none) and its prior (linearised at ``x_new``, no information)."""
        members = self._member_objects()
        buf = np.zeros(self.n_data)
        for mem in self.members:
            if mem.hi != m:
                continue
            if mem.prior:
                words = np.concatenate([x_new, self._unused[m]])
            else:
                index = self.by_signature.get((mem.kind, tuple((c + first, p)
                                                               for c, p in mem.cells)))
                words = (self._zeroed(mem.t, members[mem.t]) if index is None
                         else self._factor(index, members[mem.t]))
            buf[mem.start:mem.start + mem.words] = words
        return buf[self.new_dest[m]]

    def _member_objects(self) -> dict:
        if not hasattr(self, "_by_t"):
            t = self.template
            self._by_t = {ti: member for spec in t.factors
                          for member, ti in zip(t.blocks[spec.block].members, spec.factors,
                                                strict=True)}
        return self._by_t

    def zero_factors(self, keyframe: int, marginal: bool) -> frozenset:
        """The template factors (indices ``Member.t``) whose rows are zero during keyframe
        ``keyframe``'s solve: graph factors the window does not hold (not arrived, or gone
        with no counterpart one keyframe on) and the priors without information (every slot's
        but slot 0's once τ is there — ``marginal``: the design writes τ — and the held slots'
        during the first W updates)."""
        held_by = self.__dict__.setdefault("_held_by", [])
        while len(held_by) <= keyframe:
            held_by.append(self.check_holds(held_by[-1] if held_by else None, len(held_by)))
        held = held_by[keyframe]
        m = min(keyframe, self.size - 1)
        zero = {mem.t for mem, h in zip(self.members, held, strict=True)
                if not mem.prior and h is None}
        for mem in self.members:
            if not mem.prior:
                continue
            s = mem.slots[0]
            tau = s == 0 and keyframe >= self.size and marginal
            if s <= m and not tau:
                zero.add(mem.t)  # unused: zero square-root information (held slots: unit)
        return frozenset(zero)

    def unit_factors(self, keyframe: int) -> frozenset:
        """The priors holding a slot during keyframe ``keyframe``'s solve (the slots past it
        while the window fills): R = I at the slot's reset value, whitened rows the
        identity."""
        m = min(keyframe, self.size - 1)
        return frozenset(mem.t for mem in self.members if mem.prior and mem.slots[0] > m)

    def check_holds(self, held: list, j: int) -> list:
        """The graph factor each template factor holds after keyframe j's call (``held``: as
        after the previous call, None before the first), shifted and filled as the chip does;
        :class:`OnChipWindowError` if a graph factor inside the window j − W … j is not held
        (the stream's factors do not repeat keyframe by keyframe)."""
        last = self.size - 1
        m = min(j, last)
        first = j - m
        # (a new list: zero_factors keeps every keyframe's, which the next must not change)
        held = [None] * len(self.members) if held is None else list(held)
        if j > last:
            held = [None if mem.prior or src is None else held[src]
                    for mem, src in zip(self.members, self.next_member, strict=True)]
        for i, mem in enumerate(self.members):
            if not mem.prior and mem.hi == m:
                held[i] = self.by_signature.get((mem.kind, tuple((c + first, p)
                                                                 for c, p in mem.cells)))
        inside = set(np.flatnonzero((self.span_lo >= first) & (self.span_hi <= j)).tolist())
        have = {h for h in held if h is not None}
        if inside != have:
            missing = sorted(inside - have)
            f = self.graph.factors[missing[0]] if missing else None
            what = (f"the {f.type.name} factor on {[str(k) for k in f.keys]}" if f is not None
                    else "a factor outside it")
            raise OnChipWindowError(f"keyframes {first} … {j}: the on-chip window does not hold "
                                    f"{what}: the stream's factors do not repeat keyframe by "
                                    "keyframe as the template's")
        return held


class BatchLayout(WindowTemplate):
    """The batch kernel of the on-chip incremental design: a template of the chain's first
    ``size`` keyframes (the last batch step's), eliminated serially oldest first so that each
    keyframe's step leaves its conditional on the next (the kept net's form) and passes the
    next its τ; slot c holds keyframe c (no shift). ``keyframes``: the plan's batch steps."""

    def __init__(self, graph, program, size: int, keyframes):
        from fgc_backends.cfamily.names import identifier

        super().__init__(graph, program, size, ordering="serial")
        self.window = size - 1
        self.keyframes = tuple(keyframes)
        t = self.template
        _check_qr(t, program)
        from fgc_backends.hls.plan import _tables

        tables = _tables(t)
        index = self._read_layout(tables)
        clusters = program.schedule.clusters
        # each slot's elimination step: frontal the slot, separator the next slot, in order
        self.slot_step = [_slot_step(t, clusters, tables, index, s, self.size,
                                     "the batch kernel cannot keep its conditional")
                          for s in range(self.size)]
        self.project = identifier(t.name)

    # the factor words and the reset are laid out as the window's
    _read_layout = WindowLayout._read_layout
    _members = WindowLayout._members
    _member_objects = WindowLayout._member_objects
    _slot_words = WindowLayout._slot_words
    reset_words = WindowLayout.reset_words
    new_begin = WindowLayout.new_begin

    def context(self, linear_cxx: str, part: str = DEFAULT_PART) -> dict:
        """The batch kernel's section (accel.cpp.jinja, role "batch")."""
        return {"role": "batch", "data_words": 1, "slots": self.size, "kf_x": self.kf_words,
                "kf_t": self.kf_dim, "slot_x": [w for s in self.slot_x for w in s],
                "new_dest": [w for d in self.new_dest for w in d],
                "new_begin": self.new_begin(), "slot_step": self.slot_step,
                "max_new": max(len(d) for d in self.new_dest), "kept": 0, "batch": None,
                "sweep": None, "marginal": False, "spec": False}

    def keyframe_words(self, j: int, x_new: np.ndarray) -> np.ndarray:
        """Keyframe j's words for slot j (j < size)."""
        return self._slot_words(j, 0, x_new)

    def zero_factors(self, j: int) -> frozenset:
        """The batch template's factors with zero rows at a batch step at keyframe j: factors
        not arrived (past j) or absent from the stream, and every prior of slots 0 … j (no
        information; the slots past j hold unit priors)."""
        zero = set()
        for mem in self.members:
            if mem.prior:
                if mem.slots[0] <= j:
                    zero.add(mem.t)
            elif mem.hi > j or self.by_signature.get((mem.kind, mem.cells)) is None:
                zero.add(mem.t)
        return frozenset(zero)

    def unit_factors(self, j: int) -> frozenset:
        """The priors holding the slots past j at a batch step at keyframe j (R = I at the
        slot's reset value, whitened rows the identity)."""
        return frozenset(mem.t for mem in self.members if mem.prior and mem.slots[0] > j)


def _check_qr(t, program) -> None:
    if t.solver.linear != "qr":
        raise OnChipWindowError(
            "the on-chip design marginalises and keeps conditionals with the QR unit's rows "
            f"(paper A's design); {program.name!r} is compiled for Cholesky: compile it with "
            "--linear qr")


def _slot_step(t, clusters, tables, index, s: int, size: int, why: str) -> int:
    """The elimination step of template ``t`` (``size`` slots) whose frontal variables are slot
    s's and whose separator is slot s + 1's, in their tangent order (none for the last slot):
    its index, or :class:`OnChipWindowError` naming ``why`` it is needed."""
    step = next((st for st in t.schedule.steps if set(st.frontals) == set(clusters[s])), None)
    if step is None:
        raise OnChipWindowError(f"the template's schedule does not eliminate slot {s} in a "
                                f"step of its own: {why}")
    t_off, begin = tables["VAR_T_OFF"], tables["STEP_COL_BEGIN"]
    cols = tables["STEP_COL"][begin[step.index]:begin[step.index + 1]]
    want = ([c for k in clusters[s + 1] for c in range(t_off[index[k]], t_off[index[k] + 1])]
            if s + 1 < size else [])
    if list(cols[tables["STEP_F"][step.index]:]) != want:
        raise OnChipWindowError(f"the template's step of slot {s} is not conditioned on slot "
                                f"{s + 1}'s variables alone, in their order: {why}")
    return step.index


def _moves(shift: list[int]) -> list[tuple[int, int]]:
    """The shift's (target, source) pairs (source ZERO: write zero) in an order that reads
    every word before it is overwritten: each word is the source of at most one target (slot
    s + 1 to slot s), so the pairs form chains, each run from the target whose own word no
    one reads."""
    read_by = {src: dst for dst, src in enumerate(shift) if src >= 0}
    if len(read_by) != sum(1 for src in shift if src >= 0):
        raise OnChipWindowError("internal error: a word is the shift source of two targets")
    order, done = [], set()
    for dst, src in enumerate(shift):
        if src == KEEP or dst in done or dst in read_by:
            continue  # a chain starts at a target no one reads (its old word is dropped)
        word = dst
        while True:
            order.append((word, shift[word]))
            done.add(word)
            nxt = shift[word]
            if nxt < 0 or nxt in done or shift[nxt] == KEEP:
                break
            word = nxt
    if len(order) != sum(1 for src in shift if src != KEEP):
        raise OnChipWindowError("internal error: the shift has a cycle")
    return order


def _start_schedule(moves: list[tuple[int, int]], kf: list[int], nb: int,
                    per: int = 1) -> list[list]:
    """The shift's ``moves`` ((target, source or ZERO) in an order that reads each word before
    it is overwritten) and the keyframe's words into ``kf`` (in the call's order) over DATA_BUF
    in ``nb`` cyclic banks (word w in bank w mod nb), greedily: per iteration each bank one
    read and one write, at most ``per`` keyframe words (1 or 2), every op once the one move
    that reads its target (if any) has run in this or an earlier iteration (an iteration's
    reads come before its writes). The keyframe's words in their order, each with the moves
    its chain needs first; the moves that free no keyframe word fill the ports left. Per
    iteration per bank (word read, word written, source: a bank, ``nb + q`` the iteration's
    q-th keyframe word, None zero)."""
    reader = {src: i for i, (_, src) in enumerate(moves) if src >= 0}
    writer = {dst: i for i, (dst, _) in enumerate(moves)}
    at_kf = {w: k for k, w in enumerate(kf)}
    far = len(kf) + 1
    ops = []  # (key, kind, index): kind "m" a move, "k" a keyframe word
    for i, (_, src) in enumerate(moves):
        dist, w = 1, src
        while w >= 0 and w in writer:  # up the chain to the word no move writes
            w = moves[writer[w]][1]
            dist += 1
        ops.append(((at_kf.get(w, far) if w >= 0 else far, -dist, i), "m", i))
    ops += [((k, 0, -1), "k", k) for k in range(len(kf))]
    pending = [op for _, *op in sorted(ops)]
    done: dict[int, int] = {}  # move -> its iteration
    rows, next_kf = [], 0
    while pending:
        it = len(rows)
        row = [[None, None, None] for _ in range(nb)]
        kf_used = 0
        progress = True
        while progress:
            progress = False
            for op in list(pending):
                kind, i = op
                dst = kf[i] if kind == "k" else moves[i][0]
                r = reader.get(dst)
                if r is not None and r not in done:
                    continue
                b = dst % nb
                if row[b][1] is not None:
                    continue
                if kind == "k":
                    if kf_used == per or i != next_kf:
                        continue
                    row[b][1:] = [dst, nb + kf_used]
                    kf_used, next_kf = kf_used + 1, next_kf + 1
                else:
                    src = moves[i][1]
                    if src >= 0:
                        if row[src % nb][0] is not None:
                            continue
                        row[src % nb][0] = src
                    row[b][1:] = [dst, src % nb if src >= 0 else None]
                    done[i] = it
                pending.remove(op)
                progress = True
        if all(c[1] is None for c in row):
            raise OnChipWindowError("internal error: the update's start schedules nothing")
        rows.append([tuple(c) for c in row])
    return rows


def _check_start(moves, kf, n_data: int, nb: int, rows) -> None:
    """:class:`OnChipWindowError` unless the banked start (:func:`_start_schedule`) leaves
    DATA_BUF as the moves one after another and then the keyframe's words do, each bank at
    most one read and one write an iteration."""
    want = list(range(n_data))
    for dst, src in moves:
        want[dst] = want[src] if src >= 0 else "zero"
    for k, w in enumerate(kf):
        want[w] = ("kf", k)
    got, k = list(range(n_data)), 0
    for row in rows:
        first = k
        read = {}
        for b, (r, _, _) in enumerate(row):
            if r is not None:
                if r % nb != b:
                    raise OnChipWindowError("internal error: a start read outside its bank")
                read[b] = got[r]
        for b, (_, w, s) in enumerate(row):
            if w is None:
                continue
            if w % nb != b:
                raise OnChipWindowError("internal error: a start write outside its bank")
            if s is not None and s >= nb:
                got[w], k = ("kf", first + s - nb), k + 1
            else:
                got[w] = "zero" if s is None else read[s]
    if got != want:
        raise OnChipWindowError("internal error: the update's banked start does not leave "
                                "DATA_BUF as the shift and the keyframe's words do")


def pos_total(members: list[Member]) -> int:
    return members[-1].start + members[-1].words if members else 0
