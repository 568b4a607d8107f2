"""Streaming benchmark (issue 19): per-update time distribution of fgc's native solver and
simulator (fixed-lag window and/or incremental plan) against GTSAM's ISAM2 update and
IncrementalFixedLagSmoother update on the same LIO keyframe stream, in one process, and each
trajectory's difference from the batch optimum (GTSAM LM on the whole graph).

    python bench/bench_stream.py --N 400 --window 30 [--incremental 3 --batch-every 5,15,25]
    python bench/bench_stream.py --N 400 --window 30 --skip-sim     # native and GTSAM only

The native row (fgc_backends.native.stream) times each whole update: assembling the window's
numbers, the native LM solve and the marginalisation of the keyframe leaving; its "solve" and
"marginal" lines split that time. Its library is built before the stream (not timed). The
simulator is NumPy (a functional model of the accelerator, not a fast solver): its wall time is
not the accelerator's latency, which the "model" column estimates.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "examples"))


def _isam2_times(graph, problem, clusters):
    """One plain ISAM2 update per keyframe (QR, relinearise every variable): wall times and the
    final estimate."""
    import gtsam

    from fgc.interop import oracles
    from fgc.interop.to_gtsam import value_to_gtsam, values_from_gtsam

    isam = gtsam.ISAM2(oracles._isam2_params())
    keys = {str(k): k for k in graph.variables}
    spans = oracles._cluster_spans(graph, clusters)
    times, online = [], {}
    for c, cluster in enumerate(clusters):
        factors, values = gtsam.NonlinearFactorGraph(), gtsam.Values()
        for i, span in enumerate(spans):
            if max(span) == c:
                factors.add(problem.graph.at(i))
        for key in cluster:
            values.insert(problem.keys[keys[key]],
                          value_to_gtsam(graph.variables[keys[key]].initial))
        t0 = time.perf_counter()
        isam.update(factors, values)
        times.append(time.perf_counter() - t0)
        newest = [keys[key] for key in cluster]
        online.update(oracles._read(graph, problem, isam.calculateEstimate(), newest))
    estimate = values_from_gtsam(graph, problem, isam.calculateEstimate())
    return times, {str(k): v for k, v in estimate.items()}, online


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--N", type=int, default=400, help="keyframes (lio.py: at most 470)")
    p.add_argument("--window", type=int, default=30)
    p.add_argument("--incremental", type=int)
    p.add_argument("--batch-every", default=None)
    p.add_argument("--skip-sim", action="store_true",
                   help="leave out the simulator's rows (minutes on 400 keyframes)")
    p.add_argument("--json", help="write the numbers as JSON")
    args = p.parse_args(argv)

    import lio

    from fgc.app import streaming
    from fgc.interop import oracles
    from fgc.interop.to_gtsam import to_gtsam
    from fgc.ir.datafile import problem_data

    graph = lio.build(N=args.N)
    problem = to_gtsam(graph)
    t0 = time.perf_counter()
    optimum = streaming.batch_optimum(graph)
    rows, out = [], {"N": args.N, "window": args.window,
                     "batch_lm_seconds": time.perf_counter() - t0}
    program = streaming.compile_stream(graph, window=args.window)
    clusters = program.schedule.clusters
    data = problem_data(graph, program)

    def sim_row(name, prog, window):
        online, updates = {}, []

        def keep(u):
            online.update(u.newest(prog))
            updates.append(u)

        result = streaming.run_stream(prog, data if prog is program else
                                      problem_data(graph, prog), window, keep)
        final = {str(k): v for k, v in result.values.items()}
        acc = streaming.accuracy(graph, final, online, optimum)
        pricer = streaming.UpdatePricer(graph, prog, window)
        model = [p["latency_ms"] for p in map(pricer.price, updates) if p]
        acc["model_ms"] = {"median": float(np.median(model)),
                           "p99": float(np.percentile(model, 99)), "priced": len(model)}
        rows.append((name, streaming.timing_summary(u["seconds"] for u in result.updates),
                     acc))
        return final, updates

    from fgc_backends.native.stream import FixedLagStream

    native_stream = FixedLagStream(graph, program, args.window)  # built here, not timed
    online: dict = {}
    result = native_stream.run(data, lambda r: online.update(
        streaming.keyframe_result(program, r).newest(program)))
    final = {str(k): v for k, v in result.values.items()}
    native_acc = streaming.accuracy(graph, final, online, optimum)
    rows.append((f"fgc native, fixed-lag W={args.window} (whole update)",
                 streaming.timing_summary(u["seconds"] for u in result.updates), native_acc))
    out["native_split"] = {part: streaming.timing_summary(u[f"{part}_seconds"]
                                                          for u in result.updates)
                           for part in ("solve", "marginal")}
    out["native_status"] = result.status
    if not args.skip_sim:
        sim_final, sim_updates = sim_row(f"fgc simulator, fixed-lag W={args.window}", program,
                                         args.window)
        # native against the simulator: the same fixed-lag semantics, two solvers
        per_keyframe = max(
            max(float(np.linalg.norm(u.values[k].local(
                streaming.keyframe_result(program, r).values[k]))) for k in u.values)
            for u, r in zip(sim_updates, result.updates, strict=True))
        out["native_vs_simulator"] = {
            "final_max_tangent": max(float(np.linalg.norm(v.local(final[k])))
                                     for k, v in sim_final.items()),
            "per_keyframe_max_tangent": per_keyframe}
    if args.incremental:
        batch = (tuple(int(s) for s in args.batch_every.split(",")) if args.batch_every
                 and "," in args.batch_every else
                 (int(args.batch_every) if args.batch_every else None))
        inc = streaming.compile_stream(graph, incremental=args.incremental, batch_every=batch)
        sim_row(f"fgc simulator, incremental K={args.incremental} batch {args.batch_every}",
                inc, None)
    times, final, online = _isam2_times(graph, problem, clusters)
    rows.append(("gtsam ISAM2 update (1 per keyframe)", streaming.timing_summary(times),
                 streaming.accuracy(graph, final, online, optimum)))
    times = []
    oracles.fixed_lag_per_keyframe(graph, problem, clusters, args.window, "incremental",
                                   timings=times, estimates=False)
    rows.append((f"gtsam IncrementalFixedLagSmoother lag {args.window - 1}",
                 streaming.timing_summary(times), None))
    print(f"LIO on KITTI, {args.N} keyframes streamed; batch optimum: GTSAM LM "
          f"({out['batch_lm_seconds']:.2f} s)")
    print("update wall time per keyframe; ATE rmse (m, no alignment) against the batch optimum "
          "of the final trajectory and of the online one (each keyframe's estimate on arrival)")
    print("model: the accelerator plan's latency of each update (model estimate; "
          "fgc.app.streaming.UpdatePricer), median / p99 over the priced updates")
    print(f"{'':<55} {'median ms':>10} {'p99 ms':>10} {'model ms':>15} {'ATE final':>10} "
          f"{'ATE online':>11} {'max dist':>9}")
    for name, t, acc in rows:
        nan = float("nan")
        ate = acc["final"]["translation"]["rmse"] if acc else nan
        ate_online = acc["online"]["translation"]["rmse"] if acc else nan
        dist = acc["max_state_distance"] if acc else nan
        m = (acc or {}).get("model_ms")
        model = f"{m['median']:.3f} / {m['p99']:.3f}" if m else "-"
        print(f"{name:<55} {t['median_ms']:>10.2f} {t['p99_ms']:>10.2f} {model:>15} "
              f"{ate:>10.4g} {ate_online:>11.4g} {dist:>9.3g}")
    split = out["native_split"]
    print(f"native update split: LM solve median {split['solve']['median_ms']:.3f} ms, p99 "
          f"{split['solve']['p99_ms']:.3f} ms; marginalisation median "
          f"{split['marginal']['median_ms']:.3f} ms, p99 {split['marginal']['p99_ms']:.3f} ms "
          f"(status {out['native_status']})")
    if "native_vs_simulator" in out:
        vs = out["native_vs_simulator"]
        print(f"native vs simulator (same window, same marginalisation): largest tangent-space "
              f"distance {vs['per_keyframe_max_tangent']:.3g} over every keyframe's window, "
              f"{vs['final_max_tangent']:.3g} in the final estimate")
    out["rows"] = [{"name": n, "time": t, "accuracy": a} for n, t, a in rows]
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=1, default=float) + "\n")
    return 0


if __name__ == "__main__":
    np.set_printoptions(precision=4)
    sys.exit(main())
