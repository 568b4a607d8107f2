"""The ``fgc`` command line.

    fgc compile  SPEC --backend sim|hls --out DIR     emit a backend project (+ program.json, data)
    fgc simulate SPEC [--json F]                      run the accelerator simulator, report cost
    fgc verify   SPEC [--json F]                      simulator vs GTSAM's LM, exit 1 on mismatch
    fgc run      SPEC --backend native|sim            solve with the generated solver
    fgc report   SPEC [--json F] [--html F]           the compiled design at a glance
    fgc sweep    SPEC --units 1,2,4 --cpe 5,20 ...    design-space exploration, Pareto plot

SPEC is a ``.py`` file with ``build(**params)`` returning an ``fgc.Graph`` (``-p KEY=VALUE``), or a
g2o/TORO file. Solver options are shared by every command. Exit codes: 0 success, 1 verification
failed (or a solve did not converge), 2 bad input (one clear line on stderr).
"""

from __future__ import annotations

import argparse
import ast
import importlib.util
import inspect
import json
import os
import re
import sys
from collections.abc import Callable
from pathlib import Path
from typing import NoReturn

from fgc.dsl import Graph
from fgc.errors import FgcError

EXIT_OK, EXIT_FAILED, EXIT_BAD_INPUT = 0, 1, 2


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


def load_spec(path: str, params: dict) -> Graph:
    """Build the graph of a spec: a ``.py`` file with ``build(**params)``, or a g2o/TORO file
    (which gets a prior on its first pose to fix the gauge) given as a path or as the name of a
    file in the gtsam wheel's example data (``fgc simulate w100.graph``)."""
    p = Path(path)
    if not p.is_file() and p.suffix != ".py" and p.name == path:
        from fgc.data import gtsam_data_dir

        candidate = gtsam_data_dir() / path
        p = candidate if candidate.is_file() else p
    if not p.is_file():
        raise FgcError(f"{path}: no such file")
    if p.suffix != ".py":
        return _load_pose_graph_file(p, params)
    spec = importlib.util.spec_from_file_location(f"fgc_spec_{p.stem}", p)
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except FgcError:
        raise
    except Exception as exc:
        raise FgcError(f"{path}: the spec failed to load: {type(exc).__name__}: {exc}") from exc
    build = getattr(module, "build", None)
    if not callable(build):
        raise FgcError(f"{path}: a spec must define build(**params) returning an fgc.Graph")
    unknown = _unknown_parameters(build, params)
    if unknown:
        raise FgcError(f"{path}: build() has no parameter {', '.join(map(repr, unknown))} "
                       f"(it takes: {_parameter_list(build)})")
    try:
        graph = build(**params)
    except FgcError:
        raise
    except TypeError as exc:
        raise FgcError(f"{path}: build() rejected the parameters {sorted(params)}: {exc}") from exc
    except Exception as exc:  # the user's code: one line naming the spec, not a traceback
        raise FgcError(f"{path}: build() failed: {type(exc).__name__}: {exc}") from exc
    if not isinstance(graph, Graph):
        raise FgcError(f"{path}: build() returned {type(graph).__name__}, not an fgc.Graph")
    return graph


def _unknown_parameters(build, params: dict) -> list[str]:
    """Names in ``params`` that ``build`` cannot take (none if it accepts **kwargs)."""
    try:
        sig = inspect.signature(build)
    except (TypeError, ValueError):
        return []
    kinds = {p.kind for p in sig.parameters.values()}
    if inspect.Parameter.VAR_KEYWORD in kinds:
        return []
    names = {n for n, p in sig.parameters.items()
             if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)}
    return sorted(k for k in params if k not in names)


def _parameter_list(build) -> str:
    """``build``'s parameters with their defaults, as -p would set them."""
    parts = [f"{n}={p.default!r}" if p.default is not p.empty else n
             for n, p in inspect.signature(build).parameters.items()
             if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)]
    return ", ".join(parts) or "no parameters"


def _load_pose_graph_file(p: Path, params: dict) -> Graph:
    from fgc import noise
    from fgc.factors import PriorFactor
    from fgc.io import read_pose_graph

    unknown = sorted(set(params) - {"prior_sigma", "init"})
    if unknown:
        raise FgcError(f"{p}: unknown parameters {unknown} for a g2o/TORO file "
                       "(only prior_sigma, init=odometry|chordal)")
    graph = read_pose_graph(p, init=str(params.get("init", "odometry")))
    first = next(iter(graph.variables.values()))
    sigma = float(params.get("prior_sigma", 1e-3))
    graph.add(PriorFactor(first.key, first.initial, noise.isotropic(first.type.dim, sigma)))
    return graph


# --------------------------------------------------------------------------------------------
# shared steps
# --------------------------------------------------------------------------------------------


def solver_config(args, precision_default: str):
    from fgc.program import SolverConfig

    return SolverConfig(method=args.solver, linear=args.linear, ordering=args.ordering,
                        precision=args.precision or precision_default,
                        linear_precision=getattr(args, "linear_precision", None),
                        units=args.units, cpe=args.cpe, max_iterations=args.max_iterations)


def _compile(args, precision_default: str):
    from fgc.compile import compile_graph
    from fgc.datafile import problem_data

    graph = load_spec(args.spec, parse_params(args.param))
    program = compile_graph(graph, solver_config(args, precision_default), name=_name(args.spec))
    return graph, program, problem_data(graph, program)


def _name(spec: str) -> str:
    """A C/Python-safe project name from the spec's file name."""
    stem = "".join(c if c.isalnum() else "_" for c in Path(spec).stem.lower()).strip("_")
    return stem if stem[:1].isalpha() else f"fgc_{stem or 'problem'}"


def _write_json(path: str | None, report: dict) -> None:
    if path:
        Path(path).write_text(json.dumps(report, indent=2, sort_keys=True) + "\n")


def _estimates_out(args, graph: Graph, report: dict, result_values: dict) -> None:
    """Keyed values into the JSON report; --values file; --marginals printed and reported."""
    from fgc import export

    values = export.graph_values(graph, result_values)
    report["values"] = export.values_json(values)
    if getattr(args, "values", None):
        fmt = export.write_values(args.values, values)
        print(f"  estimates → {args.values} ({fmt})")
    if getattr(args, "marginals", None):
        from fgc.marginals import marginal_covariances, parse_keys

        covs = marginal_covariances(graph, parse_keys(args.marginals, graph), values)
        report["marginals"] = {str(k): {"key": k, "covariance": c.tolist()}
                               for k, c in covs.items()}
        for k, c in covs.items():
            print(f"  marginal covariance of {k!r} (diagonal): "
                  + " ".join(f"{x:.6g}" for x in c.diagonal()))


def _backend(name: str):
    from fgc_backends import load

    return load(name)


# --------------------------------------------------------------------------------------------
# commands
# --------------------------------------------------------------------------------------------


def _cmd_compile(args) -> int:
    _, program, data = _compile(args, "float32")
    from fgc.datafile import write_data

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "program.json").write_text(program.to_json())
    write_data(data, out / "data.txt")
    backend = _backend(args.backend)
    if args.backend == "hls":
        project = backend.emit(program, out, backend.HlsConfig(scalar=_c_scalar(program)))
        files = list(project.files)
    else:
        files = backend.emit(program, out)
    print(f"fgc compile {args.spec}: {len(program.variables)} variables, "
          f"{len(program.factors)} block instances → {out}/ ({len(files) + 2} files)")
    return EXIT_OK


def _c_scalar(program) -> str:
    return "float" if program.solver.precision == "float32" else "double"


def _cmd_simulate(args) -> int:
    from fgc.reporting import simulate_report

    graph, program, data = _compile(args, "float32")
    report = simulate_report(graph, program, data, _backend("sim"), plot_dir=args.plot)
    for line in report.pop("summary"):
        print(line)
    _estimates_out(args, graph, report, report.pop("_result_values"))
    _write_json(args.json, report)
    return EXIT_OK if report["status"] == "converged" else EXIT_FAILED


def _cmd_verify(args) -> int:
    from fgc.reporting import verify_report

    graph, program, data = _compile(args, "float64")
    report = verify_report(graph, program, data, _backend("sim"))
    for line in report.pop("summary"):
        print(line)
    _estimates_out(args, graph, report, report.pop("_result_values"))
    _write_json(args.json, report)
    return EXIT_OK if report["passed"] else EXIT_FAILED


def _cmd_run(args) -> int:
    graph, program, data = _compile(args, "float32")
    import time

    t0 = time.perf_counter()
    if args.backend == "native":
        hls = _backend("hls")
        result = hls.native.run(program, data, hls.native.default_config(program))
        status, final, iters = result.status, result.final_error, result.iterations
    else:
        result = _backend("sim").run(program, data)
        status, final, iters = result.status, result.final_error, result.iterations
    seconds = time.perf_counter() - t0
    report = {"backend": args.backend, "status": status, "final_error": final,
              "iterations": iters, "solve_seconds": seconds}
    print(f"fgc run {args.spec} ({args.backend}): {status}, {iters} iterations, "
          f"final error {final:.10g}, {seconds * 1e3:.3f} ms (build/load included on a first "
          "run)")
    values = result.values  # fgc values by Program key, from either backend
    _estimates_out(args, graph, report, values)
    _write_json(args.json, report)
    return EXIT_OK if status == "converged" else EXIT_FAILED


def _cmd_report(args) -> int:
    from fgc.report import design_report, figures, format_text, render_html

    graph, program, data = _compile(args, "float32")
    report = design_report(args.spec, parse_params(args.param), graph, program, data,
                           _backend("sim"), iterations=args.iterations)
    sys.stdout.write(format_text(report))
    _write_json(args.json, report)
    if args.html:
        Path(args.html).write_text(render_html(report, figures(report)))
    return EXIT_OK


def _cmd_sweep(args) -> int:
    from fgc import sweep
    from fgc.program import SolverConfig

    graph = load_spec(args.spec, parse_params(args.param))
    designs = sweep.design_space(args.units, args.cpe, args.precision, args.linear)
    base = SolverConfig(method=args.solver, ordering=args.ordering,
                        max_iterations=args.max_iterations)
    out = Path(args.out or f"fgc-sweep-{_name(args.spec)}")
    with sweep.open_executor(args.jobs, args.executor) as pool, \
            sweep.progress_bar(len(designs), args.progress) as progress:
        result = sweep.run_sweep(graph, base, designs, pool, _name(args.spec), progress)
    files = sweep.write_outputs(result, out, title=_name(args.spec))
    print("\n".join(sweep.summary_lines(result, args.spec)))
    print(f"wrote {', '.join(str(f) for f in files)}")
    failed = [r for r in result.rows if r["status"] != "converged"]
    return EXIT_FAILED if failed else EXIT_OK


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
                   choices=("auto", "two-ended", "serial", "min-degree", "nested-dissection"),
                   help="elimination ordering (auto = two-ended on chains)")
    s.add_argument("--max-iterations", type=_positive_int, default=100, metavar="K",
                   help="k_max")
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
                   help="arithmetic of the accelerator (default: float32; verify: float64)")
    s.add_argument("--linear-precision", choices=("float32", "float64"),
                   help="widen the linear solver alone (default: --precision); float32 with a "
                        "float64 solver suits ill-conditioned Cholesky problems")
    s.add_argument("--units", type=_positive_int, default=4, metavar="N",
                   help="n_u Update units per QR block")
    s.add_argument("--cpe", type=_positive_int, default=20, metavar="N",
                   help="#CPE Cholesky process elements")


def _command_args(name: str, p: argparse.ArgumentParser) -> None:
    if name in ("simulate", "verify", "run"):
        p.add_argument("--values", metavar="FILE",
                       help="write the optimised values: .g2o, .tum/.txt (TUM poses, t = key "
                            "order index) or .csv, by extension")
    if name in ("simulate", "run"):
        p.add_argument("--marginals", metavar="KEY,KEY",
                       help="print (and put in --json) the marginal covariances of these "
                            "variables at the estimate")
    if name == "compile":
        p.add_argument("--backend", choices=("sim", "hls"), default="sim", help="backend")
        p.add_argument("--out", required=True, metavar="DIR", help="output folder")
    elif name == "run":
        p.add_argument("--backend", choices=("native", "sim"), default="native", help="solver")
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
     "the simulator does not match GTSAM", "also write the report as JSON"),
    ("run", _cmd_run, "solve with the generated native solver (or the simulator)",
     "the solve did not converge", "also write the report as JSON"),
    ("report", _cmd_report, "the compiled design at a glance: blocks, schedule, storage, "
     "cycles, resources, energy", None, "also write the report as JSON"),
    ("sweep", _cmd_sweep, "design-space exploration: latency, resources, energy and accuracy "
     "vs GTSAM per design, Pareto plot", "a design did not converge or failed", None),
)


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="fgc", description="fgc: a factor-graph compiler",
                     epilog="Run 'fgc COMMAND --help' for a command's options. Exit status: 0 "
                            "success, 1 verification failed (or a solve did not converge), 2 "
                            "bad input (one line on stderr).", formatter_class=_Formatter)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name, func, help_text, fails, json_help in _COMMANDS:
        epilog = ("exit status: 0 success" + (f", 1 {fails}" if fails else "")
                  + ", 2 bad input (one line on stderr)")
        p = sub.add_parser(name, help=help_text, description=f"fgc {name}: {help_text}",
                           epilog=epilog, formatter_class=_Formatter)
        _spec_args(p, json_help)
        _solver_args(p, design_space=name == "sweep")
        _command_args(name, p)
        p.set_defaults(func=func)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = None
    try:
        args = build_parser().parse_args(argv)
        return args.func(args)
    except UsageError as exc:
        print(str(exc), file=sys.stderr)
        return EXIT_BAD_INPUT
    except FgcError as exc:
        spec, text = getattr(args, "spec", None), str(exc)
        where = f"{spec}: " if spec and spec not in text else ""  # which spec, if not said
        print(f"fgc: error: {where}{text}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except BrokenPipeError:  # output piped into e.g. `head`: stop quietly, like other tools
        sys.stderr = open(os.devnull, "w")  # noqa: SIM115 - silence the interpreter's flush
        return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
