"""Back-substitution (``include/fgc_backsub.h``'s ``cond_backsub``): the conditionals solved
level by level, root first, one ``backsub_set<u>`` unit per QR unit set (one for Cholesky) side
by side in back_substitute's ``backsub_level`` region; a what-if whole-matrix Cholesky solves
Lᵀδ = z by rows instead."""

from __future__ import annotations

import math

from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.plan.binding import BoundLoop, sum_operators
from fgc_backends.hls.plan.loops import _ceil_log2, _ported, _region_cycles, dot_loop, kernel_loop
from fgc_backends.hls.plan.model import PORTS, Loop, Phase, Process, Unit
from fgc_backends.hls.units.spec import UnitSpec


def backsub_chain(ops: OperatorTable) -> int:
    """The triangle's recurrence per unknown (fgc_backsub.h's CHAIN): x_r = y_r / R_rr (a multiply
    by the reciprocal), the product R_ir x_r and the subtraction from y_i."""
    return 2 * ops.mul.latency + ops.add.latency


def backsub_words(frontal: int, separator: int) -> int:
    """Words ``cond_load`` moves: each row i of the conditional from its diagonal on (R's
    structural zeros below the diagonal stay behind)."""
    return frontal * (frontal + separator + 1) - frontal * (frontal - 1) // 2


def triangle_trip(frontal: int, ops: OperatorTable) -> int:
    """Iterations of cond_backsub's triangle loop: columns r = f − 1 … 1, each max(r, CHAIN + 1)
    (a column shorter than the recurrence padded to it)."""
    pad = backsub_chain(ops) + 1
    return sum(max(r, pad) for r in range(1, frontal))


def rows_depth(ops: OperatorTable) -> int:
    """cond_backsub's row loop: the 2 PARTIALS partial sums folded and subtracted from d
    (La (1 + ⌈log₂ 2 PARTIALS⌉)) beside the reciprocal of the diagonal (Ld)."""
    la = ops.add.latency
    return max(la * (1 + _ceil_log2(2 * la)), ops.div.latency)


def load_loop(frontal: int, separator: int, ops: OperatorTable, name: str = "cond_load"
              ) -> Loop:
    """``cond_load``: the conditional's stored words two a cycle (the source memory's two
    ports), each S_ia x_a added into a partial sum as it passes (II 1: a lane's sum comes back
    PARTIALS iterations later); depth read + multiply-add + write."""
    words = backsub_words(frontal, separator) if frontal else 0
    return Loop(name, -(-words // PORTS), 1, 2 + ops.mul.latency + ops.add.latency)


def backsub_loops(frontal: int, separator: int, ops: OperatorTable,
                  name: str = "bs") -> list[Loop]:
    """The loops of ``cond_backsub`` (backends/hls/include/fgc_backsub.h) on one conditional of
    f frontal and s separator columns (S xs already summed by ``cond_load``), as its csim
    counters count them: per row (trip f, II 1) its partial sums folded and subtracted from d
    beside the diagonal's reciprocal (:func:`rows_depth`); the triangle as one flattened loop
    (trip :func:`triangle_trip`, II 1, depth CHAIN = 2 Lm + La: the chain per unknown, the
    column updates beside it); x_0 (one multiply). Nothing for f = 0."""
    if not frontal:
        return []
    return [Loop(f"{name}_rows", frontal, 1, rows_depth(ops)),
            Loop(f"{name}_triangle", triangle_trip(frontal, ops), 1, backsub_chain(ops)),
            Loop(f"{name}_last", 1, 1, ops.mul.latency)]


def backsub_chunk_loops(tables: dict, steps, ops: OperatorTable, timing: dict,
                        sets: int) -> list[Loop]:
    """back_substitute() on ``steps`` (at most ``sets``: one chunk of a level, one step per unit
    set): their separator solutions copied in side by side (the memories' two ports shared
    out: ``max(1, PORTS // sets)`` words of each step an iteration at II ⌈sets / PORTS⌉), each
    step's ``cond_load`` in turn (:func:`load_loop`), the ``backsub_level`` DATAFLOW region
    (one ``cond_backsub`` process per unit set: the slowest plus the others' fill), the frontal
    solutions out side by side."""
    per, ii = max(1, PORTS // sets), -(-sets // PORTS)
    sizes = [(tables["STEP_F"][s], tables["STEP_W"][s]) for s in steps]
    region = _region_cycles([backsub_loops(f, w - f, ops, name=f"bs{s}")
                             for s, (f, w) in zip(steps, sizes, strict=True)])
    _, depth = timing["move"]

    def copy(name, words):
        return Loop(name, -(-max(words) // per), ii, depth)

    return [copy("separator_in", [w - f for f, w in sizes]),
            *[load_loop(f, w - f, ops, name=f"cond_load{s}")
              for s, (f, w) in zip(steps, sizes, strict=True)],
            Loop("backsub_level", 1, 1, region),
            copy("solution_out", [f for f, _ in sizes])]


def backsub_copies(tables: dict, s: int, timing: dict, ops: OperatorTable
                   ) -> tuple[list[Loop], list[Loop]]:
    """back_substitute()'s loops around cond_backsub for step s alone on one unit (one unit
    set, :data:`PORTS` words a cycle): the separator's solution in and the conditional's
    ``cond_load``; the frontal solution out."""
    w, f = tables["STEP_W"][s], tables["STEP_F"][s]
    return ([kernel_loop("separator_in", _ported(w - f), "move", timing),
             load_loop(f, w - f, ops)],
            [kernel_loop("solution_out", _ported(f), "move", timing)])


def backsub_phases(ctx, unit: str, sets: int = 1) -> None:
    """The emitted back_substitute: levels root first, each level's steps (LEVEL_STEPS order)
    ``sets`` at a time through the ``backsub_level`` region (:func:`backsub_chunk_loops`)."""
    tables, timing, ops = ctx.tables, ctx.les_timing, ctx.les
    begin, order = tables["LEVEL_BEGIN"], tables["LEVEL_STEPS"]
    for li in range(len(begin) - 2, -1, -1):
        procs = []
        for i in range(begin[li], begin[li + 1], sets):
            chunk = order[i:min(i + sets, begin[li + 1])]
            procs.append(Process("backsub_" + "_".join(f"step{s}" for s in chunk), unit,
                                 tuple(backsub_chunk_loops(tables, chunk, ops, timing, sets))))
        ctx.add_phase("solve", Phase(f"backsub_level{len(begin) - 2 - li}", False, tuple(procs),
                                     linear=True))


def backsub_operators(ops: OperatorTable) -> tuple[tuple[str, int], ...]:
    """One back-substitution unit's operators as Vitis binds them
    (:mod:`fgc_backends.hls.plan.binding`), each pipelined loop its own at II 1: its
    ``cond_load`` (its own call site in back_substitute: two words an iteration, a multiply-add
    each), the row loop (2 PARTIALS − 1 adds folding, the subtraction from d, the reciprocal's
    divide), the triangle (the multiply by 1 / R_rr, the product, the subtraction), x_0's
    multiply sequential; PARTIALS is the adder's latency."""
    partials = ops.add.latency
    return sum_operators((BoundLoop("cond_load", (("add", 2), ("mul", 2)), 1),
                          BoundLoop("rows", (("add", 2 * partials), ("div", 1)), 1),
                          BoundLoop("triangle", (("add", 1), ("mul", 2)), 1),
                          BoundLoop("last", (("mul", 1),), 0)), ops)


def build(ctx) -> None:
    """QR: one back-substitution unit per unit set; Cholesky: the trisolve unit (as emitted:
    cond_backsub step by step; what-if: Lᵀδ = z by rows, Lz = g riding the cascade)."""
    program, opts, ops = ctx.program, ctx.opts, ctx.les
    if program.solver.linear == "qr":
        sets = ctx.shared["sets"]
        backsub_phases(ctx, "backsub", sets)
        for s in range(sets):
            ctx.units.append(Unit(f"qr{s}_backsub", "back-substitution (cond_backsub)", 1,
                                  backsub_operators(ops)))
        return
    if opts.hessian_storage == "frontal":
        ctx.units.append(Unit("trisolve", "back-substitution (cond_backsub; Lz = g rides the "
                              "cascade)", 1, backsub_operators(ops)))
        backsub_phases(ctx, "trisolve")
        return
    n = program.storage.columns
    ctx.units.append(Unit("trisolve", "Lᵀδ = z (Lz = g runs in the cascade)", 1,
                          (("add", 1), ("mul", 1), ("div", 1))))
    solve = dot_loop("rows", n, ops)
    ctx.add_phase("solve", Phase("trisolve", False, (Process("backward", "trisolve", (
        Loop("rows", n, max(1, math.ceil(n / 2)), solve.depth + ops.div.latency),)),),
        linear=True))


SPEC = UnitSpec(
    name="backsub", role="back-substitution through the conditionals",
    build=build, phases=("backsub", "trisolve"), header="fgc_backsub.h",
    constants=(("PARTIALS", "interleaved partial sums per row (the adder latency)"),
               ("MAX_F", "widest frontal block"), ("MAX_W", "widest step")),
    printed_by="accel.cpp.jinja: back_substitute -> backsub_level -> fgc_backsub.h cond_backsub")

