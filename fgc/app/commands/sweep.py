"""``fgc sweep SPEC --units … --cpe …``: design-space exploration (fgc.app.sweep), Pareto plot."""

from __future__ import annotations

import argparse
from pathlib import Path

from fgc.app import sweep
from fgc.app.commands.options import positive_int, scheduler_address
from fgc.app.commands.outputs import print_lines
from fgc.app.commands.steps import (
    EXIT_FAILED,
    EXIT_OK,
    Stages,
    clock_option,
    derive_with_progress,
    lm_limits,
    parse_params,
    project_name,
    show_progress,
)
from fgc.app.specs import load_spec
from fgc.ir.program import SolverConfig

NAME = "sweep"
HELP = ("design-space exploration: latency, resources, energy and accuracy vs GTSAM per "
        "design, Pareto plot")
FAILS = "a design did not converge or failed"
JSON_HELP = None
HARDWARE = None  # hardware_args: --clock only


def add_arguments(p) -> None:
    p.add_argument("--jobs", type=positive_int, metavar="N",
                   help="local worker processes (default: os.cpu_count())")
    p.add_argument("--executor", type=scheduler_address, metavar="ADDRESS",
                   help="run on the Dask scheduler at ADDRESS (tcp://host:port) instead")
    p.add_argument("--out", metavar="DIR",
                   help="folder for sweep.csv, sweep.json, pareto.png, accuracy.png "
                        "(default: fgc-sweep-NAME)")
    p.add_argument("--progress", action=argparse.BooleanOptionalAction,
                   help="progress bar on stderr (default: when stderr is a terminal)")
    sweep.add_fit_arguments(p)



def cmd_sweep(args) -> int:
    args.stages = Stages(args)
    graph = load_spec(args.spec, parse_params(args.param))
    args.stages.done("load spec")
    if derive_with_progress(graph, show_progress(args)):
        args.stages.done("derive (cold)")
    designs = sweep.design_space(args.units, args.cpe, args.precision, args.linear)
    base = SolverConfig(method=args.solver, ordering=args.ordering,
                        max_iterations=args.max_iterations, **clock_option(args),
                        **lm_limits(args))
    out = Path(args.out or f"fgc-sweep-{project_name(args.spec)}")
    with sweep.open_executor(args.jobs, args.executor) as pool, \
            sweep.progress_bar(len(designs), args.progress) as progress:
        result = sweep.run_sweep(graph, base, designs, pool, project_name(args.spec), progress,
                                 **sweep.fit_options(args, show_progress(args)))
    files = sweep.write_outputs(result, out, title=project_name(args.spec))
    print_lines(args, [*sweep.summary_lines(result, args.spec),
                  f"wrote {', '.join(str(f) for f in files)}"])
    failed = [r for r in result.rows if r["status"] != "converged"]
    return EXIT_FAILED if failed else EXIT_OK
