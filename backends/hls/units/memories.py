"""The kernel's stores: the state (X, X_TRIAL; the column design's LM X_BACK and G_BACK), the
gradient and step (G, DELTA), the data buffer
(DATA_BUF) the stream section writes a keyframe's words into, and the linear solver's
conditionals and passed factors (COND, NF)."""

from __future__ import annotations

from fgc_backends.hls.plan.model import Memory
from fgc_backends.hls.units.spec import UnitSpec


def solver_memories(sizes, ops, memories) -> None:
    """The linear solver's stores: conditionals (R | d) and the factors passed to parents."""
    memories.append(Memory("cond", sizes["N_COND"], ops.word_bits, 1))
    memories.append(Memory("nf", sizes["N_NF"], ops.word_bits, 1))


def stream_memories(layout, t_bits: int, l_bits: int, batch_words: int,
                    spec: bool = False) -> tuple[Memory, ...]:
    """The memories the on-chip stream section adds to the window kernel
    (``fgc_backends.hls.window``): the kept Bayes net's conditionals (R, S, d) and linearisation
    points, the kept estimates, and with a batch kernel its estimates and conditionals
    (``batch_words`` words a keyframe), or with batch steps as sweeps the keyframes 0 … the
    last batch step as they came (storage and words: ``sweep_x``, ``sweep_words``). ``spec``
    (the one-step update's marginal beside its back-substitution): the leaving keyframe's
    conditional's second copy (``KEEP_COND``), τ's words (``TAU_BUF``), slots 0 and 1's points
    (``LIN01``) and, with a kept net, the conditional staged (``SPEC_R`` / ``_S`` / ``_D``, its
    points)."""
    mems = []
    if spec:
        n, kf = layout.kf_dim, layout.kf_words
        mems += [Memory("keep_cond", n * (2 * n + 1), l_bits, 1),
                 Memory("tau_buf", kf + n + n * (n + 1) // 2 + 2, t_bits, 1),
                 Memory("lin01", 2 * kf, t_bits, 1)]
        if layout.kept:
            mems += [Memory("spec_r", n * n, l_bits, 1), Memory("spec_s", n * n, l_bits, 1),
                     Memory("spec_d", n, l_bits, 1), Memory("spec_lin", kf, t_bits, 1),
                     Memory("spec_next", kf, t_bits, 1)]
    if layout.kept:
        n, kf, count = layout.kf_dim, layout.kf_words, layout.kept
        mems += [Memory("kept_r", count * n * n, l_bits, 1),
                 Memory("kept_s", count * n * n, l_bits, 1),
                 Memory("kept_d", count * n, l_bits, 1),
                 Memory("kept_points", 2 * count * kf, t_bits, 1),
                 Memory("x_kept", count * kf, t_bits, 1)]
    if layout.batch is not None:
        b = layout.batch
        mems += [Memory("batch_x", b.size * layout.kf_words, t_bits, 1),
                 Memory("batch_cond", b.size * batch_words, l_bits, 1)]
    if getattr(layout, "sweep", None) is not None:  # batch steps as sweeps: the keyframes kept
        rows = layout.sweep_slots + 1  # as they came, one row for those past the last batch step
        mems += [Memory("sweep_x", rows * layout.kf_words, t_bits, 1),
                 Memory("sweep_words", rows * max(len(d) for d in layout.new_dest), t_bits, 1)]
    return tuple(mems)


def build(ctx) -> None:
    """X, X_TRIAL, G with DELTA (two banks) and DATA_BUF."""
    program, ops = ctx.program, ctx.ops
    n_x = sum(v.storage_dim for v in program.variables)
    n_t = sum(v.dim for v in program.variables)
    # the column design's LM (units/lm_control.py's retire_step_test): the trial held in X, X's
    # backup X_BACK, G and G_BACK (G moved there by the state update for LM's retries), DELTA
    from fgc_backends.hls.units.lm_control import retire_step_test
    if retire_step_test(program, ctx.opts):
        ctx.memories.append(Memory("state", n_x, ops.word_bits, 1))  # X
        ctx.memories.append(Memory("state_back", n_x, ops.word_bits, 1))  # X_BACK
        ctx.memories.append(Memory("gradient", n_t, ops.word_bits, 1))  # G
        ctx.memories.append(Memory("gradient_back", n_t, ops.word_bits, 1))  # G_BACK
        ctx.memories.append(Memory("delta", n_t, ops.word_bits, 1))  # DELTA
    else:
        ctx.memories.append(Memory("state", n_x, ops.word_bits, 1))  # X
        ctx.memories.append(Memory("state_trial", n_x, ops.word_bits, 1))  # X_TRIAL
        ctx.memories.append(Memory("gradient_delta", 2 * n_t, ops.word_bits, 2))  # G, DELTA
    # DATA_BUF: cyclic 2 where trial_cost reads it so (units/datapath.py's trial_banked)
    from fgc_backends.hls.units.datapath import TRIAL_DATA_BANKS, trial_banked
    banks = TRIAL_DATA_BANKS if trial_banked(program, ctx.opts) else 1
    ctx.memories.append(Memory("data", ctx.sizes["N_DATA"], ops.word_bits, banks))


SPEC = UnitSpec(name="memories", role="state, gradient/step and data memories", build=build,
                phases=(), printed_by="accel.cpp.jinja: X, X_TRIAL, G, DELTA, DATA_BUF")



