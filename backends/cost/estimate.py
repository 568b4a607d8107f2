"""estimate: a Program → cycles, latency, resources, power, energy and memory of its accelerator.

One iteration runs its units in sequence (the papers' dataflow phases):

    factor block (r, J) ─► [HGC] ─► factorization ─► back-substitution ─► retract ─► factor
    block (r, cost) ─► trust-region decision

A rejected LM step repeats everything after the HGC (new μ, same linearisation). Gauss-Newton
evaluates the cost too (its stopping rule tests the relative decrease) but never rejects. A whole
solve is ``iterations`` accepted iterations plus ``rejected`` rejected steps. Incremental plans
(``Schedule.incremental``) are not modelled: every iteration is a batch elimination.
"""

from __future__ import annotations

import math

from fgc.ir.program import Program

from .cholesky import CholeskyTiming, cholesky_timing
from .kernels import BlockTiming, block_timings
from .params import CostParams, OperatorTable
from .qr import QrTiming, qr_timing
from .report import CostReport, UnitCycles
from .resources import memory_words, power_w, unit_resources, utilization


def estimate(program: Program, iterations: int | None = None, params: CostParams | None = None,
             *, rejected: int = 0) -> CostReport:
    """Model the accelerator of ``program`` (its SolverConfig sets units, #CPE, precision, clock).

    ``iterations`` is the number of accepted steps (each relinearises; default
    ``program.solver.max_iterations``, the solver's worst case); ``rejected`` the number of
    rejected LM steps on top (each solves again and evaluates the cost).
    """
    params = params or CostParams()
    solver = program.solver
    ops = params.operators(solver.precision)
    les_ops = params.operators(solver.les_precision)  # the linear solver's (mixed: wider)
    k = solver.max_iterations if iterations is None else iterations
    if k < 0 or rejected < 0 or (rejected and solver.method != "lm"):
        raise ValueError(f"iterations={k}, rejected={rejected}: need k ≥ 0, rejected ≥ 0, "
                         "and rejected steps only with method='lm'")
    jacobian = block_timings(program, ops, params, "jacobian")
    cost = sum(b.cycles for b in block_timings(program, ops, params, "cost"))
    linear = (cholesky_timing(program, les_ops, params) if solver.linear == "cholesky"
              else qr_timing(program, les_ops, params))
    iteration, rejected_step = _cycles(program, ops, les_ops, params, jacobian, cost, linear)
    qr_sets = linear.sets if isinstance(linear, QrTiming) else 0
    by_unit = unit_resources(program, ops, params, qr_sets, les_ops)
    total = by_unit.total
    return CostReport(
        program=program.name, method=solver.method, linear=solver.linear,
        precision=solver.precision, clock_mhz=solver.clock_mhz, units=solver.units,
        cpe=solver.cpe, iterations=k, rejected=rejected, iteration=iteration,
        rejected_step=rejected_step, solve=iteration.scaled(k) + rejected_step.scaled(rejected),
        factor_blocks=jacobian, linear_detail=linear, resources_by_unit=by_unit,
        resources=total, utilization=utilization(total, params),
        memory=memory_words(program), power_w=power_w(total, solver.clock_mhz, params),
        linear_precision=solver.les_precision)


def _cycles(program: Program, ops: OperatorTable, les_ops: OperatorTable, params: CostParams,
            jacobian: tuple[BlockTiming, ...], cost: int,
            linear: QrTiming | CholeskyTiming) -> tuple[UnitCycles, UnitCycles]:
    """(one accepted iteration, one rejected step) by unit; ``les_ops``: the linear solver's
    operators (the HGC's included)."""
    factor = sum(b.cycles for b in jacobian)
    hessian = 0
    if isinstance(linear, CholeskyTiming):
        # The HGC eats the factor block's stream: only what outlasts it adds, and at least
        # its own pipeline tail.
        tail = les_ops.mul.latency + 2 * les_ops.add.latency
        hessian = max(linear.hgc_stream - factor, tail)
    update = retract_cycles(program, ops, params)
    decision = ops.path_latency(params.lm_decision_path) if program.solver.method == "lm" \
        else ops.add.latency  # GN: only the convergence comparison
    phases = 5 + (hessian > 0)  # handshakes between the phases of the pipeline above
    accepted = UnitCycles(factor, cost, hessian, linear.factorization,
                          linear.back_substitution, update,
                          phases * params.phase_cycles + decision)
    retry = UnitCycles(0, cost, 0, linear.factorization, linear.back_substitution, update,
                       4 * params.phase_cycles + decision)
    return accepted, retry


def retract_cycles(program: Program, ops: OperatorTable, params: CostParams) -> int:
    """Retract every variable: pipelined, one variable per cycle unless Lie coefficients
    (``retract_specials`` per Lie-group variable) saturate the update unit's special units."""
    special = ops.special
    lie_ii = max(1, math.ceil(params.retract_specials * special.ii
                              / max(1, params.retract_pool.special)))
    # A variable stored in more numbers than its dimension (Pose3: 12 for 6) is a Lie group.
    issue = sum(lie_ii if v.storage_dim > v.dim else 1 for v in program.variables)
    return ops.path_latency(params.retract_path) + issue
