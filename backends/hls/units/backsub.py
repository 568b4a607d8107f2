"""Back-substitution (``include/fgc_backsub.h``'s ``cond_backsub``): the conditionals solved
level by level, root first, one ``backsub_set<u>`` unit per QR unit set (one for Cholesky) side
by side in back_substitute's ``backsub_level`` region; a what-if whole-matrix Cholesky solves
Lᵀδ = z by rows instead."""

from __future__ import annotations

import math

from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.plan.binding import BoundLoop, sum_operators
from fgc_backends.hls.plan.loops import _ported, _region_cycles, dot_loop, kernel_loop
from fgc_backends.hls.plan.model import PORTS, Loop, Phase, Process, Unit
from fgc_backends.hls.units.spec import UnitSpec


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


def backsub_copies(tables: dict, s: int, timing: dict) -> tuple[list[Loop], list[Loop]]:
    """back_substitute()'s copies around cond_backsub for step s alone on one unit (one unit
    set, :data:`PORTS` words a cycle): the conditional from COND and the separator's solution
    in; the frontal solution out."""
    w, f = tables["STEP_W"][s], tables["STEP_F"][s]
    return ([kernel_loop("cond_in", _ported(f * (w + 1)), "move", timing),
             kernel_loop("separator_in", _ported(w - f), "move", timing)],
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
    """cond_backsub's operators as Vitis binds them (:mod:`fgc_backends.hls.plan.binding`):
    each pipelined loop its own at II 1 (S xs: a multiply-add; the fold: PARTIALS - 1 adds and
    the subtraction from d; the reciprocals: a divide; the column above the pivot: a
    multiply-add), the pivot's multiply sequential; PARTIALS is the adder's latency."""
    partials = ops.add.latency
    return sum_operators((BoundLoop("separator", (("add", 1), ("mul", 1)), 1),
                          BoundLoop("fold", (("add", partials),), 1),
                          BoundLoop("reciprocals", (("div", 1),), 1),
                          BoundLoop("solve", (("mul", 1),), 0),
                          BoundLoop("column", (("add", 1), ("mul", 1)), 1)), ops)


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

