"""The HLS C simulation's keyframe stream against GTSAM and the simulator (issue 19), at sizes
the test suite does not run: paper A's setting by default (LIO on KITTI, N = 30, incremental
K = 3, batch steps at keyframes 5, 15, 25) or a fixed-lag window.

    python bench/bench_stream_csim.py                          # paper A's setting, double
    python bench/bench_stream_csim.py --window 10 --N 30       # fixed-lag, W = 10
    python bench/bench_stream_csim.py --scalar float           # the hardware's scalar

Per keyframe it prints the largest tangent-space distance (every variable the update holds) of
the C simulation's estimate from

- ``gtsam.ISAM2`` fed the same keyframes with fgc's policy (``oracles.isam2_per_keyframe``:
  keyframes before the window held, factors across its edge kept linear, batch steps restoring
  them; fixed-lag: the window's policy), and from plain ISAM2 (to show the comparison sees the
  policy);
- the simulator's stream (the numerical reference the C simulation is built against).

The template windows are emitted and built once (fgc's cache, ``hls-stream/``); the first run
spends most of its time in g++. The kept Bayes net lives on the host in this path
(``fgc_backends.hls.streaming``): what is checked is the emitted accelerator's window solves
inside a stream.
"""

from __future__ import annotations

import argparse
import json
import sys
import time

import numpy as np


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--N", type=int, default=30, help="keyframes (default 30)")
    p.add_argument("--incremental", type=int, default=3, help="K (default 3)")
    p.add_argument("--batch-every", default="5,15,25",
                   help="batch keyframes, comma separated (default 5,15,25)")
    p.add_argument("--window", type=int, default=None,
                   help="a fixed-lag window of W keyframes instead of the incremental plan")
    p.add_argument("--scalar", choices=("double", "float"), default="double")
    p.add_argument("--host-kept", action="store_true",
                   help="the incremental plan's earlier path: each window solved by the C "
                        "simulation, the kept Bayes net on the host (default: on chip)")
    p.add_argument("--json", help="write the per-keyframe distances as JSON")
    args = p.parse_args(argv)

    from fgc.app.specs import example
    from fgc.app.streaming import compile_stream, keyframe_result, run_stream
    from fgc.interop import oracles
    from fgc.interop.to_gtsam import to_gtsam
    from fgc.ir.datafile import problem_data
    from fgc_backends.hls.streaming import (
        OnChipFixedLagStream,
        OnChipIncrementalStream,
        incremental_stream,
    )

    graph = example("lio").build(N=args.N)
    if args.window is None:
        batch = tuple(int(b) for b in args.batch_every.split(",") if b.strip())
        program = compile_stream(graph, incremental=args.incremental, batch_every=batch,
                                 name="lio")
        what = f"incremental K = {args.incremental}, batch at {batch}"
    else:
        program = compile_stream(graph, window=args.window, name="lio")
        what = f"fixed-lag window W = {args.window}"
    data = problem_data(graph, program)
    print(f"LIO N = {args.N}, {what}, HLS C simulation ({args.scalar})", flush=True)

    t0 = time.perf_counter()
    sim = []
    run_stream(program, data, args.window, sim.append)
    t1 = time.perf_counter()
    if args.window is None and args.host_kept:
        stream = incremental_stream(graph, program, args.scalar, progress_build=lambda size, i, n:
                                    print(f"  template {i + 1}/{n}: {size} keyframes", flush=True))
    elif args.window is None:  # the on-chip design: the window, the kept net, the batch kernel
        stream = OnChipIncrementalStream(graph, program, args.scalar)
    else:
        stream = OnChipFixedLagStream(graph, program, args.window, args.scalar)
    csim = stream.run(data)
    t2 = time.perf_counter()
    print(f"  simulator stream {t1 - t0:.1f} s, C simulation stream {t2 - t1:.1f} s "
          "(emit and g++ builds included on a cold cache)", flush=True)

    problem = to_gtsam(graph)
    clusters = program.schedule.clusters
    policy = [(u["first"], u["mode"] == "batch") for u in csim.updates]
    same = oracles.isam2_per_keyframe(graph, problem, clusters, policy)
    plain = oracles.isam2_per_keyframe(graph, problem, clusters, None)
    values = [{"values": keyframe_result(program, u).values} for u in csim.updates]
    d_same = oracles.per_keyframe_distance(values, same)
    d_plain = oracles.per_keyframe_distance(values, plain)
    d_sim = []
    for record, expected in zip(csim.updates, sim, strict=True):
        update = keyframe_result(program, record)
        d_sim.append(max(float(np.linalg.norm(expected.values[k].local(v)))
                         for k, v in update.values.items()))

    print("\n| keyframe | mode | first | iterations | csim vs ISAM2 (same policy) | csim vs "
          "plain ISAM2 | csim vs simulator |\n| ---: | --- | ---: | ---: | ---: | ---: | ---: |")
    for u, a, b, c in zip(csim.updates, d_same, d_plain, d_sim, strict=True):
        print(f"| {u['keyframe']} | {u['mode']} | {u['first']} | {u['iterations']} | {a:.2e} | "
              f"{b:.2e} | {c:.2e} |")
    print(f"\nworst over {len(d_same)} keyframes: csim vs same-policy ISAM2 {max(d_same):.2e} "
          f"(keyframe {int(np.argmax(d_same))}), vs plain ISAM2 {max(d_plain):.2e}, vs the "
          f"simulator {max(d_sim):.2e}; status {csim.status}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"N": args.N, "mode": what, "scalar": args.scalar,
                       "csim_vs_isam2_same_policy": d_same, "csim_vs_plain_isam2": d_plain,
                       "csim_vs_simulator": d_sim}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
