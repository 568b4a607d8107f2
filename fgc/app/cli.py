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

This module is the entry: the parser built from the command modules (fgc/app/commands/, one
per command: its options and its handler) and ``main``, which turns every error into one line
and an exit status.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path  # noqa: F401  (tests patch Path.write_text through this module)

from fgc import __version__
from fgc.app.commands import cache, metrics, report, run, simulate, stream, sweep, verify
from fgc.app.commands import compile as compile_command
from fgc.app.commands.options import (
    Formatter,
    Parser,
    UsageError,
    hardware_args,
    solver_args,
    spec_args,
    verbosity_args,
)
from fgc.app.commands.outputs import check_outputs
from fgc.app.commands.steps import (
    EXIT_BAD_INPUT,
    EXIT_FAILED,
    EXIT_INTERRUPTED,
    EXIT_OK,
    compile_spec,
    derive_with_progress,
    filename_note,
    parse_params,
    show_progress,
    solver_config,
)
from fgc.app.specs import load_spec
from fgc.errors import FgcError, caused_by_interrupt

__all__ = ["EXIT_BAD_INPUT", "EXIT_FAILED", "EXIT_INTERRUPTED", "EXIT_OK", "UsageError",
           "build_parser", "check_outputs", "derive_with_progress", "interrupted", "load_spec",
           "main", "parse_params", "solver_config"]

# the solver commands in the order ``fgc --help`` lists them (metrics and cache follow)
COMMANDS = (compile_command, simulate, verify, run, report, stream, sweep)

# each command's handler; build_parser reads these names when it runs (a test may replace one)
_cmd_compile, _cmd_simulate, _cmd_verify = (compile_command.cmd_compile, simulate.cmd_simulate,
                                            verify.cmd_verify)
_cmd_run, _cmd_report, _cmd_stream, _cmd_sweep = (run.cmd_run, report.cmd_report,
                                                  stream.cmd_stream, sweep.cmd_sweep)
_cmd_metrics, _cmd_cache = metrics.cmd_metrics, cache.cmd_cache
# the old private names, which tests call (test_cli_options.py, test_papers.py)
_show_progress, _compile = show_progress, compile_spec


def _handlers() -> dict:
    return {"compile": _cmd_compile, "simulate": _cmd_simulate, "verify": _cmd_verify,
            "run": _cmd_run, "report": _cmd_report, "stream": _cmd_stream, "sweep": _cmd_sweep,
            "metrics": _cmd_metrics, "cache": _cmd_cache}


def build_parser() -> argparse.ArgumentParser:
    parser = Parser(prog="fgc", description="fgc: a factor-graph compiler",
                    epilog="Run 'fgc COMMAND --help' for a command's options. Exit status: 0 "
                           "success, 1 verification failed (or a solve did not converge), 2 "
                           "bad input (one line on stderr).", formatter_class=Formatter)
    parser.add_argument("--version", action="version", version=f"fgc {__version__}")
    verbosity_args(parser, suppress=False)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    handlers = _handlers()
    for command in COMMANDS:
        name = command.NAME
        epilog = ("exit status: 0 success" + (f", 1 {command.FAILS}" if command.FAILS else "")
                  + ", 2 bad input (one line on stderr)")
        p = sub.add_parser(name, help=command.HELP, description=f"fgc {name}: {command.HELP}",
                           epilog=epilog, formatter_class=Formatter)
        spec_args(p, command.JSON_HELP)
        solver_args(p, design_space=name == "sweep")
        command.add_arguments(p)
        hardware_args(p, command.HARDWARE)
        verbosity_args(p, suppress=True)
        p.set_defaults(func=handlers[name])
    for command in (metrics, cache):
        command.add_parser(sub).set_defaults(func=handlers[command.NAME])
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
        _error_line(args, f"{exc.strerror or exc}{filename_note(exc)}")
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
