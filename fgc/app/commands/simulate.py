"""``fgc simulate SPEC``: the accelerator simulator's solve, cycles and resources (the HLS
design's plan); with --window / --incremental the stream's per-update prices."""

from __future__ import annotations

from fgc.app import run_report
from fgc.app.commands.options import UsageError, marginals_arg, streaming_args, values_arg
from fgc.app.commands.outputs import estimates_out, print_lines, write_json
from fgc.app.commands.steps import (
    EXIT_FAILED,
    EXIT_OK,
    WithProgress,
    compile_spec,
    filename_note,
    is_streaming,
    load_backend,
    plan_options,
    progress_display,
)
from fgc.app.commands.stream import cmd_stream
from fgc.errors import FgcError

NAME = "simulate"
HELP = "run the accelerator simulator: numbers, cycles, resources"
FAILS = "the simulator did not converge"
JSON_HELP = "also write the report as JSON"
HARDWARE = "priced"  # hardware_args: the HLS design whose plan is priced


def add_arguments(p) -> None:
    streaming_args(p)
    values_arg(p)
    marginals_arg(p)
    p.add_argument("--plot", metavar="DIR", help="write plots (needs matplotlib)")



def cmd_simulate(args) -> int:
    if is_streaming(args):
        for flag in ("part", "allocation", "unit_sets", "qr_unit", "hgc_before",
                     "cascade_lanes", "backsub_lanes", "qr_rows", "bind"):
            if getattr(args, flag, None):
                raise UsageError(f"fgc simulate: --{flag.replace('_', '-')} shapes the batch "
                                 "design; the stream's update model prices the Program's own "
                                 "(drop it, or simulate without --incremental / --window)")
        return cmd_stream(args)
    graph, program, data = compile_spec(args, "float32")
    try:
        display = progress_display(args, f"simulate {args.spec}", program, simulator=True)
        sim = WithProgress(load_backend("sim"), display)
        report = run_report.simulate_report(graph, program, data, sim, plot_dir=args.plot,
                                            plan_options=plan_options(args, program))
    except OSError as exc:
        if not args.plot or not str(getattr(exc, "filename", "")).startswith(args.plot):
            raise
        raise FgcError(f"--plot {args.plot}: cannot write the plots: "
                       f"{exc.strerror or exc}{filename_note(exc)}") from None
    print_lines(args, report.pop("summary"))
    estimates_out(args, graph, report, report.pop("_result_values"))
    report["progress"] = display.records
    write_json(args.json, report)
    return EXIT_OK if report["status"] == "converged" else EXIT_FAILED
