"""The factor datapath: one pipelined datapath per block type, shared by the Jacobian mode
(``evaluate_<b>``) and the cost mode (``cost_of_<b>``), under the options' ``ALLOCATION``
limits; the gradient pass over AB (QR) and, as a what-if design, whitening raw Jacobians while
stacking. Kernel code of accel.cpp.jinja (no static header)."""

from __future__ import annotations

import math

from fgc_backends.cost.kernels import critical_path
from fgc_backends.hls.plan.loops import (
    _block_shape,
    _ceil_log2,
    _ported,
    _sim_table,
    kernel_dot,
    kernel_loop,
)
from fgc_backends.hls.plan.model import Loop, Memory, Phase, Process, Unit
from fgc_backends.hls.units.spec import UnitSpec


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


def build(ctx) -> None:
    """Per block type a datapath unit and its AB memory; the factor_jacobian and factor_cost
    phases (the emitted instance loops run one block type after another); QR's gradient pass;
    raw Jacobians' whitening (what-if)."""
    program, opts, ops = ctx.program, ctx.opts, ctx.ops
    sim_ops = _sim_table(ops)
    alloc = dict(opts.allocation)
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
        ctx.units.append(Unit(name, f"factor datapath of block {b.name!r} (both modes)", 1,
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
        ctx.memories.append(Memory(f"ab_{i}", words, ops.word_bits, 1))
    ctx.add_phase("linearize", Phase("factor_jacobian", False, tuple(jac)))
    if program.solver.linear == "qr":  # Cholesky's gradient comes with the HGC (units.cholesky)
        ctx.add_phase("linearize", Phase("gradient", False,
                                         tuple(gradient_loops(program, ctx.timing))))
    if opts.jacobian_storage == "raw":
        # whitening while stacking: W·[J | -r] of each instance, one multiply-accumulate a
        # cycle in each of n_u lanes, before the solver reads the rows
        ctx.units.append(Unit("whiten", "W·[J | -r] while stacking the raw Jacobians",
                              opts.units, (("add", 1), ("mul", 1))))
        ctx.add_phase("linearize", Phase("whiten_stack", False, (Process("whiten", "whiten", (
            Loop("macs", math.ceil(whiten_macs / opts.units), 1,
                 ops.mul.latency + ops.add.latency),)),), linear=True))
    ctx.add_phase("cost", Phase("factor_cost", False, tuple(cost)))


SPEC = UnitSpec(
    name="datapath", role="factor datapaths (Jacobian and cost modes) and the gradient pass",
    build=build, phases=("factor_jacobian", "gradient", "whiten_stack", "factor_cost"),
    constants=(("ALLOCATION", "per block type: operator limits (PlanOptions.allocation)"),),
    printed_by="accel.cpp.jinja: evaluate_<b>, cost_of_<b>, reduce_<b>")

