"""The ``fgc`` command line.

    fgc compile  SPEC --backend sim|hls --out DIR     emit a backend project (+ program.json, data)
    fgc simulate SPEC [--json F]                      run the accelerator simulator, report cost
    fgc verify   SPEC [--json F]                      simulator vs GTSAM's LM, exit 1 on mismatch
    fgc run      SPEC --backend native|sim            solve with the generated solver

SPEC is a ``.py`` file with ``build(**params)`` returning an ``fgc.Graph`` (``-p KEY=VALUE``), or a
g2o/TORO file. Solver options are shared by every command. Exit codes: 0 success, 1 verification
failed, 2 bad input (one clear line on stderr).
"""

from __future__ import annotations

import argparse
import ast
import importlib.util
import json
import sys
from pathlib import Path

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
    (which gets a prior on its first pose to fix the gauge)."""
    p = Path(path)
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
    try:
        graph = build(**params)
    except TypeError as exc:
        raise FgcError(f"{path}: build() rejected the parameters {sorted(params)}: {exc}") from exc
    if not isinstance(graph, Graph):
        raise FgcError(f"{path}: build() returned {type(graph).__name__}, not an fgc.Graph")
    return graph


def _load_pose_graph_file(p: Path, params: dict) -> Graph:
    from fgc import noise
    from fgc.factors import PriorFactor
    from fgc.io import read_pose_graph

    unknown = sorted(set(params) - {"prior_sigma"})
    if unknown:
        raise FgcError(f"{p}: unknown parameters {unknown} for a g2o/TORO file "
                       "(only prior_sigma)")
    graph = read_pose_graph(p)
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
                        precision=args.precision or precision_default, units=args.units,
                        cpe=args.cpe, max_iterations=args.max_iterations)


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
    _write_json(args.json, report)
    return EXIT_OK if report["status"] == "converged" else EXIT_FAILED


def _cmd_verify(args) -> int:
    from fgc.reporting import verify_report

    graph, program, data = _compile(args, "float64")
    report = verify_report(graph, program, data, _backend("sim"))
    for line in report.pop("summary"):
        print(line)
    _write_json(args.json, report)
    return EXIT_OK if report["passed"] else EXIT_FAILED


def _cmd_run(args) -> int:
    graph, program, data = _compile(args, "float32")
    if args.backend == "native":
        hls = _backend("hls")
        result = hls.native.run(program, data, hls.native.default_config(program))
        status, final, iters = result.status, result.final_error, result.iterations
    else:
        result = _backend("sim").run(program, data)
        status, final, iters = result.status, result.final_error, result.iterations
    report = {"backend": args.backend, "status": status, "final_error": final,
              "iterations": iters}
    print(f"fgc run {args.spec} ({args.backend}): {status}, {iters} iterations, "
          f"final error {final:.10g}")
    _write_json(args.json, report)
    return EXIT_OK if status == "converged" else EXIT_FAILED


# --------------------------------------------------------------------------------------------
# parser
# --------------------------------------------------------------------------------------------


def _common(p: argparse.ArgumentParser) -> None:
    p.add_argument("spec", help="spec file (.py with build(**params)) or a g2o/TORO file")
    p.add_argument("-p", "--param", action="append", default=[], metavar="KEY=VALUE",
                   help="parameter passed to the spec's build() (repeatable)")
    p.add_argument("--json", metavar="FILE", help="also write the report as JSON")
    s = p.add_argument_group("solver")
    s.add_argument("--solver", choices=("gn", "lm"), default="lm", help="default: lm")
    s.add_argument("--linear", choices=("qr", "cholesky"), default="qr", help="default: qr")
    s.add_argument("--ordering", default="auto",
                   choices=("auto", "two-ended", "serial", "min-degree", "nested-dissection"),
                   help="elimination ordering (default: auto = two-ended on chains)")
    s.add_argument("--precision", choices=("float32", "float64"),
                   help="arithmetic of the accelerator (default: float32; verify: float64)")
    s.add_argument("--units", type=int, default=4, help="n_u Update units per QR block")
    s.add_argument("--cpe", type=int, default=20, help="#CPE Cholesky process elements")
    s.add_argument("--max-iterations", type=int, default=100, help="k_max (default 100)")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="fgc", description="fgc: a factor-graph compiler")
    sub = parser.add_subparsers(dest="command", required=True)
    commands = (
        ("compile", _cmd_compile, "emit a backend project for a spec"),
        ("simulate", _cmd_simulate, "run the accelerator simulator: numbers, cycles, resources"),
        ("verify", _cmd_verify, "solve with the simulator and with GTSAM and compare"),
        ("run", _cmd_run, "solve with the generated native solver (or the simulator)"),
    )
    for name, func, help_text in commands:
        p = sub.add_parser(name, help=help_text, description=help_text)
        _common(p)
        if name == "compile":
            p.add_argument("--backend", choices=("sim", "hls"), default="sim")
            p.add_argument("--out", required=True, metavar="DIR", help="output folder")
        if name == "run":
            p.add_argument("--backend", choices=("native", "sim"), default="native")
        if name == "simulate":
            p.add_argument("--plot", metavar="DIR", help="write plots (needs matplotlib)")
        p.set_defaults(func=func)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except FgcError as exc:
        print(f"fgc: error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT


if __name__ == "__main__":
    sys.exit(main())
