"""The one operator table: latency (the stages Vitis HLS binds), II and DSP/LUT/FF of each
floating-point operator, keyed by part family, precision and clock.

Every pricer reads it through the design's :class:`fgc_backends.hls.target.Target` (part and
clock): the accelerator plan, the update and window models, the HLS lint's DSP budget and the
analytic cost model (``backends/cost/params.py`` takes its per-kind view, :func:`table`, from
here: there is no second table). :func:`table` picks the row set of ``(family, precision)`` whose
clock band holds the clock.

Families: ``7series`` (Zynq-7000, Kintex-7-class fabric: xc7z…) and ``ultrascale+`` (Zynq
UltraScale+: xczu…). Clock bands: up to 150 MHz (the papers' 143 MHz, 7 ns) and above.

Sources, per row (``Operator.source``, ``status`` for the latency, ``resource_status`` for
DSP/LUT/FF):

- **Vitis core names**: Vitis HLS names each floating-point core it binds
  ``<op>_<in>ns_<in>ns_<out>_<stages>_<impl>`` and records its scheduled ``LATENCY`` (= stages -
  1) in its ``SynModuleInfo``; public Vitis HLS projects' generated files hold, e.g.,
  ``fadd_32ns_32ns_32_4_full_dsp`` (LATENCY 3) and ``fadd_32ns_32ns_32_5_full_dsp`` (LATENCY
  4), ``fmul_32ns_32ns_32_3_max_dsp`` (2) and ``fmul_32ns_32ns_32_4_max_dsp`` (3),
  ``fdiv_32ns_32ns_32_16_no_dsp`` (15) and ``fdiv_32ns_32ns_32_10_no_dsp`` (9),
  ``fcmp_32ns_32ns_1_2_no_dsp`` (1); in double ``dadd_64ns_64ns_64_5_full_dsp`` (4) and
  ``_7_`` (6), ``dmul_64ns_64ns_64_5_max_dsp`` (4) and ``_7_`` (6),
  ``ddiv_64ns_64ns_64_22_no_dsp`` (21), ``_31_`` (30) and ``_59_`` (58). The latencies are
  documented by those names; *which* binding a part family takes at a clock is not (the
  projects' part and clock were not established), so the pairing is assumed: the slower
  7-series fabric takes the deeper of the two common bindings at ≤ 150 MHz, UltraScale+ the
  shallower (the note of each row says so). Square root is bound like divide
  (``fsqrt_32ns_32ns_32_16_no_dsp`` beside ``fdiv_…_16_no_dsp``); double square root is
  assumed equal to double divide.
- **PG060 maximum**: above 150 MHz the core's *maximum* latency for the default
  customisation (speed-optimised, full DSP usage), single precision add 11, multiply 8,
  divide 28, compare 2, as the Clash compiler's binding of the Floating-Point Operator core
  documents them (clash-cores ``Clash.Cores.Xilinx.Floating``); double assumed in proportion.
  PG060 says the latency may be set between 0 and that maximum and that a slower clock meets
  timing with fewer stages, which is what the ≤ 150 MHz rows are.
- **PG060 structure** (not a number): add/sub and multiply use DSP slices in full/max usage,
  divide and square root are LUT/FF-only iterative designs, compare is LUT-only. DSP/LUT/FF
  figures are assumed (no stored source gives them per family): 7-series float32 add 2 DSP,
  multiply 3; float64 add 3, multiply 11; UltraScale+'s DSP48E2 (27 × 18 multiplier) is taken
  to need the same counts.
- **UG1399** (Vitis HLS Math Library, ``hls_math.h``): sin/cos, atan2, exp, log are
  synthesisable approximations with no published latency table: assumed.
- **design**: fgc's Lie coefficients (series and closed form, one rolled Horner loop a unit).

**Binding** (issue 33): besides Vitis's default binding of add/sub (full DSP) and multiply
(max DSP), which the rows above price, :data:`IMPLEMENTATIONS` lists the implementations a
design may bind them to (``DesignOptions.bind``, run_hls.tcl's ``config_op``): add fulldsp or
fabric, multiply maxdsp, fulldsp, meddsp or fabric, each with its DSP/LUT/FF and source
(:func:`implementations`) at the row's latency; :func:`bound` is a table so bound (what
``Target.ops`` returns for a design's binding). docs/hls.md, "Operator binding: DSP or fabric".

Before this table (issue 32): this module (the plan: float32 add 11, mul 8,
div/sqrt 28, compare 2; float64 12 / 9 / 57) and ``backends/cost/params.py`` (the analytic
model: float32 add 8, mul 5, div/sqrt 28) disagreed, and neither knew the part or the clock.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from functools import lru_cache

from fgc.errors import FgcError

PRECISIONS = ("float32", "float64")
FAMILIES = ("7series", "ultrascale+")
BANDS = (150.0, float("inf"))  # clock bands, MHz: a row set applies up to its band's clock


@dataclass(frozen=True)
class Operator:
    """One pipelined operator instance (II = ``ii``): latency, DSP/LUT/FF, provenance."""

    latency: int
    dsp: int
    lut: int
    ff: int
    source: str
    status: str  # of the latency: "documented" or "assumed"
    note: str = ""
    ii: int = 1
    resource_status: str = "assumed"  # of dsp/lut/ff

    def __post_init__(self):
        for st in (self.status, self.resource_status):
            if st not in ("documented", "assumed"):
                raise ValueError(f"operator status must be documented or assumed, got {st}")
        if not self.source:
            raise ValueError("every operator entry needs a source")


@dataclass(frozen=True)
class OperatorTable:
    """All operators of one precision on one part family in one clock band."""

    precision: str
    word_bits: int
    clock_mhz: float  # the band's upper clock (inf: above the last band)
    part: str  # the part family
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

_CORE = "Vitis core name {} (LATENCY {}) in public Vitis HLS projects"
_PAIR = "; binding for this family and clock assumed (projects' part/clock not established)"
_MAX = ("PG060 maximum latency, single, default customisation (Clash clash-cores "
        "Clash.Cores.Xilinx.Floating)")
_MAX64 = "assumed: PG060 maximum for double, in proportion to the single-precision maximum"
_UG = "UG1399 Vitis HLS Math Library (hls_math.h); no latency table published there"
_RES = "DSP/LUT/FF assumed (PG060 structure: {})"


def _core(latency, dsp, lut, ff, core, impl, pairing=_PAIR):
    return Operator(latency, dsp, lut, ff, _CORE.format(core, latency), "documented",
                    _RES.format(impl) + pairing)


def _shared(word_bits: int, sqrt: Operator, div: Operator, big: bool) -> dict:
    """The entries no core name gives (HLS-math functions, Lie coefficients, 1/sqrt)."""
    rs = Operator(sqrt.latency + div.latency, 0, sqrt.lut + div.lut, sqrt.ff + div.ff,
                  "design", "assumed", "sqrt then divide (HLS binds 1/sqrt(x) so)")
    if not big:
        return dict(recip_sqrt=rs,
                    sincos=Operator(40, 12, 2800, 3000, _UG, "assumed",
                                    "range reduction + polynomial"),
                    atan2=Operator(48, 12, 3200, 3400, _UG, "assumed",
                                   "sincos-like polynomial plus an octant reduction"),
                    exp=Operator(30, 8, 1500, 1800, _UG, "assumed", "not used by the kernels"),
                    log=Operator(30, 8, 1700, 2000, _UG, "assumed", "not used by the kernels"),
                    special=Operator(160, 17, 4200, 5800, "design", "assumed",
                                     "12 Horner terms × (mul + add) beside the closed form",
                                     ii=12))
    return dict(recip_sqrt=rs,
                sincos=Operator(60, 30, 7000, 7000, _UG, "assumed", "range reduction + poly"),
                atan2=Operator(72, 30, 8000, 8000, _UG, "assumed", "like sincos plus reduction"),
                exp=Operator(45, 20, 4000, 4500, _UG, "assumed", "not used by the kernels"),
                log=Operator(45, 20, 4500, 5000, _UG, "assumed", "not used by the kernels"),
                special=Operator(470, 44, 11700, 15000, "design", "assumed",
                                 "22 Horner terms × (mul + add) beside the closed form", ii=22))


def _f32(family: str, band: float, add, mul, div, sqrt, compare) -> OperatorTable:
    return OperatorTable("float32", 32, band, family, add, mul, div, sqrt, compare=compare,
                         **_shared(32, sqrt, div, False))


def _f64(family: str, band: float, add, mul, div, sqrt, compare) -> OperatorTable:
    return OperatorTable("float64", 64, band, family, add, mul, div, sqrt, compare=compare,
                         **_shared(64, sqrt, div, True))


_FULL, _MAXD, _LUT = "full-DSP add/sub", "max-DSP multiply", "LUT-only iterative"
_CMP = _core(1, 0, 40, 30, "fcmp_32ns_32ns_1_2_no_dsp", "LUT-only compare", "")
_CMP64 = Operator(1, 0, 70, 40, "assumed: like fcmp_32ns_32ns_1_2_no_dsp", "assumed",
                  "LUT-only compare")

_MAX32 = dict(add=Operator(11, 2, 220, 370, _MAX, "documented", _RES.format(_FULL)),
              mul=Operator(8, 3, 80, 150, _MAX, "documented", _RES.format(_MAXD)),
              div=Operator(28, 0, 800, 1400, _MAX, "documented", _RES.format(_LUT)),
              sqrt=Operator(28, 0, 500, 820, _MAX, "assumed", "like divide; " + _RES.format(_LUT)),
              compare=Operator(2, 0, 40, 30, _MAX, "documented", _RES.format("LUT-only")))
_MAX64D = dict(add=Operator(12, 3, 680, 1000, _MAX64, "assumed", _RES.format(_FULL)),
               mul=Operator(9, 11, 200, 420, _MAX64, "assumed", _RES.format(_MAXD)),
               div=Operator(57, 0, 3200, 6000, _MAX64, "assumed", _RES.format(_LUT)),
               sqrt=Operator(57, 0, 1800, 3300, _MAX64, "assumed", _RES.format(_LUT)),
               compare=Operator(2, 0, 70, 40, _MAX64, "assumed", _RES.format("LUT-only")))

TABLES: dict[tuple[str, str, float], OperatorTable] = {}
for _family in FAMILIES:
    TABLES[_family, "float32", BANDS[1]] = _f32(_family, BANDS[1], **_MAX32)
    TABLES[_family, "float64", BANDS[1]] = _f64(_family, BANDS[1], **_MAX64D)

# ≤ 150 MHz: the bindings of the Vitis core names (the deeper one on 7-series)
TABLES["7series", "float32", BANDS[0]] = _f32(
    "7series", BANDS[0],
    add=_core(4, 2, 220, 370, "fadd_32ns_32ns_32_5_full_dsp", _FULL),
    mul=_core(3, 3, 80, 150, "fmul_32ns_32ns_32_4_max_dsp", _MAXD),
    div=_core(15, 0, 800, 1400, "fdiv_32ns_32ns_32_16_no_dsp", _LUT),
    sqrt=_core(15, 0, 500, 820, "fsqrt_32ns_32ns_32_16_no_dsp", _LUT),
    compare=_CMP)
TABLES["ultrascale+", "float32", BANDS[0]] = _f32(
    "ultrascale+", BANDS[0],
    add=_core(3, 2, 220, 370, "fadd_32ns_32ns_32_4_full_dsp", _FULL),
    mul=_core(2, 3, 80, 150, "fmul_32ns_32ns_32_3_max_dsp", _MAXD),
    div=_core(9, 0, 800, 1400, "fdiv_32ns_32ns_32_10_no_dsp", _LUT),
    sqrt=Operator(9, 0, 500, 820, "assumed: bound like fdiv_32ns_32ns_32_10_no_dsp", "assumed",
                  _RES.format(_LUT)),
    compare=_CMP)
TABLES["7series", "float64", BANDS[0]] = _f64(
    "7series", BANDS[0],
    add=_core(6, 3, 680, 1000, "dadd_64ns_64ns_64_7_full_dsp", _FULL),
    mul=_core(6, 11, 200, 420, "dmul_64ns_64ns_64_7_max_dsp", _MAXD),
    div=_core(30, 0, 3200, 6000, "ddiv_64ns_64ns_64_31_no_dsp", _LUT),
    sqrt=Operator(30, 0, 1800, 3300, "assumed: bound like ddiv_64ns_64ns_64_31_no_dsp",
                  "assumed", _RES.format(_LUT)),
    compare=_CMP64)
TABLES["ultrascale+", "float64", BANDS[0]] = _f64(
    "ultrascale+", BANDS[0],
    add=_core(4, 3, 680, 1000, "dadd_64ns_64ns_64_5_full_dsp", _FULL),
    mul=_core(4, 11, 200, 420, "dmul_64ns_64ns_64_5_max_dsp", _MAXD),
    div=_core(21, 0, 3200, 6000, "ddiv_64ns_64ns_64_22_no_dsp", _LUT),
    sqrt=Operator(21, 0, 1800, 3300, "assumed: bound like ddiv_64ns_64ns_64_22_no_dsp",
                  "assumed", _RES.format(_LUT)),
    compare=_CMP64)

# the default design's tables (Zynq-7000 at 143 MHz)
FLOAT32 = TABLES["7series", "float32", BANDS[0]]
FLOAT64 = TABLES["7series", "float64", BANDS[0]]


def table(precision: str, family: str = "7series", clock_mhz: float = 143.0) -> OperatorTable:
    """The operator table of ``precision`` on ``family`` at ``clock_mhz`` (the row set of the
    first clock band that holds it). Pricers call it through ``Target.ops``."""
    if precision not in PRECISIONS:
        raise ValueError(f"precision must be one of {', '.join(PRECISIONS)}, got {precision!r}")
    if family not in FAMILIES:
        raise ValueError(f"part family must be one of {', '.join(FAMILIES)}, got {family!r}")
    if not float(clock_mhz) > 0:
        raise ValueError(f"clock must be positive, got {clock_mhz!r} MHz")
    band = next(b for b in BANDS if float(clock_mhz) <= b)
    return TABLES[family, precision, band]


# -- the operators' binding (Vitis's config_op / bind_op -impl) -------------------------------
#
# Vitis HLS binds a floating-point add/subtract or multiply to one of several implementations of
# the Floating-Point Operator core (UG1399, config_op and bind_op: ``-impl fabric | meddsp |
# fulldsp | maxdsp | primitivedsp``; primitivedsp is Versal's only): the core's C_Mult_Usage
# No_Usage / Medium_Usage / Full_Usage / Max_Usage (PG060; Vitis's generated core scripts set
# it so: a ``..._no_dsp`` core is ``c_mult_usage No_Usage``). The table above holds the
# default binding (add fulldsp, multiply maxdsp); :data:`IMPLEMENTATIONS` lists what a design
# may bind instead, :func:`implementations` prices each in a table's precision, family and
# clock, and :func:`bound` is that table with the design's binding. An emitted design pins
# every bound operator's latency (``config_op <op> -impl X -latency N``, N the table's), so
# the binding changes DSP / LUT / FF and never a cycle.

IMPLEMENTATIONS = {"add": ("fulldsp", "fabric"), "mul": ("maxdsp", "fulldsp", "meddsp", "fabric")}
DEFAULT_BIND = {"add": "fulldsp", "mul": "maxdsp"}
# the Vitis operator names a bound kind sets in each precision (config_op's <op>)
VITIS_OPS = {("add", "float32"): ("fadd", "fsub"), ("mul", "float32"): ("fmul",),
             ("add", "float64"): ("dadd", "dsub"), ("mul", "float64"): ("dmul",)}

_NO_DSP = ("Vitis core name fadd_32ns_32ns_32_5_no_dsp (SynModuleInfo: TYPE fadd IMPL fabric "
           "LATENCY 4) in public Vitis HLS projects")
_NO_DSP_RES = ("0 DSP, 338 LUT, 243 FF: a public Vitis HLS synthesis report's instance row of "
               "fadd_32ns_32ns_32_5_no_dsp_1 (its part not established: taken for 7-series "
               "and UltraScale+ alike, both 6-input-LUT fabrics)")
_IMPL_NOTE = "PG060 structure: C_Mult_Usage {}; figures assumed"


def _impl_resources(precision: str) -> dict[str, dict[str, tuple]]:
    """(dsp, lut, ff, source, resource_status, note) of each implementation of add and mul in
    ``precision``: the default bindings' figures are the table's own (filled in by
    :func:`implementations`); the others' as each entry says."""
    if precision == "float32":
        return {"add": {"fabric": (0, 338, 243, _NO_DSP, "documented", _NO_DSP_RES)},
                "mul": {
                    "fulldsp": (2, 120, 200, "assumed: PG060 Full_Usage multiply", "assumed",
                                _IMPL_NOTE.format("Full_Usage: the 24 x 24 significand product "
                                                  "in two DSP48 slices, the rounding in LUTs")),
                    "meddsp": (1, 300, 330, "assumed: PG060 Medium_Usage multiply", "assumed",
                               _IMPL_NOTE.format("Medium_Usage: one DSP48 slice takes part of "
                                                 "the significand product, LUTs the rest")),
                    "fabric": (0, 650, 700, "assumed: PG060 No_Usage multiply", "assumed",
                               _IMPL_NOTE.format("No_Usage: the whole 24 x 24 significand "
                                                 "product in LUTs"))}}
    return {"add": {"fabric": (0, 900, 1100, "assumed: PG060 No_Usage double add/subtract",
                               "assumed", _IMPL_NOTE.format("No_Usage: the 53-bit alignment "
                                                            "and add in LUTs"))},
            "mul": {
                "fulldsp": (10, 300, 500, "assumed: PG060 Full_Usage double multiply", "assumed",
                            _IMPL_NOTE.format("Full_Usage")),
                "meddsp": (9, 450, 600, "assumed: PG060 Medium_Usage double multiply", "assumed",
                           _IMPL_NOTE.format("Medium_Usage")),
                "fabric": (0, 2300, 2400, "assumed: PG060 No_Usage double multiply", "assumed",
                           _IMPL_NOTE.format("No_Usage: the 53 x 53 significand product in "
                                             "LUTs"))}}


def implementations(t: OperatorTable) -> dict[str, dict[str, Operator]]:
    """Every implementation of add and mul (:data:`IMPLEMENTATIONS`) in ``t``'s precision,
    family and clock: the default's is ``t``'s own entry; another has its own DSP/LUT/FF and
    ``t``'s latency for the kind (the emitted ``config_op ... -latency N`` pins it; the fabric
    adder's latency is documented by its core name at 4, the 7-series default's)."""
    out = {}
    extra = _impl_resources(t.precision)
    for kind, impls in IMPLEMENTATIONS.items():
        base = t.op(kind)
        out[kind] = {}
        for impl in impls:
            if impl == DEFAULT_BIND[kind]:
                out[kind][impl] = base
                continue
            dsp, lut, ff, source, res_status, note = extra[kind][impl]
            documented = (impl == "fabric" and kind == "add" and t.precision == "float32"
                          and base.latency == 4)
            out[kind][impl] = Operator(
                base.latency, dsp, lut, ff, source, "documented" if documented else "assumed",
                note + ("" if documented else f"; latency {base.latency}: the default "
                        f"binding's at this clock, pinned by config_op -latency"),
                base.ii, res_status)
    return out


class BindError(FgcError, ValueError):
    """A binding names an operator kind or an implementation the table does not have."""


def normalise_bind(bind) -> tuple[tuple[str, str], ...]:
    """``bind`` (``((kind, impl), ...)``, a mapping, or None) checked and in canonical form:
    sorted by kind, the default implementations dropped (so the default design's binding is
    ``()`` however it is spelled). Raises :class:`BindError` naming the allowed values."""
    if not bind:
        return ()
    items = tuple(bind.items()) if isinstance(bind, dict) else tuple(bind)
    seen = {}
    for item in items:
        if not (isinstance(item, tuple) and len(item) == 2):
            raise BindError(f"bind entry {item!r}: expected (kind, implementation) with kind "
                            f"one of {', '.join(IMPLEMENTATIONS)}")
        kind, impl = item
        if kind not in IMPLEMENTATIONS:
            raise BindError(f"bind: operator kind {kind!r} cannot be bound; kinds: "
                            f"{', '.join(IMPLEMENTATIONS)}")
        if impl not in IMPLEMENTATIONS[kind]:
            raise BindError(f"bind: {kind}={impl!r}: implementations of {kind}: "
                            f"{', '.join(IMPLEMENTATIONS[kind])}")
        if kind in seen:
            raise BindError(f"bind names {kind} twice")
        seen[kind] = impl
    return tuple(sorted((k, v) for k, v in seen.items() if v != DEFAULT_BIND[k]))


def parse_bind(text: str) -> tuple[tuple[str, str], ...]:
    """``"add=fabric,mul=meddsp"`` → the binding (:func:`normalise_bind`); ``""`` or
    ``"default"`` → ``()``."""
    text = text.strip()
    if text in ("", "default"):
        return ()
    items = []
    for part in text.split(","):
        kind, sep, impl = part.strip().partition("=")
        if not sep:
            raise BindError(f"bind {part.strip()!r}: expected KIND=IMPL, e.g. add=fabric "
                            f"(kinds {', '.join(IMPLEMENTATIONS)})")
        items.append((kind.strip(), impl.strip()))
    return normalise_bind(tuple(items))


def bind_label(bind) -> str:
    """``add=fabric,mul=meddsp``, or ``default``."""
    bind = normalise_bind(bind)
    return ",".join(f"{k}={v}" for k, v in bind) if bind else "default"


@lru_cache(maxsize=256)
def _bound(t: OperatorTable, bind: tuple[tuple[str, str], ...]) -> OperatorTable:
    impls = implementations(t)
    return replace(t, **{kind: impls[kind][impl] for kind, impl in bind})


def bound(t: OperatorTable, bind=()) -> OperatorTable:
    """``t`` with its add and mul entries bound as ``bind`` says (``t`` itself for the
    default binding)."""
    bind = normalise_bind(bind)
    return _bound(t, bind) if bind else t


def describe(t: OperatorTable) -> str:
    """A Markdown table of ``t``: kind, latency, DSP, LUT, FF, status, source."""
    clock = "> 150 MHz" if t.clock_mhz == BANDS[1] else f"≤ {t.clock_mhz:g} MHz"
    lines = [f"| {t.precision}, {t.part}, {clock} | latency | II | DSP | LUT | FF | status | "
             "source / note |", "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for kind, o in t.entries():
        status = o.status if o.status == o.resource_status else (
            f"latency {o.status}, resources {o.resource_status}")
        lines.append(f"| {kind} | {o.latency} | {o.ii} | {o.dsp} | {o.lut} | {o.ff} | "
                     f"{status} | {o.source}; {o.note} |")
    for kind, impls in implementations(t).items():
        for impl, o in impls.items():
            if impl == DEFAULT_BIND[kind]:
                continue
            status = o.status if o.status == o.resource_status else (
                f"latency {o.status}, resources {o.resource_status}")
            lines.append(f"| {kind} bound {impl} | {o.latency} | {o.ii} | {o.dsp} | {o.lut} | "
                         f"{o.ff} | {status} | {o.source}; {o.note} |")
    return "\n".join(lines)


assert tuple(f.name for f in fields(OperatorTable))[4:] == OPERATOR_KINDS
