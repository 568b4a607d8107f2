"""A/B of native builds: the same LIO problem solved by two or more builds of its kernel in one
process, taking turns, so that a change to the emitted C++ is measured against its base on the
same load.

    python bench/ab_native.py [--n 30] [--rounds 60] [--copies 4] OTHER.so [OTHER2.so ...]
    python bench/ab_native.py [--n 30] --print-lib     # build, print this tree's library

The first build is the current tree's (``native.load``); each OTHER.so must be built from the
same Program structure (LIO with the same N, Cholesky), e.g. from an older revision:

    git worktree add /tmp/base <rev> && mkdir /tmp/basepath
    ln -s /tmp/base/fgc /tmp/basepath/fgc && ln -s /tmp/base/backends /tmp/basepath/fgc_backends
    FGC_CACHE_DIR=/tmp/cache-base PYTHONPATH=/tmp/basepath python bench/ab_native.py --print-lib

Each build is loaded from several copies of its file (``--copies``, default 4): the same bytes
run a few per cent faster or slower depending on where the file's pages happen to sit in memory
(seen here: 4–9 % between a library and its own copy, either way round), so one file per build
is a lottery.
Each round runs every copy once untimed and three times timed; the line printed gives each
build's median over its copies of their best times, its ratio to the first build's, and the
median over the rounds of the per-round ratio (robust to load that drifts during the run). It
also prints the largest difference of each build's solution from the first's (0.0:
bit-identical).
"""

from __future__ import annotations

import argparse
import ctypes
import shutil
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent

from fgc.app.specs import example  # noqa: E402

lio = example("lio")

from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.datafile import problem_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402

try:
    from fgc_backends import native  # noqa: E402
except ImportError:  # a base revision from before the native backend split off the HLS one
    from fgc_backends.hls import native  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("others", nargs="*", help="other builds' lib<name>.so")
    parser.add_argument("--print-lib", action="store_true",
                        help="only build (or find) this tree's library and print its path")
    parser.add_argument("--n", type=int, default=30, help="LIO keyframes (default 30)")
    parser.add_argument("--rounds", type=int, default=60)
    parser.add_argument("--copies", type=int, default=4,
                        help="copies of each library file loaded (default 4)")
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
    folder = Path(tempfile.mkdtemp(prefix="ab_native"))
    runs = []  # per build: its copies' calls
    for k, path in enumerate(paths):
        calls = []
        for c in range(args.copies):
            copy = folder / f"b{k}_{c}.so"
            shutil.copyfile(path, copy)
            fn = ctypes.CDLL(str(copy)).fgc_run
            fn.argtypes, fn.restype = [ctypes.c_void_p] * 5, None
            out, errors, info = np.empty(built.n_x), np.empty(2), np.zeros(3, dtype=np.int32)
            ptrs = [a.__array_interface__["data"][0] for a in (x, d, out, errors, info)]
            calls.append((lambda fn=fn, ptrs=ptrs: fn(*ptrs), out))
        runs.append(calls)
    first_out = None
    for calls, path in zip(runs, paths, strict=True):
        for run, out in calls:
            run()
            first_out = out.copy() if first_out is None else first_out
        worst = max(np.abs(o - first_out).max() for _, o in calls)
        print(f"{path}: max |x - x_first| = {worst:.3g}")
    best = [[float("inf")] * args.copies for _ in runs]
    ratios = [[] for _ in runs]
    for _ in range(args.rounds):
        this = [float("inf")] * len(runs)
        for k, calls in enumerate(runs):
            for c, (run, _) in enumerate(calls):
                run()
                for _ in range(3):
                    t0 = time.perf_counter()
                    run()
                    t = time.perf_counter() - t0
                    best[k][c] = min(best[k][c], t)
                    this[k] = min(this[k], t)
        for k in range(len(runs)):
            ratios[k].append(this[k] / this[0])
    typical = [statistics.median(b) for b in best]
    for k, path in enumerate(paths):
        print(f"{typical[k] * 1e6:9.1f} us  ratio {typical[k] / typical[0]:.3f}  median round "
              f"ratio {statistics.median(ratios[k]):.3f}  copies {min(best[k]) * 1e6:.0f}-"
              f"{max(best[k]) * 1e6:.0f} us  {path}")
    shutil.rmtree(folder, ignore_errors=True)

if __name__ == "__main__":
    main()
