"""The command line's shared options: argparse types (each rejects bad text with one line), the
option groups several commands take (spec, solver, keyframe-by-keyframe, hardware, -v/-q) and
the parser and help formatter every command uses. A command's own options are in its module."""

from __future__ import annotations

import argparse
import re
from collections.abc import Callable
from typing import NoReturn

import numpy as np

from fgc.errors import FgcError
from fgc.ir.codes import ORDERINGS
from fgc_backends.cfamily.errors import CodegenError
from fgc_backends.cfamily.scalars import check_scalar


class UsageError(FgcError):
    """A command line argparse rejects (reported as one line, exit 2)."""


class Parser(argparse.ArgumentParser):
    """argparse, but a bad argument is one line on stderr (via main), not usage + exit."""

    def error(self, message: str) -> NoReturn:
        raise UsageError(f"{self.prog}: {message} (see {self.prog} --help)")


class Formatter(argparse.RawDescriptionHelpFormatter):
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


def positive_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a positive number, got {text!r}") from None
    if not (value > 0 and np.isfinite(value)):
        raise argparse.ArgumentTypeError(f"expected a positive finite number, got {text!r}")
    return value


def positive_int(text: str) -> int:
    if not text.strip().isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive integer")
    return int(text)


def int_list(text: str) -> tuple[int, ...]:
    """``"1,2,4"`` → ``(1, 2, 4)`` (positive, duplicates dropped)."""
    items = [s.strip() for s in text.split(",")]
    if not all(s.isdigit() and int(s) >= 1 for s in items):
        raise argparse.ArgumentTypeError(
            f"{text!r} is not a comma-separated list of positive integers (e.g. 1,2,4,8)")
    return tuple(dict.fromkeys(int(s) for s in items))


def choice_list(choices: tuple[str, ...]) -> Callable[[str], tuple[str, ...]]:
    """An argparse type for a comma-separated subset of ``choices``."""

    def parse(text: str) -> tuple[str, ...]:
        items = [s.strip() for s in text.split(",")]
        bad = [s for s in items if s not in choices]
        if bad:
            raise argparse.ArgumentTypeError(
                f"{text!r}: {', '.join(repr(b) for b in bad)} not among {', '.join(choices)}")
        return tuple(dict.fromkeys(items))

    return parse


def scheduler_address(text: str) -> str:
    if not re.fullmatch(r"[a-z]+://[^\s/]+:[0-9]+", text):
        raise argparse.ArgumentTypeError(f"{text!r} is not a scheduler address like "
                                         "tcp://host:8786")
    return text


def clock_arg(text: str) -> tuple[float, float]:
    """``--clock``: MHz or ns → (MHz, ns)."""
    # the HLS backend is imported when an option needs it, not for every command: it adds about
    # a second to start-up (python bench/import_graph.py --startup fgc_backends.hls)
    from fgc_backends.hls.config import HlsConfigError, parse_clock

    try:
        return parse_clock(text)
    except HlsConfigError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def scalar_arg(text: str) -> str:
    text = re.sub(r"\s+", "", text)
    try:
        return check_scalar(text)
    except CodegenError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def allocation_arg(text: str) -> tuple[tuple[str, int], ...]:
    from fgc_backends.hls.plan import DEFAULT_ALLOCATION  # when used (see clock_arg)

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


def bind_arg(text: str) -> tuple[tuple[str, str], ...]:
    """``--bind``: the floating-point operators' binding, ``add=fabric,mul=meddsp`` (or
    ``default``), as ``DesignOptions.bind`` takes it."""
    from fgc_backends.cost.operators import BindError, parse_bind  # when used (see clock_arg)

    try:
        return parse_bind(text)
    except BindError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def backsub_lanes_arg(text: str) -> int | None:
    """``--backsub-lanes``: ``auto`` (None: the design decides, ``DesignOptions.backsub_lanes``)
    or a width, 1, 2 or 4."""
    text = text.strip().lower()
    if text == "auto":
        return None
    if text not in ("1", "2", "4"):
        raise argparse.ArgumentTypeError(f"{text!r}: expected auto, 1, 2 or 4")
    return int(text)


def part_arg(text: str) -> str:
    if not re.fullmatch(r"[A-Za-z0-9_-]{1,64}", text):
        raise argparse.ArgumentTypeError(f"FPGA part {text!r} is not a plain part name "
                                         "(letters, digits, - and _)")
    return text


def batch_every_arg(text: str):
    """``--batch-every``: ``10`` → a period, ``5,15,25`` → those keyframes."""
    if "," not in text:
        return positive_int(text)
    items = [s.strip() for s in text.split(",") if s.strip()]
    if not items or not all(s.isdigit() for s in items):
        raise argparse.ArgumentTypeError(f"{text!r} is not a period or a comma-separated list "
                                         "of keyframe indices (e.g. 5,15,25)")
    return tuple(sorted({int(s) for s in items}))


def verbosity_args(p: argparse.ArgumentParser, suppress: bool) -> None:
    """-v / -q, on the main parser and again on each command (so they go either side of it;
    a command's copy must not reset what the main parser set, hence SUPPRESS there)."""
    v = p.add_mutually_exclusive_group()
    v.add_argument("-v", "--verbose", action="count",
                   default=argparse.SUPPRESS if suppress else 0,
                   help="stage timings and derivation progress on stderr")
    v.add_argument("-q", "--quiet", action="store_true",
                   default=argparse.SUPPRESS if suppress else False,
                   help="print only the result line")


def hardware_args(p: argparse.ArgumentParser, design: str | None) -> None:
    """--clock; with ``design`` also the HLS design's --part, --scalar, --allocation,
    --unit-sets, --qr-unit and --hgc-before: ``"emitted"`` (compile, run: the design built)
    or ``"priced"`` (simulate, report: the design whose plan is priced)."""
    h = p.add_argument_group("hardware (the cost model's figures are model estimates)")
    h.add_argument("--clock", type=clock_arg, metavar="F",
                   help="accelerator clock, e.g. 143MHz or 7ns (a bare number ≥ 20 is MHz): "
                        "the cost model's clock and, for --backend hls, run_hls.tcl's period "
                        "(default: 143 MHz; run_hls.tcl 7 ns)")
    if design is not None:
        priced = design == "priced"
        where = ("the design priced: the HLS design that fgc compile --backend hls emits with "
                 "the same flags" if priced else "--backend hls")
        h.add_argument("--part", type=part_arg, metavar="PART",
                       help=("FPGA part whose capacities the plan's fit verdict uses" if priced
                             else "FPGA part for run_hls.tcl, --backend hls only")
                            + " (default: xc7z045ffg900-2); the plan's fit verdict and the lint's "
                            "DSP budget use its device's capacities (backends/hls/target.py)")
        h.add_argument("--scalar", type=scalar_arg, metavar="T",
                       help=("C++ scalar of the priced HLS design: float or double (implies "
                             "--precision; the dataflow design has no fixed-point operator table)"
                             if priced else
                             "C++ scalar of the HLS accelerator or native solver: float, double "
                             "or ap_fixed<W,I> (2 ≤ W ≤ 1024, 1 ≤ I ≤ W; needs fgc[hls-fixed])")
                            + " (default: from --precision)")
        h.add_argument("--allocation", type=allocation_arg, metavar="KIND=N,…",
                       help=f"{where}: the factor datapaths' ALLOCATION limits, e.g. "
                            "mul=48,add=32 (kinds add, mul, div, sqrt, trig, special; the others "
                            "keep the defaults add 16, mul 24, div 4, sqrt 2, trig 2, special 2); "
                            "each block type gets a share by its instance count")
        h.add_argument("--bind", type=bind_arg, metavar="KIND=IMPL,…",
                       help=f"{where}: the floating-point operators' binding (run_hls.tcl's "
                            "config_op), e.g. add=fabric,mul=meddsp: add fulldsp (default) or "
                            "fabric, mul maxdsp (default), fulldsp, meddsp or fabric; fewer DSP "
                            "for more LUT and FF, the same cycles")
        h.add_argument("--unit-sets", type=positive_int, metavar="S",
                       help=f"{where}: unit sets eliminating a level's steps side by side, "
                            "1 … 8 (default: 2 on a two-ended chain, else 1); Cholesky: 1 or 2 "
                            "cascades (default 1)")
        h.add_argument("--cascade-lanes", type=int, choices=(1, 2), metavar="L",
                       help=f"{where}: Cholesky: words a cycle through each cascade, 1 (the "
                            "default) or 2 (every CPE two words a cycle: half a step's cycles "
                            "in the cascade, twice its multipliers and adders)")
        h.add_argument("--backsub-lanes", type=backsub_lanes_arg, metavar="auto|1|2|4",
                       help=f"{where}: back-substitution's width: auto (the default: 4 where "
                            "the elimination tree is a chain, 1 on a tree and in the streaming "
                            "designs), 1 (a step's conditional two words a cycle, one row a "
                            "cycle), 2 (COND in two banks, two rows a cycle) or 4 (by columns, "
                            "a process per end of a chain; refused on a tree)")
        h.add_argument("--qr-rows", type=int, choices=(1, 2), metavar="R",
                       help=f"{where}: QR (householder): rows a cycle through each Update unit, "
                            "1 (the default) or 2 (the reflection's vector in two lanes by row "
                            "parity: about half a unit's cycles a reflection, at 2 more adders "
                            "and multipliers a unit)")
        h.add_argument("--data-width", type=int, choices=(32, 64), metavar="BITS",
                       help=f"{where}: the streaming top's data port (--window / "
                            "--incremental, float): 32 bits a beat (the default, a word) or 64 "
                            "(two float words a beat, a Zynq HP port's width; the host packs "
                            "them): the update's start takes the keyframe's words two a cycle")
        h.add_argument("--qr-unit", choices=("householder", "stream"),
                       help=f"{where}: the QR unit set: householder (paper A's, one DATAFLOW "
                            "region per reflection; the default) or stream (n_u reflection "
                            "stages the matrix streams through)")
        h.add_argument("--hgc-before", action="store_true",
                       help=f"{where}: Cholesky only: every block type's Hessian/gradient (HGC) "
                            "region runs before the elimination (DesignOptions.hgc_beside off); "
                            "the default streams the longest one's Grams beside the elimination "
                            "(docs/hls.md). Refused for QR, for a wider --linear-precision "
                            "(its HGC is before already) and for --window / --incremental")


def spec_args(p: argparse.ArgumentParser, json_help: str | None) -> None:
    p.add_argument("spec", help="spec file (.py with build(**params)) or a g2o/TORO file")
    p.add_argument("-p", "--param", action="append", default=[], metavar="KEY=VALUE",
                   help="parameter passed to the spec's build() (repeatable)")
    if json_help:
        p.add_argument("--json", metavar="FILE", help=json_help)


def solver_args(p: argparse.ArgumentParser, design_space: bool) -> None:
    s = p.add_argument_group("solver")
    s.add_argument("--solver", choices=("gn", "lm"), default="lm", help="Gauss-Newton or LM")
    s.add_argument("--ordering", default="auto",
                   choices=ORDERINGS,
                   help="elimination ordering (auto = two-ended on chains, min-degree "
                        "otherwise; natural = declaration order)")
    s.add_argument("--max-iterations", type=positive_int, default=100, metavar="K",
                   help="k_max")
    s.add_argument("--lambda-upper-bound", type=positive_float, metavar="X",
                   help="LM gives up (failed, lambda_limit) when its damping would pass X "
                        "(default 1e10; an ap_fixed<W,I> scalar must hold it)")
    if design_space:
        d = p.add_argument_group("design space (comma-separated lists; the product is swept)")
        d.add_argument("--linear", type=choice_list(("qr", "cholesky")), metavar="LIST",
                       default=("qr", "cholesky"), help="linear solvers: qr, cholesky")
        d.add_argument("--precision", type=choice_list(("float32", "float64")),
                       metavar="LIST", default=("float32", "float64"),
                       help="arithmetic of the accelerator: float32, float64")
        d.add_argument("--units", type=int_list, default=(1, 2, 4, 8), metavar="LIST",
                       help="n_u Update units per QR block (QR designs)")
        d.add_argument("--cpe", type=int_list, default=(5, 20, 40, 80, 120), metavar="LIST",
                       help="#CPE Cholesky process elements (Cholesky designs)")
        return
    s.add_argument("--linear", choices=("qr", "cholesky"), default="qr", help="linear solver")
    s.add_argument("--precision", choices=("float32", "float64"),
                   help="arithmetic of the accelerator (default: float32; verify and the "
                        "keyframe-by-keyframe modes: float64)")
    s.add_argument("--linear-precision", choices=("float32", "float64"),
                   help="widen the linear solver alone (default: --precision); float32 with a "
                        "float64 solver suits ill-conditioned Cholesky problems")
    s.add_argument("--units", type=positive_int, default=4, metavar="N",
                   help="n_u Update units per QR block")
    s.add_argument("--cpe", type=positive_int, default=20, metavar="N",
                   help="#CPE Cholesky process elements")


def streaming_args(p: argparse.ArgumentParser, window: bool = True) -> None:
    """--incremental and --batch-every, and --window unless ``window`` is False (report)."""
    g = p.add_argument_group("keyframe by keyframe (the simulator; fgc stream --backend native "
                             "or hls solves each update in compiled code; issue 19)")
    g.add_argument("--incremental", type=positive_int, metavar="K",
                   help="incremental smoothing: each keyframe re-eliminates the newest K "
                        "clusters (SolverConfig.incremental_k)")
    g.add_argument("--batch-every", type=batch_every_arg, metavar="B",
                   help="batch steps of the incremental plan: a period (10) or keyframe "
                        "indices (5,15,25; one keyframe: 5,) (SolverConfig.batch_every)")
    if window:
        g.add_argument("--window", type=positive_int, metavar="W",
                       help="fixed-lag window: hold the newest W keyframes, marginalise the "
                            "one leaving into a prior on the window")


def values_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument("--values", metavar="FILE",
                   help="write the optimised values: .g2o, .tum/.txt (TUM poses, t = key "
                        "order index) or .csv, by extension")


def marginals_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument("--marginals", metavar="KEY,KEY",
                   help="print (and put in --json) the marginal covariances of these "
                        "variables at the estimate")
