"""``fgc sweep``: design-space exploration — latency, resources, energy and accuracy per design.

    designs = design_space(units=(1, 2, 4, 8), cpe=(5, 20, 40), precisions=("float32",),
                           linears=("qr", "cholesky"))
    with open_executor(jobs=2) as pool:
        result = run_sweep(graph, SolverConfig(), designs, pool)
    write_outputs(result, Path("sweep/"))     # sweep.csv, sweep.json, pareto.png, accuracy.png

Unit counts and precision only change the Program's SolverConfig: the kernels, schedule and
storage plan depend on the structure and the linear solver alone, and the simulator's numerics
on (linear, precision) alone — n_u and #CPE are hardware parallelism the cost model prices, the
arithmetic is the same. So the sweep compiles once per linear solver, simulates once per
(linear, precision) group, and runs the cost model for every design of the group; n_u applies to
QR designs only and #CPE to Cholesky designs only, so the product is taken over the axes that
apply. Groups run in parallel on any ``concurrent.futures.Executor`` (local processes, or a Dask
cluster's executor); workers receive the Program and its data, never the spec file, so remote
workers need fgc installed but not the user's files. GTSAM's LM optimum, the accuracy reference,
is computed once, in this process, while the workers run.

The fit verdict (``fit_reads`` not None) is the design-space search's (:mod:`fgc.app.search`,
the one bench_papers uses): per precision, the sweep's designs as the HLS backend emits them,
priced by the accelerator plan and judged on DSP = max(plan, the second reader's DSP of the
emitted design), BRAM36/LUT/FF from the plan; each row gets the plan's latency and DSP, the
reader's DSP where read, the verdict (fits / over / unread) and the figure that bound it, the
fastest design that fits is marked ``best``, and designs the re-pricing puts over the part are
raised as :class:`fgc_backends.hls.lint.HlsFitWarning`. ``fit_reads`` bounds the designs
emitted and read per precision (0: the plan's figures alone).
"""

from __future__ import annotations

import concurrent.futures as cf
import csv
import dataclasses
import json
import os
import signal
import socket
import sys
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager, suppress
from dataclasses import dataclass
from pathlib import Path

from fgc.errors import FgcError
from fgc.frontend.dsl import Graph
from fgc.ir.program import Program, SolverConfig, check_program

COLUMNS = ("linear", "precision", "units", "cpe", "status", "iterations", "latency_ms", "cycles",
           "dsp", "bram", "lut", "ff", "power_w", "energy_mj", "fits", "max_rotation_error",
           "max_translation_error", "final_error", "pareto", "error", "plan_latency_ms",
           "plan_dsp", "reader_dsp", "honest_dsp", "plan_bram36", "fit", "fit_bound", "best")


@dataclass(frozen=True)
class Design:
    """One accelerator configuration; ``units`` (n_u) is set on QR designs only, ``cpe`` on
    Cholesky designs only."""

    linear: str
    precision: str
    units: int | None = None
    cpe: int | None = None

    def solver(self, base: SolverConfig) -> SolverConfig:
        """``base`` with this design's linear solver, precision and unit count."""
        return dataclasses.replace(base, linear=self.linear, precision=self.precision,
                                   units=self.units or base.units, cpe=self.cpe or base.cpe)

    @property
    def label(self) -> str:
        """Short name for plots: ``qr f32 n_u=4`` / ``chol f64 CPE=40``."""
        units = f"n_u={self.units}" if self.linear == "qr" else f"CPE={self.cpe}"
        return f"{self.linear[:4]} f{self.precision[-2:]} {units}"


def design_space(units: Sequence[int], cpe: Sequence[int], precisions: Sequence[str],
                 linears: Sequence[str]) -> tuple[Design, ...]:
    """The cartesian product over the axes that apply: QR × n_u, Cholesky × #CPE, × precision."""
    out = []
    for linear in linears:
        for precision in precisions:
            if linear == "qr":
                out += [Design(linear, precision, units=u) for u in units]
            else:
                out += [Design(linear, precision, cpe=c) for c in cpe]
    return tuple(out)


@dataclass(frozen=True)
class GroupResult:
    """What a worker returns for one (linear, precision) group: the simulator's outcome, one
    cost row per design, and the worker's CPU and wall seconds (for utilisation)."""

    linear: str
    precision: str
    status: str
    iterations: int
    final_error: float | None
    values: dict
    costs: tuple[dict, ...]
    error: str | None
    cpu_seconds: float
    wall_seconds: float
    worker: str


def evaluate_group(program: Program, data, designs: tuple[Design, ...]) -> GroupResult:
    """Worker entry point: simulate ``program`` on ``data`` once, then run the cost model for
    every design (all share the Program's linear solver and precision). Failures are returned,
    not raised, so one bad group does not end the sweep."""
    from fgc_backends import cost as cost_model
    from fgc_backends import load

    cpu0, wall0 = time.process_time(), time.perf_counter()
    worker = f"{socket.gethostname()}:{os.getpid()}"
    solver = program.solver
    try:
        sim = load("sim")
        result = sim.run(program, data)
        costs = tuple(_cost_row(cost_model.estimate(
            dataclasses.replace(program, solver=d.solver(solver)),
            iterations=max(result.iterations, 1))) for d in designs)
    except Exception as exc:  # reported in the group's rows: the sweep goes on
        return GroupResult(solver.linear, solver.precision, "error", 0, None, {}, (),
                           f"{type(exc).__name__}: {exc}", time.process_time() - cpu0,
                           time.perf_counter() - wall0, worker)
    return GroupResult(solver.linear, solver.precision, result.status, result.iterations,
                       result.final_error, result.values, costs, None,
                       time.process_time() - cpu0, time.perf_counter() - wall0, worker)


def _cost_row(cost) -> dict:
    r = cost.resources
    return {"latency_ms": cost.latency_ms, "cycles": cost.cycles, "dsp": r.dsp,
            "bram": r.bram, "lut": r.lut, "ff": r.ff, "power_w": cost.power_w,
            "energy_mj": cost.energy_mj, "fits": cost.utilization.fits}


# --------------------------------------------------------------------------------------------
# executors
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Pool:
    """An executor and how many tasks it runs at once."""

    executor: cf.Executor
    workers: int
    description: str


@contextmanager
def open_executor(jobs: int | None = None, address: str | None = None) -> Iterator[Pool]:
    """Local processes (``jobs``, default ``os.cpu_count()``), or the Dask scheduler at
    ``address`` (``tcp://host:port``) through its ``concurrent.futures`` executor."""
    if address is None:
        n = jobs or os.cpu_count() or 1
        executor = cf.ProcessPoolExecutor(max_workers=n, initializer=_ignore_interrupts)
        try:
            yield Pool(executor, n, f"{n} local processes")
        except BaseException:  # Ctrl-C (or an error): stop the running groups, start no more
            for proc in list((getattr(executor, "_processes", None) or {}).values()):
                with suppress(OSError):
                    os.kill(proc.pid, signal.SIGINT)  # a running group unwinds, cleaning up
            executor.shutdown(wait=True, cancel_futures=True)  # all workers gone on return
            raise
        executor.shutdown(wait=True)
        return
    client_class = _dask_client_class()
    try:
        client = client_class(address, timeout=10)
    except (OSError, TimeoutError) as exc:
        raise FgcError(f"--executor {address}: cannot reach the Dask scheduler ({exc})") from exc
    with client:
        n = sum(client.nthreads().values())
        yield Pool(client.get_executor(), n, f"Dask cluster at {address} ({n} worker threads)")


def _ignore_interrupts() -> None:
    """A local worker ignores Ctrl-C while it waits for work (the sweep's process handles it
    and interrupts the running groups: :func:`_interruptible`), so no worker prints a traceback."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _interruptible(fn, *args):
    """``fn(*args)`` in a local worker with Ctrl-C raising KeyboardInterrupt while it runs (its
    temporary folders are removed as it unwinds; the interrupt is returned to the sweep's process
    as the task's exception, not printed); elsewhere (a Dask thread) just ``fn(*args)``."""
    if threading.current_thread() is not threading.main_thread():
        return fn(*args)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        return fn(*args)
    finally:
        signal.signal(signal.SIGINT, previous)


def _dask_client_class() -> type:
    try:
        from distributed import Client
    except ImportError as exc:
        raise FgcError("--executor needs dask's distributed scheduler; install it with "
                       "pip install 'fgc[sweep]' (or pip install 'dask[distributed]')") from exc
    return Client


# --------------------------------------------------------------------------------------------
# the sweep
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class SweepResult:
    """One row per design (``COLUMNS``), GTSAM's reference, and how the work was spread."""

    rows: tuple[dict, ...]
    reference: dict
    timing: dict
    fit_lines: tuple[str, ...] = ()  # the search's table and best design, per precision


def group_programs(graph: Graph, base: SolverConfig, designs: Sequence[Design],
                   name: str = "fgc_problem") -> Iterator[tuple[tuple[str, str], Program]]:
    """((linear, precision), Program) per group, lazily: compiled once per linear solver, the
    precision set in its SolverConfig (lowering only records the SolverConfig)."""
    from fgc.compile import compile_graph

    compiled: dict[str, Program] = {}
    done = set()
    for d in designs:
        if (d.linear, d.precision) in done:
            continue
        done.add((d.linear, d.precision))
        if d.linear not in compiled:
            compiled[d.linear] = compile_graph(graph, d.solver(base), name=name)
        program = dataclasses.replace(compiled[d.linear], solver=d.solver(base))
        check_program(program)
        yield (d.linear, d.precision), program


def run_sweep(graph: Graph, base: SolverConfig, designs: Sequence[Design], pool: Pool,
              name: str = "fgc_problem",
              progress: Callable[[int], None] | None = None, fit_reads: int | None = None,
              fit_progress: Callable[[str], None] | None = None,
              fit_binds: tuple = ((),)) -> SweepResult:
    """Evaluate ``designs`` on ``pool``: a simulator run per (linear, precision) group, the cost
    model per design, accuracy against GTSAM's LM optimum; ``progress(n)`` after n designs;
    with ``fit_reads`` (not None) the search's fit verdict per design (:func:`fit_search`;
    ``fit_progress`` gets its progress lines; ``fit_binds``: the operator bindings it may take,
    ``Space.binds``).

    Each group is submitted as soon as it is compiled, so compiling the next linear solver and
    GTSAM's optimisation overlap with the workers."""
    from fgc.ir.datafile import problem_data

    futures, data, t0, programs = {}, None, None, {}
    for key, program in group_programs(graph, base, designs, name):
        programs[key] = program
        data = data or problem_data(graph, program)  # one layout for every group
        members = tuple(d for d in designs if (d.linear, d.precision) == key)
        t0 = t0 or time.perf_counter()  # the workers' window opens at the first task
        futures[pool.executor.submit(_interruptible, evaluate_group, program, data,
                                     members)] = key
    reference, gtsam_values = _gtsam_reference(graph)
    groups = {}
    for future in cf.as_completed(futures):
        groups[futures[future]] = group = future.result()
        if progress:
            progress(max(len(group.costs), 1))
    wall = time.perf_counter() - t0
    cpu = sum(g.cpu_seconds for g in groups.values())
    busy = min(pool.workers, len(groups))
    timing = {"executor": pool.description, "workers": pool.workers, "tasks": len(groups),
              "designs": len(designs), "wall_seconds": wall, "worker_cpu_seconds": cpu,
              "cpu_utilization": cpu / (wall * busy) if wall > 0 else 0.0,
              "task_workers": sorted({g.worker for g in groups.values()})}
    rows = _rows(graph, designs, groups, gtsam_values)
    fit_lines: list[str] = []
    if fit_reads is not None:
        searches = fit_search(programs, designs, fit_reads, fit_progress, fit_binds)
        _add_fit(rows, searches, name)
        for precision, result in searches.items():
            floor = _floor(result, programs, precision)
            fit_lines += [f"re-priced fit, {precision}:", *result.lines(floor)]
    return SweepResult(tuple(rows), reference, timing, tuple(fit_lines))


def _floor(result, programs: dict, precision: str):
    """The latency floor (fgc.app.floor) of the best design's Program (else the fastest's), at
    its plan's operator table."""
    from fgc.app.floor import latency_floor
    from fgc_backends.hls.plan import PlanOptions, build_plan

    row = result.best or result.rows[0]
    c = row.candidate
    program = next(p for (lin, prec), p in programs.items()
                   if lin == c.linear and prec == precision)
    program = c.program({c.linear: program})
    return latency_floor(program, build_plan(program, PlanOptions.of(program)).ops)


def add_fit_arguments(parser) -> None:
    """``fgc sweep``'s fit-search option (``--fit-reads``)."""
    import argparse

    def count(text: str) -> int:
        if not text.strip().isdigit():
            raise argparse.ArgumentTypeError(f"{text!r} is not a non-negative integer")
        return int(text)

    parser.add_argument("--fit-reads", type=count, default=2, metavar="N",
                        help="designs per precision the fit search may emit and read with the "
                             "second reader (DSP = max(plan, reader)); 0: the plan alone; "
                             "reads are cached in FGC_CACHE_DIR (default 2)")

    def bind(text: str):
        from fgc_backends.cost.operators import BindError, parse_bind

        try:
            return parse_bind(text)
        except BindError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    parser.add_argument("--fit-bind", type=bind, action="append", metavar="KIND=IMPL,…",
                        help="an operator binding the fit search may also take (repeatable; "
                             "HlsConfig.bind, e.g. add=fabric or add=fabric,mul=meddsp): same "
                             "cycles, fewer DSP, more LUT/FF; a design's row takes the first "
                             "binding that fits (the default first)")


def fit_options(args, show_progress: bool) -> dict:
    """:func:`run_sweep`'s fit-search keywords from ``fgc sweep``'s parsed arguments (progress
    lines on stderr when ``show_progress``)."""
    return {"fit_reads": args.fit_reads,
            "fit_binds": ((), *(getattr(args, "fit_bind", None) or ())),
            "fit_progress": (lambda line: print(line, file=sys.stderr)) if show_progress
            else None}


def fit_search(programs: dict, designs: Sequence[Design], reads: int,
               progress: Callable[[str], None] | None = None, binds: tuple = ((),)) -> dict:
    """Per precision, :func:`fgc.app.search.search` over the sweep's designs as the HLS backend
    emits them (its default unit sets and ALLOCATION) in each of ``binds`` (the operators'
    bindings, ``Space.binds``): ``programs`` is {(linear, precision): Program}; at most
    ``reads`` designs emitted and read per precision."""
    from fgc.app.search import Space, search

    out = {}
    for precision in sorted({d.precision for d in designs}):
        members = [d for d in designs if d.precision == precision]
        progs = {lin: p for (lin, prec), p in programs.items() if prec == precision}
        space = Space(linears=tuple(progs),
                      units=tuple(sorted({d.units for d in members if d.units})) or (1,),
                      cpe=tuple(sorted({d.cpe for d in members if d.cpe})) or (5,),
                      scalar="float" if precision == "float32" else "double",
                      # the sweep's designs are the default unit's: no QR-unit axis
                      extra=(("qr_unit", ("householder",)),), binds=binds)
        out[precision] = search(progs, space, max_reads=max(0, reads), reader=reads > 0,
                                progress=progress)
    return out


def _add_fit(rows: list[dict], searches: dict, name: str) -> None:
    """The search's figures and verdict into each sweep row; an HlsFitWarning per design the
    plan fits but the honest figures do not."""
    import warnings

    from fgc.app.search import fit_warnings
    from fgc_backends.cost.operators import bind_label
    from fgc_backends.hls.lint import HlsFitWarning

    for precision, result in searches.items():
        # the sweep's designs are the emitter's default unit sets (one Cholesky cascade); the
        # search's two-cascade designs are in its lines (fit_lines) and may be its best
        # a design in several bindings: the first (in the search's binding order, the default
        # first) that fits, else the default's
        by: dict = {}
        for r in sorted(result.rows, key=lambda r: r.verdict != "fits"):  # stable: rank
            if r.candidate.linear == "qr" or r.candidate.unit_sets is None:
                key = (r.candidate.linear, r.candidate.units, r.candidate.cpe)
                if key not in by and (r.verdict == "fits" or not r.candidate.bind):
                    by[key] = r
        for row in rows:
            if row["precision"] != precision:
                continue
            r = by.get((row["linear"], row["units"], row["cpe"]))
            if r is None:
                continue
            row.update({"plan_latency_ms": r.latency_ms, "plan_dsp": r.cost.dsp,
                        "reader_dsp": r.reader_dsp, "plan_bram36": r.cost.bram36,
                        "fit": r.verdict, "honest_dsp": r.dsp,
                        "fit_bound": r.bound + (f" (bound {bind_label(r.candidate.bind)})"
                                                if r.candidate.bind else ""),
                        "part_dsp": r.caps["dsp"],
                        "best": r is result.best and r.verdict == "fits"})
        for message in fit_warnings(result, name):
            warnings.warn(message, HlsFitWarning, stacklevel=2)


def _gtsam_reference(graph: Graph) -> tuple[dict, dict]:
    """GTSAM's LM optimum (same settings as ``fgc verify``) as fgc values, and a summary."""
    from fgc.app.run_report import gtsam_optimize
    from fgc.interop.to_gtsam import to_gtsam, values_from_gtsam

    t0 = time.perf_counter()
    problem = to_gtsam(graph)
    optimum, iterations = gtsam_optimize(problem)
    summary = {"final_error": float(problem.graph.error(optimum)), "iterations": iterations,
               "seconds": time.perf_counter() - t0}
    return summary, values_from_gtsam(graph, problem, optimum)


def _rows(graph: Graph, designs: Sequence[Design], groups: dict, gtsam_values: dict) -> list:
    """One row per design, in design order, with accuracy and the Pareto flag."""
    from fgc.app.plots import pareto_front
    from fgc.app.run_report import state_errors

    errors = {}
    for key, g in groups.items():
        if g.error is None:
            ours = {k: g.values[str(k)] for k in graph.variables}
            errors[key] = state_errors(graph, ours, gtsam_values)
    rows, seen = [], {key: 0 for key in groups}
    for d in designs:
        key = (d.linear, d.precision)
        g, i = groups[key], seen[key]
        seen[key] += 1
        row = {"linear": d.linear, "precision": d.precision, "units": d.units, "cpe": d.cpe,
               "status": g.status, "iterations": g.iterations, "final_error": g.final_error,
               "error": g.error, "pareto": False, "label": d.label}
        row.update(g.costs[i] if g.error is None else {})
        row.update({k: v for k, v in errors.get(key, {}).items() if k != "max_state_error"})
        rows.append(row)
    feasible = [r for r in rows if r.get("fits") and r["status"] == "converged"]
    for i in pareto_front(feasible, "dsp", "latency_ms"):
        feasible[i]["pareto"] = True
    return rows


# --------------------------------------------------------------------------------------------
# output
# --------------------------------------------------------------------------------------------


def table_lines(result: SweepResult) -> list[str]:
    """The sweep as an aligned plain-text table (``*`` marks the Pareto front)."""
    from fgc.app.design_report import format_table

    headers = ("design", "status", "iter", "latency ms", "DSP", "BRAM36", "LUT", "FF",
               "energy mJ", "fits", "rot err rad", "pos err m", "front", "re-priced fit")
    return format_table(headers, [_display(r) for r in result.rows])


def summary_lines(result: SweepResult, spec: str) -> list[str]:
    """What ``fgc sweep`` prints: a headline, the table, and how the work was spread."""
    t, ref = result.timing, result.reference
    failures = {f"  {r['linear']} {r['precision']} failed: {r['error']}": None
                for r in result.rows if r["error"] is not None}
    return [f"fgc sweep {spec}: {len(result.rows)} designs; accuracy vs GTSAM LM (final error "
            f"{ref['final_error']:.6g} after {ref['iterations']} iterations)",
            *table_lines(result), *failures, *result.fit_lines,
            f"{t['tasks']} simulator runs on {t['executor']}: wall {t['wall_seconds']:.1f} s, "
            f"worker CPU {t['worker_cpu_seconds']:.1f} s ({t['cpu_utilization']:.0%} of the "
            "busy workers' time)"]


def _display(r: dict) -> tuple[str, ...]:
    if r["error"] is not None:
        return (r["label"], "error", "-", *("-" for _ in range(11)))
    return (r["label"], r["status"], str(r["iterations"]), f"{r['latency_ms']:.3f}",
            f"{r['dsp']:,}", f"{r['bram']:g}", f"{r['lut']:,}", f"{r['ff']:,}",
            f"{r['energy_mj']:.3f}", "yes" if r["fits"] else "no",
            f"{r['max_rotation_error']:.1e}", f"{r['max_translation_error']:.1e}",
            "*" if r["pareto"] else "",
            (r["fit"] + (" (best)" if r.get("best") else "")) if r.get("fit") else "-")


def write_outputs(result: SweepResult, out: Path, title: str = "Design space") -> list[Path]:
    """``sweep.csv``, ``sweep.json``, ``pareto.png`` and ``accuracy.png`` in ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    csv_path, json_path = out / "sweep.csv", out / "sweep.json"
    with csv_path.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=COLUMNS, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(result.rows)
    json_path.write_text(json.dumps(dataclasses.asdict(result), indent=1, sort_keys=True) + "\n")
    return [csv_path, json_path, *_plots(result, out, title)]


def _plots(result: SweepResult, out: Path, title: str) -> list[Path]:
    from fgc.app import plots
    feasible = [r for r in result.rows if r.get("fits") and r["status"] == "converged"]
    if not feasible:
        return []
    front = [r for r in feasible if r["pareto"]]
    labelled = {id(front[0]), id(front[-1])} if front else set()  # the ends: labels stay legible
    points = [{"DSP48E1 slices (model estimate)": r["dsp"],
               "latency [ms] (model estimate)": r["latency_ms"],
               **({"label": r["label"]} if id(r) in labelled else {})} for r in feasible]
    left_out = len(result.rows) - len(feasible)
    note = f" ({left_out} not fitting or not converged: not shown)" if left_out else ""
    files = [out / "pareto.png", out / "accuracy.png"]
    plots.plot_pareto(points, "DSP48E1 slices (model estimate)", "latency [ms] (model estimate)",
                      title=f"{title}: latency vs DSP{note}", path=files[0])
    plots.plot_accuracy(_accuracy_points(result.rows),
                        title=f"{title}: accuracy vs GTSAM's LM optimum", path=files[1])
    if any(r.get("fit") for r in result.rows):
        files.append(out / "fit.png")
        plot_fit(result.rows, title=f"{title}: re-priced fit", path=files[-1])
    return files


def plot_fit(rows: Sequence[dict], title: str, path: Path):
    """Plan latency against the honest DSP (max(plan, reader) where read) per design, marked by
    its re-priced verdict, the best design that fits starred, the part's DSP dashed."""
    from fgc.app import plots

    @plots._styled
    def draw():
        fig, ax = plots._figure()
        styles = {"fits": ("tab:green", "o"), "over": ("tab:red", "x"),
                  "unread": ("0.6", "s")}
        for verdict, (color, marker) in styles.items():
            pts = [r for r in rows if r.get("fit") == verdict]
            if pts:
                ax.scatter([r["honest_dsp"] for r in pts],
                           [r["plan_latency_ms"] for r in pts], color=color, marker=marker,
                           s=30, label=verdict)
        for r in rows:
            if r.get("best"):
                ax.scatter([r["honest_dsp"]], [r["plan_latency_ms"]],
                           marker="*", s=200, color="tab:green", edgecolor="k", zorder=3,
                           label=f"best: {r['label']}")
        caps = sorted({r["part_dsp"] for r in rows if r.get("fit")})
        for cap in caps:
            ax.axvline(cap, color="k", lw=0.8, ls="--", label=f"the part's {cap:,} DSP")
        ax.set(xlabel="DSP = max(plan, second reader) (model estimates; a refusal implied by "
                      "a read: that read's)",
               ylabel="latency per iteration [ms] (plan)", title=title)
        ax.legend(loc="best")
        return plots._finish(fig, path)

    return draw()


def _accuracy_points(rows: Sequence[dict]) -> list[dict]:
    """One entry per simulator solution (linear solver, precision): its largest rotation and
    translation difference from GTSAM's optimum (the unit counts do not change the numbers)."""
    solutions: dict[tuple[str, str], dict] = {}
    for r in rows:
        if r["error"] is None:
            solutions.setdefault((r["linear"], r["precision"]), r)
    return [{"label": f"{r['linear']} {r['precision']}", "rotation": r["max_rotation_error"],
             "translation": r["max_translation_error"]}
            for _, r in sorted(solutions.items())]


@contextmanager
def progress_bar(total: int, enabled: bool | None = None) -> Iterator[Callable[[int], None]]:
    """A tqdm bar on stderr (auto: only on a terminal); a no-op without tqdm."""
    try:
        from tqdm import tqdm
    except ImportError:
        yield lambda n: None
        return
    with tqdm(total=total, unit="design", file=sys.stderr, desc="fgc sweep",
              disable=None if enabled is None else not enabled) as bar:
        yield bar.update
