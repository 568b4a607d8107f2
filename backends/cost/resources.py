"""Resources (DSP, BRAM, LUT, FF) from unit counts, memory words from the plan, and power.

Every unit is its operator instances × the per-operator costs of the precision's table, plus
what the unit needs beyond operators (a CPE's index arithmetic, the factor block's operand
multiplexers, the controller). BRAM comes from the memory words: each memory rounds up to
BRAM18 halves of a BRAM36, the factor block's A/b store is banked ``factor_store_ports`` ways.
"""

from __future__ import annotations

import math

from fgc.ir.program import Program

from .kernels import factor_pool_ops, used_pool
from .params import CostParams, OperatorCounts, OperatorTable
from .report import MemoryWords, Resources, UnitResources, Utilization


def operator_resources(pool: OperatorCounts, ops: OperatorTable) -> Resources:
    """Resources of a pool of operator instances."""
    out = Resources()
    for kind, n in pool.items():
        c = ops.cost(kind)
        out = out + Resources(n * c.dsp, 0.0, n * c.lut, n * c.ff)
    return out


def memory_words(program: Program) -> MemoryWords:
    """Words of every on-chip memory (module docstring of :mod:`.report`)."""
    n = sum(v.dim for v in program.variables)
    system = program.storage.steps[-1].words
    r_words = program.schedule.r_nonzeros
    if program.solver.linear == "qr":
        factor = r_words + n  # R and its right-hand side d
    else:
        factor = max(0, r_words + n - system)  # L overwrites H; only fill needs more words
    state = 2 * sum(v.storage_dim for v in program.variables)
    measurements = sum(
        sum(size for _, size in m.measurements) + m.noise_params
        for f in program.factors for m in program.blocks[f.block].members)
    bits = 32 if program.solver.precision == "float32" else 64
    les_bits = 32 if program.solver.les_precision == "float32" else 64
    return MemoryWords(bits, system, program.storage.dense_words, factor, state, 2 * n,
                       measurements, les_bits)


def bram_of(words: int, bits: int, banks: int, params: CostParams) -> float:
    """BRAM36 for ``words`` split over ``banks`` memories, each at least ``memory_min_bram``."""
    if words <= 0:
        return 0.0
    per_bank = math.ceil(words / banks) * bits
    halves = math.ceil(per_bank / (params.device.bram_bits / 2))
    return banks * max(params.memory_min_bram, halves / 2)


def memory_resources(memory: MemoryWords, program: Program, params: CostParams) -> Resources:
    """BRAM of all memories; the A/b store (QR) is banked for the factor block's ports."""
    bits, les_bits = memory.word_bits, memory.linear_bits
    banks = params.factor_store_ports if program.solver.linear == "qr" else 1
    bram = bram_of(memory.linear_system, les_bits, banks, params)
    for words, width in ((memory.factor, les_bits), (memory.state, bits),
                         (memory.vectors, les_bits), (memory.measurements, bits)):
        bram += bram_of(words, width, 1, params)
    return Resources(bram=bram)


def unit_resources(program: Program, ops: OperatorTable, params: CostParams,
                   qr_sets: int, les_ops: OperatorTable | None = None) -> UnitResources:
    """Resources of every unit of the accelerator ``program`` describes; the Hessian, linear
    and back-substitution units use ``les_ops`` (the linear solver's precision; default
    ``ops``)."""
    les_ops = les_ops or ops
    mac = operator_resources(OperatorCounts(add=1, mul=1), les_ops)
    mux = int(params.share_lut_per_bit * ops.word_bits * factor_pool_ops(program))
    factor = operator_resources(used_pool(program, params.factor_pool), ops) + Resources(lut=mux)
    if program.solver.linear == "cholesky":
        cpe = operator_resources(params.cpe_ops, les_ops) + Resources(
            dsp=params.cpe_extra_dsp, bram=params.cpe_bram)
        hessian = mac.scaled(params.hgc_lanes)
        linear = cpe.scaled(program.solver.cpe)
        back = mac.scaled(params.solve_lanes)
    else:
        hessian = Resources()
        qr_set = operator_resources(params.evaluate_ops, les_ops) + mac.scaled(
            program.solver.units * params.update_lanes)
        linear = qr_set.scaled(qr_sets)
        back = mac.scaled(params.backsub_lanes * qr_sets)
    update = operator_resources(params.retract_pool, ops)
    control = operator_resources(params.lm_decision_path, ops) + Resources(
        lut=params.control_lut, ff=params.control_ff)
    memory = memory_resources(memory_words(program), program, params)
    return UnitResources(factor, hessian, linear, back, update, control, memory)


def utilization(total: Resources, params: CostParams) -> Utilization:
    """Fractions of the device's DSP, BRAM, LUT and FF."""
    d = params.device
    return Utilization(total.dsp / d.dsp, total.bram / d.bram36, total.lut / d.lut,
                       total.ff / d.ff)


def power_w(total: Resources, clock_mhz: float, params: CostParams) -> float:
    """Static power plus dynamic power proportional to resources and clock."""
    dynamic_mw = (total.dsp * params.power_dsp_mw + total.lut * params.power_lut_mw
                  + total.ff * params.power_ff_mw + total.bram * params.power_bram_mw)
    return params.power_static_w + dynamic_mw * 1e-3 * clock_mhz / params.power_reference_mhz
