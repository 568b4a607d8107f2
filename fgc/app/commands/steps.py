"""The steps every command shares: a spec loaded and compiled with the command line's solver
options, the backends' configurations from the hardware options, stage timings and the solve's
progress display. Exit codes live here too (0 success, 1 failed, 2 bad input, 130 interrupted).
"""

from __future__ import annotations

import ast
import sys
import time
from pathlib import Path

from fgc.app.commands.options import UsageError
from fgc.app.progress import Progress
from fgc.app.specs import load_spec
from fgc.app.streaming import HW_REFUSAL, check_mode
from fgc.compile import compile_graph
from fgc.compiler.derive import derive, is_cached
from fgc.errors import FgcError
from fgc.frontend.dsl import Graph
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import BACKENDS, load, names

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


def solver_config(args, precision_default: str):
    return SolverConfig(method=args.solver, linear=args.linear, ordering=args.ordering,
                        precision=args.precision or precision_default,
                        linear_precision=getattr(args, "linear_precision", None),
                        units=args.units, cpe=args.cpe, max_iterations=args.max_iterations,
                        incremental_k=getattr(args, "incremental", None),
                        batch_every=getattr(args, "batch_every", None), **clock_option(args),
                        **lm_limits(args))


def lm_limits(args) -> dict:
    """``{"lambda_upper_bound": …}`` from ``--lambda-upper-bound`` (nothing when not given)."""
    bound = getattr(args, "lambda_upper_bound", None)
    return {"lambda_upper_bound": bound} if bound is not None else {}


def is_streaming(args) -> bool:
    """Whether keyframe-by-keyframe mode was asked for (--incremental or --window); checks
    the combination and refuses the backends that run batch solves only."""
    incremental, window = getattr(args, "incremental", None), getattr(args, "window", None)
    batch_every = getattr(args, "batch_every", None)
    if incremental is None and window is None and batch_every is None:
        return False
    check_mode(incremental, batch_every, window)
    backend = getattr(args, "backend", "sim")
    if getattr(args, "model_only", False) and not backend_info(backend).hardware:
        raise FgcError("--model-only prices the simulator's updates on the HLS plan: it needs "
                       "--backend hls")
    if backend != "sim" and args.command != "stream" and not (
            args.command in ("compile", "report") and backend_info(backend).stream_design):
        raise FgcError(f"fgc {args.command} --backend {backend}: {HW_REFUSAL}")
    return True


def backend_info(name: str):
    """The registry's entry of backend ``name`` (fgc_backends.BACKENDS)."""
    return BACKENDS[name]


def clock_option(args) -> dict:
    """``{"clock_mhz": …}`` from ``--clock`` (nothing when it was not given)."""
    clock = getattr(args, "clock", None)
    return {"clock_mhz": clock[0]} if clock else {}


def implied_precision(args, default: str) -> str:
    """The precision a ``--scalar`` implies (float → float32, double → float64), checked
    against an explicit ``--precision``; ``default`` otherwise."""
    scalar = getattr(args, "scalar", None)
    implied = {"float": "float32", "double": "float64"}.get(scalar or "")
    if implied and args.precision and args.precision != implied:
        raise UsageError(f"fgc {args.command}: --scalar {scalar} contradicts --precision "
                         f"{args.precision}")
    return implied or default


def hls_config(args, program):
    """The HLS backend's config: --scalar (default: the Program's precision) and the design's
    options (``HlsConfig.design``) from --part, --clock, --allocation, --unit-sets, --qr-unit,
    --qr-rows, --cascade-lanes, --backsub-lanes (auto: None), --data-width and --hgc-before
    (one clock for the cost model and run_hls.tcl: ``clock_ns`` is ``1000 /
    SolverConfig.clock_mhz``; ``DesignOptions.check`` checks them)."""
    hls = load_backend("hls")
    clock = getattr(args, "clock", None)
    design = hls.DesignOptions(**{
        name: value for name, value in (
            ("part", getattr(args, "part", None)), ("clock_ns", clock[1] if clock else None),
            ("allocation", getattr(args, "allocation", None)),
            ("unit_sets", getattr(args, "unit_sets", None)),
            ("qr_unit", getattr(args, "qr_unit", None)),
            ("cascade_lanes", getattr(args, "cascade_lanes", None)),
            ("qr_rows", getattr(args, "qr_rows", None)),
            ("backsub_lanes", getattr(args, "backsub_lanes", None)),
            ("bind", getattr(args, "bind", None)),
            ("data_width", getattr(args, "data_width", None))) if value},
        **({"hgc_beside": False} if getattr(args, "hgc_before", False) else {}))
    config = hls.HlsConfig(scalar=getattr(args, "scalar", None) or c_scalar(program),
                           design=design)
    if not design.hgc_beside:
        check_hgc_before(args, program, config)
    return config


def check_hgc_before(args, program, config) -> None:
    """--hgc-before turns off the HGC beside the elimination, which only a batch Cholesky
    design in one scalar has (units/cholesky.py): anywhere else the flag would change nothing,
    so it is refused rather than ignored."""
    if any(getattr(args, name, None) is not None
           for name in ("incremental", "window", "batch_every")):
        raise UsageError(f"fgc {args.command}: --hgc-before shapes the batch Cholesky design; "
                         "the stream's design (--window / --incremental) has no HGC beside its "
                         "elimination (drop --hgc-before)")
    if program.solver.linear != "cholesky":
        raise UsageError(f"fgc {args.command}: --hgc-before applies to Cholesky designs "
                         f"(--linear cholesky); a {program.solver.linear} design has no HGC "
                         "beside its elimination")
    wide = load_backend("hls").emitter.for_program(program, config)
    if wide.mixed:
        raise UsageError(f"fgc {args.command}: --hgc-before: this design's linear solver "
                         f"({wide.linear_cxx}) is wider than the rest ({wide.scalar_cxx}), so "
                         "its HGC runs before the elimination already (drop --hgc-before or "
                         "--linear-precision)")


def plan_options(args, program):
    """The accelerator plan's options for the design ``fgc compile --backend hls`` emits with
    the same --scalar, --part, --clock, --allocation, --unit-sets, --qr-unit and --hgc-before
    (what ``fgc simulate`` and ``fgc report`` price). A fixed-point --scalar is refused: the
    dataflow design has no fixed-point units and the plan no fixed-point operator table."""
    config = hls_config(args, program)
    config.check(program)
    if config.is_fixed_point:
        raise UsageError(f"fgc {args.command}: --scalar {config.scalar}: the HLS dataflow design "
                         "is float or double only (no fixed-point operator table to price it); "
                         "the native backend runs ap_fixed (fgc run --backend native --scalar)")
    return load_backend("hls").emitter.accel_plan(program, config).options


def refuse_hls_design(args, backend: str) -> None:
    """--allocation, --unit-sets, --qr-unit, --cascade-lanes, --backsub-lanes (a width, not
    auto), --bind and --hgc-before shape the HLS design: other backends have no such thing."""
    for flag in ("allocation", "unit_sets", "qr_unit", "hgc_before", "cascade_lanes",
                 "backsub_lanes", "qr_rows", "bind", "data_width"):
        if getattr(args, flag, None):
            raise UsageError(f"fgc {args.command}: --{flag.replace('_', '-')} applies to "
                             f"--backend hls only (not {backend})")


def native_config(args, program):
    """The native backend's config from --scalar (default: the Program's precision); --part
    names an FPGA, which a CPU program has none of."""
    if getattr(args, "part", None):
        raise UsageError(f"fgc {args.command}: --part applies to fgc compile --backend hls only "
                         "(the native backend builds a CPU program)")
    refuse_hls_design(args, "native")
    native = load_backend("native")
    return native.NativeConfig(scalar=getattr(args, "scalar", None) or c_scalar(program))


class Stages:
    """Stage timings for ``-v`` (stderr, so stdout stays deterministic)."""

    def __init__(self, args):
        self.verbose = getattr(args, "verbose", 0) > 0
        self.t0 = time.perf_counter()

    def done(self, name: str) -> None:
        t = time.perf_counter()
        if self.verbose:
            print(f"fgc: {name}: {t - self.t0:.2f} s", file=sys.stderr)
        self.t0 = t


def show_progress(args) -> bool:
    if getattr(args, "quiet", False):
        return False
    return getattr(args, "verbose", 0) > 0 or sys.stderr.isatty()


def derive_with_progress(graph: Graph, show: bool) -> int:
    """Derive every factor type of ``graph`` not yet in the disk cache, printing "deriving
    factor X (n/m)…" on stderr before each when ``show``; returns how many were derived."""
    types = list({f.type.name: f.type for f in graph.factors}.values())
    cold = [ftype for ftype in types if not is_cached(ftype)]
    for i, ftype in enumerate(cold, 1):
        if show:
            print(f"fgc: deriving factor {ftype.name} ({i}/{len(cold)}, not cached; "
                  "sympy takes seconds per factor)…", file=sys.stderr, flush=True)
        derive(ftype)
    return len(cold)


def load_graph(args, precision_default: str):
    """The spec's graph (derivations done, with progress) and its solver configuration, timed
    in the returned stages."""
    stages = Stages(args)
    graph = load_spec(args.spec, parse_params(args.param))
    stages.done("load spec")
    if derive_with_progress(graph, show_progress(args)):
        stages.done("derive (cold)")
    return stages, graph, solver_config(args, implied_precision(args, precision_default))


def compile_spec(args, precision_default: str):
    stages, graph, config = load_graph(args, precision_default)
    try:
        program = compile_graph(graph, config, name=project_name(args.spec))
    except ValueError as exc:
        if config.incremental_k is None:
            raise
        raise FgcError(f"incremental plan: {exc}") from None  # --incremental/--batch-every
    stages.done("compile")
    data = problem_data(graph, program)
    args.stages = stages
    return graph, program, data


def project_name(spec: str) -> str:
    """A C/Python-safe project name from the spec's file name."""
    stem = "".join(c if c.isalnum() else "_" for c in Path(spec).stem.lower()).strip("_")
    return stem if stem[:1].isalpha() else f"fgc_{stem or 'problem'}"


def load_backend(name: str):
    return load(name)


def backend_names() -> tuple[str, ...]:
    """The registry's backend names (fgc_backends.BACKENDS): the CLI hard-codes none."""
    return names()


def backend_help() -> str:
    return "; ".join(f"{b.name}: {b.summary}" for b in BACKENDS.values())


def c_scalar(program) -> str:
    return "float" if program.solver.precision == "float32" else "double"


def filename_note(exc: OSError) -> str:
    return f" ({exc.filename})" if getattr(exc, "filename", None) else ""


SIM_LARGE_VARIABLES = 2000  # above this, the simulator says what it is before it starts


def progress_display(args, command: str, program, simulator: bool = False):
    """The per-iteration progress display of a solve (fgc.app.progress): stderr unless -q.
    With ``simulator``, a large Program gets a note first: the simulator steps every
    elimination step in NumPy (the accelerator's model, not a fast solver)."""
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


class WithProgress:
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
