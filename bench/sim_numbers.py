"""The simulator's numbers on the examples at full precision, to compare two versions of it.

A change of the run-time or of what is printed into the problem module (the retraction, local
coordinates, kernels) should move the results by rounding only. ``record`` runs each example in
batch (float64 and float32) and, on a chain, in a fixed-lag window of 3 keyframes, and writes the
final error, iterations, status and the final storage of every run as JSON; ``compare`` prints,
per run, the relative change of the final error and the largest change of the state.

    python bench/sim_numbers.py record before.json     # on the old checkout
    python bench/sim_numbers.py record after.json
    python bench/sim_numbers.py compare before.json after.json
"""

from __future__ import annotations

import argparse
import json
import sys

import numpy as np

from fgc.app.specs import load_spec
from fgc.compile import compile_graph
from fgc.ir.datafile import problem_data
from fgc_backends import sim

CASES = (("lio", "examples/lio.py", {}), ("imu_window", "examples/imu_window.py", {"N": 8}),
         ("pose_graph", "examples/pose_graph.py", {"dataset": "pose3example.txt"}))


def record(path: str) -> None:
    out = {}
    for name, spec, params in CASES:
        graph = load_spec(spec, params)
        program = compile_graph(graph)
        data = problem_data(graph, program)
        runs = [("float64", {"precision": "float64"}), ("float32", {"precision": "float32"})]
        if program.schedule.structure_class == "chain":
            runs.append(("window3", {"window": 3, "precision": "float64"}))
        for run, options in runs:
            result = sim.run(program, data, **options)
            state = np.concatenate([np.asarray(v, dtype=float).reshape(-1)
                                    for v in result.storage.values()])
            out[f"{name}/{run}"] = {"final_error": result.final_error,
                                    "iterations": result.iterations, "status": result.status,
                                    "reason": result.reason, "storage": state.tolist()}
            print(f"{name}/{run}: final error {result.final_error!r}, {result.iterations} "
                  f"iterations, {result.status}", flush=True)
    with open(path, "w") as handle:
        json.dump(out, handle)


def compare(before_path: str, after_path: str) -> None:
    with open(before_path) as handle:
        before = json.load(handle)
    with open(after_path) as handle:
        after = json.load(handle)
    for run in before:
        a, b = before[run], after.get(run)
        if b is None:
            print(f"{run}: missing in {after_path}")
            continue
        sa, sb = np.array(a["storage"]), np.array(b["storage"])
        error = abs(a["final_error"] - b["final_error"]) / abs(a["final_error"])
        state = float(np.max(np.abs(sa - sb)))
        print(f"{run:20s} final error {a['final_error']!r} -> {b['final_error']!r} "
              f"(relative {error:.2e}); iterations {a['iterations']} -> {b['iterations']}; "
              f"{a['status']} -> {b['status']}; state max |change| {state:.2e} "
              f"(relative to max |x| {state / float(np.max(np.abs(sa))):.2e})")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("record").add_argument("out")
    cmp = sub.add_parser("compare")
    cmp.add_argument("before")
    cmp.add_argument("after")
    args = parser.parse_args(argv)
    if args.command == "record":
        record(args.out)
    else:
        compare(args.before, args.after)
    return 0


if __name__ == "__main__":
    sys.exit(main())
