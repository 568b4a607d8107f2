"""Paper reproduction: each published figure of paper A (LIO, ICCAD 2022) and paper B (IMU
window) beside fgc's figure for the same configuration, with why they differ.

fgc's hardware figures are the accelerator plan's arithmetic (``fgc_backends.hls.plan``:
``plan_cost(build_plan(...))``, model estimates at 143 MHz on the xc7z045); GTSAM's per-iteration
time and ISAM2's per-update time are measured here, in this process (gtsam python wheel).
Storage ratios are ``Program.storage`` (fgc/compiler/storage.py).

The "best design" is the design-space search's (``fgc.app.search``, the one ``fgc sweep`` uses):
the fastest design (plan cycles) over linear solver, n_u, QR unit sets, #CPE and ALLOCATION
scale that FITS the xc7z045 on honest figures, DSP = max(plan, the second reader's DSP of the
emitted design), BRAM36 from the plan; the latency floor of one iteration
(``fgc.app.floor``) is printed beside it. Reading a design emits it (tens of seconds for LIO
N=30): the search reads in plan-speed order, skipping designs the plan puts over the part,
until one fits as re-priced (so it cannot miss the fastest that fits); reads are cached in
``$FGC_CACHE_DIR``, progress on stderr, ``--reads N`` an optional cap.

    FGC_CACHE_DIR=... python bench/bench_papers.py            # LIO N=30, IMU N=50
    FGC_CACHE_DIR=... python bench/bench_papers.py --reads 0  # the plan's figures alone
    FGC_CACHE_DIR=... python bench/bench_papers.py --small    # LIO N=5, IMU N=5, plan only
"""

from __future__ import annotations

import argparse
import dataclasses
import re
import statistics
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fgc.app.floor import latency_floor, limits_line  # noqa: E402
from fgc.app.search import Space, search
from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends.hls.config import auto_backsub_lanes  # noqa: E402
from fgc_backends.hls.plan import (  # noqa: E402
    DEFAULT_ALLOCATION,
    PART_DSP,
    PlanOptions,
    build_plan,
    plan_cost,
    plan_power_w,
)

imu_window = example("imu_window")
lio = example("lio")


@dataclass(frozen=True)
class Row:
    paper: str
    figure: str
    published: str
    fgc: str
    why: str


@dataclass(frozen=True)
class Config:
    lio_n: int = 30
    imu_n: int = 50
    storage_ns: tuple[int, int] = (20, 80)
    units: tuple[int, ...] = (1, 4, 8, 16, 32)
    unit_sets: tuple[int, ...] = (1, 2)
    # the batch searches' QR Update units' rows a cycle (HlsConfig.qr_rows; (1, 2) doubles
    # their QR candidates)
    qr_rows: tuple[int, ...] = (1,)
    alloc_scales: tuple[int, ...] = (1, 2)
    # Cholesky designs of LIO in the search (15: a two-ended LIO step's pivots, the longest cascade
    # a step fills)
    lio_cpes: tuple[int, ...] = (5, 10, 15, 20, 80)
    cpes: tuple[int, ...] = (5, 20, 40, 80, 120)
    cascades: tuple[int, ...] = (1, 2)  # Cholesky: one cascade, or two side by side
    # back-substitution's widths (HlsConfig; None: the default, automatic - by columns, a
    # process per end, on a chain, one lane on a tree - so the default design is a candidate
    # without an extra option; 1 and 2 the slot designs)
    backsub_lanes: tuple[int | None, ...] = (None, 1, 2)
    # Cholesky: words a cycle through each cascade (HlsConfig.cascade_lanes; (1, 2) lets the
    # search weigh two words a cycle against more CPEs)
    lanes: tuple[int, ...] = (1,)
    c123: tuple[int, ...] = (20, 40, 80)  # paper B's C1-C3 #CPE (backends/cost/params.py)
    # the floating-point operators' bindings searched (HlsConfig.bind; run_hls.tcl's
    # config_op), fewer DSP and more LUT each: Vitis's default (fulldsp adders, maxdsp
    # multipliers), adders in fabric, then with two-DSP (fulldsp) and one-DSP (meddsp)
    # multipliers. A binding never changes a cycle: it trades DSP
    # for LUT and FF, so it decides which designs fit (LUT and FF judged too)
    binds: tuple = ((), (("add", "fabric"),), (("add", "fabric"), ("mul", "fulldsp")),
                    (("add", "fabric"), ("mul", "meddsp")))
    gtsam_iterations: int = 5
    gtsam_repeats: int = 5
    # a cap on the designs the search may emit and read per search (cache hits are free);
    # None: no cap, the search reads in plan-speed order until one fits (fgc.app.search);
    # 0: the plan's figures alone
    reads: int | None = None
    stream_batch: tuple[int, ...] = (5, 15, 25)  # paper A's batch keyframes
    # the stream's update policy: ISAM2's, one Gauss-Newton step an update (what the timed
    # isam.update does per keyframe; fgc.app.streaming.one_step_solver), or False: LM to
    # convergence each update
    stream_one_step: bool = True
    isam_repeats: int = 3
    # the on-chip stream design's search (paper_a_stream): n_u, unit sets, the factor datapaths'
    # ALLOCATION limits (None: the default design's; smaller limits: fewer operators)
    stream_units: tuple[int, ...] = (1, 2, 3, 4, 8, 16)
    stream_unit_sets: tuple[int, ...] = (1, 2)
    # the QR Update units' rows a cycle (HlsConfig.qr_rows: 1, or 2 for 10 more DSP a unit in
    # float32: n_u 3, two rows beside n_u 4, one)
    stream_qr_rows: tuple[int, ...] = (1, 2)
    stream_allocations: tuple = (None, (("add", 8), ("mul", 12), ("div", 2)),
                                 (("add", 4), ("mul", 6), ("div", 1)),
                                 (("add", 2), ("mul", 3), ("div", 1)),
                                 (("add", 1), ("mul", 1), ("div", 1)))
    stream_reads: int = 2  # stream designs the search emits and reads (about 25 s each)
    stream_binds: tuple = ((), (("add", "fabric"),), (("add", "fabric"), ("mul", "fulldsp")),
                           (("add", "fabric"), ("mul", "meddsp")))
    # the root step in a wavefront (HlsConfig.root_wave) on every stream design of two unit
    # sets where the window can take it: it wins on each (keyframe 14, n_u 1 / 2 / 4 / 8, one
    # or two rows a cycle: 409 to 2,812 cycles fewer, the same DSP, 3 BRAM36 more; docs/hls.md,
    # "The root step in a wavefront"), so it is not an axis (no design priced twice)
    stream_root_wave: bool = True
    # the streaming top's data port (HlsConfig.data_width) on every searched stream design (not
    # the default design's row): 64 bits, two float words a beat (a Zynq HP port's width, the
    # host packing them), takes the update's start from 243 cycles to 130 (keyframe 14 of the
    # pick 8,747 -> 8,634) for no DSP, DATA_BUF's 8 banks (2 BRAM36 more) and the port's LUT /
    # FF (docs/hls.md, "The update's start off the path"), so it is not an axis
    stream_data_width: int = 64
    # the state update's special-function instances a retraction (HlsConfig.retire_special:
    # None the design's one, 2 a second: the retire's II 36 -> 22 on LIO's Pose3, -28 cycles an
    # incremental update of the n_u 8 pick for +20 DSP by the plan; docs/hls.md,
    # "Back-substitution after lin_level"): an axis, tried on every stream design of the grid
    stream_retire_special: tuple = (None, 2)
    # paper B's solve: run the best design's counting C simulation on the problem (a minute or
    # two at N = 50) and price the solve by the linearisations and solves it really runs;
    # False: the per-solve figure is the plan's iteration times GTSAM's iteration count, said so
    design_run: bool = True


SMALL = Config(lio_n=5, imu_n=5, storage_ns=(4, 6), units=(1, 8), alloc_scales=(1,),
               lio_cpes=(5,), cpes=(5, 20), c123=(20,), gtsam_iterations=2, gtsam_repeats=1,
               reads=0, stream_batch=(4,), isam_repeats=1, backsub_lanes=(None,),
               stream_units=(1, 4), stream_qr_rows=(1,), stream_retire_special=(None,),
               stream_allocations=(None, (("add", 1), ("mul", 1), ("div", 1))), stream_reads=1,
               design_run=False, binds=((),), stream_binds=((),))


def _progress(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


def _cost(program, **options):
    return plan_cost(build_plan(program, PlanOptions.of(program, **options)))


def _scaled(scale: int) -> tuple[tuple[str, int], ...]:
    return tuple((k, n * scale) for k, n in DEFAULT_ALLOCATION)


def lio_programs(graph, ordering: str = "two-ended") -> dict:
    """LIO's Programs per linear solver, GN in float32 (paper A's accelerator)."""
    return {lin: compile_graph(graph, SolverConfig(method="gn", linear=lin, ordering=ordering,
                                                   precision="float32"), name="lio")
            for lin in ("qr", "cholesky")}


def search_space(cfg: Config, linears=("qr", "cholesky")) -> Space:
    """The design space :func:`best_design` searches."""
    return Space(linears=linears, units=cfg.units, unit_sets=cfg.unit_sets,
                 cpe=cfg.lio_cpes if "qr" in linears else cfg.cpes, cascades=cfg.cascades,
                 lanes=cfg.lanes, alloc_scales=cfg.alloc_scales,
                 backsub_lanes=cfg.backsub_lanes, binds=cfg.binds,
                 extra=(("qr_rows", cfg.qr_rows),) if tuple(cfg.qr_rows) != (1,) else ())


def best_design(programs: dict, cfg: Config, linears=("qr", "cholesky")):
    """The design-space search (fgc.app.search) over ``programs``: the fastest design that fits
    the xc7z045 as re-priced (DSP = max(plan, second reader), BRAM36, LUT and FF from the
    plan)."""
    return search(programs, search_space(cfg, linears), max_reads=cfg.reads,
                  reader=cfg.reads != 0, progress=_progress)


def gtsam_ms_per_iteration(graph, cfg: Config) -> dict[str, tuple[float, float]]:
    """(median, fastest) wall time in ms of one GTSAM LM iteration (``iterate()``), per linear
    solver; the machine is shared, so the fastest is the least disturbed."""
    import gtsam

    from fgc.interop.to_gtsam import to_gtsam

    problem = to_gtsam(graph)
    out = {}
    for solver in ("MULTIFRONTAL_CHOLESKY", "MULTIFRONTAL_QR"):
        params = gtsam.LevenbergMarquardtParams()
        params.setLinearSolverType(solver)
        gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params).optimize()
        times = []
        for _ in range(cfg.gtsam_repeats):
            opt = gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params)
            for _ in range(cfg.gtsam_iterations):
                t0 = time.perf_counter()
                opt.iterate()
                times.append(time.perf_counter() - t0)
        out[solver] = (statistics.median(times) * 1e3, min(times) * 1e3)
    return out


def _levels(c) -> int:
    return sum(1 for name, _ in c.phase_cycles if name.startswith("qr_level"))


def _other(c) -> float:
    return 1 - c.linear_cycles / c.cycles


def _dominant(c) -> str:
    """The phase group (prefix before the level number) taking most of one iteration."""
    groups: dict[str, int] = {}
    for name, cycles in c.phase_cycles:
        key = re.sub(r"_level\d+$", "", name)
        groups[key] = groups.get(key, 0) + cycles
    name, cycles = max(groups.items(), key=lambda kv: kv[1])
    return f"{name} {cycles / c.cycles:.0%}"


def _res(c) -> str:
    return f"{c.dsp} DSP / {c.bram36:g} BRAM36 / {c.lut:,} LUT / {c.ff:,} FF"


def _honest(row) -> str:
    if row.reader_dsp is not None:
        read = f"reader {row.reader_dsp:,}"
    elif row.implied_by:
        read = f"reader <= {row.implied_by}'s, implied"
    else:
        read = "not read"
    return (f"{row.dsp:,} DSP (plan {row.cost.dsp:,}, {read}) / {row.cost.bram36:g} BRAM36 / "
            f"{row.cost.lut:,} LUT / {row.cost.ff:,} FF")


def paper_a(cfg: Config) -> list[Row]:
    graph = lio.build(N=cfg.lio_n)
    progs = lio_programs(graph)
    serial = compile_graph(graph, SolverConfig(method="gn", linear="qr", ordering="serial",
                                               precision="float32"), name="lio")
    a = f"A (LIO N={cfg.lio_n})"
    result = best_design(progs, cfg)
    print("\n".join(result.lines()))
    best = result.best
    fastest = result.rows[0]
    shown = best or fastest  # the figures below are the best's, or (none fits) the fastest's
    prog = shown.candidate.program(progs)
    floor = latency_floor(prog, build_plan(prog, PlanOptions.of(prog)).ops)
    gt = gtsam_ms_per_iteration(graph, cfg)
    g_med = min(med for med, _ in gt.values())
    g_fast = min(fast for _, fast in gt.values())
    gtsam = ("GTSAM LM ms/iteration here, median / fastest: "
             + ", ".join(f"{k.split('_')[1].lower()} {m:.3f} / {f:.3f}"
                         for k, (m, f) in gt.items()))
    if best is not None:
        verdict = (f"{best.label}: {best.latency_ms:.3f} ms per GN iteration "
                   f"({best.cycles:,} cycles), {_honest(best)}; {g_med / best.latency_ms:.2f}× "
                   f"GTSAM's median LM iteration, {g_fast / best.latency_ms:.2f}× its fastest")
    else:
        small = min((r for r in result.rows if r.reader_dsp is not None),
                    key=lambda r: r.reader_dsp, default=None)
        verdict = (f"none of {len(result.rows)} designs fits as re-priced"
                   + (f" (the smallest read, {small.label}, needs {small.reader_dsp:,} DSP)"
                      if small else "")
                   + f"; the fastest by the plan, {fastest.label}: {fastest.latency_ms:.3f} ms "
                   f"per GN iteration, {_honest(fastest)}, {fastest.verdict}"
                   + (f" ({fastest.bound})" if fastest.bound else "")
                   + f"; it would be {g_med / fastest.latency_ms:.2f}× GTSAM's median LM "
                   "iteration")
    rows = [Row(a, "fastest design that fits the xc7z045 (re-priced) vs GTSAM per iteration",
                "9.3× GTSAM (16-core Intel); 473 DSP / 163 BRAM36",
                verdict + f" ({gtsam}; {result.reads} designs emitted and read, "
                f"{result.cached} from the cache, of {len(result.rows)})",
                f"{limits_line(floor, shown.cost)}. {floor.describe()}: no design of this "
                f"Program beats {g_med / floor.latency_ms:.1f}× GTSAM's median iteration. "
                "Fit is judged on DSP = max(plan, second reader): the reader counts the "
                "operators Vitis instantiates per pipelined loop and call site, and the plan "
                "prices every loop that way (the units' headers included)")]
    same = {"two-ended": progs["qr"], "serial": serial}
    units = shown.candidate.units if shown.candidate.linear == "qr" else 4
    costs = {o: _cost(p, units=units) for o, p in same.items()}
    rows.append(Row(a, "two-ended vs serial speed-up", "1.6×",
                    f"{costs['serial'].cycles / costs['two-ended'].cycles:.2f}× at n_u={units} "
                    "(plan cycles, each ordering's default unit sets)",
                    f"two unit sets halve the sequential QR and back-substitution levels "
                    f"({_levels(costs['serial'])} → {_levels(costs['two-ended'])}); the factor "
                    "datapaths, gradient pass, state update and LM control "
                    f"({_other(costs['two-ended']):.0%} of the two-ended iteration) and each "
                    "step's stacking and commit are not split, so the speed-up stays under 2×"))
    rows.append(Row(a, "parallel (two-ended) resources", "473 DSP / 163 BRAM36 / 184,990 LUT / "
                    "211,895 FF", _honest(shown) + (" (best design)" if best else
                                                   " (fastest design; does not fit)"),
                    "operator DSP/LUT/FF are assumed (operators.py); the reader's DSP is a "
                    "lower bound on what Vitis binds; BRAM counts only the plan's memories (no "
                    "AXI/DMA or HLS control overhead)"))
    rows.append(Row(a, "serial resources", "255 DSP / 88 BRAM36 / 99,733 LUT / 120,416 FF",
                    _res(costs["serial"]) + f" (plan, n_u={units}, one unit set)",
                    "one unit set instead of two, same factor datapaths: the plan's factor "
                    "units are not halved as the paper's are"))
    st = progs["qr"].storage
    st_cost = {s: _cost(progs["qr"], units=units, jacobian_storage=s)
               for s in ("whitened", "raw")}
    words = {s: c.words for s, c in st_cost.items()}
    whiten = dict(st_cost["raw"].phase_cycles)["whiten_stack"]
    rows.append(Row(a, f"storage reduction, 3 steps, {cfg.lio_n} keyframes",
                    "15.5× / 19.0× / 56.3×",
                    " / ".join(f"{st.ratio(i):.1f}×" for i in (1, 2, 3))
                    + f"; plan memory words whitened {words['whitened']:,} → raw "
                    f"{words['raw']:,}, for +{whiten:,} whiten_stack cycles an iteration "
                    f"({st_cost['raw'].latency_ms / st_cost['whitened'].latency_ms - 1:+.1%})",
                    "fgc stores the whitened A = W·J: a full square-root information W mixes "
                    "rows and leaves no structural zeros to skip in step 3; the papers store raw "
                    "Jacobians (PlanOptions jacobian_storage='raw' prices that choice - a "
                    "what-if the emitter does not build, so the search does not take it)"))
    rows += paper_a_stream(cfg)
    return rows


@dataclass
class StreamDesign:
    """One candidate of the on-chip stream design's search (:func:`stream_search`): its options,
    the plan's resources (by part) and its price of every update of the stream (ms, model
    estimates), the second reader's DSP when it was read."""

    units: int
    unit_sets: int | None
    allocation: tuple | None
    dsp: int
    bram36: float
    parts: dict
    latency_ms: np.ndarray
    device: tuple[int, float]  # the part's DSP, BRAM36
    reader_dsp: int | None = None
    reader_parts: tuple = ()
    held: dict = dataclasses.field(default_factory=dict)  # WindowUpdateModel.duplicated()
    default: bool = False  # the default design (n_u the Program's, default unit sets, ALLOCATION)
    part: str = ""  # the FPGA part it is priced on
    qr_rows: int = 1  # the QR Update units' rows a cycle (HlsConfig.qr_rows)
    bind: tuple = ()  # the operators' binding (HlsConfig.bind)
    root_wave: bool = False  # the root step in a wavefront (HlsConfig.root_wave)
    data_width: int = 32  # the streaming top's data port, bits a beat (HlsConfig.data_width)
    retire_special: int | None = None  # the retire's special-function instances (HlsConfig)
    lut: int = 0  # the plan's LUT and FF, and the part's
    ff: int = 0
    fabric: tuple[int, int] = (0, 0)

    @property
    def one_set_dsp(self) -> int:
        """A design NOT built, by this candidate's plan: one set of units and datapaths for the
        window's solve and the batch steps (each unit kind at the larger of the two kernels'
        DSP) and the stream section (its marginal on LM's unit set 0) — the bound issue 33 item
        5's sharing could reach with these options."""
        kernel = sum(max(w.get("window kernel", 0), w.get("batch kernel", 0))
                     for w in self.held.values())
        return kernel + self.parts["stream section"][0]

    @property
    def label(self) -> str:
        alloc = ("default ALLOCATION" if self.allocation is None else "ALLOCATION "
                 + ",".join(f"{k}={v}" for k, v in self.allocation))
        sets = "default unit sets" if self.unit_sets is None else f"{self.unit_sets} unit set(s)"
        rows = f", {self.qr_rows} rows a cycle" if self.qr_rows > 1 else ""
        bind = ", operators bound " + ",".join(f"{k}={v}" for k, v in self.bind) \
            if self.bind else ""
        wave = ", the root in a wavefront" if self.root_wave else ""
        wave += f", data port {self.data_width} bits" if self.data_width != 32 else ""
        wave += (f", {self.retire_special} special-function instances a retraction"
                 if self.retire_special else "")
        return f"n_u={self.units}, {sets}, {alloc}{rows}{wave}{bind}"

    @property
    def median_ms(self) -> float:
        return float(np.median(self.latency_ms))

    @property
    def p99_ms(self) -> float:
        return float(np.percentile(self.latency_ms, 99))

    @property
    def fits_plan(self) -> bool:
        """The plan's DSP, BRAM36, LUT and FF within the part (a design bound to fabric trades
        DSP for LUT: its LUTs decide too)."""
        return (self.dsp <= self.device[0] and self.bram36 <= self.device[1]
                and self.lut <= self.fabric[0] and self.ff <= self.fabric[1])

    @property
    def honest_dsp(self) -> int:
        """DSP = max(plan, reader): the batch search's rule (the reader's when read)."""
        return max(self.dsp, self.reader_dsp or 0)

    @property
    def fits(self) -> bool:
        """Fits as re-priced: the plan fits and the reader's DSP (read) does too."""
        return self.fits_plan and self.reader_dsp is not None and self.honest_dsp <= self.device[0]

    def line(self) -> str:
        read = "unread" if self.reader_dsp is None else f"reader {self.reader_dsp:,}"
        return (f"{self.label}: median {self.median_ms:.3f} ms / p99 {self.p99_ms:.3f} ms per "
                f"update, {self.dsp:,} DSP ({read}) / {self.bram36:g} BRAM36 / {self.lut:,} "
                f"LUT / {self.ff:,} FF ("
                + ", ".join(f"{name} {d:,}" for name, (d, _) in self.parts.items()) + ")"
                + (": fits" if self.fits else ": over" if not self.fits_plan else ""))


def _stream_solver(cfg: Config) -> SolverConfig:
    """The on-chip stream's solver in paper A's setting: float32 QR, one Gauss-Newton step an
    update (ISAM2's policy) unless ``cfg.stream_one_step`` is off (LM to convergence)."""
    from fgc.app import streaming

    solver = SolverConfig(precision="float32", linear="qr")
    return streaming.one_step_solver(solver) if cfg.stream_one_step else solver


def paper_a_window(cfg: Config, units: int | None = None):
    """Paper A's stream (LIO N = ``cfg.lio_n``, K = 3, batch steps at ``cfg.stream_batch`` below
    N, :func:`_stream_solver`; ``units``: its n_u, else the solver's): (graph, Program, the
    stream program)."""
    import dataclasses

    from fgc.app import streaming

    n = cfg.lio_n
    graph = lio.build(N=n)
    solver = _stream_solver(cfg)
    if units is not None:
        solver = dataclasses.replace(solver, units=units)
    program = streaming.compile_stream(graph, solver, incremental=3,
                                       batch_every=tuple(b for b in cfg.stream_batch if b < n))
    return graph, program, streaming.stream_program(graph, program)


def stream_updates(graph, program, sp) -> list:
    """The simulator's run of stream program ``sp``: its update records, in order."""
    from fgc.app import streaming
    from fgc.ir.datafile import problem_data

    updates = []
    streaming.run_stream(sp, problem_data(graph, program), progress=updates.append)
    return updates


def parse_allocation(text: str) -> tuple[tuple[str, int], ...] | None:
    """A ``--allocation`` option: ``kind=count`` items (``add=8,mul=12,div=2``), or "default" /
    empty for the design's own limits (None)."""
    from fgc.errors import FgcError

    if text in ("", "default"):
        return None
    out = []
    for item in text.split(","):
        kind, _, count = item.partition("=")
        if not count.isdigit():
            raise FgcError(f"--allocation {text!r}: expected kind=count items, e.g. add=2,mul=3")
        out.append((kind.strip(), int(count)))
    return tuple(out)


def _stream_candidate(cfg: Config, sp, units: int, sets, alloc, rows: int, bind: tuple,
                      special, default_units, updates: list, prices: dict):
    """One candidate of :func:`stream_search`'s grid priced by its plan: the design of these
    options (the root in a wavefront on two unit sets where the window takes it, else
    without; the data port ``cfg.stream_data_width`` but on the default design's row) and each
    of ``updates`` priced as it runs them (``prices``: by the options that change a cycle; a
    binding changes none). Returns the :class:`StreamDesign` and the unit sets its plan
    resolves, or None when its options cannot be built (said on stderr)."""
    from fgc.app import streaming
    from fgc.errors import FgcError
    from fgc_backends.hls import HlsConfig
    from fgc_backends.hls.plan.report import unit_sets

    # (the root in a wavefront on two unit sets where the window takes it)
    wave = cfg.stream_root_wave and sets == 2
    # (the default design's row: HlsConfig's default port)
    width = 32 if units == default_units and sets is None else cfg.stream_data_width
    config = HlsConfig(scalar="float", unit_sets=sets, allocation=alloc, qr_rows=rows,
                       bind=bind, root_wave=wave, data_width=width, retire_special=special)
    try:
        pricer = streaming.WindowPricer(sp, config=config)
    except FgcError as exc:  # a unit-set count the window's levels cannot take
        if not wave:
            _progress(f"stream search: n_u={units}, {sets} unit sets, {alloc}: {exc}")
            return None
        wave = False  # (its schedule cannot take the wave: the design without)
        config = HlsConfig(scalar="float", unit_sets=sets, allocation=alloc, qr_rows=rows,
                           bind=bind, data_width=width, retire_special=special)
        try:
            pricer = streaming.WindowPricer(sp, config=config)
        except FgcError as exc2:
            _progress(f"stream search: n_u={units}, {sets} unit sets, {alloc}: {exc2}")
            return None
    res = pricer.model.resources()
    device = pricer.model.plan.target.device
    # a binding changes no cycle (config_op pins each latency): one binding's prices serve the
    # others of the same options
    key = (sets, alloc, rows, wave, width, special)
    if key not in prices:
        prices[key] = np.array([pricer.price(u).latency_ms for u in updates])
    default = (units == default_units and sets is None and alloc is None and rows == 1
               and not bind and special is None)
    d = StreamDesign(units, sets, alloc, res["dsp"], res["bram36"], res["parts"], prices[key],
                     (device.dsp, device.bram36), held=pricer.model.duplicated(),
                     default=default, part=res["part"], qr_rows=rows, bind=config.bind,
                     lut=res["lut"], ff=res["ff"], fabric=(device.lut, device.ff),
                     root_wave=wave, data_width=width, retire_special=special)
    return d, max(1, unit_sets(pricer.model.plan))


def stream_search(cfg: Config, graph, k: int, batch: tuple, updates: list,
                  default_units: int | None = None) -> list[StreamDesign]:
    """The on-chip stream design's search (issue 33 item 6): every n_u, unit-set count and
    factor-datapath ALLOCATION of ``cfg``'s stream axes priced by its plan
    (``WindowUpdateModel``: resources, and each of ``updates`` — the simulator's run of the
    stream — priced as that design runs it); then the fastest designs that fit by the plan are
    emitted and read by the second reader (``bench_second_reader.measure_stream``, at most
    ``cfg.stream_reads``) until one fits as re-priced (DSP = max(plan, reader)). When none fits
    by the plan, the smallest design is read (the search's floor). ``default_units``: the
    default design (that n_u, default unit sets and ALLOCATION) is a candidate too, marked
    ``default`` and always read (paper_a_stream reports it; the grid's design of the same
    options is not priced again). Returns every candidate, fastest first (the median, then the
    p99, per update). ``--qr-unit stream`` is not in the space: the stream model prices the
    Householder unit's steps alone (WindowUpdateModel)."""
    from fgc.app import streaming
    from fgc_backends.hls import HlsConfig

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from bench_second_reader import measure_stream

    base = _stream_solver(cfg)
    out = []
    axis = tuple(cfg.stream_units)
    if default_units is not None and default_units not in axis:
        axis = (default_units, *axis)
    default_sets = None  # the default design's unit sets, as its plan resolves them
    for units in axis:
        solver = dataclasses.replace(base, units=units)
        sp = streaming.stream_program(graph, streaming.compile_stream(
            graph, solver, incremental=k, batch_every=batch))
        prices: dict = {}
        grid = [(sets, alloc, rows, tuple(cfg.stream_binds)) for rows in cfg.stream_qr_rows
                for sets in cfg.stream_unit_sets for alloc in cfg.stream_allocations]
        if units == default_units:
            grid.insert(0, (None, None, 1, ((),)))
        for sets, alloc, rows, binds in grid:
            # the bindings in cfg's order (fewer DSP, more LUT, each): per retire_special, the
            # first that fits by the plan ends them (a later one is as fast, never preferred), as
            # does one over on LUT or FF (a later one has more)
            specials = list(cfg.stream_retire_special)
            default_row = units == default_units and sets is None
            if default_row:
                specials = [None]  # (the default design's row: HlsConfig's default retire)
            for bind in binds:
                if not specials:
                    break
                for special in list(specials):
                    if (units == default_units and alloc is None and sets is not None
                            and sets == default_sets and rows == 1 and not bind
                            and special is None
                            and not (cfg.stream_root_wave and sets == 2)):
                        continue  # the default design's own options: priced above
                    got = _stream_candidate(cfg, sp, units, sets, alloc, rows, bind, special,
                                            default_units, updates, prices)
                    if got is None:  # its options cannot be built: no binding will
                        specials = []
                        break
                    d, resolved = got
                    if d.default:
                        default_sets = resolved
                    out.append(d)
                    if d.fits_plan or d.lut > d.fabric[0] or d.ff > d.fabric[1]:
                        specials.remove(special)
    # equal speed (a binding changes no cycle): the binding order of cfg.stream_binds, the
    # default first, then the fewer DSP
    rank = {tuple(b): i for i, b in enumerate(cfg.stream_binds)}
    out.sort(key=lambda d: (d.median_ms, d.p99_ms, rank.get(d.bind, len(rank)), d.dsp))
    fitting = [d for d in out if d.fits_plan]
    to_read = fitting[:cfg.stream_reads] if fitting else [min(out, key=lambda d: d.dsp)]

    def read(d: StreamDesign) -> None:
        _progress(f"stream search: reading {d.label}")
        with tempfile.TemporaryDirectory() as tmp:
            got = measure_stream(cfg.lio_n, Path(tmp) / "stream",
                                 HlsConfig(scalar="float", unit_sets=d.unit_sets,
                                           allocation=d.allocation, qr_rows=d.qr_rows,
                                           bind=d.bind, root_wave=d.root_wave,
                                           data_width=d.data_width,
                                           retire_special=d.retire_special),
                                 d.units, batch,
                                 solver=base)
        d.reader_dsp = got["reader_dsp"]
        d.reader_parts = tuple(got["parts"])

    for d in to_read:
        read(d)
        if d.fits:
            break
    for d in out:  # the default design, read once (paper_a_stream's row)
        if d.default and d.reader_dsp is None:
            read(d)
    return out


def paper_a_stream(cfg: Config) -> list[Row]:
    """Paper A's own setting: incremental K = 3, batch steps at keyframes 5/15/25, N = 30, on
    the emitted on-chip design (its plan's price of each update, bench_stream.py --hls-model's
    model), against ISAM2 (relinearise all: the oracle's policy) timed in this process: the
    default design (read by the second reader) and the fastest design of the stream design's
    search (:func:`stream_search`) that fits, else the smallest it found."""
    from fgc.app import streaming
    from fgc.interop.to_gtsam import to_gtsam

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from bench_stream import _isam2_times

    n, k = cfg.lio_n, 3
    batch = tuple(b for b in cfg.stream_batch if b < n)
    policy = ("one Gauss-Newton step an update, relinearising the window (ISAM2's policy: one "
              "isam.update per keyframe, relinearise all; the store is the step's own "
              "factorisation)" if cfg.stream_one_step else
              "LM to convergence each update (ISAM2 takes one step: not the same policy)")
    graph, program, sp = paper_a_window(cfg)
    a = f"A (LIO N={n}, K={k}, batch at {', '.join(map(str, batch))})"
    if not streaming.on_chip(sp):
        return [Row(a, "per-update latency vs ISAM2", "9.3× ISAM2", "not emitted on chip",
                    "the stream's Program has no on-chip design")]
    updates = stream_updates(graph, program, sp)
    # the default design is one of the search's candidates, priced and read by the second
    # reader there once (bench_second_reader.measure_stream: the same setting): the fit is
    # judged on DSP = max(plan, reader), as the batch search judges it
    designs = stream_search(cfg, graph, k, batch, updates, default_units=program.solver.units)
    print("paper A's on-chip stream design, searched (fastest first; plan DSP, the reader's "
          "where read):")
    for d in designs:
        print("  " + d.line())
    default = next(d for d in designs if d.default)
    model = default.latency_ms
    dsp, fits = default.honest_dsp, default.fits
    fit = [d for d in designs if d.fits]
    best = fit[0] if fit else min(designs, key=lambda d: d.honest_dsp)
    one_set = "batch kernel" not in default.parts  # the one-step policy's sweep design
    problem = to_gtsam(graph)
    runs = [_isam2_times(graph, problem, program.schedule.clusters)[0]
            for _ in range(cfg.isam_repeats)]
    isam = np.median(np.asarray(runs), axis=0) * 1e3
    ratio = float(np.median(isam / model))
    best_ratio = float(np.median(isam / best.latency_ms))
    parts = ", ".join(f"{name} {d:,} DSP / {b:g} BRAM36"
                      for name, (d, b) in default.parts.items())
    searched = (f"the search ({len(designs)} designs: n_u {cfg.stream_units}, unit sets "
                f"{cfg.stream_unit_sets}, {len(cfg.stream_allocations)} ALLOCATION limits of "
                f"the factor datapaths, QR rows a cycle {cfg.stream_qr_rows}, operator bindings "
                + "; ".join(",".join(f"{k}={v}" for k, v in b) or "default"
                            for b in cfg.stream_binds)
                + ", and the default): "
                + (f"fastest that fits: {best.line()}; ISAM2 / design median {best_ratio:.2f}×"
                   if fit else
                   f"NONE fits the {default.part}; the smallest: {best.line()}, DSP = max(plan, "
                   f"reader) = {best.honest_dsp:,} against {best.device[0]:,}; ISAM2 / design "
                   f"median {best_ratio:.2f}×" + ("" if one_set else
                   f"; one set of units for its window's solve and "
                   f"batch steps (by its plan, each unit kind at the larger "
                   f"kernel's DSP, no marginal copy) would hold {best.one_set_dsp:,} DSP")))
    kernels = ("one set of units: each batch step a sweep through the window kernel (no batch "
               "kernel; docs/hls.md, 'One set of units')" if one_set else
               "its window and batch kernels each carry their own units and factor datapaths "
               "(LM to convergence; the one-step policy's design sweeps the window instead)")
    return [Row(a, "per-update latency vs ISAM2 (relinearise all, one update per keyframe)",
                "9.3× ISAM2; fits the xc7z045",
                f"on-chip design (n_u={program.solver.units}, default unit sets and ALLOCATION; "
                f"{policy}):"
                f" median {np.median(model):.3f} ms / p99 {np.percentile(model, 99):.3f} ms per "
                f"update; ISAM2 median {np.median(isam):.3f} ms / p99 "
                f"{np.percentile(isam, 99):.3f} ms (median of {cfg.isam_repeats} runs per "
                f"keyframe); ISAM2 / design per keyframe, median {ratio:.2f}×; "
                f"{default.dsp:,} DSP / {default.bram36:g} BRAM36 by the plan ({parts}), "
                f"{default.reader_dsp:,} DSP by the second reader ("
                + ", ".join(f"{part} {r:,}" for part, _, r in default.reader_parts) + "): "
                + ("fits" if fits else "does not fit") + f" the {default.part} "
                f"(DSP = max(plan, reader) = {dsp:,}); {searched}",
                "the update's price is the plan's (model estimates: the iterations the "
                "simulator ran, each priced as the emitted design runs it); the plan prices "
                "every copy the emitted text holds (plan >= second reader on every part; "
                "docs/hls.md); within each kernel the gradient and the rounding-noise pass "
                f"are one module for every block type; {kernels}; "
                "the marginal runs on LM's units and the kept net's re-expression beside the "
                "next update's solve, its Log and retraction one datapath module; where an "
                "update's cycles go: docs/hls.md, 'Paper A's setting against ISAM2'")]


def paper_b(cfg: Config) -> list[Row]:
    graph = imu_window.build(N=cfg.imu_n)
    prog = compile_graph(graph, SolverConfig(method="lm", linear="cholesky",
                                             precision="float32"))
    iters = _lm_iterations(graph)  # GTSAM's (float64 QR): what a well-conditioned solve takes
    b = f"B (IMU N={cfg.imu_n})"
    result = best_design({"cholesky": prog}, cfg, linears=("cholesky",))
    print("\n".join(result.lines()))
    # per #CPE the fastest design (one or two cascades) that fits, else that is not known over,
    # else the fastest
    rank = {"fits": 2, "unread": 1}
    by_cpe = {}
    for r in result.rows:
        if r.candidate.alloc_scale != 1:
            continue
        had = by_cpe.get(r.candidate.cpe)
        key = (rank.get(r.verdict, 0), -r.cycles)
        if had is None or key > (rank.get(had.verdict, 0), -had.cycles):
            by_cpe[r.candidate.cpe] = r
    floor = latency_floor(prog, build_plan(prog, PlanOptions.of(prog)).ops)
    # the cycles' ratio from the fewest to the most CPEs, one cascade each, and with two
    # cascades at the most (twice the CPEs)
    one = {r.candidate.cpe: r for r in result.rows if r.candidate.alloc_scale == 1
           and r.candidate.unit_sets is None and not r.candidate.extra}
    two = {r.candidate.cpe: r for r in result.rows if r.candidate.alloc_scale == 1
           and r.candidate.unit_sets == 2 and not r.candidate.extra}
    lo, hi = cfg.cpes[0], cfg.cpes[-1]
    lo_hi = f"{one[lo].cycles / one[hi].cycles:.2f}×" + (
        f", {lo} → {hi} x2: {one[lo].cycles / two[hi].cycles:.2f}×" if hi in two else "")
    # issue 33's 5 -> 80: CPEs counted in all (two cascades of 40 hold 80), any options, against
    # one cascade of the fewest with the default options
    at80 = [r for r in result.rows if r.candidate.alloc_scale == 1
            and r.candidate.cpe * (r.candidate.unit_sets or 1) == 80]
    if at80:
        fast80 = min(at80, key=lambda r: r.cycles)
        lo_hi += (f", {lo} → 80 CPEs in all: {one[lo].cycles / fast80.cycles:.2f}× "
                  f"({fast80.label}, {fast80.verdict})")
    rows = [Row(b, "latency per solve at #CPE " + " / ".join(map(str, cfg.cpes))
                + " (re-priced fit)", "171 ms (5) / 8.97 ms (120)",
                " / ".join(f"#CPE={c}{' x2' if by_cpe[c].candidate.unit_sets else ''}"
                           + "".join(f" {k}={v}" for k, v in by_cpe[c].candidate.extra)
                           + f" "
                           f"{by_cpe[c].latency_ms * iters:.2f} ms "
                           f"({by_cpe[c].verdict}: {by_cpe[c].bound})" for c in cfg.cpes)
                + f" ({iters} LM iterations each, GTSAM's float64 QR count: assumed, not "
                f"the float32 design's, see the next row; {cfg.cpes[0]} → {cfg.cpes[-1]} CPEs "
                f"{lo_hi}; best that fits: "
                + (f"{result.best.label} {result.best.latency_ms * iters:.2f} ms"
                   if result.best is not None else "none") + ")",
                f"{limits_line(floor, by_cpe[cfg.cpes[-1]].cost)} (at #CPE={cfg.cpes[-1]}). "
                f"{floor.describe()}; fit: DSP = max(plan, second reader), read designs and "
                "what the reader's monotonicity in #CPE implies")]
    rows += paper_b_solve(graph, prog, result, cfg, iters)
    lo, hi = cfg.cpes[0], cfg.cpes[-1]
    # the emitted design's back-substitution width (by columns on this chain: HlsConfig's
    # automatic backsub_lanes), not PlanOptions' one-lane default; the what-if designs keep one
    emitted = {"backsub_lanes": auto_backsub_lanes(prog)}
    costs = {(c, h): _cost(prog, cpe=c, hessian_storage=h, **(emitted if h == "frontal" else {}))
             for c in cfg.cpes for h in ("frontal", "dense", "blocked")}
    def solve(c, h):
        cost = costs[c, h]
        return f"{cost.latency_ms * iters:.2f} ms" + (
            "" if cost.fits else f" (does not fit: {', '.join(cost.over)})")

    rows.append(Row(b, f"solve at #CPE={lo} / {hi}", "171 ms (5) / 8.97 ms (120)",
                    " / ".join(solve(c, "frontal") for c in (lo, hi))
                    + " emitted (multifrontal: each step's frontal [H | g]); what-if whole-"
                    "matrix designs: dense H "
                    + " / ".join(solve(c, "dense") for c in (lo, hi)) + "; blocked H "
                    + " / ".join(solve(c, "blocked") for c in (lo, hi))
                    + f" ({iters} LM iterations, GTSAM's float64 QR count: assumed)",
                    "the emitted design streams each elimination step's frontal matrix through "
                    "the cascade, one word a cycle per round, steps one after another; a pivot "
                    "no longer stalls the stream (about 14 cycles a CPE in float32), so a step "
                    "costs about its words and CPEs beyond its f pivots idle "
                    "(docs/hls.md, 'The Cholesky cascade'); the what-if "
                    "designs stream H's whole trailing triangle (or its envelope); the paper's "
                    "iteration count and CPE pipeline are not known here"))
    cpe = build_plan(prog, PlanOptions.of(prog, cpe=lo)).unit("cpe")
    ops = build_plan(prog, PlanOptions.of(prog, cpe=lo)).ops
    per_cpe = sum(n * ops.op(k).dsp for k, n in cpe.operators) + cpe.extra_dsp
    rows.append(Row(b, "DSP per CPE", "6", str(per_cpe),
                    "per CPE an adder 2 + two multipliers 3 each (assumed DSP of the full-DSP "
                    "cores: its Update loop's x - h_i (h_c / d)); its tap's divide is LUT-only "
                    "and no square root is taken"))
    c123 = [c for c in cfg.c123 if (c, "dense") in costs] or list(cfg.c123)
    for c in c123:
        if (c, "dense") not in costs:
            costs[c, "dense"] = _cost(prog, cpe=c)
            costs[c, "blocked"] = _cost(prog, cpe=c, hessian_storage="blocked")
    rows.append(Row(b, "C1-C3 DSP share of 900", "30.9 % - 70.9 %",
                    ", ".join(f"#CPE={c} {costs[c, 'dense'].dsp / PART_DSP:.1%}"
                              + ("" if costs[c, "dense"].fits else " (does not fit)")
                              for c in c123),
                    "the plan's factor datapaths (one per block type, ALLOCATION-limited) and "
                    "16 HGC lanes add a fixed ~"
                    f"{costs[c123[0], 'dense'].dsp - per_cpe * c123[0]} DSP to the CPEs' "
                    f"{per_cpe} each; "
                    "paper B's factor units are smaller"))
    c1 = costs[(c123[0], "dense")]
    c1b = costs[(c123[0], "blocked")]
    rows.append(Row(b, "linear solve share of the time", "82.4 %",
                    f"{c1.linear_cycles / c1.cycles:.1%} dense H, "
                    f"{c1b.linear_cycles / c1b.cycles:.1%} blocked H at #CPE={c123[0]} (HGC + "
                    "cascade + triangular solve)",
                    "a dense cascade streams all of H's trailing triangle every round; the "
                    "blocked plan streams only H's envelope, so the factor phases weigh more"))
    rows.append(Row(b, "power C1 / C2 / C3", "2.293 / 2.956 / 3.759 W",
                    " / ".join(f"{plan_power_w(costs[c, 'dense']):.3f} W" for c in c123)
                    + f" (#CPE {', '.join(map(str, c123))})",
                    "not modelled by the plan: the sim model's static + per-resource power, "
                    "whose coefficients were fitted to these three figures (with the sim "
                    "model's resources), applied to the plan's resources - not a reproduction"))
    ratios = []
    for n in cfg.storage_ns:
        p = compile_graph(imu_window.build(N=n), SolverConfig(method="lm", linear="cholesky",
                                                              precision="float32"))
        dense_words = p.storage.dense_words
        blocked = _cost(p, hessian_storage="blocked").words
        ratios.append(f"N={n}: {p.storage.ratio(3):.1f}× (plan words dense "
                      f"{_cost(p).words:,} → blocked {blocked:,}; dense H+g {dense_words:,})")
    rows.append(Row(b, "Hessian storage reduction", "21.1× (N=20) / 82.8× (N=80)",
                    "; ".join(ratios),
                    "fgc's step 3 skips H's fixed zeros of the whitened Jacobians; the full IMU "
                    "square-root information fills the blocks the paper's raw Jacobians keep "
                    "sparse"))
    return rows


def _counted_solve(graph, program, best, space: Space) -> tuple[str, float]:
    """The solve of the search's design ``best`` (a row of :func:`best_design` over
    ``program``) as its counting C simulation runs it on ``graph``'s data
    (bench_cycles.measure: every loop counted, the plan's figure of the same executions beside
    it): (what it ran, ms a solve)."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import bench_cycles

    linear = best.candidate.linear
    design = best.candidate.program({linear: program})
    phases, events = bench_cycles.measure(f"paper B {best.label}", graph, design.solver,
                                          best.candidate.config(space))
    counted = sum(c for c, _ in phases.values())
    model = sum(m for _, m in phases.values())
    ms = counted / (design.solver.clock_mhz * 1e3)
    lins, solves = events.get("linearize", 0), events.get("solve", 0)
    return (f"{best.label} ({best.cost.dsp} DSP by the plan, {best.verdict}): {lins} "
            f"linearisations, {solves} solves ({solves - lins} retries at a larger μ), "
            f"{counted:,} cycles counted (plan {model:,}, csim/plan {counted / model:.3f}) = "
            f"{ms:.2f} ms a solve at {design.solver.clock_mhz:g} MHz ({8.97 / ms:.2f}× paper "
            f"B's 8.97 ms)"), ms


def paper_b_solve(graph, prog, result, cfg: Config, iters: int) -> list[Row]:
    """Paper B's solve priced by what the designs run: the best float32 Cholesky design that
    fits (paper B's architecture) and the best float32 QR design that fits, each by its
    counting C simulation on the problem, beside the simulator's float32 runs of the same
    Programs. ``cfg.design_run`` False: only what is assumed is said."""
    import warnings

    from fgc.ir.datafile import problem_data
    from fgc_backends.sim.runner import run as sim_run

    b = f"B (IMU N={cfg.imu_n})"
    if result.best is None or not cfg.design_run:
        return [Row(b, "latency per solve, the design's own run", "8.97 ms (120)",
                    "not run (Config.design_run False, or no design fits): the solve figures "
                    f"above assume {iters} LM iterations", "bench/bench_solve_path.py traces "
                    "the float32 runs")]

    def simulated(program):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            sim = sim_run(program, problem_data(graph, program))
        ill = [str(w.message) for w in caught if "ill-conditioned" in str(w.message)]
        return (f"the float32 simulator: {sim.iterations} iterations, {sim.status} "
                f"({sim.reason})" + (f"; it warns: {ill[0]}" if ill else ""))

    text, _ = _counted_solve(graph, prog, result.best, search_space(cfg, ("cholesky",)))
    rows = [Row(b, "latency per solve, the design's own run (counting C simulation), float32 "
                "Cholesky", "8.97 ms (120)",
                f"{text}; at {iters} iterations it would be "
                f"{result.best.latency_ms * iters:.2f} ms; {simulated(prog)}",
                "on this problem float32 Cholesky is below its rounding: the root step's Schur "
                "complement of H + μI is not positive definite in float32 at μ ≤ 1 or is, as "
                "the last bits fall, and float32 rounding alone moves the first step by 30-40 % "
                "(bench/bench_solve_path.py: both runs try by try); so LM's path and its "
                "iteration count are the rounding's, and the two runs end at the float32 noise "
                "floor centimetres apart (docs/hls.md, 'Paper B's solve in float32')")]
    # the QR designs over n_u and the QR unit, default unit sets, ALLOCATION and back-
    # substitution (each QR plan of N = 50 takes seconds: the full space is 120 of them)
    qr = compile_graph(graph, SolverConfig(method="lm", linear="qr", precision="float32"))
    space = Space(linears=("qr",), units=cfg.units)
    found = search({"qr": qr}, space, max_reads=cfg.reads, reader=cfg.reads != 0,
                   progress=_progress)
    if found.best is None:
        rows.append(Row(b, "latency per solve, float32 QR", "8.97 ms (120)",
                        "no float32 QR design fits", ""))
        return rows
    text, _ = _counted_solve(graph, qr, found.best, space)
    rows.append(Row(b, "latency per solve, the design's own run (counting C simulation), float32 "
                    "QR", "8.97 ms (120)", f"{text}; {simulated(qr)}",
                    "QR never forms H, so float32 holds this problem (κ ≈ 5e3 after "
                    "equilibration; QR tolerates up to 8.4e6, Cholesky 2.9e3): LM takes "
                    "float64's iterations and the C simulation stays within 1 cm / 1 mrad of "
                    "the simulator; a float64 linear solver would save Cholesky too, but its "
                    "CPEs (25 DSP each in double, 8 in float) and HGC do not fit the xc7z045"))
    return rows


def _lm_iterations(graph) -> int:
    from fgc.app.run_report import gtsam_optimize
    from fgc.interop.to_gtsam import to_gtsam

    return max(1, gtsam_optimize(to_gtsam(graph), linear="qr")[1])


def table(cfg: Config = Config()) -> list[Row]:
    return paper_a(cfg) + paper_b(cfg)


def format_rows(rows: list[Row]) -> str:
    lines = []
    for r in rows:
        lines += [f"[{r.paper}] {r.figure}", f"    published: {r.published}",
                  f"    fgc:       {r.fgc}", f"    why:       {r.why}"]
    return "\n".join(lines)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--small", action="store_true",
                    help="LIO N=5, IMU N=5, the plan's figures alone: a smoke run")
    ap.add_argument("--reads", type=int, default=None,
                    help="a cap on the designs each search may emit and read (default: none, "
                         "the search reads in plan-speed order until one fits; 0: the plan's "
                         "figures alone; cached reads are free)")
    args = ap.parse_args(argv)
    cfg = SMALL if args.small else Config()
    if args.reads is not None:
        cfg = dataclasses.replace(cfg, reads=max(0, args.reads))
    t0 = time.perf_counter()
    rows = table(cfg)
    print(format_rows(rows))
    print(f"({time.perf_counter() - t0:.0f} s)")


if __name__ == "__main__":
    main()
