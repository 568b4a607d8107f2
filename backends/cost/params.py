"""Every number the cost model assumes, as named, documented parameters.

Each field of :class:`OperatorCost`, :class:`OperatorCounts`, :class:`Device` and
:class:`CostParams` carries ``metadata["doc"]`` (what it is, its unit, where the default comes
from); :func:`describe` prints them as a table. The defaults describe a Zynq-7000 ZC706 (xc7z045)
at 143 MHz, the board and clock of both papers.

Sources and assumptions, once (the per-field notes refer to them):

- **[PG060]** the operators' latencies and resources are the HLS backend's one operator table
  (``backends/cost/operators.py``: per part family, precision and clock, each row with its
  source — Vitis core names, PG060's maximum latencies — or "assumed" with the reason);
  :func:`view` gives this model its six kinds. The defaults are the xc7z045's at 143 MHz.
- **[HLS-math]** ``hls::sin``/``cos`` of the Vitis HLS math library: range reduction plus a
  polynomial, a few DSPs and ~3 k LUTs, latency of a few tens of cycles.
- **[Lie]** fgc's Lie coefficients (``fgc.frontend.geometry.special``) are a Horner series in t =
θ² for
  small angles *and* a closed form (sin/cos and a divide) selected by t; the hardware computes
  both. The series is the longer path: 12 terms × (mul + add) in float32 (22 in float64, for the
  D coefficient's Bernoulli series). One rolled Horner loop per unit, so a unit accepts a new
  argument every ``terms`` cycles (``ii``).
- **[B]** paper B (docs/design.md): "each CPE adds 6 DSPs"; Vivado power estimates C1 (20 CPEs)
  2.293 W, C2 (40) 2.956 W, C3 (80) 3.759 W.
- **[fit]** values fitted to paper B's published points (``bench/bench_cost_model.py`` prints
  the fit): the power coefficients (static + one scale on XPE-like per-resource weights).
- **[design]** a design choice of the modelled accelerator (unit counts, lanes, stream widths):
  sized to fit the xc7z045 next to paper B's largest design (80 CPEs).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Literal

from . import operators
from .target import DEFAULT


def _doc(default, doc: str):
    """A dataclass field with its documentation in ``metadata["doc"]``."""
    return field(default=default, metadata={"doc": doc})


def _doc_factory(factory, doc: str):
    return field(default_factory=factory, metadata={"doc": doc})


@dataclass(frozen=True)
class OperatorCost:
    """One pipelined floating-point operator: latency, issue interval and resources."""

    latency: int = _doc(1, "cycles from operands to result")
    dsp: int = _doc(0, "DSP48E1 slices per operator instance")
    lut: int = _doc(0, "LUTs per operator instance")
    ff: int = _doc(0, "flip-flops per operator instance")
    ii: int = _doc(1, "cycles between two issues to one instance (1 = fully pipelined)")


@dataclass(frozen=True)
class OperatorCounts:
    """A number per operator kind — a pool of operator instances, or ops on a critical path."""

    add: int = _doc(0, "floating-point add/subtract operators")
    mul: int = _doc(0, "floating-point multiply operators")
    div: int = _doc(0, "floating-point divide (also reciprocal)")
    sqrt: int = _doc(0, "floating-point square root")
    trig: int = _doc(0, "sin/cos/atan-like library function [HLS-math]")
    special: int = _doc(0, "Lie coefficient or SO(3) log component [Lie]")

    def items(self) -> tuple[tuple[str, int], ...]:
        """(kind, count) pairs in the fixed kind order."""
        return tuple((f.name, getattr(self, f.name)) for f in fields(self))


KINDS: tuple[str, ...] = tuple(f.name for f in fields(OperatorCounts))


@dataclass(frozen=True)
class OperatorTable:
    """Operator costs for one precision, one :class:`OperatorCost` per kind."""

    word_bits: int = _doc(32, "bits per stored word (BRAM sizing)")
    add: OperatorCost = _doc(OperatorCost(), "cost of one add/subtract operator")
    mul: OperatorCost = _doc(OperatorCost(), "cost of one multiply operator")
    div: OperatorCost = _doc(OperatorCost(), "cost of one divide operator")
    sqrt: OperatorCost = _doc(OperatorCost(), "cost of one square-root operator")
    trig: OperatorCost = _doc(OperatorCost(), "cost of one sin/cos/atan unit")
    special: OperatorCost = _doc(OperatorCost(), "cost of one Lie-coefficient / SO(3)-log unit")
    atan2: OperatorCost | None = _doc(None, "cost of one arctangent (atan2, atan, asin, acos) "
                                      "where it differs from a sin/cos (None: the trig figure); "
                                      "the critical path takes its latency")

    def cost(self, kind: str) -> OperatorCost:
        """The cost of operator ``kind`` (one of :data:`KINDS`)."""
        return getattr(self, kind)

    def path_latency(self, path: OperatorCounts) -> int:
        """Cycles of a dependent chain holding ``path``'s operators."""
        return sum(n * self.cost(kind).latency for kind, n in path.items())


def view(ops: operators.OperatorTable) -> OperatorTable:
    """This model's per-kind view of the one operator table (``backends/cost/operators.py``):
    its six kinds, ``trig`` being one sin/cos call."""
    def c(o):
        return OperatorCost(latency=o.latency, dsp=o.dsp, lut=o.lut, ff=o.ff, ii=o.ii)

    return OperatorTable(word_bits=ops.word_bits, add=c(ops.add), mul=c(ops.mul),
                         div=c(ops.div), sqrt=c(ops.sqrt), trig=c(ops.sincos),
                         special=c(ops.special), atan2=c(ops.atan2))


# the default target's (xc7z045, 143 MHz) operators, read from the one table [PG060]
FLOAT32 = view(operators.FLOAT32)
FLOAT64 = view(operators.FLOAT64)


@dataclass(frozen=True)
class Device:
    """Capacity of the target FPGA (utilisation is reported against it)."""

    name: str = _doc(DEFAULT.name, "device name (ZC706 board; the table in cost/target.py)")
    dsp: int = _doc(DEFAULT.dsp, "DSP48E1 slices (cost/target.py)")
    bram36: int = _doc(DEFAULT.bram36, "36 Kb block RAMs (cost/target.py)")
    lut: int = _doc(DEFAULT.lut, "6-input LUTs (cost/target.py)")
    ff: int = _doc(DEFAULT.ff, "flip-flops (cost/target.py)")
    bram_bits: int = _doc(36_864, "bits per BRAM36 (36 Kb); a BRAM18 is half")


@dataclass(frozen=True)
class CostParams:
    """All latencies, unit sizes, resource and power coefficients of the cost model.

    Unit *counts* that the compiler chooses (n_u Update units, #CPE, clock, precision) come from
    the Program's :class:`fgc.ir.program.SolverConfig`; everything else is here. Latencies are in
    cycles at ``SolverConfig.clock_mhz`` (the defaults assume 143 MHz; they are not rescaled if
    the clock changes — re-time the operators instead).
    """

    float32: OperatorTable = _doc(FLOAT32, "operator costs in float32 [PG060][HLS-math][Lie]")
    float64: OperatorTable = _doc(FLOAT64, "operator costs in float64 [PG060][HLS-math][Lie]")
    device: Device = _doc_factory(Device, "target device capacities")

    # -- factor block (EJCC) ----------------------------------------------------------------
    factor_pool: OperatorCounts = _doc(
        OperatorCounts(add=16, mul=24, div=4, sqrt=2, trig=2, special=2),
        "operator instances of the factor block, time-shared by every block type; a block "
        "type's initiation interval is max over kinds of ceil(ops × ii / instances); kinds "
        "no kernel uses are not instantiated [design]")
    factor_store_ports: int = _doc(
        8, "words per cycle the factor block writes to the A/b store (QR) — BRAM banks × "
        "ports; a factor's stored words / ports bounds its initiation interval [design]")
    share_lut_per_bit: float = _doc(
        0.25, "LUTs of operand multiplexing per kernel operation per word bit when a kernel's "
        "operations share the pool (a LUT6 is a 4:1 mux bit; ~1 extra input per op) [design]")
    balanced_reductions: bool = _doc(
        True, "sums and products of many terms are reduced as trees, earliest operands first, "
        "as the HLS printer prints them (cfamily/trees.py; False: left-to-right chains in "
        "printed order, what Vitis builds from flat text: it does not reassociate floats)")

    # -- HGC (Cholesky path) ----------------------------------------------------------------
    hgc_lanes: int = _doc(
        16, "multiply-accumulate lanes of the Hessian/gradient unit; H = JᵀJ, g = Jᵀr over "
        "the structurally non-zero whitened Jacobian entries only [design]")

    # -- Cholesky LES (paper B) -------------------------------------------------------------
    cpe_ops: OperatorCounts = _doc(
        OperatorCounts(add=1, mul=1, div=1, sqrt=1),
        "operators of one CPE: Evaluate = sqrt + divide (l_jj, l_ij = s_ij / l_jj); Update = "
        "one multiply-subtract lane (s_ik −= l_ij·l_kj)")
    cpe_extra_dsp: int = _doc(
        1, "DSPs of a CPE beyond its operators (index/address arithmetic) — makes a float32 "
        "CPE 6 DSPs as paper B reports [B]")
    cpe_bram: float = _doc(0.5, "BRAM36 per CPE: one BRAM18 for its column buffer / FIFO [design]")
    cpe_words_per_cycle: int = _doc(1, "words per cycle streamed through the CPE cascade")
    cholesky_stream: Literal["whole", "trailing", "dense"] = _doc(
        "whole", "what each round streams through the cascade: 'whole' = the whole stored "
        "(structurally non-zero) lower triangle of [L | g], finished columns passing through "
        "— the compressed, index-free layout is read from its start; 'trailing' = only the "
        "columns not yet factored; 'dense' = the trailing m × m lower triangle with its zeros "
        "(an index-free dense cascade). With 8 iterations 'whole' matches paper B's two N = 50 "
        "points; 'dense' matches their ratio and 'N = 20 under 1 ms' but only with ≈ 1.7 "
        "solves per solve (bench/bench_cost_model.py prints all three) [fit]")
    solve_lanes: int = _doc(
        1, "multiply-accumulate lanes of the triangular solve Lᵀδ = z (Lz = g runs in the "
        "cascade as the augmented column g) [design]")

    # -- partial QR (paper A) ---------------------------------------------------------------
    qr_unit_sets: int = _doc(
        2, "most sets of QR + back-substitution blocks; a Program gets min(this, widest "
        "schedule level): two for two-ended chains, one for serial elimination [A]")
    evaluate_lanes: int = _doc(1, "multiply-accumulate lanes of an Evaluate unit (‖x‖²)")
    update_lanes: int = _doc(
        1, "multiply-accumulate lanes of one Update unit: a column update is a dot product "
        "vᵀa then an axpy a −= τ(vᵀa)v, both streamed through the lane")
    evaluate_ops: OperatorCounts = _doc(
        OperatorCounts(add=2, mul=2, div=1, sqrt=1),
        "operators of an Evaluate unit: MAC for ‖x‖², sqrt, α and τ = 1/(α·v0), 1/R_kk")
    backsub_lanes: int = _doc(1, "multiply-accumulate lanes of a back-substitution unit")

    # -- state update and control -----------------------------------------------------------
    retract_path: OperatorCounts = _doc(
        OperatorCounts(add=4, mul=4, special=1),
        "operators on the critical path of one retract (Pose3 Expmap: a Lie coefficient, "
        "then R·[ω]× products and sums); variables are pipelined one per cycle")
    retract_pool: OperatorCounts = _doc(
        OperatorCounts(add=3, mul=4, special=1),
        "operator instances of the state-update unit [design]")
    retract_specials: int = _doc(
        3, "Lie coefficients per Lie-group variable retract (A, B, C of SE(3)); they bound "
        "the update unit's initiation interval through the special unit's ii")
    phase_cycles: int = _doc(
        16, "handshake cycles between two dataflow phases (start/done, FIFO drain check)")
    lm_decision_path: OperatorCounts = _doc(
        OperatorCounts(add=2, mul=2, div=1),
        "critical path of the trust-region decision after a cost evaluation (gain ratio, "
        "μ update)")
    control_lut: int = _doc(6_000, "LUTs of the controller, sequencer and AXI interfaces [design]")
    control_ff: int = _doc(9_000, "flip-flops of the controller and interfaces [design]")
    memory_min_bram: float = _doc(
        0.5, "smallest BRAM allocation of one memory (a BRAM18 = 0.5 BRAM36)")

    # -- power (paper B's Vivado estimates) ---------------------------------------------------
    power_static_w: float = _doc(
        0.79, "power independent of the modelled units, W: device static power plus whatever "
        "of the processing system and I/O Vivado's estimate includes [fit]")
    power_dsp_mw: float = _doc(1.20, "dynamic mW per DSP48E1 at the reference clock [fit]")
    power_lut_mw: float = _doc(0.0080, "dynamic mW per LUT at the reference clock [fit]")
    power_ff_mw: float = _doc(0.0012, "dynamic mW per flip-flop at the reference clock [fit]")
    power_bram_mw: float = _doc(1.60, "dynamic mW per BRAM36 at the reference clock [fit]")
    power_reference_mhz: float = _doc(
        143.0, "clock of the dynamic coefficients; dynamic power scales linearly with clock")

    def operators(self, precision: str) -> OperatorTable:
        """The operator table of ``precision`` ("float32" or "float64")."""
        if precision not in ("float32", "float64"):
            raise ValueError(f"precision must be float32 or float64, got {precision!r}")
        return getattr(self, precision)


def describe(cls: type = CostParams) -> str:
    """A Markdown table of ``cls``'s fields: name, default, documentation."""
    lines = ["| parameter | default | meaning |", "| --- | --- | --- |"]
    instance = cls()
    for f in fields(cls):
        lines.append(f"| `{f.name}` | `{getattr(instance, f.name)!r}` | {f.metadata['doc']} |")
    return "\n".join(lines)
