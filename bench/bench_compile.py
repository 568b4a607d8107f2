"""Compile time of the LIO factor set (CombinedImu + LiDAR + GPS + priors), cold and warm cache.

Each measurement runs in a fresh Python process (so no in-memory memo helps): *cold* with an empty
derivation cache, *warm* with the cache the cold run left. Times are the ``compile_graph`` call
only (graph building and imports excluded), and GTSAM's own setup for the same graph is printed
beside them for scale (building its NonlinearFactorGraph from the same data).

    python bench/bench_compile.py [--n 30] [--repeat 3]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

CHILD = """
import json, sys, time
sys.path.insert(0, {examples!r})
import lio
from fgc.compile import compile_graph
from fgc.verify import to_gtsam
graph = lio.build(N={n})
t0 = time.perf_counter()
program = compile_graph(graph)
t1 = time.perf_counter()
to_gtsam(graph)
t2 = time.perf_counter()
print(json.dumps({{"compile_s": t1 - t0, "gtsam_graph_s": t2 - t1,
                   "blocks": [b.name for b in program.blocks]}}))
"""


def run_once(n: int, cache: str) -> dict:
    env = dict(os.environ, FGC_CACHE_DIR=cache)
    code = CHILD.format(examples=str(ROOT / "examples"), n=n)
    out = subprocess.run([sys.executable, "-c", code], env=env, check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


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
    best_cold = min(r["compile_s"] for r in cold)
    best_warm = min(r["compile_s"] for r in warm)
    gtsam_s = min(r["gtsam_graph_s"] for r in warm)
    print(f"LIO factor set, N={args.n}, blocks: {', '.join(cold[0]['blocks'])}")
    print(f"{'case':<10}{'best s':>10}{'all runs (s)':>40}")
    print(f"{'cold':<10}{best_cold:>10.3f}{str([round(r['compile_s'], 3) for r in cold]):>40}")
    print(f"{'warm':<10}{best_warm:>10.3f}{str([round(r['compile_s'], 3) for r in warm]):>40}")
    print(f"cold/warm ratio {best_cold / best_warm:.1f}x; goals: cold <= 10 s, warm <= 0.5 s")
    print(f"GTSAM graph construction for the same problem: {gtsam_s:.3f} s "
          f"(warm compile / GTSAM = {best_warm / gtsam_s:.1f}x)")


if __name__ == "__main__":
    main()
