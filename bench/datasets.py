"""Every file in the gtsam wheel's data folder that GTSAM's readers accept: factor counts fgc vs
GTSAM, and with ``--verify`` what ``fgc verify`` says (float64 simulator vs GTSAM's LM).

    python bench/datasets.py [--verify [--timeout S] [--skip-verify-over N]]
                             [--only FILE ...] [--verify-arg=ARG ...] [--out table.md]

A file is listed when ``gtsam.load2D`` or ``gtsam.load3D`` returns at least one factor. fgc's
column is ``fgc.interop.datasets.read_pose_graph``'s factor count (it adds no factor: the gauge
prior of
``fgc verify`` comes later), or the reason it refuses the file. The verify column runs
``fgc verify FILE`` in a subprocess per file (exit 0 PASSED / 1 FAILED / 2 error), stopped after
``--timeout`` seconds; it gives the verdict, the wall and CPU time of that run (on a shared
machine wall time says little), the state difference and, unless the states simply match,
the verdict's reason. ``--skip-verify-over N`` leaves files with more than N factors out of the
verify column; ``--only`` runs the named files alone (one large file at a time); ``--verify-arg``
passes an argument on to ``fgc verify`` (``--verify-arg=-p --verify-arg=init=chordal``).
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import time

import gtsam

from fgc.errors import FgcError
from fgc.interop.datasets import read_pose_graph
from fgc.interop.gtsam_data import gtsam_data_dir
from fgc.interop.to_gtsam import value_to_gtsam

VERIFY = "import sys; from fgc.app.cli import main; sys.exit(main(sys.argv[1:]))"


def fgc_error_in_gtsam(graph, problem, result) -> float:
    """GTSAM's error of its own graph at fgc's solution (``problem``: ``to_gtsam(graph)``;
    bench_native.py and bench_large.py compare the two solvers' optima with it)."""
    values = gtsam.Values()
    for key, var in graph.variables.items():
        value = type(var.initial).from_storage(result.values[str(key)])
        values.insert(problem.keys[key], value_to_gtsam(value))
    return problem.graph.error(values)


def gtsam_count(path: str) -> tuple[str, int] | None:
    for name, reader in (("load2D", gtsam.load2D), ("load3D", gtsam.load3D)):
        try:
            graph, _ = reader(path)
        except (RuntimeError, ValueError):  # GTSAM raises both for files it rejects
            continue
        if graph.size():
            return name, int(graph.size())
    return None


def _cpu_of_children() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def verify(path: str, timeout: float, extra: list[str]) -> str:
    """The verify cell of one file: verdict (wall s, CPU s; state difference[; reason])."""
    cpu0, t0 = _cpu_of_children(), time.perf_counter()
    try:
        proc = subprocess.run([sys.executable, "-c", VERIFY, "verify", path, *extra],
                              capture_output=True, text=True, timeout=timeout, check=False)
    except subprocess.TimeoutExpired:
        return (f"not finished: stopped after {timeout:.0f} s wall "
                f"({_cpu_of_children() - cpu0:.0f} s CPU)")
    times = f"{time.perf_counter() - t0:.0f} s wall, {_cpu_of_children() - cpu0:.0f} s CPU"
    lines = [ln.strip() for ln in proc.stdout.splitlines()]
    if proc.returncode not in (0, 1):
        last = (proc.stderr.strip().splitlines() or ["(no message)"])[-1]
        return f"error (exit {proc.returncode}, {times}): {last[:160]}"
    state = next((ln for ln in lines if ln.startswith("max state")), "")
    cell = f"{'PASSED' if proc.returncode == 0 else 'FAILED'} ({times}; {state})"
    verdict = next((ln for ln in reversed(lines) if ln.startswith(("PASSED", "FAILED"))), "")
    if not (verdict.startswith("PASSED: fgc converged")
            and "its answer matches GTSAM's" in verdict):  # say why, unless plain
        cell += f" — {verdict[:400]}"
    return cell


def _row(cells: list[str]) -> str:
    """A Markdown table row; a cell's own "|" and newlines cannot split it."""
    return "| " + " | ".join(c.replace("|", "\\|").replace("\n", " ") for c in cells) + " |"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--verify", action="store_true", help="run fgc verify per file")
    ap.add_argument("--timeout", type=float, default=900.0,
                    help="seconds per verify run (default 900)")
    ap.add_argument("--skip-verify-over", type=int, default=None, metavar="N")
    ap.add_argument("--only", action="append", default=[], metavar="FILE",
                    help="only this data file (repeatable)")
    ap.add_argument("--verify-arg", action="append", default=[], metavar="ARG")
    ap.add_argument("--out")
    args = ap.parse_args()
    names = sorted(os.listdir(gtsam_data_dir()))
    unknown = sorted(set(args.only) - set(names))
    if unknown:
        ap.error(f"not in {gtsam_data_dir()}: {', '.join(unknown)}")
    header = "| file | GTSAM reader | GTSAM factors | fgc factors |"
    rows = [header + (" `fgc verify` |" if args.verify else ""),
            "|---|---|---|---|" + ("---|" if args.verify else "")]
    print("\n".join(rows), flush=True)
    for name in names:
        if args.only and name not in args.only:
            continue
        path = str(gtsam_data_dir() / name)
        counted = gtsam_count(path)
        if counted is None:
            continue
        reader, n_gtsam = counted
        try:
            fgc_cell = str(len(read_pose_graph(path).factors))
            ok = True
        except FgcError as exc:
            fgc_cell, ok = f"refused: {str(exc).split(': ', 1)[-1][:110]}", False
        cells = [name, reader, str(n_gtsam), fgc_cell]
        if args.verify:
            if not ok:
                cells.append("— (refused)")
            elif args.skip_verify_over is not None and n_gtsam > args.skip_verify_over:
                cells.append(f"not run (> {args.skip_verify_over} factors)")
            else:
                cells.append(verify(path, args.timeout, args.verify_arg))
        rows.append(_row(cells))
        print(rows[-1], flush=True)
    if args.out:
        with open(args.out, "w") as fh:
            fh.write("\n".join(rows) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
