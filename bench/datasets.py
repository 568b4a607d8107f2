"""Every file in the gtsam wheel's data folder that GTSAM's readers accept: factor counts fgc vs
GTSAM and what ``fgc verify`` says (float64 simulator vs GTSAM's LM).

    python bench/datasets.py [--no-verify] [--skip-verify-over N] [--out docs/datasets.md]

A file is listed when ``gtsam.load2D`` or ``gtsam.load3D`` returns at least one factor. fgc's
column is ``fgc.io.read_pose_graph``'s factor count, or the reason it refuses the file. The
verify column is the verdict on this branch (exit 0 PASSED / 1 FAILED / 2 error) with its wall
time; ``--skip-verify-over N`` skips files with more than N factors (their cell says so).
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import sys
import time

import gtsam

from fgc.cli import main as cli_main
from fgc.data import gtsam_data_dir
from fgc.errors import FgcError
from fgc.io import read_pose_graph


def gtsam_count(path: str) -> tuple[str, int] | None:
    for name, reader in (("load2D", gtsam.load2D), ("load3D", gtsam.load3D)):
        try:
            graph, _ = reader(path)
        except (RuntimeError, ValueError):  # GTSAM raises both for files it rejects
            continue
        if graph.size():
            return name, int(graph.size())
    return None


def verify(name: str) -> str:
    out, err = io.StringIO(), io.StringIO()
    t0 = time.perf_counter()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli_main(["verify", name])
    dt = time.perf_counter() - t0
    if code == 2:
        return f"error: {err.getvalue().strip()[:120]}"
    lines = [ln.strip() for ln in out.getvalue().splitlines()]
    state = next((ln for ln in lines if ln.startswith("max state")), "")
    return f"{'PASSED' if code == 0 else 'FAILED'} ({dt:.0f} s; {state})"


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--no-verify", action="store_true")
    ap.add_argument("--skip-verify-over", type=int, default=None)
    ap.add_argument("--out")
    args = ap.parse_args()
    rows = ["| file | GTSAM reader | GTSAM factors | fgc factors | fgc verify |",
            "|---|---|---|---|---|"]
    for name in sorted(os.listdir(gtsam_data_dir())):
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
        if not ok or args.no_verify:
            v = "—"
        elif args.skip_verify_over is not None and n_gtsam > args.skip_verify_over:
            v = f"not run (> {args.skip_verify_over} factors)"
        else:
            v = verify(name)
        rows.append(f"| {name} | {reader} | {n_gtsam} | {fgc_cell} | {v} |".replace("\n", " "))
        print(rows[-1], flush=True)
    if args.out:
        with open(args.out, "w") as fh:
            fh.write("\n".join(rows) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
