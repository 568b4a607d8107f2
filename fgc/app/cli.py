"""The ``fgc`` command line.

    fgc compile  SPEC --backend B --out DIR           emit a project of backend B: sim, hls, native
    fgc simulate SPEC [--json F]                      run the accelerator simulator, report cost
    fgc verify   SPEC [--json F]                      simulator vs GTSAM's LM, exit 1 if FAILED
    fgc run      SPEC --backend native|sim|hls        solve with the generated solver
    fgc stream   SPEC --window W | --incremental K    keyframes one at a time (simulator;
                 [--backend sim|hls|native]           native solver; hls: C simulation per
                                                      update, priced on the HLS plan)
    fgc report   SPEC [--json F] [--html F]           the compiled design at a glance
    fgc sweep    SPEC --units 1,2,4 --cpe 5,20 ...    design-space exploration, Pareto plot
    fgc metrics  EST.tum REF.tum [--align se3]        ATE / RPE (translation m, rotation deg)
    fgc cache    info|clear                           derivations and builds ($FGC_CACHE_DIR)

SPEC is a ``.py`` file with ``build(**params)`` returning an ``fgc.Graph`` (``-p KEY=VALUE``), or a
g2o/TORO file. Solver options are shared by every command. Exit codes: 0 success, 1 verification
failed (or a solve did not converge), 2 bad input, a non-finite initial error, an output that
cannot be written or an internal error (one clear line on stderr, never a traceback), 130
interrupted (Ctrl-C: ``fgc: interrupted``, temporary files removed). Global
options: ``--version``; ``-q`` prints only the result line; ``-v`` adds stage timings (stderr) and
progress while factors are derived for the first time (also shown when stderr is a terminal).
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import re
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import NoReturn

import numpy as np

from fgc.app.specs import load_spec
from fgc.errors import FgcError, caused_by_interrupt
from fgc.frontend.dsl import Graph
from fgc.ir.codes import ORDERINGS

EXIT_OK, EXIT_FAILED, EXIT_BAD_INPUT = 0, 1, 2
EXIT_INTERRUPTED = 130  # Ctrl-C


def parse_params(items: list[str]) -> dict:
    """``["N=30", "dataset=w100.graph"]`` → ``{"N": 30, "dataset": "w100.graph"}``."""
    params = {}
    for item in items:
        key, sep, raw = item.partition("=")
        if not sep or not key.isidentifier():
            raise FgcError(f"parameter {item!r} must look like KEY=VALUE")
        try:
            params[key] = ast.literal_eval(raw)
        except (ValueError, SyntaxError):
            params[key] = raw
    return params


# --------------------------------------------------------------------------------------------
# shared steps
# --------------------------------------------------------------------------------------------


def solver_config(args, precision_default: str):
    from fgc.ir.program import SolverConfig

    return SolverConfig(method=args.solver, linear=args.linear, ordering=args.ordering,
                        precision=args.precision or precision_default,
                        linear_precision=getattr(args, "linear_precision", None),
                        units=args.units, cpe=args.cpe, max_iterations=args.max_iterations,
                        incremental_k=getattr(args, "incremental", None),
                        batch_every=getattr(args, "batch_every", None), **_clock_mhz(args),
                        **_lm_limits(args))


def _lm_limits(args) -> dict:
    """``{"lambda_upper_bound": …}`` from ``--lambda-upper-bound`` (nothing when not given)."""
    bound = getattr(args, "lambda_upper_bound", None)
    return {"lambda_upper_bound": bound} if bound is not None else {}


def _streaming(args) -> bool:
    """Whether keyframe-by-keyframe mode was asked for (--incremental or --window); checks
    the combination and refuses the backends that run batch solves only."""
    from fgc.app.streaming import HW_REFUSAL, check_mode

    incremental, window = getattr(args, "incremental", None), getattr(args, "window", None)
    batch_every = getattr(args, "batch_every", None)
    if incremental is None and window is None and batch_every is None:
        return False
    check_mode(incremental, batch_every, window)
    backend = getattr(args, "backend", "sim")
    if getattr(args, "model_only", False) and not _backend_info(backend).hardware:
        raise FgcError("--model-only prices the simulator's updates on the HLS plan: it needs "
                       "--backend hls")
    if backend != "sim" and args.command != "stream" and not (
            args.command in ("compile", "report") and _backend_info(backend).stream_design):
        raise FgcError(f"fgc {args.command} --backend {backend}: {HW_REFUSAL}")
    return True


def _backend_info(name: str):
    """The registry's entry of backend ``name`` (fgc_backends.BACKENDS)."""
    from fgc_backends import BACKENDS

    return BACKENDS[name]


def _clock_mhz(args) -> dict:
    """``{"clock_mhz": …}`` from ``--clock`` (nothing when it was not given)."""
    clock = getattr(args, "clock", None)
    return {"clock_mhz": clock[0]} if clock else {}


def _precision_default(args, default: str) -> str:
    """The precision a ``--scalar`` implies (float → float32, double → float64), checked
    against an explicit ``--precision``; ``default`` otherwise."""
    scalar = getattr(args, "scalar", None)
    implied = {"float": "float32", "double": "float64"}.get(scalar or "")
    if implied and args.precision and args.precision != implied:
        raise UsageError(f"fgc {args.command}: --scalar {scalar} contradicts --precision "
                         f"{args.precision}")
    return implied or default


def _hls_config(args, program):
    """The HLS backend's config from --scalar, --part and --clock (one clock for the cost
    model and run_hls.tcl: ``HlsConfig.clock_ns`` is ``1000 / SolverConfig.clock_mhz``)."""
    hls = _backend("hls")
    options = {"scalar": getattr(args, "scalar", None) or _c_scalar(program)}
    if getattr(args, "part", None):
        options["part"] = args.part
    if getattr(args, "clock", None):
        options["clock_ns"] = args.clock[1]
    if getattr(args, "allocation", None):
        options["allocation"] = args.allocation
    if getattr(args, "unit_sets", None):
        options["unit_sets"] = args.unit_sets
    if getattr(args, "qr_unit", None):
        options["qr_unit"] = args.qr_unit
    return hls.HlsConfig(**options)


def _plan_options(args, program):
    """The accelerator plan's options for the design ``fgc compile --backend hls`` emits with
    the same --scalar, --part, --clock, --allocation and --unit-sets (what ``fgc simulate`` and
    ``fgc report`` price). A fixed-point --scalar is refused: the dataflow design has no
    fixed-point units and the plan no fixed-point operator table."""
    config = _hls_config(args, program)
    config.check()
    if config.is_fixed_point:
        raise UsageError(f"fgc {args.command}: --scalar {config.scalar}: the HLS dataflow design "
                         "is float or double only (no fixed-point operator table to price it); "
                         "the native backend runs ap_fixed (fgc run --backend native --scalar)")
    return _backend("hls").emitter.accel_plan(program, config).options


def _refuse_hls_design(args, backend: str) -> None:
    """--allocation and --unit-sets shape the HLS design: other backends have no such thing."""
    for flag in ("allocation", "unit_sets", "qr_unit"):
        if getattr(args, flag, None):
            raise UsageError(f"fgc {args.command}: --{flag.replace('_', '-')} applies to "
                             f"--backend hls only (not {backend})")


def _native_config(args, program):
    """The native backend's config from --scalar (default: the Program's precision); --part
    names an FPGA, which a CPU program has none of."""
    if getattr(args, "part", None):
        raise UsageError(f"fgc {args.command}: --part applies to fgc compile --backend hls only "
                         "(the native backend builds a CPU program)")
    _refuse_hls_design(args, "native")
    native = _backend("native")
    return native.NativeConfig(scalar=getattr(args, "scalar", None) or _c_scalar(program))


class _Stages:
    """Stage timings for ``-v`` (stderr, so stdout stays deterministic)."""

    def __init__(self, args):
        self.verbose = getattr(args, "verbose", 0) > 0
        self.t0 = time.perf_counter()

    def done(self, name: str) -> None:
        t = time.perf_counter()
        if self.verbose:
            print(f"fgc: {name}: {t - self.t0:.2f} s", file=sys.stderr)
        self.t0 = t


def _show_progress(args) -> bool:
    if getattr(args, "quiet", False):
        return False
    return getattr(args, "verbose", 0) > 0 or sys.stderr.isatty()


def derive_with_progress(graph: Graph, show: bool) -> int:
    """Derive every factor type of ``graph`` not yet in the disk cache, printing "deriving
    factor X (n/m)…" on stderr before each when ``show``; returns how many were derived."""
    from fgc.compiler.derive import derive, is_cached

    types = list({f.type.name: f.type for f in graph.factors}.values())
    cold = [ftype for ftype in types if not is_cached(ftype)]
    for i, ftype in enumerate(cold, 1):
        if show:
            print(f"fgc: deriving factor {ftype.name} ({i}/{len(cold)}, not cached; "
                  "sympy takes seconds per factor)…", file=sys.stderr, flush=True)
        derive(ftype)
    return len(cold)


def _load(args, precision_default: str):
    """The spec's graph (derivations done, with progress) and its solver configuration, timed
    in the returned stages."""
    stages = _Stages(args)
    graph = load_spec(args.spec, parse_params(args.param))
    stages.done("load spec")
    if derive_with_progress(graph, _show_progress(args)):
        stages.done("derive (cold)")
    return stages, graph, solver_config(args, _precision_default(args, precision_default))


def _compile(args, precision_default: str):
    from fgc.compile import compile_graph
    from fgc.ir.datafile import problem_data

    stages, graph, config = _load(args, precision_default)
    try:
        program = compile_graph(graph, config, name=_name(args.spec))
    except ValueError as exc:
        if config.incremental_k is None:
            raise
        raise FgcError(f"incremental plan: {exc}") from None  # --incremental/--batch-every
    stages.done("compile")
    data = problem_data(graph, program)
    args.stages = stages
    return graph, program, data


def _print(args, lines: list[str], result: str | None = None) -> None:
    """``lines`` to stdout, or only ``result`` (default: the first line) under ``-q``."""
    if getattr(args, "quiet", False):
        print(result if result is not None else lines[0])
    else:
        print("\n".join(lines))
    stages = getattr(args, "stages", None)
    if stages is not None:
        stages.done(args.command)


def _name(spec: str) -> str:
    """A C/Python-safe project name from the spec's file name."""
    stem = "".join(c if c.isalnum() else "_" for c in Path(spec).stem.lower()).strip("_")
    return stem if stem[:1].isalpha() else f"fgc_{stem or 'problem'}"


def _write_json(path: str | None, report: dict) -> None:
    if path:
        _write_text(path, json.dumps(report, indent=2, sort_keys=True) + "\n", "--json")


def _write_text(path: str, text: str, option: str) -> None:
    """Write a user-named output file; an OSError becomes one line naming the path."""
    try:
        Path(path).write_text(text)
    except OSError as exc:
        raise FgcError(f"{option} {path}: cannot write the file: "
                       f"{exc.strerror or exc}") from None


# options naming an output, and whether each is a folder (checked before any solve starts)
_OUTPUTS = (("json", "--json", False), ("html", "--html", False), ("out", "--out", True),
            ("plot", "--plot", True), ("values", "--values", False), ("tum", "--tum", False))


def check_outputs(args) -> None:
    """Raise FgcError naming the path if an output given on the command line cannot be written,
    before the (possibly long) solve, so no result is computed only to be lost."""
    for attr, option, folder in _OUTPUTS:
        path = getattr(args, attr, None)
        if path:
            _check_writable(str(path), option, folder)
    if getattr(args, "values", None):
        from fgc.interop.estimates import FORMATS

        if Path(args.values).suffix.lower() not in FORMATS:
            raise FgcError(f"--values {args.values}: unknown values format "
                           f"{Path(args.values).suffix!r}; use {', '.join(FORMATS)}")


def _check_writable(path: str, option: str, folder: bool) -> None:
    p = Path(path)
    if folder:
        if p.exists() and not p.is_dir():
            raise FgcError(f"{option} {path}: exists and is not a folder")
        target = p
        while not target.exists() and target != target.parent:
            target = target.parent
        if not target.is_dir():
            raise FgcError(f"{option} {path}: cannot create the folder: {target} is not a "
                           "folder")
    else:
        if p.is_dir():
            raise FgcError(f"{option} {path}: is a folder, not a file")
        target = p.parent
        if not target.is_dir():
            raise FgcError(f"{option} {path}: the folder {target} does not exist")
        if p.exists() and not os.access(p, os.W_OK):
            raise FgcError(f"{option} {path}: the file is not writable")
    if not os.access(target, os.W_OK | os.X_OK):
        raise FgcError(f"{option} {path}: no permission to write in {target}")


def _estimates_out(args, graph: Graph, report: dict, result_values: dict) -> None:
    """Keyed values into the JSON report; --values file; --marginals printed and reported."""
    from fgc.interop import estimates as export
    values = export.graph_values(graph, result_values)
    report["values"] = export.values_json(values)
    quiet = getattr(args, "quiet", False)
    if getattr(args, "values", None):
        fmt = export.write_values(args.values, values)
        if not quiet:
            print(f"  estimates → {args.values} ({fmt})")
    if getattr(args, "marginals", None):
        from fgc.app.marginals import marginal_covariances, parse_keys

        covs = marginal_covariances(graph, parse_keys(args.marginals, graph), values)
        report["marginals"] = {str(k): {"key": k, "covariance": c.tolist()}
                               for k, c in covs.items()}
        for k, c in covs.items() if not quiet else ():
            print(f"  marginal covariance of {k!r} (diagonal): "
                  + " ".join(f"{x:.6g}" for x in c.diagonal()))


def _backend(name: str):
    from fgc_backends import load

    return load(name)


def _backend_names() -> tuple[str, ...]:
    """The registry's backend names (fgc_backends.BACKENDS): the CLI hard-codes none."""
    from fgc_backends import names

    return names()


def _backend_help() -> str:
    from fgc_backends import BACKENDS

    return "; ".join(f"{b.name}: {b.summary}" for b in BACKENDS.values())


# --------------------------------------------------------------------------------------------
# commands
# --------------------------------------------------------------------------------------------


def _cmd_compile(args) -> int:
    window = getattr(args, "window", None) if _streaming(args) else None
    if _streaming(args) and _backend_info(args.backend).stream_design:
        return _compile_window(args, window)
    if window is not None:
        raise UsageError("fgc compile: --window is a run-time mode of the simulator and the "
                         "native solver (the same build serves every window); pass it to "
                         "simulate, verify or stream, or compile the on-chip window with "
                         "--backend hls")
    _, program, data = _compile(args, "float32")
    from fgc.ir.datafile import write_data

    out = Path(args.out)
    try:
        out.mkdir(parents=True, exist_ok=True)
        (out / "program.json").write_text(program.to_json())
        write_data(data, out / "data.txt")
        backend = _backend(args.backend)
        if args.backend == "hls":
            project = backend.emit(program, out, _hls_config(args, program))
            files = list(project.files)
            # the testbench checks its result against the simulator's (exit 4 on a mismatch)
            from fgc_backends.cfamily.results import reference_run

            files.append(backend.build.write_project_reference(
                project, program, data, reference_run(program, data)))
        elif args.backend == "native":
            files = list(backend.emit(program, out, _native_config(args, program)).files)
        else:
            if getattr(args, "scalar", None) or getattr(args, "part", None):
                raise UsageError("fgc compile: --scalar applies to --backend hls or native "
                                 "only, --part to --backend hls only")
            _refuse_hls_design(args, args.backend)
            files = backend.emit(program, out)
    except OSError as exc:
        raise FgcError(f"--out {out}: cannot write the project: "
                       f"{exc.strerror or exc}{_filename(exc)}") from None
    _print(args, [f"fgc compile {args.spec}: {len(program.variables)} variables, "
                  f"{len(program.factors)} block instances → {out}/ ({len(files) + 2} files)"])
    return EXIT_OK


def _compile_window(args, window: int | None) -> int:
    """``fgc compile --backend hls --window W | --incremental K``: the on-chip design (the
    backend's ``emit`` of the StreamProgram: its policy, not a loose window, shapes it)."""
    sp, _ = _stream_setup(args, "float32")
    program = sp.program
    out = Path(args.out)
    try:
        # the design first: a stream it cannot run is refused before anything is written
        project = _backend(args.backend).emit(sp, out, _hls_config(args, program))
        (out / "program.json").write_text(program.to_json())
    except OSError as exc:
        raise FgcError(f"--out {out}: cannot write the project: "
                       f"{exc.strerror or exc}{_filename(exc)}") from None
    what = (f"on-chip fixed-lag window of {window} keyframes" if window is not None else
            f"on-chip incremental design, the newest {program.schedule.incremental.window} "
            "keyframes re-eliminated and the kept Bayes net")
    _print(args, [f"fgc compile {args.spec}: {what} "
                  f"({len(program.schedule.clusters)} in the stream), top "
                  f"{project.name}_stream → {out}/ ({len(project.files) + 1} files; make && "
                  f"./tb_{project.name} --stream data.txt stream.txt stream_result.txt)"])
    return EXIT_OK


def _c_scalar(program) -> str:
    return "float" if program.solver.precision == "float32" else "double"


def _filename(exc: OSError) -> str:
    return f" ({exc.filename})" if getattr(exc, "filename", None) else ""


SIM_LARGE_VARIABLES = 2000  # above this, the simulator says what it is before it starts


def _progress(args, command: str, program, simulator: bool = False):
    """The per-iteration progress display of a solve (fgc.app.progress): stderr unless -q.
    With ``simulator``, a large Program gets a note first: the simulator steps every
    elimination step in NumPy (the accelerator's model, not a fast solver)."""
    from fgc.app.progress import Progress

    quiet = getattr(args, "quiet", False)
    if simulator and not quiet and len(program.variables) > SIM_LARGE_VARIABLES:
        widest = max(s.frontal_dim + s.separator_dim for s in program.schedule.steps)
        print(f"fgc {command}: {len(program.variables)} variables, "
              f"{len(program.schedule.steps)} elimination steps (widest {widest} columns) "
              "stepped one by one in NumPy by the accelerator simulator: expect seconds to "
              "minutes per iteration (each iteration's time and an estimate of the rest "
              "follow); `fgc run --backend native` solves it in compiled code",
              file=sys.stderr, flush=True)
    return Progress(f"fgc {command}", program.solver.max_iterations, show=not quiet)


class _WithProgress:
    """The simulator backend with a progress display on its batch solves (for the reports
    that take the backend module and call its ``run``)."""

    def __init__(self, backend, display) -> None:
        self._backend, self._display = backend, display

    def __getattr__(self, name: str):
        return getattr(self._backend, name)

    def run(self, program, data, *rest, **options):
        # a batch solve (out_dir, precision, config, in_process may be given by position)
        batch = (len(rest) <= 4 and not options.get("incremental")
                 and options.get("window") is None and "progress" not in options)
        if batch:
            options["progress"] = self._display
        self._display.start()
        try:
            return self._backend.run(program, data, *rest, **options)
        finally:
            self._display.finish()


def _cmd_simulate(args) -> int:
    from fgc.app.run_report import simulate_report

    if _streaming(args):
        for flag in ("part", "allocation", "unit_sets", "qr_unit"):
            if getattr(args, flag, None):
                raise UsageError(f"fgc simulate: --{flag.replace('_', '-')} shapes the batch "
                                 "design; the stream's update model prices the Program's own "
                                 "(drop it, or simulate without --incremental / --window)")
        return _cmd_stream(args)
    graph, program, data = _compile(args, "float32")
    try:
        display = _progress(args, f"simulate {args.spec}", program, simulator=True)
        report = simulate_report(graph, program, data, _WithProgress(_backend("sim"), display),
                                 plot_dir=args.plot,
                                 plan_options=_plan_options(args, program))
    except OSError as exc:
        if not args.plot or not str(getattr(exc, "filename", "")).startswith(args.plot):
            raise
        raise FgcError(f"--plot {args.plot}: cannot write the plots: "
                       f"{exc.strerror or exc}{_filename(exc)}") from None
    _print(args, report.pop("summary"))
    _estimates_out(args, graph, report, report.pop("_result_values"))
    report["progress"] = display.records
    _write_json(args.json, report)
    return EXIT_OK if report["status"] == "converged" else EXIT_FAILED


def _cmd_verify(args) -> int:
    from fgc.app.run_report import verify_report

    if _streaming(args):
        return _cmd_verify_stream(args)
    graph, program, data = _compile(args, "float64")
    display = _progress(args, f"verify {args.spec}", program, simulator=True)
    report = verify_report(graph, program, data, _WithProgress(_backend("sim"), display))
    report["progress"] = display.records
    _print(args, report.pop("summary"),
           f"fgc verify {args.spec}: {'PASSED' if report['passed'] else 'FAILED'}")
    _estimates_out(args, graph, report, report.pop("_result_values"))
    _write_json(args.json, report)
    return EXIT_OK if report["passed"] else EXIT_FAILED


def _cmd_run(args) -> int:
    if _streaming(args):
        return _cmd_stream(args)
    graph, program, data = _compile(args, "float32")
    import time

    t0 = time.perf_counter()
    display = _progress(args, f"run {args.spec}", program, simulator=args.backend == "sim")
    timings: dict = {}
    if args.backend == "native":
        config = _native_config(args, program)
        if not getattr(args, "quiet", False) and sys.stderr.isatty():
            print(f"fgc run: building or loading the native library "
                  f"({len(program.variables)} variables; a first build runs g++: seconds to "
                  "minutes for a large graph)…", file=sys.stderr, flush=True)
        result = _backend("native").run(program, data, config, progress=display,
                                        timings=timings)
    elif args.backend == "hls":  # the accelerator's C simulation (make csim), g++ on this host
        result = _backend("hls").run(program, data, _hls_config(args, program))
    else:
        if getattr(args, "scalar", None) or getattr(args, "part", None):
            raise UsageError("fgc run: --scalar applies to --backend native or hls, --part to "
                             "--backend hls; the simulator runs float32 or float64 (--precision)")
        _refuse_hls_design(args, "sim")
        result = _backend("sim").run(program, data, progress=display)
        timings = {"setup_seconds": result.setup_seconds, "solve_seconds": result.solve_seconds}
    display.finish()
    status, final, iters = result.status, result.final_error, result.iterations
    seconds = time.perf_counter() - t0
    from fgc.app.run_report import (
        final_error_text,
        float64_error,
        require_finite_start,
        status_text,
    )

    require_finite_start(graph, result)
    solve_s = timings.get("solve_seconds", seconds)
    report = {"backend": args.backend, "status": status, "reason": result.reason,
              "final_error": final, "iterations": iters, "solve_seconds": solve_s,
              **{k: v for k, v in timings.items() if k != "solve_seconds"},
              "total_seconds": seconds, "progress": display.records,
              "final_error_float64": float64_error(graph, result.values),
              "precision": program.solver.precision}
    lines = [f"fgc run {args.spec} ({args.backend}): {status_text(status, result.reason)}, "
             f"{iters} iterations, final error {final_error_text(report)}, "
             f"{_run_times(args.backend, solve_s, timings, seconds)}"]
    if status != "converged" and result.message:
        lines.append(f"fgc run: not converged: {result.message}")
    _print(args, lines)
    _estimates_out(args, graph, report, result.values)  # fgc values by Program key
    _write_json(args.json, report)
    return EXIT_OK if status == "converged" else EXIT_FAILED


def _run_times(backend: str, solve_s: float, timings: dict, total_s: float) -> str:
    """The solve's time, with what the build / load / set-up took beside it."""
    if backend == "native":
        if timings.get("built"):
            extra = ("native library built (emit + g++) and loaded in "
                     f"{timings['build_seconds']:.2f} s")
        elif timings.get("load_seconds"):
            extra = ("cached native library found and loaded in "
                     f"{timings['load_seconds'] * 1e3:.1f} ms")
        else:
            extra = "native library already loaded"
        return f"solve {solve_s * 1e3:.3f} ms ({extra})"
    if backend == "sim":
        return (f"solve {solve_s * 1e3:.3f} ms (simulator emit, data and set-up "
                f"{(total_s - solve_s) * 1e3:.1f} ms)")
    return f"{total_s * 1e3:.3f} ms (emit, make csim build and C simulation run)"


def _stream_setup(args, precision_default: str):
    """The stream stage's StreamProgram (the options' policy) and the graph's data."""
    from fgc.compiler.stream import compile_stream, policy_of
    from fgc.ir.datafile import problem_data

    stages, graph, config = _load(args, precision_default)
    if config.incremental_k is not None:  # _load put the plan in the solver options
        policy = policy_of(config.incremental_k, config.batch_every)
    else:
        policy = policy_of(window=getattr(args, "window", None))
    sp = compile_stream(graph, config, policy, name=_name(args.spec))
    stages.done("compile")
    args.stages = stages
    return sp, problem_data(graph, sp.program)


def _mode_text(program, window) -> str:
    if window is not None:
        return f"fixed-lag window of {window} keyframes"
    plan = program.schedule.incremental
    batches = ",".join(str(b) for b in plan.batch_keyframes) or "none"
    return f"incremental, newest {plan.window} clusters re-eliminated, batch steps {batches}"


def _newest_text(update, program) -> str:
    from fgc.frontend.geometry import Pose2, Pose3

    parts = []
    for key, value in update.newest(program).items():
        if isinstance(value, (Pose3, Pose2)):
            parts.append(f"{key} t=[" + " ".join(f"{x:.4f}" for x in np.asarray(value.t, float))
                         + "]")
    return ", ".join(parts) or f"{len(update.values)} variables"


def _cmd_stream(args, precision_default: str = "float64") -> int:
    from fgc.app import streaming
    from fgc.interop import estimates as export
    if not _streaming(args):
        raise FgcError(f"fgc {args.command} needs --incremental K or --window W")
    sp, data = _stream_setup(args, precision_default)
    graph, program, window = sp.graph, sp.program, sp.window
    quiet = getattr(args, "quiet", False)
    n = len(program.schedule.clusters)
    backend = getattr(args, "backend", "sim")
    hls = _backend_info(backend).hardware  # the backend prices its own design
    model_only = hls and getattr(args, "model_only", False)
    runs = "sim" if model_only else backend
    # the backend's runner first: a stream it cannot run is refused before anything is printed
    runner = streaming.make_runner(sp, runs)
    who, timed = runner.who, runner.timing_key
    on_chip = hls and _backend(backend).on_chip(sp)
    if not quiet:
        if hls:
            print(_stream_hls_head(args, program, n, window, model_only, on_chip), flush=True)
        else:
            print(f"fgc {_stream_word(args)} {args.spec}: {n} keyframes, "
                  f"{_mode_text(program, window)}, "
                  f"{who} {program.solver.precision}; per keyframe: the accelerator plan's "
                  f"latency (model estimate: the update's iterations as batch iterations of a "
                  f"chain as long as its window; {streaming.UNPRICED} otherwise) and the "
                  f"{who}'s wall time", flush=True)
    online: dict = {}
    if on_chip:  # the emitted on-chip design's own price
        pricer = streaming.WindowPricer(graph, program, window, backend=backend)
    elif hls:
        pricer = streaming.update_model(graph, program, backend=backend)
    else:
        pricer = streaming.UpdatePricer(graph, program, window)
    priced: list = []
    builds = {"seconds": 0.0, "since": None}  # building the template windows (g++ or cache)

    def progress(update) -> None:
        if builds["since"] is not None:  # the first update after a build: that build's time
            since = time.perf_counter() - builds["since"]
            seconds = update.seconds if update.seconds == update.seconds else 0.0
            builds["seconds"] += max(0.0, since - seconds)
            builds["since"] = None
        online.update(update.newest(program))
        price = pricer.price(update)
        priced.append(price.as_dict() if hls else price)
        if quiet:
            return
        if on_chip:
            model = f"accelerator {price.latency_ms:7.3f} ms (model estimate, on chip)"
        elif hls:
            model = (f"accelerator {price.latency_ms:7.3f} ms + {price.assumed_ms:.3f} ms "
                     f"assumed (model estimate, {price.window}-keyframe window)")
        else:
            model = (f"{price['latency_ms']:7.3f} ms (model estimate, {price['window']}-"
                     "keyframe chain)" if price else "model estimate not available")
        wall = ("" if update.seconds != update.seconds  # NaN: no wall time to show
                else f"{update.seconds * 1e3:8.2f} ms ({who} wall time); ")
        print(f"  keyframe {update.keyframe:>4} ({update.mode}, from {update.first}): "
              f"{update.iterations:>3} iterations, {update.status}, {model}, {wall}"
              f"{_newest_text(update, program)}", flush=True)

    def building(size, index, count) -> None:
        builds["since"] = time.perf_counter()
        if not quiet:
            print(f"  compiling the {who}'s {size}-keyframe template window ({index + 1} of "
                  f"{count}; built once, reused by every update of that size)", flush=True)

    started = time.perf_counter()
    result = streaming.run_stream(program, data, window, progress, progress_build=building,
                                  sp=sp, runner=runner)
    stream_wall = time.perf_counter() - started
    from fgc.app.run_report import require_finite_start

    require_finite_start(graph, result)
    final = {str(k): v for k, v in result.values.items()}
    acc = streaming.accuracy(graph, final, online, streaming.batch_optimum(graph))
    times = streaming.timing_summary(u["seconds"] for u in result.updates)
    report = {"spec": args.spec, "keyframes": n,
              "mode": "fixed-lag" if window else
              "incremental", "window": window, "incremental_k": program.solver.incremental_k,
              "batch_every": program.solver.batch_every, "status": result.status,
              "reason": result.reason, "iterations": result.iterations,
              "backend": backend, "solved_by": who, "model_estimate": priced,
              f"{timed}_update_time": times,
              "accuracy_vs_batch_optimum": acc, "wall_seconds": stream_wall,
              "build_seconds": builds["seconds"],
              "updates": [{k: v for k, v in u.items() if k != "values"}
                          for u in result.updates]}
    ate = acc.get("final", {}).get("translation", {})
    ate_online = acc.get("online", {}).get("translation", {})
    wall = (f"{who} update median {times['median_ms']:.2f} ms, p99 {times['p99_ms']:.2f} ms "
            "(wall time)" if times["median_ms"] == times["median_ms"]
            else f"{who}: no wall time (a C simulation's is not the accelerator's)")
    ate_text = (f"ATE rmse {ate['rmse']:.4g} m final, {ate_online['rmse']:.4g} m online"
                if "rmse" in ate and "rmse" in ate_online else
                "ATE not applicable (no Pose2/Pose3 variables: no trajectory)")
    head = (f"fgc {_stream_word(args)} {args.spec}: {result.status} over {n} keyframes; {wall}; "
            f"vs batch optimum: {ate_text}")
    lines = [head, f"  largest tangent-space distance from the batch optimum "
                   f"{acc['max_state_distance']:.3g} (final estimate)"]
    if runs == "native" and builds["seconds"] > 0.05 * stream_wall:  # the build was the cost
        lines.append(f"  wall time {stream_wall:.1f} s, of which {builds['seconds']:.1f} s "
                     "building or loading the native library's template window(s) (built once "
                     "per design: a later run finds them in the cache)")
    model = [p["latency_ms"] for p in priced if p]
    if on_chip:
        lines.append(f"  accelerator per update (the on-chip design priced on its plan, model "
                     f"estimate): median {np.median(model):.3f} ms, p99 "
                     f"{np.percentile(model, 99):.3f} ms")
        res = pricer.model.resources()
        report["on_chip_resources"] = res
        parts = ", ".join(f"{name} {d} DSP / {b:g} BRAM36" for name, (d, b) in
                          res["parts"].items())
        lines.append(f"  on-chip design: {res['dsp']} DSP, {res['bram36']:g} BRAM36 (model "
                     f"estimate: {parts}); "
                     + ("fits " if res["fits"] else "does not fit ") + res["part"])
    elif hls:
        NOT_EMITTED = _backend(backend).NOT_EMITTED  # noqa: N806  (the backend's constant)

        report["not_emitted"] = NOT_EMITTED
        extra = [p["latency_with_assumed_ms"] for p in priced]
        lines.append(f"  accelerator per update (update model on the HLS plan, model estimate): "
                     f"median {np.median(model):.3f} ms, p99 {np.percentile(model, 99):.3f} ms; "
                     f"with the assumed terms median {np.median(extra):.3f} ms; {NOT_EMITTED}")
    elif model:
        lines.append(f"  accelerator plan per update (model estimate): median "
                     f"{np.median(model):.3f} ms, p99 {np.percentile(model, 99):.3f} ms over "
                     f"{len(model)} priced updates ({len(priced) - len(model)} not priced: "
                     f"{streaming.UNPRICED})")
    if getattr(args, "tum", None):
        values = export.graph_values(graph, result.values)
        export.write_values(args.tum, values)
        lines.append(f"  trajectory → {args.tum} (TUM, t = key order index)")
    _print(args, lines)
    _estimates_out(args, graph, report, result.values)
    _write_json(args.json, report)
    return EXIT_OK if result.status == "converged" else EXIT_FAILED


def _stream_hls_head(args, program, n: int, window, model_only: bool, on_chip: bool) -> str:
    solver = program.solver
    unit = (f"n_u = {solver.units} Update units" if solver.linear == "qr"
            else f"#CPE = {solver.cpe}")
    scalar = "double" if solver.precision == "float64" else "float"
    if on_chip:
        who = (f"simulator {solver.precision}" if model_only else
               f"the on-chip design's C simulation ({scalar})")
        kept = ("" if window is not None else
                ", kept as its conditional with every earlier one (the kept Bayes net on chip, "
                "walked back each update)")
        tail = ("The emitted design keeps the window, its factors' words and the marginal prior "
                "in its memories between calls; a call brings one keyframe's storage and data "
                "words, and the keyframe leaving the window is eliminated on the accelerator's "
                f"QR unit{kept}"
                + (" (the estimate comes from the simulator)" if model_only else ""))
        return (f"fgc {_stream_word(args)} {args.spec}: {n} keyframes, "
                f"{_mode_text(program, window)}, {who}; "
                f"per keyframe: the accelerator's latency, the emitted design's plan per call "
                f"({solver.linear.upper()}, n_u = {solver.units}, {solver.precision}, "
                f"{solver.clock_mhz:g} MHz; model estimate), beside the estimate. {tail}")
    who = (f"simulator {solver.precision}" if model_only else
           f"the HLS design's C simulation ({scalar}) per update, the kept Bayes net on the host")
    tail = ("The accelerator's incremental mode is not emitted in C++: the estimate comes from "
            "the simulator" if model_only else
            "Each update's window is solved by the C simulation of an emitted template window "
            "(built once); its conditionals, marginal prior and back-substitution are kept on "
            "the host, not on chip")
    return (f"fgc {_stream_word(args)} {args.spec}: {n} keyframes, "
            f"{_mode_text(program, window)}, {who}; per "
            f"keyframe: the accelerator's latency from the update model on the HLS plan "
            f"({solver.linear.upper()}, {unit}, {solver.precision}, {solver.clock_mhz:g} MHz; "
            "model estimate: the plan's terms, then the assumed ones) beside the wall time and "
            f"estimate. {tail}")


def _cmd_verify_stream(args) -> int:
    from fgc.app import streaming
    from fgc.app.run_report import ROT_TOL_F32, STATE_TOL_F64, require_finite_start
    from fgc.interop import oracles
    from fgc.interop.to_gtsam import to_gtsam

    sp, data = _stream_setup(args, "float64")
    graph, program, window = sp.graph, sp.program, sp.window
    result = streaming.run_stream(program, data, window, sp=sp)
    require_finite_start(graph, result)
    problem = to_gtsam(graph)
    clusters = program.schedule.clusters
    windows = [(u["first"], u["mode"] == "batch") for u in result.updates]
    oracle = oracles.isam2_per_keyframe(graph, problem, clusters, windows)
    oracle = [{k: e[k] for k in u["values"]} for u, e in zip(result.updates, oracle,
                                                              strict=True)]
    dist = oracles.per_keyframe_distance(result.updates, oracle)
    tol = STATE_TOL_F64 if program.solver.precision == "float64" else ROT_TOL_F32
    worst = int(np.argmax(dist))
    passed = result.status == "converged" and max(dist) <= tol
    report = {"mode": "fixed-lag" if window else "incremental", "window": window,
              "keyframes": len(clusters), "status": result.status, "tolerance": tol,
              "per_keyframe_distance_isam2": dist, "passed": passed}
    lines = [f"fgc verify {args.spec}: {len(clusters)} keyframes, {_mode_text(program, window)}"
             f", simulator {program.solver.precision} vs gtsam.ISAM2 with the same policy "
             "(older keyframes held, factors across the window's edge kept linear), after "
             "every keyframe",
             f"  largest state difference {max(dist):.2e} at keyframe {worst} (tolerance "
             f"{tol:g})"]
    if window is not None:
        fls = oracles.fixed_lag_per_keyframe(graph, problem, clusters, window, "batch")
        fdist = oracles.per_keyframe_distance(result.updates, fls)
        report["per_keyframe_distance_batch_fixed_lag"] = fdist
        lines.append(f"  gtsam.BatchFixedLagSmoother (lag {window - 1}, timestamps = keyframe "
                     f"index): largest difference {max(fdist):.2e} (reported, not judged: "
                     "measured up to 1e-2 on LIO once keyframes are marginalised; see the "
                     "README)")
    verdict = "PASSED" if passed else "FAILED"
    why = ([f"fgc's stream ended {result.status}"] if result.status != "converged" else []) + (
        [f"largest difference {max(dist):.2e} > {tol:g}"] if max(dist) > tol else [])
    lines.append(f"  {verdict}: " + (f"fgc's stream converged and every keyframe is within "
                                     f"{tol:g} of ISAM2" if passed else "; ".join(why)))
    _print(args, lines, f"fgc verify {args.spec}: {verdict}")
    _estimates_out(args, graph, report, result.values)
    _write_json(args.json, report)
    return EXIT_OK if passed else EXIT_FAILED


def _cmd_report(args) -> int:
    from fgc.app.design_report import design_report, figures, format_text, render_html

    if _streaming(args):
        return _report_stream(args)
    graph, program, data = _compile(args, "float32")
    report = design_report(args.spec, parse_params(args.param), graph, program, data,
                           _backend("sim"), iterations=args.iterations,
                           plan_options=_plan_options(args, program))
    c = report["cost"]
    fits = "fits" if c["fits"] else "does NOT fit"
    _print(args, format_text(report).rstrip("\n").split("\n"),
           f"fgc report {args.spec}: {c['cycles']:,} cycles = {c['latency_ms']:.3f} ms at "
           f"{c['clock_mhz']:g} MHz, {c['resources']['dsp']} DSP, {fits} {c['device']} "
           "(model estimate)")
    _write_json(args.json, report)
    if args.html:
        _write_text(args.html, render_html(report, figures(report)), "--html")
    return EXIT_OK


def _stream_word(args) -> str:
    """How a stream's output names its command: ``report`` when fgc report priced it, else
    ``stream`` (simulate and stream run the same stream)."""
    return "report" if getattr(args, "command", None) == "report" else "stream"


def _report_stream(args) -> int:
    """``fgc report --window W | --incremental K``: the design ``fgc compile --backend hls``
    emits for the stream, priced per update on the simulator's updates (``fgc stream --backend
    hls --model-only``): the on-chip design for a QR Program, the host-kept path's update model
    for Cholesky; its DSP and BRAM."""
    if getattr(args, "html", None):
        raise UsageError("fgc report --html renders batch designs; a stream's per-update report "
                         "is text and --json")
    for flag in ("part", "allocation", "unit_sets", "qr_unit", "scalar"):
        if getattr(args, flag, None):
            raise UsageError(f"fgc report: --{flag.replace('_', '-')} shapes the batch design; "
                             "the stream's design is priced on the Program's own")
    args.backend, args.model_only = "hls", True
    return _cmd_stream(args, precision_default="float32")


def _cmd_sweep(args) -> int:
    from fgc.app import sweep
    from fgc.ir.program import SolverConfig

    args.stages = _Stages(args)
    graph = load_spec(args.spec, parse_params(args.param))
    args.stages.done("load spec")
    if derive_with_progress(graph, _show_progress(args)):
        args.stages.done("derive (cold)")
    designs = sweep.design_space(args.units, args.cpe, args.precision, args.linear)
    base = SolverConfig(method=args.solver, ordering=args.ordering,
                        max_iterations=args.max_iterations, **_clock_mhz(args),
                        **_lm_limits(args))
    out = Path(args.out or f"fgc-sweep-{_name(args.spec)}")
    with sweep.open_executor(args.jobs, args.executor) as pool, \
            sweep.progress_bar(len(designs), args.progress) as progress:
        result = sweep.run_sweep(graph, base, designs, pool, _name(args.spec), progress)
    files = sweep.write_outputs(result, out, title=_name(args.spec))
    _print(args, [*sweep.summary_lines(result, args.spec),
                  f"wrote {', '.join(str(f) for f in files)}"])
    failed = [r for r in result.rows if r["status"] != "converged"]
    return EXIT_FAILED if failed else EXIT_OK


def _cmd_metrics(args) -> int:
    from fgc.app import metrics
    est, ref = metrics.read_tum(args.estimate), metrics.read_tum(args.reference)
    results, lines = {}, [f"fgc metrics {args.estimate} vs {args.reference}: {len(est)} poses, "
                          f"alignment {args.align}, RPE delta {args.delta} frames"
                          + (" (all pairs)" if args.all_pairs else "")]
    for name, func, kw in (("ate", metrics.ate, {}),
                           ("rpe", metrics.rpe, {"delta": args.delta,
                                                 "all_pairs": args.all_pairs})):
        for relation in metrics.RELATIONS:
            res = func(est, ref, align=args.align, relation=relation,
                       max_time_diff=args.max_time_diff, **kw)
            stats = res.statistics()
            results[f"{name}_{relation}"] = {"unit": res.unit, **stats}
            lines.append(f"  {name.upper()} {relation:<11} [{res.unit:>3}]  " + "  ".join(
                f"{k} {v:.6g}" for k, v in stats.items() if k != "sse"))
        if name == "ate" and args.align != "none":
            results["alignment"] = {"rotation": res.alignment.rotation.tolist(),
                                    "translation": res.alignment.translation.tolist(),
                                    "scale": res.alignment.scale}
    _print(args, lines, lines[1].strip())
    _write_json(args.json, results)
    return EXIT_OK


def _metrics_parser(sub) -> None:
    p = sub.add_parser("metrics", help="ATE and RPE of a TUM trajectory against a reference "
                       "(translation in m, rotation in degrees; evo's definitions)",
                       description="fgc metrics: absolute trajectory error (ATE) and relative "
                       "pose error (RPE) of EST against REF, both TUM files (timestamp tx ty tz "
                       "qx qy qz qw) paired by index; translation (m) and rotation angle "
                       "(degrees), as evo_ape / evo_rpe compute them",
                       epilog="exit status: 0 success, 2 bad input (one line on stderr)",
                       formatter_class=_Formatter)
    p.add_argument("estimate", metavar="EST", help="estimated trajectory (TUM)")
    p.add_argument("reference", metavar="REF", help="reference trajectory (TUM)")
    p.add_argument("--align", choices=("none", "se3", "sim3"), default="none",
                   help="Umeyama alignment of EST onto REF: se3 = evo's --align, sim3 = "
                        "--align --correct_scale")
    p.add_argument("--delta", type=_positive_int, default=1, metavar="N",
                   help="RPE frame distance")
    p.add_argument("--all-pairs", action="store_true",
                   help="RPE over every pair (i, i+delta), not (0, delta), (delta, 2 delta), …")
    p.add_argument("--max-time-diff", type=float, default=0.01, metavar="S",
                   help="largest timestamp difference between paired poses")
    p.add_argument("--json", metavar="FILE", help="also write the statistics as JSON")
    _verbosity_args(p, suppress=True)
    p.set_defaults(func=_cmd_metrics)


# --------------------------------------------------------------------------------------------
# parser
# --------------------------------------------------------------------------------------------


class UsageError(FgcError):
    """A command line argparse rejects (reported as one line, exit 2)."""


class _Parser(argparse.ArgumentParser):
    """argparse, but a bad argument is one line on stderr (via main), not usage + exit."""

    def error(self, message: str) -> NoReturn:
        raise UsageError(f"{self.prog}: {message} (see {self.prog} --help)")


class _Formatter(argparse.RawDescriptionHelpFormatter):
    """Keeps the description's layout and appends real defaults (not None/False) to help."""

    def _get_help_string(self, action: argparse.Action) -> str:
        text = action.help or ""
        if action.default not in (None, False, [], argparse.SUPPRESS) and action.option_strings \
                and "default" not in text:
            default = action.default
            if isinstance(default, tuple):
                default = ",".join(str(v) for v in default)
            text += f" (default: {default})"
        return text


def _positive_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}") from None
    if not (value > 0 and np.isfinite(value)):
        raise argparse.ArgumentTypeError(f"expected a positive finite number, got {text!r}")
    return value


def _positive_int(text: str) -> int:
    if not text.strip().isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive integer")
    return int(text)


def _int_list(text: str) -> tuple[int, ...]:
    """``"1,2,4"`` → ``(1, 2, 4)`` (positive, duplicates dropped)."""
    items = [s.strip() for s in text.split(",")]
    if not all(s.isdigit() and int(s) >= 1 for s in items):
        raise argparse.ArgumentTypeError(
            f"{text!r} is not a comma-separated list of positive integers (e.g. 1,2,4,8)")
    return tuple(dict.fromkeys(int(s) for s in items))


def _choice_list(choices: tuple[str, ...]) -> Callable[[str], tuple[str, ...]]:
    """An argparse type for a comma-separated subset of ``choices``."""

    def parse(text: str) -> tuple[str, ...]:
        items = [s.strip() for s in text.split(",")]
        bad = [s for s in items if s not in choices]
        if bad:
            raise argparse.ArgumentTypeError(
                f"{text!r}: {', '.join(repr(b) for b in bad)} not among {', '.join(choices)}")
        return tuple(dict.fromkeys(items))

    return parse


def _scheduler_address(text: str) -> str:
    if not re.fullmatch(r"[a-z]+://[^\s/]+:[0-9]+", text):
        raise argparse.ArgumentTypeError(f"{text!r} is not a scheduler address like "
                                         "tcp://host:8786")
    return text


def _clock(text: str) -> tuple[float, float]:
    """``--clock``: MHz or ns → (MHz, ns)."""
    from fgc_backends.hls.config import HlsConfigError, parse_clock

    try:
        return parse_clock(text)
    except HlsConfigError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _scalar(text: str) -> str:
    from fgc_backends.cfamily.errors import CodegenError
    from fgc_backends.cfamily.scalars import check_scalar

    text = re.sub(r"\s+", "", text)
    try:
        return check_scalar(text)
    except CodegenError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _allocation(text: str) -> tuple[tuple[str, int], ...]:
    from fgc_backends.hls.plan import DEFAULT_ALLOCATION

    kinds, out = dict(DEFAULT_ALLOCATION), {}
    for item in text.split(","):
        kind, sep, value = item.strip().partition("=")
        if not sep or kind not in kinds or not value.strip().isdigit() or int(value) < 1:
            raise argparse.ArgumentTypeError(
                f"{item.strip()!r}: expected KIND=N with KIND one of {', '.join(kinds)} and N a "
                "whole number ≥ 1")
        if kind in out:
            raise argparse.ArgumentTypeError(f"{kind} is given twice")
        out[kind] = int(value)
    return tuple(out.items())


def _part(text: str) -> str:
    if not re.fullmatch(r"[A-Za-z0-9_-]{1,64}", text):
        raise argparse.ArgumentTypeError(f"FPGA part {text!r} is not a plain part name "
                                         "(letters, digits, - and _)")
    return text


def _verbosity_args(p: argparse.ArgumentParser, suppress: bool) -> None:
    """-v / -q, on the main parser and again on each command (so they go either side of it;
    a command's copy must not reset what the main parser set, hence SUPPRESS there)."""
    v = p.add_mutually_exclusive_group()
    v.add_argument("-v", "--verbose", action="count",
                   default=argparse.SUPPRESS if suppress else 0,
                   help="stage timings and derivation progress on stderr")
    v.add_argument("-q", "--quiet", action="store_true",
                   default=argparse.SUPPRESS if suppress else False,
                   help="print only the result line")


def _hardware_args(p: argparse.ArgumentParser, name: str) -> None:
    h = p.add_argument_group("hardware (the cost model's figures are model estimates)")
    h.add_argument("--clock", type=_clock, metavar="F",
                   help="accelerator clock, e.g. 143MHz or 7ns (a bare number ≥ 20 is MHz): "
                        "the cost model's clock and, for --backend hls, run_hls.tcl's period "
                        "(default: 143 MHz; run_hls.tcl 7 ns)")
    if name in ("compile", "run", "simulate", "report"):
        priced = name in ("simulate", "report")
        where = ("the design priced: the HLS design that fgc compile --backend hls emits with "
                 "the same flags" if priced else "--backend hls")
        h.add_argument("--part", type=_part, metavar="PART",
                       help=("FPGA part whose capacities the plan's fit verdict uses" if priced
                             else "FPGA part for run_hls.tcl, --backend hls only")
                            + " (default: xc7z045ffg900-2); the plan's fit verdict and the lint's "
                            "DSP budget use its device's capacities (backends/hls/target.py)")
        h.add_argument("--scalar", type=_scalar, metavar="T",
                       help=("C++ scalar of the priced HLS design: float or double (implies "
                             "--precision; the dataflow design has no fixed-point operator table)"
                             if priced else
                             "C++ scalar of the HLS accelerator or native solver: float, double "
                             "or ap_fixed<W,I> (2 ≤ W ≤ 1024, 1 ≤ I ≤ W; needs fgc[hls-fixed])")
                            + " (default: from --precision)")
        h.add_argument("--allocation", type=_allocation, metavar="KIND=N,…",
                       help=f"{where}: the factor datapaths' ALLOCATION limits, e.g. "
                            "mul=48,add=32 (kinds add, mul, div, sqrt, trig, special; the others "
                            "keep the defaults add 16, mul 24, div 4, sqrt 2, trig 2, special 2); "
                            "each block type gets a share by its instance count")
        h.add_argument("--unit-sets", type=_positive_int, metavar="S",
                       help=f"{where}: unit sets eliminating a level's steps side by side, "
                            "1 … 8 (default: 2 on a two-ended chain, else 1)")
        h.add_argument("--qr-unit", choices=("householder", "stream"),
                       help=f"{where}: the QR unit set: householder (paper A's, one DATAFLOW "
                            "region per reflection; the default) or stream (n_u reflection "
                            "stages the matrix streams through)")


def _spec_args(p: argparse.ArgumentParser, json_help: str | None) -> None:
    p.add_argument("spec", help="spec file (.py with build(**params)) or a g2o/TORO file")
    p.add_argument("-p", "--param", action="append", default=[], metavar="KEY=VALUE",
                   help="parameter passed to the spec's build() (repeatable)")
    if json_help:
        p.add_argument("--json", metavar="FILE", help=json_help)


def _solver_args(p: argparse.ArgumentParser, design_space: bool) -> None:
    s = p.add_argument_group("solver")
    s.add_argument("--solver", choices=("gn", "lm"), default="lm", help="Gauss-Newton or LM")
    s.add_argument("--ordering", default="auto",
                   choices=ORDERINGS,
                   help="elimination ordering (auto = two-ended on chains, min-degree "
                        "otherwise; natural = declaration order)")
    s.add_argument("--max-iterations", type=_positive_int, default=100, metavar="K",
                   help="k_max")
    s.add_argument("--lambda-upper-bound", type=_positive_float, metavar="X",
                   help="LM gives up (failed, lambda_limit) when its damping would pass X "
                        "(default 1e10; an ap_fixed<W,I> scalar must hold it)")
    if design_space:
        d = p.add_argument_group("design space (comma-separated lists; the product is swept)")
        d.add_argument("--linear", type=_choice_list(("qr", "cholesky")), metavar="LIST",
                       default=("qr", "cholesky"), help="linear solvers: qr, cholesky")
        d.add_argument("--precision", type=_choice_list(("float32", "float64")),
                       metavar="LIST", default=("float32", "float64"),
                       help="arithmetic of the accelerator: float32, float64")
        d.add_argument("--units", type=_int_list, default=(1, 2, 4, 8), metavar="LIST",
                       help="n_u Update units per QR block (QR designs)")
        d.add_argument("--cpe", type=_int_list, default=(5, 20, 40, 80, 120), metavar="LIST",
                       help="#CPE Cholesky process elements (Cholesky designs)")
        return
    s.add_argument("--linear", choices=("qr", "cholesky"), default="qr", help="linear solver")
    s.add_argument("--precision", choices=("float32", "float64"),
                   help="arithmetic of the accelerator (default: float32; verify and the "
                        "keyframe-by-keyframe modes: float64)")
    s.add_argument("--linear-precision", choices=("float32", "float64"),
                   help="widen the linear solver alone (default: --precision); float32 with a "
                        "float64 solver suits ill-conditioned Cholesky problems")
    s.add_argument("--units", type=_positive_int, default=4, metavar="N",
                   help="n_u Update units per QR block")
    s.add_argument("--cpe", type=_positive_int, default=20, metavar="N",
                   help="#CPE Cholesky process elements")


def _streaming_args(name: str, p: argparse.ArgumentParser) -> None:
    if name not in ("compile", "simulate", "verify", "run", "report", "stream"):
        return
    g = p.add_argument_group("keyframe by keyframe (the simulator; fgc stream --backend native "
                             "or hls solves each update in compiled code; issue 19)")
    g.add_argument("--incremental", type=_positive_int, metavar="K",
                   help="incremental smoothing: each keyframe re-eliminates the newest K "
                        "clusters (SolverConfig.incremental_k)")
    g.add_argument("--batch-every", type=_batch_every, metavar="B",
                   help="batch steps of the incremental plan: a period (10) or keyframe "
                        "indices (5,15,25; one keyframe: 5,) (SolverConfig.batch_every)")
    if name != "report":
        g.add_argument("--window", type=_positive_int, metavar="W",
                       help="fixed-lag window: hold the newest W keyframes, marginalise the "
                            "one leaving into a prior on the window")


def _batch_every(text: str):
    """``--batch-every``: ``10`` → a period, ``5,15,25`` → those keyframes."""
    if "," not in text:
        return _positive_int(text)
    items = [s.strip() for s in text.split(",") if s.strip()]
    if not items or not all(s.isdigit() for s in items):
        raise argparse.ArgumentTypeError(f"{text!r} is not a period or a comma-separated list "
                                         "of keyframe indices (e.g. 5,15,25)")
    return tuple(sorted({int(s) for s in items}))


def _command_args(name: str, p: argparse.ArgumentParser) -> None:
    _streaming_args(name, p)
    if name == "stream":
        p.add_argument("--tum", metavar="FILE", help="write the streamed trajectory (TUM)")
        p.add_argument("--backend", choices=_backend_names(), default="sim",
                       help="sim: the simulator's updates and the plan's batch-iteration "
                            "price; native: the native solver solves each update; hls: the "
                            "HLS design's C simulation solves each update (--precision "
                            "float64: double, float32: float), priced by the accelerator "
                            "plan's update model, --units / --cpe / --clock as for the HLS "
                            "design (model estimates). native and hls compile a template "
                            "window once and keep the Bayes net on the host")
        p.add_argument("--model-only", action="store_true",
                       help="with --backend hls: no C simulation; the simulator's updates "
                            "priced by the update model")
    if name in ("simulate", "verify", "run", "stream"):
        p.add_argument("--values", metavar="FILE",
                       help="write the optimised values: .g2o, .tum/.txt (TUM poses, t = key "
                            "order index) or .csv, by extension")
    if name in ("simulate", "run"):
        p.add_argument("--marginals", metavar="KEY,KEY",
                       help="print (and put in --json) the marginal covariances of these "
                            "variables at the estimate")
    if name == "compile":
        p.add_argument("--backend", choices=_backend_names(), default="sim",
                       help="backend: " + _backend_help())
        p.add_argument("--out", required=True, metavar="DIR", help="output folder")
    elif name == "run":
        p.add_argument("--backend", choices=_backend_names(), default="native",
                       help="solver (hls: the accelerator's C simulation): " + _backend_help())
    elif name == "simulate":
        p.add_argument("--plot", metavar="DIR", help="write plots (needs matplotlib)")
    elif name == "report":
        p.add_argument("--html", metavar="FILE", help="also write a self-contained HTML page")
        p.add_argument("--iterations", type=_positive_int, metavar="K",
                       help="cost K iterations instead of running the simulator")
    elif name == "sweep":
        p.add_argument("--jobs", type=_positive_int, metavar="N",
                       help="local worker processes (default: os.cpu_count())")
        p.add_argument("--executor", type=_scheduler_address, metavar="ADDRESS",
                       help="run on the Dask scheduler at ADDRESS (tcp://host:port) instead")
        p.add_argument("--out", metavar="DIR",
                       help="folder for sweep.csv, sweep.json, pareto.png, accuracy.png "
                            "(default: fgc-sweep-NAME)")
        p.add_argument("--progress", action=argparse.BooleanOptionalAction,
                       help="progress bar on stderr (default: when stderr is a terminal)")


_COMMANDS = (
    # name, function, one-line help, what exit code 1 means, --json help
    ("compile", _cmd_compile, "emit a backend project for a spec", None, None),
    ("simulate", _cmd_simulate, "run the accelerator simulator: numbers, cycles, resources",
     "the simulator did not converge", "also write the report as JSON"),
    ("verify", _cmd_verify, "solve with the simulator and with GTSAM and compare",
     "FAILED (the verdict line says why)", "also write the report as JSON"),
    ("run", _cmd_run, "solve with the generated native solver (or the simulator, or the HLS "
                      "accelerator's C simulation: --backend sim|hls)",
     "the solve did not converge", "also write the report as JSON"),
    ("report", _cmd_report, "the compiled design at a glance: blocks, schedule, storage, "
     "cycles, resources, energy", None, "also write the report as JSON"),
    ("stream", _cmd_stream, "feed a chain's keyframes one at a time to the simulator, the "
     "native solver or the HLS C simulation (--window W or --incremental K): per-keyframe "
     "latency and estimate, trajectory, accuracy against the batch optimum",
     "the stream did not converge", "also write the report as "
     "JSON"),
    ("sweep", _cmd_sweep, "design-space exploration: latency, resources, energy and accuracy "
     "vs GTSAM per design, Pareto plot", "a design did not converge or failed", None),
)


def _cmd_cache(args) -> int:
    from fgc.compiler import cache
    if args.action == "clear":
        n = cache.clear()
        print(f"removed {n} entr{'y' if n == 1 else 'ies'} from {cache.cache_root()}")
        return EXIT_OK
    stats = cache.info()
    if args.json_stdout:
        print(json.dumps(stats, indent=2))
        return EXIT_OK
    print(f"cache dir: {stats['dir']}")
    for kind, n in stats["entries"].items():
        print(f"  {kind:<10} {n:>6} entries")
    print(f"total size: {stats['bytes'] / 1e6:.1f} MB ({stats['bytes']} bytes)")
    return EXIT_OK


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="fgc", description="fgc: a factor-graph compiler",
                     epilog="Run 'fgc COMMAND --help' for a command's options. Exit status: 0 "
                            "success, 1 verification failed (or a solve did not converge), 2 "
                            "bad input (one line on stderr).", formatter_class=_Formatter)
    from fgc import __version__

    parser.add_argument("--version", action="version", version=f"fgc {__version__}")
    _verbosity_args(parser, suppress=False)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, func, help_text, fails, json_help in _COMMANDS:
        epilog = ("exit status: 0 success" + (f", 1 {fails}" if fails else "")
                  + ", 2 bad input (one line on stderr)")
        p = sub.add_parser(name, help=help_text, description=f"fgc {name}: {help_text}",
                           epilog=epilog, formatter_class=_Formatter)
        _spec_args(p, json_help)
        _solver_args(p, design_space=name == "sweep")
        _command_args(name, p)
        _hardware_args(p, name)
        _verbosity_args(p, suppress=True)
        p.set_defaults(func=func)
    _metrics_parser(sub)
    help_text = ("fgc's cache ($FGC_CACHE_DIR, default ~/.cache/fgc: derivations, native and "
                 "HLS-stream builds): info or clear")
    p = sub.add_parser("cache", help=help_text, description=f"fgc cache: {help_text}",
                       epilog="exit status: 0 success", formatter_class=_Formatter)
    p.add_argument("action", choices=("info", "clear"),
                   help="info: directory, entries per kind, total size; clear: delete all of "
                        "them")
    p.add_argument("--json", action="store_true", dest="json_stdout",
                   help="info as JSON on stdout")
    _verbosity_args(p, suppress=True)
    p.set_defaults(func=_cmd_cache)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run one command; every error reaches the user as one line on stderr (exit 2), never as a
    traceback (set FGC_TRACEBACK=1 to see the traceback of an unexpected error). Ctrl-C prints
    ``fgc: interrupted`` and exits 130 (temporary files are removed as the stack unwinds)."""
    args = None
    try:
        args = build_parser().parse_args(argv)
        check_outputs(args)
        return args.func(args)
    except KeyboardInterrupt:
        return interrupted()
    except UsageError as exc:
        print(str(exc), file=sys.stderr)
        return EXIT_BAD_INPUT
    except FgcError as exc:
        if caused_by_interrupt(exc):
            return interrupted()
        _error_line(args, str(exc))
        return EXIT_BAD_INPUT
    except BrokenPipeError:  # output piped into e.g. `head`: stop quietly, like other tools
        sys.stderr = open(os.devnull, "w")  # noqa: SIM115 - silence the interpreter's flush
        return EXIT_OK
    except OSError as exc:  # a file the user named (spec, data, output) cannot be read/written
        if caused_by_interrupt(exc):
            return interrupted()
        _error_line(args, f"{exc.strerror or exc}{_filename(exc)}")
        return EXIT_BAD_INPUT
    except Exception as exc:
        if caused_by_interrupt(exc):  # e.g. an extension module's ImportError caused by Ctrl-C
            return interrupted()
        if os.environ.get("FGC_TRACEBACK"):
            raise
        _error_line(args, f"internal error (a bug in fgc; FGC_TRACEBACK=1 shows the traceback): "
                          f"{type(exc).__name__}: {exc}")
        return EXIT_BAD_INPUT


def interrupted() -> int:
    """Ctrl-C: one line on stderr, exit status 130 (128 + SIGINT, as shells report it)."""
    print("fgc: interrupted", file=sys.stderr, flush=True)
    return EXIT_INTERRUPTED


def _error_line(args, text: str) -> None:
    spec = getattr(args, "spec", None)
    where = f"{spec}: " if spec and spec not in text else ""  # which spec, if not said
    line = " ".join(f"fgc: error: {where}{text}".split())  # one line, whatever the message
    print(line, file=sys.stderr)


if __name__ == "__main__":
    from fgc_cli import main as entry  # the console script's entry: Ctrl-C handled throughout

    sys.exit(entry())
