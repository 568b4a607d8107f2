"""Streaming benchmark (issue 19): per-update time distribution of fgc's native solver and
simulator (fixed-lag window and/or incremental plan) against GTSAM's ISAM2 update and
IncrementalFixedLagSmoother update on the same LIO keyframe stream, in one process, and each
trajectory's difference from the batch optimum (GTSAM LM on the whole graph).

    python bench/bench_stream.py --N 400 --window 30 [--incremental 3 --batch-every 5,15,25]
    python bench/bench_stream.py --hls-model [--precision float32|float64] [--units 4] [--reader]
    python bench/bench_stream.py --N 400 --window 30 --skip-sim     # native and GTSAM only

``--hls-model`` is paper A's setting (LIO N = 30, incremental K = 3, batch at keyframes 5, 15,
25, float32 by default; its Fig. 5.3): per keyframe, the update as the simulator ran it, priced
on the emitted on-chip incremental design's plan
(``fgc_backends.hls.plan.stream.WindowUpdateModel``: model estimates, not measurements; a
Cholesky design is priced by the host-kept path's update model, ``fgc_backends.hls.plan.update``),
beside two wall times
measured in this process, median of ``--repeat`` runs per keyframe, the runs interleaved: the
native solver's IncrementalStream on the same stream (same K and batch keyframes, double; its
template libraries built before timing) and GTSAM's ISAM2 update. It also prints how far the
native estimate is from the simulator's after every keyframe.

Default mode. The native fixed-lag row (fgc_backends.native.streaming) times each whole update:
assembling the window's numbers, the native LM solve and the marginalisation of the keyframe
leaving; its "solve" and "marginal" lines split that time. With ``--incremental`` a native
incremental row (IncrementalStream; the whole update: the library's window solve, the host's
assembly and NumPy store elimination of the window, and the back-substitution through every kept
conditional and the re-expression, one library call each; split into the solve and the rest)
and its distance from gtsam.ISAM2 run with the same policy and from the plain ISAM2 row. The
libraries are built before the stream (not timed). The simulator is NumPy (a functional model
of the accelerator, not a fast solver): its wall time is not the accelerator's latency, which
the "model" column estimates; ``--skip-sim`` leaves its rows out (the native rows do not need
them).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent


def _isam2_times(graph, problem, clusters, params=None):
    """One ISAM2 update per keyframe (default ``params``: QR, relinearise every variable):
    wall times and the final estimate."""
    import gtsam

    from fgc.interop import oracles
    from fgc.interop.to_gtsam import value_to_gtsam, values_from_gtsam

    isam = gtsam.ISAM2(params if params is not None else oracles._isam2_params())
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


def _batch(text):
    if not text:
        return None
    if "," in text:
        return tuple(int(s) for s in text.split(",") if s.strip())
    return int(text)


def _max_distance(program, record, expected) -> float:
    """The largest tangent-space distance between a native update record's estimate and a
    simulator KeyframeResult of the same update (every variable both hold)."""
    from fgc.app import streaming

    update = streaming.keyframe_result(program, record)
    if (update.keyframe, update.mode, update.first) != (expected.keyframe, expected.mode,
                                                        expected.first):
        raise SystemExit(f"keyframe {update.keyframe}: the native stream ran "
                         f"({update.mode}, from {update.first}), the simulator "
                         f"({expected.mode}, from {expected.first})")
    return max(float(np.linalg.norm(expected.values[k].local(v)))
               for k, v in update.values.items())


def _native_incremental(graph, program, log=print):
    """The native IncrementalStream of ``program`` (double), its template libraries built here
    (not timed)."""
    from fgc_backends.native.config import NativeConfig
    from fgc_backends.native.streaming import IncrementalStream

    def built(size, i, count):
        log(f"building the native {size}-keyframe template window ({i + 1} of {count}; "
            "not timed)")

    return IncrementalStream(graph, program, NativeConfig(scalar="double"),
                             progress_build=built)


def hls_model(args) -> dict:
    """Paper A's Fig. 5.3 setting: per-keyframe accelerator latency (update model on the HLS
    plan) and the native solver's update wall time against GTSAM's ISAM2 update time on the
    same stream."""
    import gtsam

    from fgc.app.specs import example

    lio = example("lio")

    from fgc.app import streaming
    from fgc.interop.to_gtsam import to_gtsam
    from fgc.ir.datafile import problem_data
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls.plan.update import NOT_EMITTED

    n, k = args.N or 30, args.incremental or 3
    batch = _batch(args.batch_every if args.batch_every is not None else "5,15,25")
    graph = lio.build(N=n)
    solver = SolverConfig(precision=args.precision, units=args.units, cpe=args.cpe,
                          linear=args.linear)
    if args.one_step:  # ISAM2's policy: one Gauss-Newton step an update, as the timed update
        solver = streaming.one_step_solver(solver)
    program = streaming.compile_stream(graph, solver, incremental=k, batch_every=batch)
    sp = streaming.stream_program(graph, program)
    on_chip = streaming.on_chip(sp)
    # the emitted on-chip design's own price (QR); Cholesky: the update model of the host-kept path
    model = (streaming.WindowPricer(sp) if on_chip
             else streaming.update_model(graph, program))
    updates = []
    result = streaming.run_stream(sp, problem_data(graph, program), progress=updates.append)
    prices = [model.price(u) for u in updates]
    # the same update had it run one iteration (ISAM2 takes one Gauss-Newton step per update)
    once = [model.price(replace(u, iterations=1)) for u in updates]
    # the native solver on the same stream: same K and batch keyframes, in double (a float64
    # Program: the native build's scalar), against the float64 simulator and the one priced
    native_program = (program if args.precision == "float64" else
                      streaming.compile_stream(graph, replace(solver, precision="float64"),
                                               incremental=k, batch_every=batch))
    native_data = problem_data(graph, native_program)
    native = _native_incremental(graph, native_program)
    sim64 = updates
    if native_program is not program:
        sim64 = []
        streaming.run_stream(native_program, native_data, None, sim64.append)
    problem = to_gtsam(graph)
    clusters = program.schedule.clusters
    default = gtsam.ISAM2Params()  # GTSAM's defaults: Gauss-Newton, relinearise when > 0.1
    runs, runs_default, runs_native = [], [], []
    for _ in range(args.repeat):  # interleaved: a load change on the host hits all three
        runs.append(_isam2_times(graph, problem, clusters)[0])
        runs_default.append(_isam2_times(graph, problem, clusters, default)[0])
        runs_native.append(native.run(native_data).updates)
    isam = np.median(np.asarray(runs), axis=0) * 1e3
    isam_default = np.median(np.asarray(runs_default), axis=0) * 1e3
    native_ms = np.median([[r["seconds"] for r in run] for run in runs_native], axis=0) * 1e3
    native_solve_ms = np.median([[r["solve_seconds"] for r in run] for run in runs_native],
                                axis=0) * 1e3
    records = runs_native[0]
    statuses = {r["status"] for run in runs_native for r in run}
    vs_sim64 = [_max_distance(native_program, r, u)
                for r, u in zip(records, sim64, strict=True)]
    vs_priced = [_max_distance(native_program, r, u)
                 for r, u in zip(records, updates, strict=True)]
    rows = [{"keyframe": u.keyframe, "mode": u.mode, "first": u.first, "window": pr.window,
             "iterations": u.iterations, "status": u.status, "model_ms": pr.latency_ms,
             "model_with_assumed_ms": pr.latency_with_assumed_ms,
             "model_one_iteration_ms": one.latency_ms,
             "native_ms": float(native_ms[i]), "native_solve_ms": float(native_solve_ms[i]),
             "native_iterations": records[i]["iterations"],
             "native_vs_simulator_float64": vs_sim64[i],
             "native_vs_simulator_priced": vs_priced[i],
             "isam2_ms": float(isam[i]), "isam2_default_ms": float(isam_default[i]),
             "simulator_ms": u.seconds * 1e3, "terms": pr.as_dict()["terms"]}
            for i, (u, pr, one) in enumerate(zip(updates, prices, once, strict=True))]
    sol = program.solver
    unit = f"n_u = {sol.units}" if sol.linear == "qr" else f"#CPE = {sol.cpe}"
    print(f"paper A's setting: LIO on KITTI, N = {n}, incremental K = {k}, batch at "
          f"{args.batch_every or '5,15,25'}; simulator {sol.precision}: {result.status}")
    if on_chip:
        print(f"accelerator: the on-chip incremental design (the window, the kept Bayes net and "
              f"the batch kernel in its memories; fgc compile --backend hls --incremental "
              f"{k} --batch-every ...) priced on its plan ({sol.linear.upper()}, {unit}, "
              f"{sol.precision}, {sol.clock_mhz:g} MHz) - model estimates, not measured")
    else:
        print(f"accelerator: update model on the HLS plan ({sol.linear.upper()}, {unit}, "
              f"{sol.precision}, {sol.clock_mhz:g} MHz) - model estimates, not measured; "
              f"{NOT_EMITTED}")
    print(f"native: fgc_backends.native.streaming.IncrementalStream, double, the same K and batch "
          f"keyframes; wall time of the whole update (the library's LM solve of the window, "
          f"the host's assembly and NumPy store elimination of the window, and the "
          f"back-substitution through the kept conditionals and the re-expression, one "
          f"library call each), median of {args.repeat} runs in this process, its template "
          f"libraries built before timing; 'solve': the library call alone "
          f"(status {', '.join(sorted(statuses))})")
    print(f"ISAM2: one update per keyframe, wall time, median of {args.repeat} runs in this "
          "process; 'all': QR, relinearise every variable (the oracle's policy); 'default': "
          "gtsam.ISAM2Params()")
    print("model ms: the plan's terms for the iterations the simulator ran; +assumed: with the "
          "assumed terms; 1 it: the plan's terms had the update run one iteration")
    print("all/mdl, all/nat, def/mdl, def/nat: ISAM2 ('all' or 'default') time / model latency "
          "or native time, per keyframe; wall times from this shared host, model figures "
          "estimates; nat-sim: the native estimate's largest tangent-space distance from the "
          "float64 simulator's after the keyframe (every variable so far)")
    head = (f"{'kf':>3} {'mode':<12} {'win':>3} {'it':>3} {'model ms':>9} {'+assumed':>9} "
            f"{'1 it':>7} {'native ms':>10} {'solve':>7} {'ISAM2 all':>10} {'all/mdl':>8} "
            f"{'all/nat':>8} {'ISAM2 def':>10} {'def/mdl':>8} {'def/nat':>8} {'nat-sim':>8}")
    print(head)
    for r in rows:
        print(f"{r['keyframe']:>3} {r['mode']:<12} {r['window']:>3} {r['iterations']:>3} "
              f"{r['model_ms']:>9.3f} {r['model_with_assumed_ms']:>9.3f} "
              f"{r['model_one_iteration_ms']:>7.3f} {r['native_ms']:>10.3f} "
              f"{r['native_solve_ms']:>7.3f} {r['isam2_ms']:>10.3f} "
              f"{r['isam2_ms'] / r['model_ms']:>8.2f} {r['isam2_ms'] / r['native_ms']:>8.2f} "
              f"{r['isam2_default_ms']:>10.3f} {r['isam2_default_ms'] / r['model_ms']:>8.2f} "
              f"{r['isam2_default_ms'] / r['native_ms']:>8.2f} "
              f"{r['native_vs_simulator_float64']:>8.1e}")
    summary = {}
    ratios = {"ratio_isam2": ("isam2_ms", "model_ms"),
              "ratio_isam2_native": ("isam2_ms", "native_ms"),
              "ratio_isam2_default": ("isam2_default_ms", "model_ms"),
              "ratio_isam2_default_native": ("isam2_default_ms", "native_ms"),
              "ratio_isam2_native_solve": ("isam2_ms", "native_solve_ms")}
    for name, sel in (("all", rows), ("incremental", [r for r in rows if r["mode"] !=
                                                       "batch"]),
                      ("batch", [r for r in rows if r["mode"] == "batch"])):
        if not sel:
            continue
        med = {key: float(np.median([r[key] for r in sel])) for key in
               ("model_ms", "model_with_assumed_ms", "model_one_iteration_ms", "native_ms",
                "native_solve_ms", "isam2_ms", "isam2_default_ms")}
        for key, (num, den) in ratios.items():
            med[key] = float(np.median([r[num] / r[den] for r in sel]))
        summary[name] = med
        print(f"median {name:<12} ({len(sel):>2}) {med['model_ms']:>9.3f} "
              f"{med['model_with_assumed_ms']:>9.3f} {med['model_one_iteration_ms']:>7.3f} "
              f"{med['native_ms']:>10.3f} {med['native_solve_ms']:>7.3f} "
              f"{med['isam2_ms']:>10.3f} {med['ratio_isam2']:>8.2f} "
              f"{med['ratio_isam2_native']:>8.2f} {med['isam2_default_ms']:>10.3f} "
              f"{med['ratio_isam2_default']:>8.2f} {med['ratio_isam2_default_native']:>8.2f}")
    print("ratios: median over the keyframes of the per-keyframe ratios")
    lat = [r["model_ms"] for r in rows]
    tails = {"model_median_ms": float(np.median(lat)),
             "model_p99_ms": float(np.percentile(lat, 99)),
             "isam2_median_ms": float(np.median([r["isam2_ms"] for r in rows]))}
    tails["ratio_isam2_of_medians"] = tails["isam2_median_ms"] / tails["model_median_ms"]
    print(f"per-update latency (model, every keyframe): median {tails['model_median_ms']:.3f} ms, "
          f"p99 {tails['model_p99_ms']:.3f} ms; ISAM2 all median {tails['isam2_median_ms']:.3f} "
          f"ms; ISAM2 median / model median {tails['ratio_isam2_of_medians']:.2f}")
    resources = _design_resources(args, graph, program, model) if on_chip else None
    print("ISAM2 all / the native library's LM solve alone (without the host's part of the "
          "update): median " + ", ".join(f"{name} {med['ratio_isam2_native_solve']:.2f}"
                                         for name, med in summary.items()))
    agreement = {"float64": max(vs_sim64), "priced": max(vs_priced)}
    print(f"native (double) vs the float64 simulator's incremental stream: largest "
          f"tangent-space distance over every keyframe's estimate {agreement['float64']:.3g} "
          f"(keyframe {int(np.argmax(vs_sim64))})")
    if native_program is not program:
        print(f"native (double) vs the {sol.precision} simulator run priced above: "
              f"{agreement['priced']:.3g} (keyframe {int(np.argmax(vs_priced))}; "
              f"{sol.precision} rounding)")
    return {"N": n, "incremental": k, "batch": batch, "precision": sol.precision,
            "linear": sol.linear, "units": sol.units, "cpe": sol.cpe,
            "clock_mhz": sol.clock_mhz, "status": result.status, "repeat": args.repeat,
            "native_status": sorted(statuses), "native_vs_simulator": agreement,
            "rows": rows, "median": summary, "tails": tails, "resources": resources,
            "not_emitted": NOT_EMITTED}


def _design_resources(args, graph, program, pricer) -> dict:
    """The on-chip design's DSP / BRAM36 as its plan prices them (``resources()``: window
    kernel, batch kernel, stream section) and, with ``--reader``, the second reader's DSP of
    the emitted design (``fgc_backends.hls.reader.read_design`` of the ``<name>_stream`` top:
    every call site its own module; a lower bound on what Vitis binds)."""
    res = pricer.model.resources()
    parts = ", ".join(f"{k} {d} DSP / {b:g} BRAM36" for k, (d, b) in res["parts"].items())
    print(f"design (plan): {res['dsp']} DSP, {res['bram36']:g} BRAM36 on {res['part']} "
          f"({'fits' if res['fits'] else 'does not fit'}; {parts})")
    out = {"plan_dsp": res["dsp"], "plan_bram36": res["bram36"], "fits": res["fits"],
           "parts": {k: list(v) for k, v in res["parts"].items()}}
    if args.reader:
        import tempfile

        import fgc_backends
        from fgc.app.streaming import stream_program
        from fgc_backends.hls.reader import emitted_files, read_design

        hls = fgc_backends.load("hls")
        scalar = "float" if args.precision == "float32" else "double"
        with tempfile.TemporaryDirectory(prefix="fgc-bench-stream-") as folder:
            hls.emit(stream_program(graph, program, None), folder, hls.Config(scalar=scalar))
            files, top = emitted_files(folder)
        tab = pricer.model.plan.ops
        design = read_design(files, top, tab.add.latency)
        dsp = design.dsp({k: getattr(tab, k).dsp for k in ("add", "mul", "div", "sqrt",
                                                           "special")})
        print(f"design (second reader, {top}): {dsp} DSP (a lower bound on what Vitis binds "
              "from the emitted text)")
        out["reader_dsp"] = dsp
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--N", type=int, default=None,
                   help="keyframes (lio.py: at most 470; default 400, --hls-model 30)")
    p.add_argument("--window", type=int, default=30)
    p.add_argument("--incremental", type=int)
    p.add_argument("--batch-every", default=None)
    p.add_argument("--hls-model", action="store_true",
                   help="paper A's setting priced by the accelerator plan's update model "
                        "against ISAM2 per keyframe")
    p.add_argument("--precision", choices=("float32", "float64"), default="float32",
                   help="--hls-model: the Program's and the plan's precision")
    p.add_argument("--linear", choices=("qr", "cholesky"), default="qr")
    p.add_argument("--one-step", action="store_true",
                   help="--hls-model: the stream on ISAM2's policy, one Gauss-Newton step an "
                        "update (default: LM to convergence)")
    p.add_argument("--units", type=int, default=4, help="--hls-model: n_u Update units")
    p.add_argument("--cpe", type=int, default=20, help="--hls-model: #CPE (Cholesky)")
    p.add_argument("--repeat", type=int, default=5,
                   help="--hls-model: ISAM2 and native runs (per-keyframe median)")
    p.add_argument("--skip-sim", action="store_true",
                   help="leave out the simulator's rows (minutes on 400 keyframes)")
    p.add_argument("--json", help="write the numbers as JSON")
    p.add_argument("--reader", action="store_true",
                   help="--hls-model: also emit the on-chip design and read its DSP back with "
                        "the second reader (minutes)")
    args = p.parse_args(argv)
    if args.hls_model:
        out = hls_model(args)
        if args.json:
            Path(args.json).write_text(json.dumps(out, indent=1, default=float) + "\n")
        return 0
    args.N = args.N or 400

    from fgc.app.specs import example

    lio = example("lio")

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
        pricer = streaming.UpdatePricer(streaming.stream_program(graph, prog, window))
        model = [p["latency_ms"] for p in map(pricer.price, updates) if p]
        acc["model_ms"] = {"median": float(np.median(model)),
                           "p99": float(np.percentile(model, 99)), "priced": len(model)}
        rows.append((name, streaming.timing_summary(u["seconds"] for u in result.updates),
                     acc))
        return final, updates

    from fgc_backends.native.streaming import FixedLagStream

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
    inc_native = None
    if args.incremental:
        batch = _batch(args.batch_every)
        inc = streaming.compile_stream(graph, incremental=args.incremental, batch_every=batch)
        inc_data = problem_data(graph, inc)
        plan = f"incremental K={args.incremental} batch {args.batch_every or '-'}"
        stream = _native_incremental(graph, inc)  # template libraries built here, not timed
        inc_online: dict = {}
        inc_result = stream.run(inc_data, lambda r: inc_online.update(
            streaming.keyframe_result(inc, r).newest(inc)))
        inc_final = {str(k): v for k, v in inc_result.values.items()}
        rows.append((f"fgc native, {plan} (whole update)",
                     streaming.timing_summary(u["seconds"] for u in inc_result.updates),
                     streaming.accuracy(graph, inc_final, inc_online, optimum)))
        inc_native = (inc, inc_result, inc_final, inc_online)
        out["native_incremental_split"] = {
            part: streaming.timing_summary(u[f"{part}_seconds"] for u in inc_result.updates)
            for part in ("solve", "store")}
        out["native_incremental_status"] = inc_result.status
        if not args.skip_sim:
            sim_row(f"fgc simulator, {plan}", inc, None)
    times, final, online = _isam2_times(graph, problem, clusters)
    rows.append(("gtsam ISAM2 update (1 per keyframe)", streaming.timing_summary(times),
                 streaming.accuracy(graph, final, online, optimum)))
    if inc_native is not None:
        inc, inc_result, inc_final, inc_online = inc_native
        # the oracle: ISAM2 fed the same keyframes with the same policy (older clusters held,
        # the factors across the window's edge kept linear), every variable after every update
        windows = [(u["first"], u["mode"] == "batch") for u in inc_result.updates]
        oracle = oracles.isam2_per_keyframe(graph, problem, clusters, windows)
        per_keyframe = oracles.per_keyframe_distance(
            [{"values": streaming.keyframe_result(inc, u).values} for u in inc_result.updates],
            oracle)
        out["native_incremental_vs_isam2"] = {
            "same_policy_per_keyframe_max_tangent": max(per_keyframe),
            "same_policy_worst_keyframe": int(np.argmax(per_keyframe)),
            "plain_final_max_tangent": max(float(np.linalg.norm(final[k].local(v)))
                                           for k, v in inc_final.items()),
            "plain_online_max_tangent": max(float(np.linalg.norm(online[k].local(v)))
                                            for k, v in inc_online.items())}
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
    print(f"{'':<58} {'median ms':>10} {'p99 ms':>10} {'model ms':>15} {'ATE final':>10} "
          f"{'ATE online':>11} {'max dist':>9}")
    for name, t, acc in rows:
        nan = float("nan")
        ate = acc["final"]["translation"]["rmse"] if acc else nan
        ate_online = acc["online"]["translation"]["rmse"] if acc else nan
        dist = acc["max_state_distance"] if acc else nan
        m = (acc or {}).get("model_ms")
        model = f"{m['median']:.3f} / {m['p99']:.3f}" if m else "-"
        print(f"{name:<58} {t['median_ms']:>10.2f} {t['p99_ms']:>10.2f} {model:>15} "
              f"{ate:>10.4g} {ate_online:>11.4g} {dist:>9.3g}")
    split = out["native_split"]
    print(f"native update split: LM solve median {split['solve']['median_ms']:.3f} ms, p99 "
          f"{split['solve']['p99_ms']:.3f} ms; marginalisation median "
          f"{split['marginal']['median_ms']:.3f} ms, p99 {split['marginal']['p99_ms']:.3f} ms "
          f"(status {out['native_status']})")
    if "native_incremental_split" in out:
        split = out["native_incremental_split"]
        print(f"native incremental update split: library LM solve median "
              f"{split['solve']['median_ms']:.3f} ms, p99 {split['solve']['p99_ms']:.3f} ms; "
              f"after the solve (store elimination in NumPy; re-expression and back-substitution "
              f"through the kept conditionals in the library) "
              f"median {split['store']['median_ms']:.3f} ms, p99 "
              f"{split['store']['p99_ms']:.3f} ms (status {out['native_incremental_status']})")
        vs = out["native_incremental_vs_isam2"]
        print(f"native incremental vs gtsam.ISAM2 with the same policy (older keyframes held, "
              f"edge factors kept linear): largest tangent-space distance "
              f"{vs['same_policy_per_keyframe_max_tangent']:.3g} over every variable after "
              f"every keyframe (worst keyframe {vs['same_policy_worst_keyframe']})")
        print(f"native incremental vs the plain ISAM2 row (relinearises everything, holds "
              f"nothing): largest tangent-space distance {vs['plain_final_max_tangent']:.3g} "
              f"in the final estimate, {vs['plain_online_max_tangent']:.3g} online")
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
