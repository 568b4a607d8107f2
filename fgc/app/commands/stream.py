"""``fgc stream SPEC --window W | --incremental K``: a chain's keyframes one at a time (the
simulator, the native solver or the HLS C simulation), each update priced and timed, the
trajectory's accuracy against the batch optimum. ``simulate``, ``run`` and ``report`` with a
streaming option come here too."""

from __future__ import annotations

import time

import numpy as np

from fgc.app import streaming
from fgc.app.commands.options import streaming_args, values_arg
from fgc.app.commands.outputs import estimates_out, print_lines, write_json
from fgc.app.commands.steps import (
    EXIT_FAILED,
    EXIT_OK,
    backend_info,
    backend_names,
    is_streaming,
    load_backend,
    load_graph,
    project_name,
)
from fgc.app.run_report import require_finite_start
from fgc.compiler.stream import compile_stream, policy_of
from fgc.errors import FgcError
from fgc.frontend.geometry import Pose2, Pose3
from fgc.interop import estimates as export
from fgc.ir.datafile import problem_data
from fgc.ir.stream import FixedLag

NAME = "stream"
HELP = ("feed a chain's keyframes one at a time to the simulator, the native solver or the HLS "
        "C simulation (--window W or --incremental K): per-keyframe latency and estimate, "
        "trajectory, accuracy against the batch optimum")
FAILS = "the stream did not converge"
JSON_HELP = "also write the report as JSON"
HARDWARE = None  # hardware_args: --clock only


def add_arguments(p) -> None:
    streaming_args(p)
    p.add_argument("--tum", metavar="FILE", help="write the streamed trajectory (TUM)")
    p.add_argument("--backend", choices=backend_names(), default="sim",
                   help="sim: the simulator's updates and the plan's batch-iteration "
                        "price; native: the native solver solves each update; hls: the "
                        "HLS design's C simulation solves each update (--precision "
                        "float64: double, float32: float), priced by the accelerator "
                        "plan's update model, --units / --cpe / --clock as for the HLS "
                        "design (model estimates). native and hls compile a template "
                        "window once and keep the Bayes net on the host")
    p.add_argument("--model-only", action="store_true",
                   help="with --backend hls: no C simulation; the simulator's updates "
                        "priced by the update model")
    values_arg(p)



def stream_setup(args, precision_default: str):
    """The stream stage's StreamProgram (the options' policy) and the graph's data."""
    stages, graph, config = load_graph(args, precision_default)
    if config.incremental_k is not None:  # load_graph put the plan in the solver options
        policy = policy_of(config.incremental_k, config.batch_every)
    else:
        policy = policy_of(window=getattr(args, "window", None))
    sp = compile_stream(graph, config, policy, name=project_name(args.spec))
    stages.done("compile")
    args.stages = stages
    return sp, problem_data(graph, sp.program)


def mode_text(sp) -> str:
    """The StreamProgram's policy in words."""
    if isinstance(sp.policy, FixedLag):
        return f"fixed-lag window of {sp.policy.window} keyframes"
    plan = sp.program.schedule.incremental
    batches = ",".join(str(b) for b in plan.batch_keyframes) or "none"
    return f"incremental, newest {plan.window} clusters re-eliminated, batch steps {batches}"


def _newest_text(update, program) -> str:
    parts = []
    for key, value in update.newest(program).items():
        if isinstance(value, (Pose3, Pose2)):
            parts.append(f"{key} t=[" + " ".join(f"{x:.4f}" for x in np.asarray(value.t, float))
                         + "]")
    return ", ".join(parts) or f"{len(update.values)} variables"


def stream_word(args) -> str:
    """How a stream's output names its command: ``report`` when fgc report priced it, else
    ``stream`` (simulate and stream run the same stream)."""
    return "report" if getattr(args, "command", None) == "report" else "stream"


def cmd_stream(args, precision_default: str = "float64") -> int:
    if not is_streaming(args):
        raise FgcError(f"fgc {args.command} needs --incremental K or --window W")
    sp, data = stream_setup(args, precision_default)
    graph, program, window = sp.graph, sp.program, sp.window
    quiet = getattr(args, "quiet", False)
    n = len(program.schedule.clusters)
    backend = getattr(args, "backend", "sim")
    hls = backend_info(backend).hardware  # the backend prices its own design
    model_only = hls and getattr(args, "model_only", False)
    runs = "sim" if model_only else backend
    # the backend's runner first: a stream it cannot run is refused before anything is printed
    runner = streaming.make_runner(sp, runs)
    who, timed = runner.who, runner.timing_key
    on_chip = hls and load_backend(backend).on_chip(sp)
    if not quiet:
        if hls:
            print(_stream_hls_head(args, sp, n, model_only, on_chip), flush=True)
        else:
            print(f"fgc {stream_word(args)} {args.spec}: {n} keyframes, "
                  f"{mode_text(sp)}, "
                  f"{who} {program.solver.precision}; per keyframe: the accelerator plan's "
                  f"latency (model estimate: the update's iterations as batch iterations of a "
                  f"chain as long as its window; {streaming.UNPRICED} otherwise) and the "
                  f"{who}'s wall time", flush=True)
    online: dict = {}
    if on_chip:  # the emitted on-chip design's own price
        pricer = streaming.WindowPricer(sp, backend=backend)
    elif hls:
        pricer = streaming.update_model(graph, program, backend=backend)
    else:
        pricer = streaming.UpdatePricer(sp)
    priced: list = []
    builds = {"seconds": 0.0, "since": None}  # building the template windows (g++ or cache)

    def progress(update) -> None:
        if builds["since"] is not None:  # the first update after a build: that build's time
            since = time.perf_counter() - builds["since"]
            seconds = update.seconds if update.seconds == update.seconds else 0.0
            builds["seconds"] += max(0.0, since - seconds)
            builds["since"] = None
        online.update(update.newest(program))
        price = pricer.price(update)
        priced.append(price.as_dict() if hls else price)
        if quiet:
            return
        if on_chip:
            model = f"accelerator {price.latency_ms:7.3f} ms (model estimate, on chip)"
        elif hls:
            model = (f"accelerator {price.latency_ms:7.3f} ms + {price.assumed_ms:.3f} ms "
                     f"assumed (model estimate, {price.window}-keyframe window)")
        else:
            model = (f"{price['latency_ms']:7.3f} ms (model estimate, {price['window']}-"
                     "keyframe chain)" if price else "model estimate not available")
        wall = ("" if update.seconds != update.seconds  # NaN: no wall time to show
                else f"{update.seconds * 1e3:8.2f} ms ({who} wall time); ")
        print(f"  keyframe {update.keyframe:>4} ({update.mode}, from {update.first}): "
              f"{update.iterations:>3} iterations, {update.status}, {model}, {wall}"
              f"{_newest_text(update, program)}", flush=True)

    def building(size, index, count) -> None:
        builds["since"] = time.perf_counter()
        if not quiet:
            print(f"  compiling the {who}'s {size}-keyframe template window ({index + 1} of "
                  f"{count}; built once, reused by every update of that size)", flush=True)

    started = time.perf_counter()
    result = streaming.run_stream(sp, data, progress=progress, progress_build=building,
                                  runner=runner)
    stream_wall = time.perf_counter() - started
    require_finite_start(graph, result)
    final = {str(k): v for k, v in result.values.items()}
    acc = streaming.accuracy(graph, final, online, streaming.batch_optimum(graph))
    times = streaming.timing_summary(u["seconds"] for u in result.updates)
    report = {"spec": args.spec, "keyframes": n,
              "mode": sp.mode, "window": window, "incremental_k": program.solver.incremental_k,
              "batch_every": program.solver.batch_every, "status": result.status,
              "reason": result.reason, "iterations": result.iterations,
              "backend": backend, "solved_by": who, "model_estimate": priced,
              f"{timed}_update_time": times,
              "accuracy_vs_batch_optimum": acc, "wall_seconds": stream_wall,
              "build_seconds": builds["seconds"],
              "updates": [{k: v for k, v in u.items() if k != "values"}
                          for u in result.updates]}
    ate = acc.get("final", {}).get("translation", {})
    ate_online = acc.get("online", {}).get("translation", {})
    wall = (f"{who} update median {times['median_ms']:.2f} ms, p99 {times['p99_ms']:.2f} ms "
            "(wall time)" if times["median_ms"] == times["median_ms"]
            else f"{who}: no wall time (a C simulation's is not the accelerator's)")
    ate_text = (f"ATE rmse {ate['rmse']:.4g} m final, {ate_online['rmse']:.4g} m online"
                if "rmse" in ate and "rmse" in ate_online else
                "ATE not applicable (no Pose2/Pose3 variables: no trajectory)")
    head = (f"fgc {stream_word(args)} {args.spec}: {result.status} over {n} keyframes; {wall}; "
            f"vs batch optimum: {ate_text}")
    lines = [head, f"  largest tangent-space distance from the batch optimum "
                   f"{acc['max_state_distance']:.3g} (final estimate)"]
    if runs == "native" and builds["seconds"] > 0.05 * stream_wall:  # the build was the cost
        lines.append(f"  wall time {stream_wall:.1f} s, of which {builds['seconds']:.1f} s "
                     "building or loading the native library's template window(s) (built once "
                     "per design: a later run finds them in the cache)")
    model = [p["latency_ms"] for p in priced if p]
    if on_chip:
        lines.append(f"  accelerator per update (the on-chip design priced on its plan, model "
                     f"estimate): median {np.median(model):.3f} ms, p99 "
                     f"{np.percentile(model, 99):.3f} ms")
        res = pricer.model.resources()
        report["on_chip_resources"] = res
        parts = ", ".join(f"{name} {d} DSP / {b:g} BRAM36" for name, (d, b) in
                          res["parts"].items())
        lines.append(f"  on-chip design: {res['dsp']} DSP, {res['bram36']:g} BRAM36 (model "
                     f"estimate: {parts}); "
                     + ("fits " if res["fits"] else "does not fit ") + res["part"])
    elif hls:
        NOT_EMITTED = load_backend(backend).NOT_EMITTED  # noqa: N806  (the backend's constant)

        report["not_emitted"] = NOT_EMITTED
        extra = [p["latency_with_assumed_ms"] for p in priced]
        lines.append(f"  accelerator per update (update model on the HLS plan, model estimate): "
                     f"median {np.median(model):.3f} ms, p99 {np.percentile(model, 99):.3f} ms; "
                     f"with the assumed terms median {np.median(extra):.3f} ms; {NOT_EMITTED}")
    elif model:
        lines.append(f"  accelerator plan per update (model estimate): median "
                     f"{np.median(model):.3f} ms, p99 {np.percentile(model, 99):.3f} ms over "
                     f"{len(model)} priced updates ({len(priced) - len(model)} not priced: "
                     f"{streaming.UNPRICED})")
    if getattr(args, "tum", None):
        values = export.graph_values(graph, result.values)
        export.write_values(args.tum, values)
        lines.append(f"  trajectory → {args.tum} (TUM, t = key order index)")
    print_lines(args, lines)
    estimates_out(args, graph, report, result.values)
    write_json(args.json, report)
    # the one-step policy (one Gauss-Newton step an update) ends its updates at the iteration
    # limit by design
    done = ("converged", "max_iterations") if program.solver.one_step else ("converged",)
    return EXIT_OK if result.status in done else EXIT_FAILED


def _stream_hls_head(args, sp, n: int, model_only: bool, on_chip: bool) -> str:
    solver = sp.program.solver
    unit = (f"n_u = {solver.units} Update units" if solver.linear == "qr"
            else f"#CPE = {solver.cpe}")
    scalar = "double" if solver.precision == "float64" else "float"
    if on_chip:
        who = (f"simulator {solver.precision}" if model_only else
               f"the on-chip design's C simulation ({scalar})")
        kept = ("" if isinstance(sp.policy, FixedLag) else
                ", kept as its conditional with every earlier one (the kept Bayes net on chip, "
                "walked back each update)")
        tail = ("The emitted design keeps the window, its factors' words and the marginal prior "
                "in its memories between calls; a call brings one keyframe's storage and data "
                "words, and the keyframe leaving the window is eliminated on the accelerator's "
                f"QR unit{kept}"
                + (" (the estimate comes from the simulator)" if model_only else ""))
        return (f"fgc {stream_word(args)} {args.spec}: {n} keyframes, "
                f"{mode_text(sp)}, {who}; "
                f"per keyframe: the accelerator's latency, the emitted design's plan per call "
                f"({solver.linear.upper()}, n_u = {solver.units}, {solver.precision}, "
                f"{solver.clock_mhz:g} MHz; model estimate), beside the estimate. {tail}")
    who = (f"simulator {solver.precision}" if model_only else
           f"the HLS design's C simulation ({scalar}) per update, the kept Bayes net on the host")
    tail = ("The accelerator's incremental mode is not emitted in C++: the estimate comes from "
            "the simulator" if model_only else
            "Each update's window is solved by the C simulation of an emitted template window "
            "(built once); its conditionals, marginal prior and back-substitution are kept on "
            "the host, not on chip")
    return (f"fgc {stream_word(args)} {args.spec}: {n} keyframes, "
            f"{mode_text(sp)}, {who}; per "
            f"keyframe: the accelerator's latency from the update model on the HLS plan "
            f"({solver.linear.upper()}, {unit}, {solver.precision}, {solver.clock_mhz:g} MHz; "
            "model estimate: the plan's terms, then the assumed ones) beside the wall time and "
            f"estimate. {tail}")
