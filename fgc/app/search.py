"""Design-space search: the fastest accelerator design that fits its part, judged honestly.

    space = Space(units=(1, 4, 16), unit_sets=(1, 2), alloc_scales=(1, 2), cpe=(5, 20))
    result = search({"qr": qr_program, "cholesky": chol_program}, space, progress=print)
    print("\\n".join(result.lines()))      # every design, its verdict and what bound it

Each candidate is an emitted HLS design (:class:`Candidate`: linear solver, n_u, QR unit sets,
#CPE, the factor datapaths' ``ALLOCATION`` scale, the floating-point operators' binding
(``Space.binds``: DSP or fabric, ``HlsConfig.bind``), and any option the plan grows: the
``qr_unit`` field of ``PlanOptions`` and ``DesignOptions`` is an axis over ``QR_UNITS``;
``Space(extra=(("qr_rows", (1, 2)),))`` adds the Householder unit's rows a cycle,
``HlsConfig.qr_rows``). Its speed is the accelerator plan's
(``plan_cost(build_plan(program, PlanOptions.for_config(config, program)))``: cycles of one
iteration); its fit is judged on honest figures:

- **DSP** = max(the plan's DSP, the second reader's DSP of the emitted design:
  ``fgc_backends.hls.reader``, what Vitis would instantiate from the text, a lower bound). Once
  the plan is proven to price at least what the reader reads, the max is a no-op;
- **BRAM36, LUT, FF** from the plan.

A design fits when every figure is within the part's capacity; the figure with the largest share
of its capacity is the one that *bound* the verdict, and each row names it.

Reading a design means emitting it (tens of seconds for LIO N=30), so the search reads as few as
it can, and caches what it read. Its rule cannot miss the fastest design that fits:

1. every candidate is priced by the plan (cheap); one the plan already puts over the part is
   refused without reading (its honest DSP, max(plan, reader), is at least the plan's);
2. the others are read in plan-speed order, fastest first, until one fits as re-priced: that
   one is the best, and every faster design was read and found over or refused by the plan.
   Where the plan prices at least what the reader reads (``bench/bench_second_reader.py``'s
   check_dsp column, ``tests/hls/reader/test_plan_reader.py``), the first read is the best;
3. a read that fits also marks the designs below it on every ordered axis (fewer Update units,
   unit sets, CPEs, less ALLOCATION: never more operators) as fitting, for the table; they are
   all slower, so this never decides the best. A read over the part implies nothing: the next
   design is read.

``max_reads`` is an optional cap (None: none); when it stops the search, the faster designs
left are reported ``unread``, and the best is then not known to be the fastest that fits.

Reads are cached under ``$FGC_CACHE_DIR`` (kind ``reader``), keyed by the Program's fingerprint,
the HLS config and a digest of the backends' sources (a change to the emitter reads again).
"""

from __future__ import annotations

import dataclasses
import hashlib
import tempfile
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from fgc.errors import FgcError
from fgc.ir.program import Program

ORDERED = ("units", "unit_sets", "cpe", "alloc_scale")  # axes the reader's DSP grows with
READ_KIND = "reader"


class SearchError(FgcError):
    """The design space is malformed (an unknown option, an empty axis)."""


@dataclass(frozen=True)
class Space:
    """The axes searched. ``units`` and ``unit_sets`` apply to QR designs, ``cpe`` and
    ``cascades`` (one cascade, or two side by side: ``HlsConfig.unit_sets`` of a Cholesky
    design) to Cholesky ones; ``unit_sets=None`` means the emitter's default (two on a
    two-ended chain, else one); ``lanes``: Cholesky's words a cycle through each cascade
    (``HlsConfig.cascade_lanes``, 1 or 2; a design of 2 carries it as its ``extra``);
    ``alloc_scales`` multiply the factor datapaths' default ``ALLOCATION`` limits;
    ``backsub_lanes``: back-substitution's widths (``HlsConfig.backsub_lanes``, both solvers;
    ``None``, the default, is the candidate without the option: the emitter's automatic width,
    4 on a chain and 1 on a tree; 1, 2 and 4 are given to the design, 4, by columns, only where
    the elimination tree is a chain: elsewhere the plan refuses it and the search skips it);
    ``extra``: further ``PlanOptions`` fields the emitter knows as ``HlsConfig`` fields,
    (name, values)."""

    linears: tuple[str, ...] = ("qr", "cholesky")
    units: tuple[int, ...] = (1, 2, 4, 8, 16, 32)
    unit_sets: tuple[int | None, ...] = (None,)
    cpe: tuple[int, ...] = (5, 20, 40, 80, 120)
    cascades: tuple[int, ...] = (1, 2)
    lanes: tuple[int, ...] = (1,)
    alloc_scales: tuple[int, ...] = (1,)
    backsub_lanes: tuple[int | None, ...] = (None,)
    scalar: str = "float"
    part: str | None = None  # None: HlsConfig's default part
    extra: tuple[tuple[str, tuple], ...] = ()
    # the floating-point operators' bindings (HlsConfig.bind: ((kind, implementation), ...);
    # () is Vitis's default, fulldsp adders and maxdsp multipliers): a design dimension that
    # never changes a cycle, only DSP / LUT / FF, so among designs of equal speed the search
    # reads them in this order (the default first: a binding is taken when it buys a fit)
    binds: tuple[tuple[tuple[str, str], ...], ...] = ((),)

    def __post_init__(self):
        for name in ("linears", "units", "unit_sets", "cpe", "cascades", "lanes",
                     "alloc_scales", "backsub_lanes", "binds"):
            if not getattr(self, name):
                raise SearchError(f"design space: axis {name!r} is empty")
        from fgc_backends.cost.operators import BindError, normalise_bind

        try:
            binds = tuple(dict.fromkeys(normalise_bind(b) for b in self.binds))
        except BindError as exc:
            raise SearchError(f"design space: {exc}") from None
        object.__setattr__(self, "binds", binds)
        bad = [u for u in (*self.units, *self.cpe, *self.alloc_scales,
                           *(b for b in self.backsub_lanes if b is not None)) if int(u) < 1]
        bad += [k for k in self.cascades if int(k) not in (1, 2)]
        bad += [k for k in self.lanes if int(k) not in (1, 2)]
        bad += [s for s in self.unit_sets if s is not None and int(s) < 1]
        if bad:
            raise SearchError(f"design space: counts must be >= 1 (cascades and lanes 1 or 2), "
                              f"got {bad}")
        unknown = sorted(set(self.linears) - {"qr", "cholesky"})
        if unknown:
            raise SearchError(f"design space: unknown linear solver(s) {unknown}")


def qr_unit_axis() -> tuple:
    """The QR unit kinds when ``PlanOptions`` has a ``qr_unit`` option (and ``HlsConfig`` or its
    design options the same field, so the emitter builds it): ``QR_UNITS`` of the options
    module if it names them, else the option's default alone; () when there is no such
    option."""
    from fgc_backends.hls.plan import options

    names = {f.name: f for f in dataclasses.fields(options.PlanOptions)}
    if "qr_unit" not in names or "qr_unit" not in _config_names():
        return ()
    kinds = getattr(options, "QR_UNITS", None)
    return tuple(kinds) if kinds else (names["qr_unit"].default,)


def _init_names(cls) -> set[str]:
    import inspect

    return set(inspect.signature(cls).parameters)


def _config_names() -> set[str]:
    """The option names an ``HlsConfig`` takes: its own, and its design options' where the
    config carries them (``HlsConfig.design``)."""
    from fgc_backends.hls import HlsConfig
    from fgc_backends.hls import config as hls_config

    names = _init_names(HlsConfig)
    design = getattr(hls_config, "DesignOptions", None)
    return names | (_init_names(design) if design is not None else set())


@dataclass(frozen=True)
class Candidate:
    """One emitted design: what the search varies."""

    linear: str
    units: int | None = None  # QR
    unit_sets: int | None = None  # QR; None: the emitter's default; Cholesky: 2 cascades or None
    cpe: int | None = None  # Cholesky
    alloc_scale: int = 1
    extra: tuple[tuple[str, object], ...] = ()
    bind: tuple[tuple[str, str], ...] = ()  # the operators' binding (HlsConfig.bind)

    @property
    def label(self) -> str:
        if self.linear == "qr":
            sets = "default" if self.unit_sets is None else str(self.unit_sets)
            head = f"qr n_u={self.units} sets={sets}"
        else:
            head = f"cholesky #CPE={self.cpe}" + (f" cascades={self.unit_sets}"
                                                 if self.unit_sets else "")
        tail = "".join(f" {k}={v}" for k, v in self.extra)
        if self.bind:
            tail += " bind " + ",".join(f"{k}={v}" for k, v in self.bind)
        return f"{head} ALLOC×{self.alloc_scale}{tail}"

    def program(self, programs: Mapping[str, Program]) -> Program:
        p = programs[self.linear]
        solver = dataclasses.replace(p.solver, units=self.units or p.solver.units,
                                     cpe=self.cpe or p.solver.cpe)
        return dataclasses.replace(p, solver=solver)

    def config(self, space: Space):
        """The ``HlsConfig`` that emits this design."""
        from fgc_backends.hls import HlsConfig
        from fgc_backends.hls.plan import DEFAULT_ALLOCATION

        alloc = (None if self.alloc_scale == 1
                 else tuple((k, n * self.alloc_scale) for k, n in DEFAULT_ALLOCATION))
        kw = dict(scalar=space.scalar, unit_sets=self.unit_sets, allocation=alloc,
                  **dict(self.extra))
        if self.bind:
            kw["bind"] = self.bind
        if space.part is not None:
            kw["part"] = space.part
        direct = {k: v for k, v in kw.items() if k in _init_names(HlsConfig)}
        design = {k: v for k, v in kw.items() if k not in direct}
        if design:  # options only the design-options object knows (HlsConfig.design)
            from fgc_backends.hls import config as hls_config

            direct["design"] = hls_config.DesignOptions(**design)
        return HlsConfig(**direct)

    def below(self, other: Candidate) -> bool:
        """Every ordered axis of this design <= ``other``'s, the rest equal: the reader's DSP
        of this design is at most ``other``'s."""
        if (self.linear, self.extra, self.bind) != (other.linear, other.extra, other.bind):
            return False
        for axis in ORDERED:
            a, b = getattr(self, axis), getattr(other, axis)
            if a is None or b is None:
                if a != b:
                    return False
            elif a > b:
                return False
        return True


def candidates(space: Space, programs: Mapping[str, Program]) -> tuple[Candidate, ...]:
    """The cartesian product over the axes that apply to each linear solver present."""
    extra_axes = list(space.extra)
    if "qr_unit" not in dict(extra_axes) and qr_unit_axis():
        extra_axes.append(("qr_unit", qr_unit_axis()))
    extras = [()]
    for name, values in extra_axes:
        extras = [e + ((name, v),) for e in extras for v in values]
    # the Update units' rows a cycle (an ``extra`` axis ``qr_rows``) are the Householder unit's:
    # no design of the streaming unit with two
    extras = [e for e in extras
              if dict(e).get("qr_rows", 1) == 1 or dict(e).get("qr_unit") != "stream"]
    # back-substitution's width on either solver (None, the automatic width, is no option)
    widths = [() if b is None else (("backsub_lanes", b),) for b in space.backsub_lanes]
    out = []
    for linear in space.linears:
        if linear not in programs:
            continue
        before = len(out)
        for scale in space.alloc_scales:
            if linear == "qr":
                for units in space.units:
                    for sets in space.unit_sets:
                        for e in extras:
                            out += [Candidate("qr", units, sets, None, scale, e + b)
                                    for b in widths]
            else:
                out += [Candidate("cholesky", None, None if k == 1 else k, c, scale,
                                  (() if la == 1 else (("cascade_lanes", la),)) + b)
                        for c in space.cpe for k in space.cascades for la in space.lanes
                        for b in widths]
        # every design in each binding of the space
        out[before:] = [dataclasses.replace(c, bind=bind) for c in out[before:]
                        for bind in space.binds]
    return tuple(dict.fromkeys(out))


@dataclass
class Row:
    """One candidate: the plan's price, the reader's DSP if read, the verdict and its reason."""

    candidate: Candidate
    cost: object  # the plan's Cost
    caps: dict  # the part's capacities: dsp, bram36, lut, ff
    reader_dsp: int | None = None
    read: str = ""  # "", "read" (emitted and read now), "cached"
    verdict: str = "unread"  # "fits", "over", "unread", "unbuildable" (the emitter refuses it)
    bound: str = ""  # the figure that decided (or, unread, the plan's tightest)
    implied_by: str = ""  # the read design an implied fit follows from
    read_seconds: float = 0.0
    details: dict = field(default_factory=dict)

    @property
    def label(self) -> str:
        return self.candidate.label

    @property
    def cycles(self) -> int:
        return self.cost.cycles

    @property
    def latency_ms(self) -> float:
        return self.cost.latency_ms

    def figures(self) -> list[tuple[str, float, float]]:
        """(figure, value, capacity) of every honest figure known."""
        c = self.cost
        out = [("plan DSP", c.dsp, self.caps["dsp"]),
               ("plan BRAM36", c.bram36, self.caps["bram36"]),
               ("plan LUT", c.lut, self.caps["lut"]), ("plan FF", c.ff, self.caps["ff"])]
        if self.reader_dsp is not None:
            out.insert(1, ("reader DSP", self.reader_dsp, self.caps["dsp"]))
        return out

    @property
    def dsp(self) -> int:
        """The honest DSP: max(plan, reader) where read, the plan's otherwise."""
        return max(self.cost.dsp, self.reader_dsp or 0)

    def judge(self) -> None:
        """Set ``verdict`` / ``bound`` from the figures known (a read design, or the plan's over
        the part); an unread design the plan fits stays ``unread``."""
        name, value, cap = max(self.figures(), key=lambda f: f[1] / f[2])
        self.bound = f"{name} {value:,.0f}/{cap:,}"
        if value > cap:
            self.verdict = "over"
        elif self.reader_dsp is not None:
            self.verdict = "fits"


@dataclass(frozen=True)
class SearchResult:
    rows: tuple[Row, ...]  # fastest (plan cycles) first
    best: Row | None  # the fastest design that fits
    reads: int  # designs emitted and read in this search (cache hits not counted)
    cached: int
    unchecked_faster: int  # undecided designs faster than ``best`` (read budget spent)
    part: str
    seconds: float

    def lines(self, floor=None) -> list[str]:
        """The table of every design and the best; ``floor`` (:class:`fgc.app.floor.Floor`)
        adds the latency floor and what limits the best design."""
        from fgc.app.design_report import format_table

        headers = ("design", "cycles/it", "ms/it", "plan DSP", "reader DSP", "BRAM36", "fit",
                   "bound by", "how")
        body = []
        for r in self.rows:
            how = r.read or (f"implied by {r.implied_by}" if r.implied_by else
                             ("plan" if r.verdict == "over" else "-"))
            body.append(((("* " if r is self.best else "  ") + r.label), f"{r.cycles:,}",
                         f"{r.latency_ms:.3f}", f"{r.cost.dsp:,}",
                         "-" if r.reader_dsp is None else f"{r.reader_dsp:,}",
                         f"{r.cost.bram36:g}", r.verdict, r.bound, how))
        out = [f"design search on {self.part}: {len(self.rows)} designs, {self.reads} emitted "
               f"and read, {self.cached} from the cache ({self.seconds:.0f} s); fit: DSP = "
               "max(plan, second reader), BRAM36/LUT/FF from the plan",
               *format_table(headers, body)]
        if self.best is None:
            out.append("no design is known to fit" + (
                f" ({self.unchecked_faster} left unread: raise the read budget)"
                if self.unchecked_faster else ""))
            return out
        b = self.best
        read = "-" if b.reader_dsp is None else f"{b.reader_dsp:,}"
        out.append(f"best design that fits: {b.label}: {b.cycles:,} cycles = "
                   f"{b.latency_ms:.3f} ms per iteration, {b.dsp:,} DSP "
                   f"(plan {b.cost.dsp:,}, reader {read}), {b.cost.bram36:g} BRAM36; "
                   + (f"bound by {b.bound}" if b.verdict == "fits" else
                      "judged on the plan alone: not read")
                   + (f"; {self.unchecked_faster} faster design(s) left unread (read budget)"
                      if self.unchecked_faster else ""))
        if floor is not None:
            from fgc.app.floor import limits_line

            out += [f"  {floor.describe()}", f"  best design: {limits_line(floor, b.cost)}"]
        return out


def sources_digest() -> str:
    """Digest of the backends' sources (Python, templates, headers): what emits a design."""
    import fgc_backends

    root = Path(fgc_backends.__file__).parent
    h = hashlib.sha256()
    for path in sorted(root.rglob("*")):
        if path.is_file() and path.suffix in (".py", ".jinja", ".h", ".cpp", ".tcl") \
                and "__pycache__" not in path.parts:
            h.update(str(path.relative_to(root)).encode() + b"\0" + path.read_bytes() + b"\0")
    return h.hexdigest()


def _precision(config) -> str:
    from fgc_backends.hls.plan import scalar_precision

    return scalar_precision(config.scalar_cxx)


def read_dsp(program: Program, config, digest: str | None = None,
             use_cache: bool = True) -> tuple[dict, bool]:
    """The second reader's figures of ``program`` emitted with ``config``: (``{"dsp", "ii_short",
    "carried", "operators", "seconds"}``, whether they came from the cache)."""
    from fgc.compiler import cache
    from fgc_backends.hls import emit
    from fgc_backends.hls.plan import PlanOptions, build_plan
    from fgc_backends.hls.reader import check, dsp_table, emitted_files, emitted_ops, read_design

    key = hashlib.sha256("\0".join((program.fingerprint, repr(config),
                                    digest or sources_digest())).encode()).hexdigest()
    path = cache.entry(READ_KIND, program.name, key) if use_cache else None
    hit = cache.load(path, key, dict)
    if hit is not None:
        return hit, True
    t0 = time.perf_counter()
    target = build_plan(program, PlanOptions.for_config(config, program)).target
    tab = target.ops(_precision(config))
    with tempfile.TemporaryDirectory(prefix="fgc-search-") as tmp:
        import warnings

        from fgc_backends.hls.lint import HlsFitWarning

        with warnings.catch_warnings():  # the search reports the fit itself
            warnings.simplefilter("ignore", HlsFitWarning)
            emit(program, Path(tmp) / "design", config)
        files, top = emitted_files(Path(tmp) / "design")
        design = read_design(files, top, tab.add.latency)
        # each operator in its own type's table (a mixed design's double linear solver in
        # float64's), bound as the emitted run_hls.tcl binds it (config_op): from the text
        ops_of = emitted_ops(Path(tmp) / "design")
    dsp_of = dsp_table(ops_of, _precision(config))
    issues = check(design.loops)
    out = {"dsp": design.dsp(dsp_of), "operators": dict(design.operators),
           "ii_short": sum(i.rule == "ii_ports" for i in issues),
           "carried": sum(i.rule == "ii_recurrence" for i in issues),
           "seconds": time.perf_counter() - t0}
    cache.store(path, key, out)
    return out, False


def price(program: Program, cand: Candidate, space: Space, plans: dict | None = None):
    """The plan's Cost of ``cand`` and the part's capacities. ``plans``: a cache of the plans
    built, by the candidate without its binding: a design's other bindings are that plan
    bound anew (``plan.cost.rebind``: the same cycles, exact)."""
    from fgc_backends.hls.emitter import for_program
    from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
    from fgc_backends.hls.plan.cost import rebind

    key = (program.fingerprint, dataclasses.replace(cand, bind=()))
    if plans is not None and key in plans:
        plan = rebind(plans[key], cand.bind)
    else:
        # the design the emitter builds: a Program compiled with linear_precision float64 gets
        # a double linear solver (the mixed design), priced in its own operator table
        config = for_program(program, cand.config(space))
        plan = build_plan(program, PlanOptions.for_config(config, program))
        if plans is not None:
            plans[key] = plan
    d = plan.target.device
    return plan_cost(plan), {"dsp": d.dsp, "bram36": d.bram36, "lut": d.lut, "ff": d.ff}, d.name


def search(programs: Mapping[str, Program], space: Space = Space(),
           max_reads: int | None = None, reader: bool = True,
           progress: Callable[[str], None] | None = None,
           reader_fn: Callable | None = None, use_cache: bool = True) -> SearchResult:
    """The fastest design of ``space`` that fits, over ``programs`` (linear solver → Program,
    compiled for that solver; n_u and #CPE are set per candidate): designs read in plan-speed
    order until one fits as re-priced (the module's rule), at most ``max_reads`` emitted (None:
    no cap; cache hits are free). ``reader=False`` judges on the plan alone (no design is then
    known to fit: every plan-fitting design stays unread and the best is the fastest of them,
    marked as plan-only); ``reader_fn(program, config)`` → (figures, cached) replaces
    :func:`read_dsp` (tests)."""
    t0 = time.perf_counter()
    say = progress or (lambda s: None)
    cands = candidates(space, programs)
    if not cands:
        raise SearchError("design space: no candidate (no Program for its linear solvers)")
    rows, part, plans = [], "", {}
    for i, c in enumerate(cands):
        try:
            cost, caps, part = price(c.program(programs), c, space, plans)
        except FgcError as exc:  # the plan refuses the design (backsub_lanes 4 on a tree)
            say(f"  {c.label}: no design ({type(exc).__name__}: {exc})")
            continue
        rows.append(Row(c, cost, caps))
        if progress and (i + 1) % 10 == 0:
            say(f"  priced {i + 1}/{len(cands)} designs")
    rank = {b: i for i, b in enumerate(space.binds)}  # equal speed: the space's binding order
    rows.sort(key=lambda r: (r.cycles, rank.get(r.candidate.bind, len(rank)), r.cost.dsp,
                             r.label))
    for r in rows:
        r.judge()
    digest = sources_digest() if reader and reader_fn is None else None
    fn = reader_fn or (lambda p, cfg: read_dsp(p, cfg, digest, use_cache))
    reads = cached = 0

    def known_fit() -> int:
        return next((i for i, r in enumerate(rows) if r.verdict == "fits"), len(rows))

    def undecided() -> list[Row]:
        return [r for r in rows[:known_fit()] if r.verdict == "unread"]

    while reader and undecided() and (max_reads is None or reads < max_reads):
        pending = undecided()
        r = pending[0]  # the fastest design not yet decided: every faster one is over
        say(f"  reading {r.label} (plan {r.cycles:,} cycles, {r.cost.dsp:,} DSP) with the "
            f"second reader (emitted unless cached): the fastest of {len(pending)} undecided")
        try:
            figures, hit = fn(r.candidate.program(programs), r.candidate.config(space))
        except FgcError as exc:  # the emitter refuses the design: it is no candidate
            r.verdict, r.bound, r.read = "unbuildable", f"{type(exc).__name__}: {exc}", "read"
            reads += 1
            say(f"  {r.label}: not emitted ({r.bound})")
            continue
        r.reader_dsp, r.details, r.read = int(figures["dsp"]), figures, "cached" if hit else "read"
        r.read_seconds = float(figures.get("seconds", 0.0))
        cached += hit
        reads += not hit
        r.judge()
        if r.verdict != "fits":
            continue
        for o in rows:  # slower designs below it fit too (the reader's monotonicity)
            if o.verdict == "unread" and o.candidate.below(r.candidate):
                o.verdict, o.implied_by = "fits", r.label
                o.bound = f"reader DSP <= {r.reader_dsp:,}/{o.caps['dsp']:,}"
    best_i = known_fit()
    best = rows[best_i] if best_i < len(rows) else None
    unchecked = len(undecided()) if reader else 0
    if not reader:
        best = next((r for r in rows if r.verdict == "unread"), None)
    say(f"  search done: {reads} designs read, {cached} cached, "
        f"{time.perf_counter() - t0:.0f} s")
    return SearchResult(tuple(rows), best, reads, cached, unchecked, part,
                        time.perf_counter() - t0)


def fit_warnings(result: SearchResult, name: str) -> list[str]:
    """One message per design the plan fits but the honest figures do not: what ``fgc sweep``
    raises as ``HlsFitWarning``."""
    return [f"{name}: {r.label} does not fit {result.part} as re-priced: {r.bound} "
            f"(plan DSP {r.cost.dsp:,})" for r in result.rows
            if r.verdict == "over" and r.cost.fits]


__all__ = ["Candidate", "Row", "SearchError", "SearchResult", "Space", "candidates",
           "fit_warnings", "price", "read_dsp", "search", "sources_digest"]

