"""The operator table of the accelerator plan: latency and cost of each floating-point operator.

One frozen table per precision, read by :mod:`fgc_backends.hls.plan` (and, later, by the emitter
and the cost model). Every entry is an :class:`Operator` carrying its ``source`` and whether its
numbers are ``documented`` (read from the cited document) or ``assumed`` (chosen, with the reason
in ``note``). Target: Zynq-7000 xc7z045, -2 speed grade, 143 MHz (7 ns), the part and clock of
both papers; Zynq-7000 programmable logic is Kintex-7 class fabric.

Sources:

- **PG060**: Xilinx LogiCORE *Floating-Point Operator v7.1* product guide and its per-family
  resource-utilisation page (xilinx.com "ip_docs/pru_files/floating-point.html": Fmax, LUT, FF,
  DSP per configuration and family). The search tool found the guide and that page, but no stored
  excerpt reached their latency or utilisation rows (the stored copies of PG060, DS816 and DS335
  hold the title pages only), so no number here is read from PG060 itself. Structure that *is*
  PG060's own description (and not a number): the add/sub and multiply cores use DSP48E1 slices
  in "full usage", divide and square root are LUT/FF-only iterative-digit designs whose latency
  grows with the fraction width (≈ mantissa bits + a few cycles), and compare is a LUT-only core.
  The core's older data sheet (DS816, v6.0, which adds Zynq-7000 to the families) lists
  reciprocal and reciprocal square root among its operators; whether Vitis HLS binds
  ``1/sqrt(x)`` to that operator was not established, so ``recip_sqrt`` is costed as sqrt then
  divide.
- **Clash**: the Clash compiler's binding of that core, ``clash-cores`` module
  ``Clash.Cores.Xilinx.Floating`` (github.com/clash-lang/clash-compiler,
  clash-cores/src/Clash/Cores/Xilinx/Floating/Explicit.hs, "The default delay for floating
  point addition with default customization"), documents the core's *maximum* latency for
  single precision with its default customisation (speed-optimised, full DSP usage): add and
  subtract 11, multiply 8, divide 28 cycles, compare 2. Those are the float32 latencies below
  (status ``documented``). PG060's "Latency and Rate Configuration" section (quoted in the
  Clash pull request that added these defaults, github.com/clash-lang/clash-compiler/pull/2333)
  says the latency can be set between 0 and that maximum and that a slower clock meets timing
  with fewer stages: the maximum is an upper bound at 143 MHz, where Vitis HLS picks fewer
  stages (its generated cores are named by their stage count, e.g. ``fadd_..._5_full_dsp`` in
  public Vitis projects, at clocks this table does not know). Their DSP/LUT/FF, and all
  float64, square-root and HLS-math entries, remain ``assumed`` (``resource_status`` says which
  half of an entry is sourced): no stored source gives them for the xc7z045.
- **UG1399**: *Vitis HLS User Guide*, "HLS Math Library": functions in ``hls_math.h`` are
  synthesisable bit-approximate implementations (1-4 ULP) in single and double precision. The
  guide gives no latency/resource table for them; latency and cost here are ``assumed``.
- **design**: a choice of this plan, explained in the note.

Where this table and ``backends/cost/params.py`` disagree (see :data:`DISAGREEMENTS`): the
sim table has no ``compare`` or ``recip_sqrt`` kind, lumps sin/cos/atan2 into one ``trig`` kind
and has no ``exp``/``log``; it models the Lie coefficients as one ``special`` unit (series +
closed form). The numbers of the kinds both have were kept equal on purpose; the float32 add and
multiply latencies now differ (11 and 8 here, documented; 8 and 5 there, assumed).
"""

from __future__ import annotations

from dataclasses import dataclass, fields

PRECISIONS = ("float32", "float64")


@dataclass(frozen=True)
class Operator:
    """One pipelined operator instance (II = ``ii``): latency, DSP48E1/LUT/FF, provenance."""

    latency: int
    dsp: int
    lut: int
    ff: int
    source: str
    status: str  # "documented" or "assumed"
    note: str = ""
    ii: int = 1
    resource_status: str = "assumed"  # of dsp/lut/ff; ``status`` is the latency's


    def __post_init__(self):
        for st in (self.status, self.resource_status):
            if st not in ("documented", "assumed"):
                raise ValueError(f"operator status must be documented or assumed, got {st}")
        if not self.source:
            raise ValueError("every operator entry needs a source")


@dataclass(frozen=True)
class OperatorTable:
    """All operators of one precision at one clock on one part."""

    precision: str
    word_bits: int
    clock_mhz: float
    part: str
    add: Operator  # add / subtract
    mul: Operator
    div: Operator
    sqrt: Operator
    recip_sqrt: Operator
    compare: Operator
    sincos: Operator  # sin or cos (one call)
    atan2: Operator
    exp: Operator
    log: Operator
    special: Operator  # one Lie coefficient (series and closed form, selected)

    def op(self, kind: str) -> Operator:
        """The operator of ``kind``; kernel kinds ``trig`` map to ``sincos``."""
        kind = KERNEL_KINDS.get(kind, kind)
        if kind not in OPERATOR_KINDS:
            raise KeyError(f"no operator kind {kind!r} (known: {', '.join(OPERATOR_KINDS)})")
        return getattr(self, kind)

    def entries(self) -> tuple[tuple[str, Operator], ...]:
        return tuple((k, getattr(self, k)) for k in OPERATOR_KINDS)


OPERATOR_KINDS = ("add", "mul", "div", "sqrt", "recip_sqrt", "compare", "sincos", "atan2", "exp",
                  "log", "special")
# fgc.compiler.kernel.OP_KINDS -> operator kinds of this table
KERNEL_KINDS = {"trig": "sincos"}

_PG = "PG060 (Floating-Point Operator v7.1), 7-series"
_SIM = "equal to backends/cost/params.py [PG060] until the PG060 rows are read"
_CLASH = ("Clash clash-cores Clash.Cores.Xilinx.Floating (Explicit.hs): maximum latency of "
          "Floating-Point Operator v7.1, single, speed-optimised, full DSP usage")
_RES = "DSP/LUT/FF " + _SIM
_UG = "UG1399 Vitis HLS Math Library (hls_math.h); no latency table published there"

FLOAT32 = OperatorTable(
    precision="float32", word_bits=32, clock_mhz=143.0, part="xc7z045-2",
    add=Operator(11, 2, 220, 370, _CLASH, "documented",
                 "latency 11 (was 8, assumed); " + _RES + "; full-DSP add/sub"),
    mul=Operator(8, 3, 80, 150, _CLASH, "documented",
                 "latency 8 (was 5, assumed); " + _RES + "; full-DSP multiply"),
    div=Operator(28, 0, 800, 1400, _CLASH, "documented",
                 "latency 28 (≈ 24-bit fraction + 4, PG060's structure); " + _RES
                 + "; LUT-only"),
    sqrt=Operator(28, 0, 500, 820, _PG, "assumed", _SIM + "; LUT-only, like divide"),
    recip_sqrt=Operator(32, 0, 1300, 2200, _PG, "assumed",
                        "design: bound as sqrt then divide when the core's rsqrt is not used "
                        "(HLS binds 1/sqrt(x) so); LUT/FF = sqrt + div"),
    compare=Operator(2, 0, 40, 30, _CLASH, "documented",
                     "latency 2; LUT/FF assumed; LUT-only compare core"),
    sincos=Operator(40, 12, 2800, 3000, _UG, "assumed",
                    "equal to sim params [HLS-math] trig: range reduction + polynomial"),
    atan2=Operator(48, 12, 3200, 3400, _UG, "assumed",
                   "design: sincos-like polynomial plus a divide-free octant reduction"),
    exp=Operator(30, 8, 1500, 1800, _UG, "assumed", "not used by the kernels today"),
    log=Operator(30, 8, 1700, 2000, _UG, "assumed", "not used by the kernels today"),
    special=Operator(160, 17, 4200, 5800, "design", "assumed",
                     "sim params [Lie]: 12 Horner terms × (mul + add) beside the closed form",
                     ii=12),
)

FLOAT64 = OperatorTable(
    precision="float64", word_bits=64, clock_mhz=143.0, part="xc7z045-2",
    add=Operator(12, 3, 680, 1000, _PG, "assumed", _SIM + "; full-DSP add/sub"),
    mul=Operator(9, 11, 200, 420, _PG, "assumed", _SIM + "; full-DSP multiply"),
    div=Operator(57, 0, 3200, 6000, _PG, "assumed",
                 _SIM + "; LUT-only, latency ≈ 53-bit fraction + 4 (PG060's structure)"),
    sqrt=Operator(57, 0, 1800, 3300, _PG, "assumed", _SIM + "; LUT-only, like divide"),
    recip_sqrt=Operator(66, 0, 5000, 9300, _PG, "assumed",
                        "design: sqrt then divide; LUT/FF = sqrt + div"),
    compare=Operator(2, 0, 70, 40, _PG, "assumed", "LUT-only compare core"),
    sincos=Operator(60, 30, 7000, 7000, _UG, "assumed", "equal to sim params [HLS-math] trig"),
    atan2=Operator(72, 30, 8000, 8000, _UG, "assumed", "design: like sincos plus reduction"),
    exp=Operator(45, 20, 4000, 4500, _UG, "assumed", "not used by the kernels today"),
    log=Operator(45, 20, 4500, 5000, _UG, "assumed", "not used by the kernels today"),
    special=Operator(470, 44, 11700, 15000, "design", "assumed",
                     "sim params [Lie]: 22 Horner terms × (mul + add) beside the closed form",
                     ii=22),
)

TABLES = {"float32": FLOAT32, "float64": FLOAT64}

DISAGREEMENTS = (
    "float32 add / multiply latency: 11 / 8 here (documented, Clash's binding of PG060's core), "
    "8 / 5 in sim params (assumed)",
    "sim params has no compare kind: its LM decision path ignores the compare latency",
    "sim params has no recip_sqrt: Householder α/τ are modelled as sqrt + div there too",
    "sim params 'trig' stands for sin, cos and atan alike; here atan2 is its own, dearer entry",
    "sim params has no exp/log (no kernel uses them; listed here for completeness)",
    "ap_fixed: no entry here or there - fixed point is not a precision fgc supports yet",
)


def table(precision: str) -> OperatorTable:
    """The operator table of ``precision``."""
    try:
        return TABLES[precision]
    except KeyError:
        raise ValueError(f"precision must be one of {', '.join(PRECISIONS)}, "
                         f"got {precision!r}") from None


def describe(t: OperatorTable) -> str:
    """A Markdown table of ``t``: kind, latency, DSP, LUT, FF, status, source."""
    lines = [f"| {t.precision} | latency | II | DSP | LUT | FF | status | source / note |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for kind, o in t.entries():
        status = o.status if o.status == o.resource_status else (
            f"latency {o.status}, resources {o.resource_status}")
        lines.append(f"| {kind} | {o.latency} | {o.ii} | {o.dsp} | {o.lut} | {o.ff} | "
                     f"{status} | {o.source}; {o.note} |")
    return "\n".join(lines)


assert tuple(f.name for f in fields(OperatorTable))[4:] == OPERATOR_KINDS
