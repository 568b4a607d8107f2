"""What a command writes: its lines on stdout (only the result line under ``-q``), the files
the user named (--json, --html, --values; checked writable before the solve starts) and the
estimates and marginals a solve reports."""

from __future__ import annotations

import json
import os
from pathlib import Path

from fgc.app.marginals import marginal_covariances, parse_keys
from fgc.errors import FgcError
from fgc.frontend.dsl import Graph
from fgc.interop import estimates as export
from fgc.interop.estimates import FORMATS


def print_lines(args, lines: list[str], result: str | None = None) -> None:
    """``lines`` to stdout, or only ``result`` (default: the first line) under ``-q``."""
    if getattr(args, "quiet", False):
        print(result if result is not None else lines[0])
    else:
        print("\n".join(lines))
    stages = getattr(args, "stages", None)
    if stages is not None:
        stages.done(args.command)


def write_json(path: str | None, report: dict) -> None:
    if path:
        write_text(path, json.dumps(report, indent=2, sort_keys=True) + "\n", "--json")


def write_text(path: str, text: str, option: str) -> None:
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
    if getattr(args, "values", None) and Path(args.values).suffix.lower() not in FORMATS:
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


def estimates_out(args, graph: Graph, report: dict, result_values: dict) -> None:
    """Keyed values into the JSON report; --values file; --marginals printed and reported."""
    values = export.graph_values(graph, result_values)
    report["values"] = export.values_json(values)
    quiet = getattr(args, "quiet", False)
    if getattr(args, "values", None):
        fmt = export.write_values(args.values, values)
        if not quiet:
            print(f"  estimates → {args.values} ({fmt})")
    if getattr(args, "marginals", None):
        covs = marginal_covariances(graph, parse_keys(args.marginals, graph), values)
        report["marginals"] = {str(k): {"key": k, "covariance": c.tolist()}
                               for k, c in covs.items()}
        for k, c in covs.items() if not quiet else ():
            print(f"  marginal covariance of {k!r} (diagonal): "
                  + " ".join(f"{x:.6g}" for x in c.diagonal()))
