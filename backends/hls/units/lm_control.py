"""LM control (optimize / try_steps): the gradient's maximum, |x|, the step test, the scalar
decision, the accepted state copied back; the top's copies once per call and the rounding-noise
pass on a rejected step. Its rules are the static header ``fgc_lm.h`` both C-family kernels
share (``backends/cfamily/include/``), its reductions ``fgc_lm_units.h``, configured by the
kernel's ``LmConfig`` (constants and hooks); the top's copies and the rounding-noise pass
(problem-specific: per block type) are kernel code of accel.cpp.jinja."""

from __future__ import annotations

import math

from fgc_backends.cfamily.sparsity import TILE
from fgc_backends.hls.plan.binding import BoundLoop, bound_unit
from fgc_backends.hls.plan.loops import _block_shape, _ceil_log2, _ported, kernel_dot, kernel_loop
from fgc_backends.hls.plan.model import PORTS, Loop, Phase, Process
from fgc_backends.hls.units.spec import UnitSpec


def retire_step_test(program, opts) -> bool:
    """Whether the emitted kernel forms LM's step test in back_substitute's state update
    (accel.cpp.jinja's ``retire_test``): Cholesky with back-substitution by columns (never an
    on-chip stream's design: those refuse the column width). Then |δ|², δᵀg, δ's finiteness
    and the gradient's largest |entry| (tested after the solve) are summed by
    ``backsub_retire_cols`` a variable an iteration at its II (the state update's
    loop; its operators :func:`retire_test_loop`), which also holds the trial in X (x ⊕ δ
    written into X in place, X's words backed up into X_BACK as they are read: fgc_lm.h's
    FGC_LM_TRIAL_IN_X, so an accepted step copies nothing and a trial not taken is restored),
    sums |x ⊕ δ|² (the next |X|; the top's x_in the first) and moves G into G_BACK, zeroing it
    for the next linearisation (the top's data copy zeroes it once a call): LM control keeps
    the step test's scalars and the decision, and the restore of a trial not taken."""
    return (program.solver.linear == "cholesky" and opts.backsub_lanes == 4
            and opts.hessian_storage == "frontal")


def fused_step_test(program, opts) -> bool:
    """Whether the emitted kernel forms LM's per-linearisation scalars and its step test in one
    loop after the solve (accel.cpp.jinja's ``fused_test``): the one-step policy
    (``SolverConfig.one_step``: Gauss-Newton, μ = 0, one iteration, so one solve a
    linearisation) on a design whose state update does not sum them (not
    :func:`retire_step_test`). Then fgc_lm.h tests the gradient after the solve
    (FGC_LM_GRADIENT_IN_SOLVE: the same outcome, X is not written by the solve) and reads |X|
    there (FGC_LM_NORM_IN_SOLVE), and fgc_lm_units.h's ``lm_solved_test`` reads G, X and δ two
    words of each a cycle in one loop over the longer of N_X and N_TANGENT: the gradient's
    largest |entry|, |X|², |δ|², δᵀg and δ's finiteness, in place of lm_iterate's loop before
    the solve and lm_step_test's after it (the same operators, one loop's depth instead of
    two loops one after the other)."""
    return bool(program.solver.one_step) and not retire_step_test(program, opts)


def retire_solved_test(program, opts) -> bool:
    """Whether the one-step policy's sums (:func:`fused_step_test`: the gradient's largest
    |entry|, |X|², |δ|², δᵀg and δ's finiteness) are formed by back_substitute's state update of
    the slot design (fgc_backsub.h's ``backsub_retire`` with FGC_BS_STEP_TEST: a variable an
    iteration, as its δ arrives, its G and X words read beside its retraction; the kernel's
    ``retract_variable`` forms the variable's terms, the loop sums them, :func:`retire_solved_loop`
    its operators at the retire's II) instead of ``lm_solved_test``'s loop after the region:
    LM control keeps the step test's scalars and the decision. X is not written in the region
    (the trial goes to X_TRIAL), G is not written after the linearisation, and every variable
    is a frontal variable of exactly one step: the same sums over the same words (in the retire's
    order). The column design (``backsub_lanes`` 4) keeps ``lm_solved_test``."""
    from fgc_backends.hls.units.state_update import fed_by_backsub
    return (fused_step_test(program, opts) and fed_by_backsub(program, opts)
            and opts.backsub_lanes != 4)


def retire_test_loop(program, ii: int) -> BoundLoop:
    """The step test's operators in the state update's loop (II ``ii``): per variable of the
    widest tangent its δ_k² and δ_k g_k (a multiply each) and their two sums (a chain of adds
    each, the running sums' add included), |g_k| against the variable's maximum and that against
    the running one (compares), and per word of the widest storage its (x ⊕ δ)_k² and their sum
    (|X|² of the trial held in X: a multiply and an add each, the running sum's add one more),
    shared at that II as Vitis binds a pipelined loop."""
    w = max(v.dim for v in program.variables)
    s = max(v.storage_dim for v in program.variables)
    return BoundLoop("retire_step_test", (("add", 2 * w + s + 1), ("mul", 2 * w + s),
                                          ("compare", w + 1)), ii)


def retire_solved_loop(program, ii: int) -> BoundLoop:
    """The one-step policy's sums in the slot design's state update (:func:`retire_solved_test`)
    at the retire's II ``ii``: per variable type (``retract_variable``'s exclusive branches,
    counted apart as the second reader reads them) its δ_k², δ_k g_k and x_k² (a multiply each)
    and their sums (an add each), |g_k| against the variable's maximum (a compare each); the
    loop's running sums of |δ|², δᵀg and |X|² (three adds) and its maximum (a compare)."""
    kinds: dict[str, tuple[int, int]] = {}
    for v in program.variables:
        kinds.setdefault(v.type_name, (v.dim, v.storage_dim))
    mul = sum(2 * d + s for d, s in kinds.values())
    return BoundLoop("retire_solved_test", (("add", mul + 3), ("mul", mul),
                                            ("compare", sum(d for d, _ in kinds.values()) + 1)),
                     ii)


def pair_dot(words: int, timing: dict, kind: str = "acc", extra: int = 0,
             partials: int | None = None, lanes: int = PORTS) -> tuple[int, int, int]:
    """(trip, II, depth) of a reduction of ``words`` terms two a cycle (fgc_lm_units.h's
    pair_ii / pair_depth: the memories' two ports): lane h of a pair into its own ``ii`` =
    latency interleaved partials (the dot-product rule, :func:`kernel_dot`, on a lane's trip),
    the 2k partials folded in a tree; ``kind`` the recurrence (``acc`` a sum: the multiply
    ahead; ``max`` a running maximum: the read and |·| ahead), ``extra`` the latency the loop
    adds around it (the step test's μ‖δ‖² after the folds); ``partials``: a lane's partials if not
    the recurrence's latency (lm_iterate's maxima: as many as its sums); ``lanes``: words a
    cycle."""
    ii, depth = timing[kind]
    trip = -(-words // lanes)
    k = max(1, min(trip, ii if partials is None else partials))
    return trip, math.ceil(ii / k), extra + (depth - ii) + ii * (1 + _ceil_log2(lanes * k))


def lm_control_phases(n_t: int, n_x: int, timing: dict,
                      retire_test: bool = False, fused: bool = False,
                      in_retire: bool = False) -> tuple[Phase, ...]:
    """LM control as emitted (optimize / try_steps) over ``n_t`` tangent and ``n_x`` storage
    words, in three phases by how often their loops run: ``lm_iteration`` once per
    linearisation (the gradient's largest entry and |x| in one loop, ``lm_iterate``: |x| is
    kept for try_steps' x_norm, X unchanged in between), ``lm_control`` once per linear solve
    (the step test over δ, the scalar decision) and ``lm_accept`` once per accepted step
    (x_trial copied into x). A plan iteration has one of each; an LM retry adds a solve, not an
    iteration, and the last iteration of a run often accepts nothing. Every loop takes two
    words a cycle of each memory it reads (:data:`PORTS`): the gradient maximum into partial
    maxima, the sums (|x|², ‖δ‖² and δᵀ(g + μδ)) into interleaved partial sums, two lanes
    each, PIPELINEd at II 1 (:func:`pair_dot`); the step test sums ‖δ‖² and δᵀg (two products
    a word) and adds μ‖δ‖² to the latter after the folds (δᵀ(g + μδ)), a multiply and an add
    more in its depth. ``retire_test`` (:func:`retire_step_test`): the step test's sums come
    from the state update, so ``decide`` is the step test's scalars (μ‖δ‖², + δᵀg) and the
    decision; no ``lm_accept``: the state update held the trial in X, summed its |X|² and moved
    G out of the next linearisation's way; instead ``lm_restore`` once per solve that ran and
    was not taken (a rejection, or the way out on a small gradient or step: per="rejection"),
    X_BACK copied into X two words a cycle (lm_restore);
    no ``lm_iteration``: the state update finds the gradient's largest
    entry too and fgc_lm.h tests it after the solve (FGC_LM_GRADIENT_IN_SOLVE; the gradient's
    own pass, ``lm_gradient_max``, runs only where no solve of a linearisation succeeded, before
    LM gives up: once a run at most, not priced). ``fused`` (:func:`fused_step_test`): no
    ``lm_iteration`` either; ``decide`` is one loop over the longer of the two (``solved_test``:
    the gradient's maximum, |X|², |δ|² and δᵀg, two words of each a cycle, its depth the
    longest of the three reductions'), the step test's scalars and the decision (the gradient's
    own pass as with ``retire_test``: where the solve failed, not priced). ``fused`` and
    ``in_retire`` (:func:`retire_solved_test`): those sums come from the state update, so
    ``decide`` is the step test's scalars and the decision alone."""
    tail = timing["acc"][1]  # after the folds: μ‖δ‖², then δᵀg + μ‖δ‖²
    # (the maxima as many as the sums: lm_iterate's one DEPENDENCE distance, PARTIALS)
    _, gii, gdepth = pair_dot(n_t, timing, kind="max", partials=timing["acc"][0])
    _, xii, xdepth = pair_dot(n_x, timing)
    trip = _ported(max(n_t, n_x))  # one loop over the longer of the two
    step = pair_dot(n_t, timing, extra=tail)
    if fused:
        _, dii, ddepth = pair_dot(n_t, timing)
        solved = () if in_retire else (
            Loop("solved_test", trip, max(gii, xii, dii), max(gdepth, xdepth, ddepth)),)
        return (Phase("lm_control", False, (Process("decide", "lm_control", (
                    *solved,
                    Loop("step_scalars", 1, 1, tail),
                    kernel_loop("decision", 1, "decision", timing))),)),
                Phase("lm_accept", False, (Process("accept", "lm_control", (
                    kernel_loop("accept", _ported(n_x), "move", timing),)),)))
    if retire_test:
        return (Phase("lm_control", False, (Process("decide", "lm_control", (
                    Loop("step_scalars", 1, 1, tail),
                    kernel_loop("decision", 1, "decision", timing))),)),
                Phase("lm_restore", False, (Process("restore", "lm_control", (
                    kernel_loop("restore", _ported(n_x), "move", timing),)),),
                      per="rejection"))
    return (Phase("lm_iteration", False, (Process("iterate", "lm_control", (
                Loop("gradient_x_norm", trip, max(gii, xii), max(gdepth, xdepth)),)),)),
            Phase("lm_control", False, (Process("decide", "lm_control", (
                Loop("step_test", *step),
                kernel_loop("decision", 1, "decision", timing))),)),
            Phase("lm_accept", False, (Process("accept", "lm_control", (
                kernel_loop("accept", _ported(n_x), "move", timing),)),)))


def setup_phase(x_in: int, data_in: int, x_out: int, timing: dict, zero: int = 0) -> Phase:
    """The top's copies once per call: ``x_in`` state words and ``data_in`` data words in,
    ``x_out`` state words out. ``zero`` > 0 (:func:`retire_step_test`; ``zero`` the gradient's
    words): lm_top_norm, whose x_in copy also sums |x|² into the adder latency's interleaved
    partial sums (:func:`kernel_dot`) and whose data copy zeroes G (a loop over the longer)."""
    if zero:
        return Phase("setup", False, (Process("top", "lm_control", (
            kernel_dot("x_in", x_in, timing),
            kernel_loop("data_in", max(data_in, zero), "move", timing),
            kernel_loop("x_out", x_out, "move", timing))),), per="call")
    return Phase("setup", False, (Process("top", "lm_control", (
        kernel_loop("x_in", x_in, "move", timing), kernel_loop("data_in", data_in, "move", timing),
        kernel_loop("x_out", x_out, "move", timing))),), per="call")


def rounding_noise_loops(program, timing: dict) -> list[Process]:
    """rounding_noise_all(): each variable's largest storage entry, then per instance its rows
    loaded (:data:`PORTS` words a cycle), the column scales, the rows' moved terms (one
    rounding_noise module for every block type: a row every widest padded + 3 cycles, its
    products sharing one multiplier, its adds one adder) and their sum (TILE rows a step into
    TILE partial sums)."""
    la, lm = timing["acc"][0], timing["acc"][1] - timing["acc"][0]
    procs = [Process("variable_scale", "lm_control", tuple(
        kernel_loop("scale", v.storage_dim, "max", timing) for v in program.variables))]
    # one rounding_noise module for every block type (rounding_noise_all's ALLOCATION), its
    # sizes run-time: a row every widest + 3 cycles through one multiplier and one adder (the
    # widest padded row's last product issues by then, its chain of widest / TILE adds and the
    # fold follow), whatever the block type's width
    widest = max(_block_shape(b)[2] for b in program.blocks)
    row_ii = widest + 3
    row_depth = max(2 * lm + la * (widest // TILE + 2), row_ii + 2 * lm + 2 * la)
    for i, b in enumerate(program.blocks):
        m, _, padded, _ = _block_shape(b)
        n = sum(1 for f in program.factors if f.block == i)
        procs.append(Process(f"noise_{i}", "lm_control", (
            kernel_loop("load", _ported(m * padded), "move", timing, n),
            kernel_loop("scales", padded, "fill", timing, n),
            Loop("rows", m, row_ii, row_depth, n),
            kernel_loop("terms", -(-m // TILE), "acc2", timing, n))))
    return procs


def build(ctx) -> None:
    """The lm_control unit and its phases: per iteration, per call (setup) and per rejected
    step (rounding noise)."""
    program, timing = ctx.program, ctx.timing
    n_x = sum(v.storage_dim for v in program.variables)
    n_t = sum(v.dim for v in program.variables)
    # LM control (optimize / try_steps): the gradient's largest entry with |x|, the step test
    # over δ (|δ|² and the predicted decrease), the scalar decision, the accepted x copied back,
    # two words a cycle each (the step test at II 1 starts four multiplies and four adds a
    # cycle: per word δ·δ and δ·g into their partial sums)
    # its operators as Vitis binds them (plan.binding): each pipelined loop its own (lm_iterate:
    # two multiply-adds and two compares a cycle; the step test: four), the scalar
    # decision sequential, one of each kind it uses in one module (fgc_lm.h's try_steps, the
    # LmConfig wrappers and lm_step_test / lm_iterate are INLINE into optimize, so their
    # sequential folds, half and step-size test share its operators; as separate modules each
    # bound its own: the second reader counts them apart); the rounding-noise pass, one
    # rounding_noise module for every block type (rounding_noise_all's ALLOCATION function
    # limit=1, each noise_<b> INLINE there): a row every widest padded + 3 cycles through its
    # products and moved's three adds, then the rows' terms (at II 3·TILE: one multiplier and
    # one adder), and the block types' running sums (one adder)
    fused = retire_step_test(program, ctx.opts)
    solved = fused_step_test(program, ctx.opts)
    in_retire = retire_solved_test(program, ctx.opts)
    if in_retire:
        # the sums in the state update's loop (units/backsub.py's retire_solved_test unit); the
        # gradient's own pass (only where the solve failed: two compares a cycle)
        loops = [BoundLoop("gradient_max", (("compare", 2),), 1),
                 BoundLoop("decision", (("add", 2), ("mul", 2), ("div", 1), ("compare", 1)), 0)]
    elif solved:
        # one loop after the solve (lm_solved_test): per lane the gradient's |entry| against
        # its partial maximum (a compare), x_k² into |X|² and δ_k², δ_k g_k into the step
        # test's sums (three multiply-adds), two lanes: lm_iterate's and lm_step_test's
        # operators, now one loop's; the gradient's own pass (only where the solve failed: two
        # compares a cycle)
        loops = [BoundLoop("solved_test", (("add", 6), ("mul", 6), ("compare", 2)), 1),
                 BoundLoop("gradient_max", (("compare", 2),), 1),
                 BoundLoop("decision", (("add", 2), ("mul", 2), ("div", 1), ("compare", 1)), 0)]
    elif fused:  # (the step test's sums: the state update's loop, units/backsub.py)
        # the gradient's maximum (two compares a cycle), lm_top_norm's x_in |x|² (a
        # multiply-add a cycle) and its fold (its own function: one adder); the restore moves
        # words only (|X|² of a trial taken: the state update's, units/backsub.py)
        loops = [BoundLoop("gradient_max", (("compare", 2),), 1),
                 BoundLoop("x_in_norm", (("add", 1), ("mul", 1)), 1),
                 BoundLoop("x_in_fold", (("add", 1),), 0),
                 BoundLoop("decision", (("add", 2), ("mul", 2), ("div", 1), ("compare", 1)), 0)]
    else:
        loops = [BoundLoop("gradient_x_norm", (("add", 2), ("mul", 2), ("compare", 2)), 1),
                 BoundLoop("step_test", (("add", 4), ("mul", 4)), 1),
                 BoundLoop("decision", (("add", 2), ("mul", 2), ("div", 1), ("compare", 1)), 0)]
    widest = max(_block_shape(b)[2] for b in program.blocks)
    loops += [BoundLoop("noise_rows", (("add", widest + 3), ("mul", widest + 1)), widest + 3),
              BoundLoop("noise_terms", (("add", 2 * TILE), ("mul", 3 * TILE)),
                        timing["acc2"][0])]
    # the block types' running sums (noise += ...): noise_<b> is INLINE into
    # rounding_noise_all, whose sequential body adds them one after another through one adder
    loops.append(BoundLoop("noise_sum", (("add", len(program.blocks)),), 0))
    ctx.units.append(bound_unit("lm_control", "gain ratio, μ update, stopping rules, "
                                "rounding noise", loops, table=ctx.ops))
    for phase in lm_control_phases(n_t, n_x, timing, fused, solved, in_retire):
        ctx.add_phase("control", phase)
    # once per call: the top's copies of x and the data in and x out
    ctx.add_phase("call", setup_phase(n_x, ctx.sizes["N_DATA"], n_x, timing,
                                      n_t if fused else 0))
    # when a trial step does not lower the cost: the rounding-noise band from AB
    ctx.add_phase("rejection", Phase("rounding_noise", False,
                                     tuple(rounding_noise_loops(program, timing)),
                                     per="rejection"))


SPEC = UnitSpec(
    name="lm_control", role="LM control, the top's copies and the rounding-noise pass",
    build=build, phases=("lm_iteration", "lm_control", "lm_accept", "lm_restore", "setup",
                         "rounding_noise"),
    header="fgc_lm_units.h",
    constants=(("N_X", "storage words of the state"), ("N_TANGENT", "tangent words"),
               ("PARTIALS", "interleaved partial sums (the adder latency)"),
               ("MAXIMA", "interleaved partial maxima (the compare latency)"),
               ("MOVE_II", "the accepted state's copy"), ("DECISION_II", "the scalar decision")),
    printed_by="accel.cpp.jinja: the top -> fgc_lm_units.h lm_top (the copies) -> fgc_lm.h "
    "optimize -> LmConfig's hooks -> fgc_lm_units.h; rounding_noise_all is kernel code")

