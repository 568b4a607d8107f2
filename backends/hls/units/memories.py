"""The kernel's stores: the state (X, X_TRIAL), the gradient and step (G, DELTA), the data buffer
(DATA_BUF) the stream section writes a keyframe's words into, and the linear solver's
conditionals and passed factors (COND, NF)."""

from __future__ import annotations

from fgc_backends.hls.plan.model import Memory
from fgc_backends.hls.units.spec import UnitSpec


def solver_memories(sizes, ops, memories) -> None:
    """The linear solver's stores: conditionals (R | d) and the factors passed to parents."""
    memories.append(Memory("cond", sizes["N_COND"], ops.word_bits, 1))
    memories.append(Memory("nf", sizes["N_NF"], ops.word_bits, 1))


def build(ctx) -> None:
    """X, X_TRIAL, G with DELTA (two banks) and DATA_BUF."""
    program, ops = ctx.program, ctx.ops
    n_x = sum(v.storage_dim for v in program.variables)
    n_t = sum(v.dim for v in program.variables)
    ctx.memories.append(Memory("state", n_x, ops.word_bits, 1))  # X
    ctx.memories.append(Memory("state_trial", n_x, ops.word_bits, 1))  # X_TRIAL
    ctx.memories.append(Memory("gradient_delta", 2 * n_t, ops.word_bits, 2))  # G, DELTA
    ctx.memories.append(Memory("data", ctx.sizes["N_DATA"], ops.word_bits, 1))  # DATA_BUF


SPEC = UnitSpec(name="memories", role="state, gradient/step and data memories", build=build,
                phases=(), printed_by="accel.cpp.jinja: X, X_TRIAL, G, DELTA, DATA_BUF")



