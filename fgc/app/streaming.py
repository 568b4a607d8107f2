"""Streaming: a chain example's keyframes fed one at a time to an incremental or fixed-lag
update, per-keyframe results, the trajectory and its accuracy against the batch optimum. Behind
``fgc stream`` and :func:`fgc.stream`; ``fgc simulate / verify`` with ``--incremental`` or
``--window`` use the same pieces.

The stream itself is the middle end's (:mod:`fgc.compiler.stream`: a
:class:`fgc.ir.stream.StreamProgram`, the chain Program with its policy and slot layout); who
runs the updates (``run_stream(..., backend=)``) is a backend reached through the registry and
its contract's ``stream`` (``fgc_backends.load(name).stream(stream_program, config)``): the
simulator (the reference semantics: the emitted simulator's incremental module), the native
solver or the HLS design's C simulation (template windows compiled once, docs/native.md,
docs/hls.md).

Modes:

- **incremental** (``SolverConfig.incremental_k`` = K, ``batch_every``): each keyframe
  re-eliminates the newest K clusters on the kept Bayes net (paper A), batch steps re-eliminate
  all; every variable keeps an estimate (back-substitution through the kept conditionals).
- **fixed-lag window** (``window`` = W): after each keyframe the newest W keyframes are held; the
  one leaving is marginalised into a dense Gaussian prior on the window, linear in the local
  coordinates at the point where it was formed (its linearisation point never moves; every
  other factor of the window is relinearised each iteration). Marginalised keyframes keep the
  estimate of the update that marginalised them.

Latency: the accelerator's cost model (``plan_cost``) prices batch iterations of a Program.
:class:`UpdatePricer` prices an update as that many batch iterations of a chain as long as the
update's window (a model estimate of an approximation: the window's dense marginal prior is
priced as the chain's own priors); the simulator's wall time is reported beside it.
:func:`update_model` (``fgc stream --backend hls``) prices each update as the plan's units would
run it: the window's factors and clusters only, the kept conditionals, batch keyframes as batch
iterations of their Program (:mod:`fgc_backends.hls.plan.update`, docs/hls.md).
"""

from __future__ import annotations

import queue
import threading
from collections.abc import Iterator
from dataclasses import dataclass, replace

import numpy as np

from fgc.app import metrics
from fgc.app.run_report import gtsam_optimize, plan_summary
from fgc.compiler.stream import check_mode, compile_chain, policy_of, prefix_program, stream_program
from fgc.compiler.stream import compile_stream as stream_stage
from fgc.errors import FgcError
from fgc.frontend.dsl import Graph
from fgc.frontend.geometry import Pose2, Pose3, type_named
from fgc.interop.to_gtsam import to_gtsam, values_from_gtsam
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc.ir.stream import FixedLag, StreamProgram
from fgc_backends import load

__all__ = ["KeyframeResult", "StreamProgram", "UpdatePricer", "WindowPricer", "accuracy",
           "batch_optimum", "check_mode", "compile_stream", "keyframe_result", "make_runner",
           "on_chip", "one_step_solver", "poses", "prefix_program", "run_stream", "stream",
           "stream_program", "timing_summary", "update_model"]

UNPRICED = "one-keyframe windows and window sizes past the first four others seen"
HW_REFUSAL = ("incremental and fixed-lag modes run keyframe by keyframe in fgc stream (--backend "
              "sim, native or hls: the simulator, the native solver or the HLS design's C "
              "simulation solves each update; fgc compile --backend hls --window W emits the "
              "on-chip fixed-lag window); this command runs batch solves on this backend")


@dataclass(frozen=True)
class KeyframeResult:
    """One keyframe's update: its index, mode ("incremental", "batch" or "fixed-lag"), the
    first cluster re-eliminated, LM iterations, status, the window cost, the simulator's wall
    time (s) and the estimate after the update (fgc values by key, of the variables that have
    arrived — of the window, fixed-lag)."""

    keyframe: int
    mode: str
    first: int
    iterations: int
    status: str
    cost: float
    seconds: float
    values: dict
    # LM's rejected trial steps and the iterations that worked out the rounding-noise band
    # (the simulator's records count them; the native and C-simulation streams' do not: None)
    rejected: int | None = None
    noise_passes: int | None = None

    def newest(self, program) -> dict:
        """The estimate of this keyframe's own variables."""
        return {k: self.values[k] for k in program.schedule.clusters[self.keyframe]}


def one_step_solver(solver: SolverConfig | None = None) -> SolverConfig:
    """ISAM2's update policy as a stream's solver: one Gauss-Newton step per update
    (``method="gn"``, ``max_iterations=1``: relinearise every variable of the update's window
    at its estimate, solve without damping, take the step; ``fgc stream --solver gn
    --max-iterations 1``), what ``gtsam.ISAM2.update`` does per keyframe with relinearisation
    threshold 0, instead of LM to convergence. The window, the kept Bayes net, the marginal and
    the batch steps are the stream's as before; each update's record has status
    "max_iterations". ``solver``'s other options are kept (default: SolverConfig())."""
    return replace(solver if solver is not None else SolverConfig(), method="gn",
                   max_iterations=1)


def compile_stream(graph: Graph, solver=None, incremental: int | None = None,
                   batch_every=None, window: int | None = None, name: str = "stream"):
    """The Program for a stream: ``solver`` (a SolverConfig, default float64) with the
    incremental plan, if asked for. Raises FgcError when the graph is not a chain
    (:func:`fgc.compiler.stream.compile_chain`; :func:`stream_program` adds the policy and the
    slot layout)."""
    return compile_chain(graph, solver, policy_of(incremental, batch_every, window), name)


def run_stream(stream, data, window: int | None = None, progress=None, precision=None,
               backend: str = "sim", graph: Graph | None = None, scalar: str | None = None,
               progress_build=None, runner=None):
    """Run the updates keyframe by keyframe under ``stream``'s policy; ``progress(KeyframeResult)``
    after each keyframe. ``stream`` is the stream stage's StreamProgram (its policy, graph and
    slot layout: what the commands pass), or, for a caller holding only a chain Program, that
    Program with its ``window`` (None: the Program's incremental plan) and ``graph``.

    ``backend`` is reached through the contract (:func:`make_runner`): ``"sim"`` returns the
    simulator's SimResult (``precision`` overrides the Program's); ``"native"`` and ``"hls"``
    (``scalar`` "double" or "float", default the Program's precision) need the ``graph`` the
    Program was compiled from, compile their template windows first (``progress_build(size,
    index, count)`` before each) and return a :class:`fgc_backends.cfamily.stream.StreamResult`.
    ``runner``: the backend's runner of the stream, if already made."""
    if isinstance(stream, StreamProgram):
        if window is not None or graph is not None:
            raise FgcError("run_stream: a StreamProgram carries its policy and graph")
        sp = stream
    else:
        sp = stream_program(graph, stream, window)
    program = sp.program
    callback = None
    if progress is not None:
        def callback(raw):
            progress(keyframe_result(program, raw))
    runner = runner or make_runner(sp, backend, precision=precision, scalar=scalar)
    return runner.run(data, callback, progress_build)


def make_runner(sp: StreamProgram, backend: str = "sim", precision=None, scalar=None):
    """``backend``'s stream runner of ``sp`` (the contract's ``stream``): checked when made, so
    a stream the backend cannot run is refused before anything runs. ``precision`` (the
    simulator's) and ``scalar`` (a C-family backend's Config) only when given."""
    module = load(backend)
    if precision is not None:
        return module.stream(sp, precision=precision)
    return module.stream(sp, module.Config(scalar=scalar) if scalar is not None else None)


def keyframe_result(program, record: dict) -> KeyframeResult:
    """A KeyframeResult from an update record (raw storage lists or fgc values)."""
    values = record["values"]
    if isinstance(values, list):
        values = {spec.key: type_named(spec.type_name, spec.dim).from_storage(
            np.asarray(v, dtype=np.float64))
            for spec, v in zip(program.variables, values, strict=True) if v is not None}
    return KeyframeResult(record["keyframe"], record["mode"], record["first"],
                          record["iterations"], record["status"], float(record["cost"]),
                          float(record.get("seconds", float("nan"))), values,
                          record.get("rejected"), record.get("noise_passes"))


def stream(graph: Graph, window: int | None = None, incremental: int | None = None,
           batch_every=None, solver=None, backend: str = "sim") -> Iterator[KeyframeResult]:
    """Feed ``graph``'s keyframes one at a time to ``backend`` (sim, native or hls, as
    :func:`run_stream`) and yield each keyframe's :class:`KeyframeResult` as soon as its update
    is done (the updates run in a worker thread). Either ``window`` (fixed-lag, W keyframes) or
    ``incremental`` (K, with optional ``batch_every``)."""
    if window is None and incremental is None:
        raise FgcError("fgc.stream needs window=W or incremental=K")
    sp = stream_stage(graph, solver, policy_of(incremental, batch_every, window))
    data = problem_data(graph, sp.program)
    results: queue.Queue = queue.Queue()

    def work():
        try:
            run_stream(sp, data, progress=lambda r: results.put(("update", r)), backend=backend)
            results.put(("done", None))
        except BaseException as exc:  # handed to the consumer, raised there
            results.put(("error", exc))

    worker = threading.Thread(target=work, daemon=True)
    worker.start()
    while True:
        kind, item = results.get()
        if kind == "update":
            yield item
        elif kind == "error":
            raise item
        else:
            break
    worker.join()


# --------------------------------------------------------------------------------------------
# a model estimate per update
# --------------------------------------------------------------------------------------------


class UpdatePricer:
    """The accelerator plan's price of a keyframe update (``plan_summary``, what ``fgc
    simulate`` prints): the update's iterations priced as batch iterations of a chain of the
    same factors with as many keyframes as the update re-eliminates (the graph's first S
    keyframes, whose priors stand in for the window's marginal prior). One Program is compiled
    per window size: the steady size (W + 1 of a fixed-lag window, K of an incremental plan)
    and at most ``max_sizes`` others as they come (later sizes: not priced, None)."""

    def __init__(self, sp: StreamProgram, max_sizes: int = 4):
        program = sp.program
        self.graph, self.program, self.max_sizes = sp.graph, program, max_sizes
        self.per_iteration: dict[int, dict | None] = {}
        steady = sp.policy.window + 1 if isinstance(sp.policy, FixedLag) else \
            program.schedule.incremental.window
        n = len(program.schedule.clusters)
        if steady is not None and 2 <= steady <= n:  # the size most updates have: first
            self._add(steady)

    def _add(self, size: int) -> None:
        self.per_iteration[size] = plan_summary(self._sub_program(size), 1)

    def _sub_program(self, size: int):
        return prefix_program(self.graph, self.program, size)

    def price(self, update: KeyframeResult) -> dict | None:
        """{"cycles", "latency_ms", "window"} of the update, or None when not priced."""
        size = update.keyframe - update.first + 1
        if size not in self.per_iteration:
            if len(self.per_iteration) > self.max_sizes or size < 2:
                return None
            self._add(size)
        one = self.per_iteration[size]
        k = max(1, update.iterations)
        return {"cycles": k * one["iteration_cycles"], "latency_ms": k * one["latency_ms"],
                "window": size}


def on_chip(sp: StreamProgram, backend: str = "hls") -> bool:
    """Whether the hardware ``backend``'s design runs the stream ``sp`` on chip (its
    ``on_chip``)."""
    return load(backend).on_chip(sp)


class WindowPricer:
    """The on-chip design's price of each update (``fgc_backends.hls.window_model``: the
    design ``fgc compile --backend hls --window W`` or ``--incremental K`` emits; model
    estimates): ``price(update)`` from its keyframe and iterations."""

    def __init__(self, sp: StreamProgram, scalar: str | None = None, backend: str = "hls",
                 config=None):
        # config: the backend's design options (HLS: an HlsConfig), default its default design
        self.model = (load(backend).window_model(sp, scalar) if config is None
                      else load(backend).window_model(sp, scalar, config))

    def price(self, update):
        price = self.model.price(int(update.keyframe), int(update.iterations),
                                 status=update.status)
        if price.mode != update.mode or price.first != update.first:
            raise FgcError(f"internal error: keyframe {update.keyframe} is a {update.mode} "
                           f"update from {update.first}, the on-chip design's model prices a "
                           f"{price.mode} one from {price.first}")
        return price


def update_model(graph: Graph, program, units: int | None = None, cpe: int | None = None,
                 backend: str = "hls"):
    """The accelerator plan's update model of a stream over ``program``
    (``fgc_backends.hls.update_model``; model estimates, the accelerator's incremental mode is
    not emitted): ``units`` / ``cpe`` default to the Program's; a batch keyframe j is priced on
    :func:`prefix_program` of its j + 1 keyframes."""
    return load(backend).update_model(graph, program, units, cpe)


# --------------------------------------------------------------------------------------------
# accuracy and summaries
# --------------------------------------------------------------------------------------------


def poses(graph: Graph, values: dict) -> dict:
    """The pose values (Pose3, else Pose2) of ``values`` ({str key: value}) in graph order."""
    out = {str(k): values[str(k)] for k in graph.variables if str(k) in values}
    kind = Pose3 if any(isinstance(v, Pose3) for v in out.values()) else Pose2
    return {k: v for k, v in out.items() if isinstance(v, kind)}


def batch_optimum(graph: Graph) -> dict:
    """GTSAM's LM optimum of the whole graph ({str key: fgc value})."""
    problem = to_gtsam(graph)
    result, _ = gtsam_optimize(problem)
    return {str(k): v for k, v in values_from_gtsam(graph, problem, result).items()}


def accuracy(graph: Graph, final: dict, online: dict, optimum: dict) -> dict:
    """ATE (translation m, rotation deg; no alignment: both in the graph's frame) of the final
    streamed trajectory and of the online one (each keyframe's estimate when it arrived)
    against the batch optimum, and the largest tangent-space distance of any variable."""
    ref = poses(graph, optimum)
    out = {}
    for name, values in (("final", final), ("online", online)):
        est = poses(graph, values)
        keys = [k for k in ref if k in est]
        if not keys:
            continue
        e = metrics.as_trajectory({k: est[k] for k in keys})
        r = metrics.as_trajectory({k: ref[k] for k in keys})
        out[name] = {rel: metrics.ate(e, r, relation=rel).statistics()
                     for rel in metrics.RELATIONS}
    out["max_state_distance"] = max(float(np.linalg.norm(optimum[k].local(v)))
                                    for k, v in final.items())
    return out


def timing_summary(seconds) -> dict:
    s = np.asarray(list(seconds), dtype=float)
    return {"updates": int(s.size), "median_ms": float(np.median(s) * 1e3),
            "p99_ms": float(np.percentile(s, 99) * 1e3), "max_ms": float(s.max() * 1e3),
            "total_s": float(s.sum())}
