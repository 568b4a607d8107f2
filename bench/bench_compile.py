"""Compile time of the LIO factor set (CombinedImu + LiDAR + GPS + priors), cold and warm cache.

Each measurement runs in a fresh Python process (so no in-memory memo helps): *cold* with an empty
derivation cache, *warm* with the cache the cold run left. Times are the ``compile_graph`` call
only (graph building and imports excluded): wall time (median and best of the runs) and CPU time
(``time.process_time``, which other processes on a loaded machine do not inflate), and the CPU
time of each compiler phase. GTSAM's own setup for the same graph is printed beside them for
scale (building its NonlinearFactorGraph from the same data).

    python bench/bench_compile.py [--n 30] [--repeat 3]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

CHILD = """
import json, sys, time
from fgc.app.specs import example
lio = example("lio")
from fgc import compile as stages
from fgc.compile import compile_graph
from fgc.interop.to_gtsam import to_gtsam

cpu = {{}}


def timed(name, fn):
    def wrapper(*args, **kwargs):
        c0 = time.process_time()
        try:
            return fn(*args, **kwargs)
        finally:
            cpu[name] = cpu.get(name, 0.0) + time.process_time() - c0
    return wrapper


for name in ("graph_structure", "check_structure", "schedule", "fuse", "plan_storage",
             "lower", "check_program"):
    setattr(stages, name, timed(name, getattr(stages, name)))
graph = lio.build(N={n})
t0, c0 = time.perf_counter(), time.process_time()
program = compile_graph(graph)
t1, c1 = time.perf_counter(), time.process_time()
to_gtsam(graph)
t2 = time.perf_counter()
print(json.dumps({{"compile_s": t1 - t0, "compile_cpu_s": c1 - c0, "gtsam_graph_s": t2 - t1,
                   "phases_cpu_s": cpu, "blocks": [b.name for b in program.blocks]}}))
"""


def run_once(n: int, cache: str) -> dict:
    env = dict(os.environ, FGC_CACHE_DIR=cache)
    code = CHILD.format(n=n)
    out = subprocess.run([sys.executable, "-c", code], env=env, check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def _row(case: str, runs: list[dict], key: str) -> str:
    values = [r[key] for r in runs]
    return (f"{case:<10}{statistics.median(values):>10.3f}{min(values):>10.3f}"
            f"{str([round(v, 3) for v in values]):>30}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=30, help="keyframes (default 30)")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    cold, warm = [], []
    for _ in range(args.repeat):
        with tempfile.TemporaryDirectory() as cache:
            cold.append(run_once(args.n, cache))
            warm.append(run_once(args.n, cache))
    print(f"LIO factor set, N={args.n}, blocks: {', '.join(cold[0]['blocks'])}")
    print(f"{'case':<10}{'median s':>10}{'best s':>10}{'all runs (s)':>30}")
    for case, runs in (("cold", cold), ("warm", warm)):
        print(_row(f"{case}", runs, "compile_s"))
        print(_row(f"{case} cpu", runs, "compile_cpu_s"))
    med_cold = statistics.median(r["compile_s"] for r in cold)
    med_warm = statistics.median(r["compile_s"] for r in warm)
    print(f"cold/warm ratio {med_cold / med_warm:.1f}x (medians); goals: cold <= 10 s, "
          "warm <= 0.5 s")
    for case, runs in (("cold", cold), ("warm", warm)):
        phases = {name: statistics.median(r["phases_cpu_s"].get(name, 0.0) for r in runs)
                  for name in runs[0]["phases_cpu_s"]}
        print(f"{case} CPU per phase (median s): "
              + ", ".join(f"{name} {t:.3f}" for name, t in phases.items()))
    gtsam_s = statistics.median(r["gtsam_graph_s"] for r in warm)
    print(f"GTSAM graph construction for the same problem: {gtsam_s:.3f} s "
          f"(warm compile / GTSAM = {med_warm / gtsam_s:.1f}x)")


if __name__ == "__main__":
    main()
