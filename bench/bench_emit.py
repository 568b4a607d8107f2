"""What emitting an HLS design costs (the test suite's emits and ``fgc compile --backend hls``):
the wall and CPU time of ``fgc_backends.hls.emit`` on a LIO stream design (the on-chip
incremental plan, K = 3, a batch step at keyframe 3: two emits, the batch kernel and the window,
each linted) and on a plain batch design, and of the lint alone on what the emit wrote.

A design's first emit is cold (its Program's kernels parsed and printed; the batch design
shares some kernels with the stream design emitted before it); the later ones are warm (the
Program's printed blocks and the compiled templates reused): the first run and the median of
``--repeat`` warm runs are printed. The derivation cache
(``FGC_CACHE_DIR``) is assumed warm.

    python bench/bench_emit.py                 # LIO N = 6, float, stream and batch
    python bench/bench_emit.py --n 8 --scalar double --repeat 5
"""
from __future__ import annotations

import argparse
import statistics
import tempfile
import time
import warnings
from pathlib import Path

from fgc.app.specs import example
from fgc.app.streaming import compile_stream
from fgc.compile import compile_graph
from fgc.compiler.stream import stream_program
from fgc_backends import hls
from fgc_backends.hls import emitter
from fgc_backends.hls.config import HlsConfig


def _timed(fn):
    wall, cpu = time.perf_counter(), time.process_time()
    fn()
    return time.perf_counter() - wall, time.process_time() - cpu


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=6, help="LIO keyframes (default 6)")
    ap.add_argument("--scalar", default="float", choices=("float", "double"))
    ap.add_argument("--repeat", type=int, default=3, help="warm emits per design (median)")
    args = ap.parse_args(argv)
    warnings.simplefilter("ignore")  # an HlsFitWarning is no error here
    graph = example("lio").build(N=args.n)
    config = HlsConfig(scalar=args.scalar)
    designs = {
        "stream": stream_program(graph, compile_stream(graph, incremental=3, batch_every=(3,))),
        "batch": compile_graph(graph),
    }
    lints = []  # (project, synthesised) of every lint the emits ran
    lint_project = emitter.lint_project

    def recording(project, synthesised, strict=True):
        lints.append((project, list(synthesised)))
        return lint_project(project, synthesised, strict)

    emitter.lint_project = recording
    last = {}
    try:
        for name, target in designs.items():
            root = Path(tempfile.mkdtemp(prefix="fgc-bench-emit-"))
            runs = [_timed(lambda i=i, t=target, r=root: hls.emit(t, r / str(i), config))
                    for i in range(args.repeat + 1)]
            cold, warm = runs[0], runs[1:]
            print(f"{name} LIO N={args.n} {args.scalar}: emit cold {cold[0]:.2f} s wall "
                  f"({cold[1]:.2f} s CPU), warm median {statistics.median(w[0] for w in warm):.2f}"
                  f" s wall ({statistics.median(w[1] for w in warm):.2f} s CPU) of {len(warm)}")
            last[name] = lints[-1]
    finally:
        emitter.lint_project = lint_project
    for name, (project, synthesised) in last.items():
        wall, cpu = _timed(lambda p=project, s=synthesised: lint_project(p, s))
        print(f"{name}: its last emit's lint again {wall:.2f} s wall ({cpu:.2f} s CPU)")


if __name__ == "__main__":
    main()
