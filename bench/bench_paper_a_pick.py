"""Paper A's ratio for one on-chip design, ISAM2 timed several times in a fresh process.

bench_papers.py's paper A row times ISAM2 once (3 runs a keyframe, their median), in the same
process, after its design search; on a shared host that one timing moves a lot from run to run
(stop 49: ISAM2's median 0.949 ms in the bench's run, 0.533-0.595 ms in five runs just after).
This prices each update of paper A's setting (LIO N = 30, K = 3, batch at 5 / 15 / 25, one
Gauss-Newton step an update) on one design with the plan, as the bench does (WindowPricer:
model estimates at the Program's clock), and times ISAM2 (relinearise all, one update per
keyframe) --repeats times, each as the bench does, printing the per-keyframe ratios' median of
each repeat: the spread the bench's single figure hides.

    python bench/bench_paper_a_pick.py --repeats 5      # the search's pick (stop 49)
    python bench/bench_paper_a_pick.py --units 4        # another n_u, the pick's other options
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

import bench_papers as b  # noqa: E402
from bench_stream import _isam2_times  # noqa: E402

from fgc.app import streaming  # noqa: E402
from fgc.interop.to_gtsam import to_gtsam  # noqa: E402
from fgc_backends.cost.operators import parse_bind  # noqa: E402
from fgc_backends.hls import HlsConfig  # noqa: E402


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5, help="ISAM2 timings (each 3 runs a keyframe)")
    ap.add_argument("--units", type=int, default=8, help="n_u (default 8: the search's pick)")
    ap.add_argument("--allocation", default="add=8,mul=12,div=2")
    ap.add_argument("--bind", default="add=fabric")
    args = ap.parse_args(argv)
    if args.repeats < 1:
        ap.error("--repeats must be at least 1")
    graph, program, sp = b.paper_a_window(b.Config(), units=args.units)
    updates = b.stream_updates(graph, program, sp)
    config = HlsConfig(scalar="float", unit_sets=2, qr_rows=2, root_wave=True, data_width=64,
                       allocation=b.parse_allocation(args.allocation), bind=parse_bind(args.bind))
    pricer = streaming.WindowPricer(sp, config=config)
    clock_khz = program.solver.clock_mhz * 1e3
    cycles = np.array([pricer.price(u).cycles for u in updates])
    model = cycles / clock_khz  # ms
    print(f"n_u {args.units}, two unit sets, ALLOCATION {args.allocation}, two rows a cycle, "
          f"the root in a wavefront, data port 64 bits, bind {args.bind}: median "
          f"{np.median(model):.4f} ms / p99 {np.percentile(model, 99):.3f} ms per update "
          f"(model estimates; keyframe 14 {cycles[14]:,} cycles)")
    problem = to_gtsam(graph)
    ratios = []
    for _ in range(args.repeats):
        runs = [_isam2_times(graph, problem, program.schedule.clusters)[0] for _ in range(3)]
        isam = np.median(np.asarray(runs), axis=0) * 1e3
        ratios.append(float(np.median(isam / model)))
        print(f"{time.strftime('%H:%M:%S')} ISAM2 median {np.median(isam):.3f} ms, p99 "
              f"{np.percentile(isam, 99):.3f} ms: ISAM2 / design per keyframe, median "
              f"{ratios[-1]:.2f}x", flush=True)
    print(f"ISAM2 / design over {args.repeats} timings: {min(ratios):.2f}x ... {max(ratios):.2f}x")


if __name__ == "__main__":
    main()
