"""``fgc run SPEC --backend native|sim|hls``: solve with the generated solver and report its
status, error and times."""

from __future__ import annotations

import sys
import time

from fgc.app.commands.options import UsageError, marginals_arg, streaming_args, values_arg
from fgc.app.commands.outputs import estimates_out, print_lines, write_json
from fgc.app.commands.steps import (
    EXIT_FAILED,
    EXIT_OK,
    backend_help,
    backend_names,
    compile_spec,
    hls_config,
    is_streaming,
    load_backend,
    native_config,
    progress_display,
    refuse_hls_design,
)
from fgc.app.commands.stream import cmd_stream
from fgc.app.run_report import final_error_text, float64_error, require_finite_start, status_text

NAME = "run"
HELP = ("solve with the generated native solver (or the simulator, or the HLS accelerator's C "
        "simulation: --backend sim|hls)")
FAILS = "the solve did not converge"
JSON_HELP = "also write the report as JSON"
HARDWARE = "emitted"  # hardware_args: the HLS design this command builds


def add_arguments(p) -> None:
    streaming_args(p)
    values_arg(p)
    marginals_arg(p)
    p.add_argument("--backend", choices=backend_names(), default="native",
                   help="solver (hls: the accelerator's C simulation): " + backend_help())



def cmd_run(args) -> int:
    if is_streaming(args):
        if getattr(args, "hgc_before", False):
            raise UsageError("fgc run: --hgc-before shapes the batch Cholesky design; the "
                             "stream's design (--window / --incremental) has no HGC beside its "
                             "elimination (drop --hgc-before)")
        if getattr(args, "backsub_lanes", None) not in (None, 1):
            raise UsageError(f"fgc run: --backsub-lanes {args.backsub_lanes}: the stream's "
                             "design (--window / --incremental) back-substitutes one lane "
                             "(drop it, or --backsub-lanes auto)")
        return cmd_stream(args)
    graph, program, data = compile_spec(args, "float32")
    t0 = time.perf_counter()
    display = progress_display(args, f"run {args.spec}", program, simulator=args.backend == "sim")
    timings: dict = {}
    if args.backend == "native":
        config = native_config(args, program)
        if not getattr(args, "quiet", False) and sys.stderr.isatty():
            print(f"fgc run: building or loading the native library "
                  f"({len(program.variables)} variables; a first build runs g++: seconds to "
                  "minutes for a large graph)…", file=sys.stderr, flush=True)
        result = load_backend("native").run(program, data, config, progress=display,
                                        timings=timings)
    elif args.backend == "hls":  # the accelerator's C simulation (make csim), g++ on this host
        result = load_backend("hls").run(program, data, hls_config(args, program))
    else:
        if getattr(args, "scalar", None) or getattr(args, "part", None):
            raise UsageError("fgc run: --scalar applies to --backend native or hls, --part to "
                             "--backend hls; the simulator runs float32 or float64 (--precision)")
        refuse_hls_design(args, "sim")
        result = load_backend("sim").run(program, data, progress=display)
        timings = {"setup_seconds": result.setup_seconds, "solve_seconds": result.solve_seconds}
    display.finish()
    status, final, iters = result.status, result.final_error, result.iterations
    seconds = time.perf_counter() - t0

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
    print_lines(args, lines)
    estimates_out(args, graph, report, result.values)  # fgc values by Program key
    write_json(args.json, report)
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
