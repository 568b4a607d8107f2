"""``fgc report SPEC``: the compiled design at a glance (text, --json, --html); with --window /
--incremental the stream design's per-update price."""

from __future__ import annotations

from fgc.app.commands.options import UsageError, positive_int, streaming_args
from fgc.app.commands.outputs import print_lines, write_json, write_text
from fgc.app.commands.steps import (
    EXIT_OK,
    compile_spec,
    is_streaming,
    load_backend,
    parse_params,
    plan_options,
)
from fgc.app.commands.stream import cmd_stream
from fgc.app.design_report import design_report, figures, format_text, render_html

NAME = "report"
HELP = ("the compiled design at a glance: blocks, schedule, storage, cycles, resources, "
        "energy")
FAILS = None
JSON_HELP = "also write the report as JSON"
HARDWARE = "priced"  # hardware_args: the HLS design whose plan is priced


def add_arguments(p) -> None:
    streaming_args(p, window=False)
    p.add_argument("--html", metavar="FILE", help="also write a self-contained HTML page")
    p.add_argument("--iterations", type=positive_int, metavar="K",
                   help="cost K iterations instead of running the simulator")



def cmd_report(args) -> int:
    if is_streaming(args):
        return _report_stream(args)
    graph, program, data = compile_spec(args, "float32")
    report = design_report(args.spec, parse_params(args.param), graph, program, data,
                           load_backend("sim"), iterations=args.iterations,
                           plan_options=plan_options(args, program))
    c = report["cost"]
    fits = "fits" if c["fits"] else "does NOT fit"
    print_lines(args, format_text(report).rstrip("\n").split("\n"),
           f"fgc report {args.spec}: {c['cycles']:,} cycles = {c['latency_ms']:.3f} ms at "
           f"{c['clock_mhz']:g} MHz, {c['resources']['dsp']} DSP, {fits} {c['device']} "
           "(model estimate)")
    write_json(args.json, report)
    if args.html:
        write_text(args.html, render_html(report, figures(report)), "--html")
    return EXIT_OK


def _report_stream(args) -> int:
    """``fgc report --window W | --incremental K``: the design ``fgc compile --backend hls``
    emits for the stream, priced per update on the simulator's updates (``fgc stream --backend
    hls --model-only``): the on-chip design for a QR Program, the host-kept path's update model
    for Cholesky; its DSP and BRAM."""
    if getattr(args, "html", None):
        raise UsageError("fgc report --html renders batch designs; a stream's per-update report "
                         "is text and --json")
    for flag in ("part", "allocation", "unit_sets", "qr_unit", "hgc_before", "cascade_lanes",
                 "backsub_lanes", "qr_rows", "scalar", "bind"):
        if getattr(args, flag, None):
            raise UsageError(f"fgc report: --{flag.replace('_', '-')} shapes the batch design; "
                             "the stream's design is priced on the Program's own")
    args.backend, args.model_only = "hls", True
    return cmd_stream(args, precision_default="float32")
