"""A/B of native builds: the same LIO problem solved by two or more builds of its kernel in one
process, taking turns, so that a change to the emitted C++ is measured against its base on the
same load.

    python bench/ab_native.py [--n 30] [--rounds 150] OTHER.so [OTHER2.so ...]
    python bench/ab_native.py [--n 30] --print-lib     # build, print this tree's library

The first build is the current tree's (``native.load``); each OTHER.so must be built from the
same Program structure (LIO with the same N, Cholesky), e.g. from an older revision:

    git worktree add /tmp/base <rev> && mkdir /tmp/basepath
    ln -s /tmp/base/fgc /tmp/basepath/fgc && ln -s /tmp/base/backends /tmp/basepath/fgc_backends
    FGC_CACHE_DIR=/tmp/cache-base PYTHONPATH=/tmp/basepath python bench/ab_native.py --print-lib

Each round runs every build once untimed and three times timed; the line printed gives each
build's best time, its ratio to the first build's best, and the median over the rounds of the
per-round ratio (robust to load that drifts during the run). It also prints the largest
difference of each build's solution from the first's (0.0: bit-identical).
"""

from __future__ import annotations

import argparse
import ctypes
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "examples"))

import lio  # noqa: E402

from fgc.compile import compile_graph  # noqa: E402
from fgc.datafile import problem_data  # noqa: E402
from fgc.program import SolverConfig  # noqa: E402
from fgc_backends.hls import native  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("others", nargs="*", help="other builds' lib<name>.so")
    parser.add_argument("--print-lib", action="store_true",
                        help="only build (or find) this tree's library and print its path")
    parser.add_argument("--n", type=int, default=30, help="LIO keyframes (default 30)")
    parser.add_argument("--rounds", type=int, default=150)
    args = parser.parse_args()
    graph = lio.build(N=args.n)
    program = compile_graph(graph, SolverConfig(linear="cholesky", max_iterations=100),
                            name="lio")
    built = native.load(program)
    if args.print_lib or not args.others:
        print(built.library._name)
        return
    x, d = built.flatten(problem_data(graph, program))
    paths = [built.library._name] + args.others
    runs = []
    for path in paths:
        fn = ctypes.CDLL(path).fgc_run
        fn.argtypes, fn.restype = [ctypes.c_void_p] * 5, None
        out, errors, info = np.empty(built.n_x), np.empty(2), np.zeros(3, dtype=np.int32)
        ptrs = [a.__array_interface__["data"][0] for a in (x, d, out, errors, info)]
        runs.append((lambda fn=fn, ptrs=ptrs: fn(*ptrs), out))
    for (run, out), path in zip(runs, paths, strict=True):
        run()
        print(f"{path}: max |x - x_first| = {np.abs(out - runs[0][1]).max():.3g}")
    best = [float("inf")] * len(runs)
    ratios = [[] for _ in runs]
    for _ in range(args.rounds):
        this = [float("inf")] * len(runs)
        for k, (run, _) in enumerate(runs):
            run()
            for _ in range(3):
                t0 = time.perf_counter()
                run()
                this[k] = min(this[k], time.perf_counter() - t0)
            best[k] = min(best[k], this[k])
        for k in range(len(runs)):
            ratios[k].append(this[k] / this[0])
    for k, path in enumerate(paths):
        print(f"{best[k] * 1e6:9.1f} us  best ratio {best[k] / best[0]:.3f}  median round ratio "
              f"{statistics.median(ratios[k]):.3f}  {path}")


if __name__ == "__main__":
    main()
