"""The on-chip fixed-lag window's cycles: its counting C simulation against the update model, per
keyframe (fgc issue 19).

For LIO at N keyframes and window W: emit the on-chip window's design (``<name>_stream``,
backends/hls/window.py), build its testbench with -DFGC_COUNT_CYCLES (every loop of the kernel and
the units reports trip, II and depth as it runs: fgc_cycles.h) and stream the keyframes through it
(``tb --stream``): after each call the testbench prints that update's cycles and events. The model
(``WindowUpdateModel``) prices the same call from the emitted plan: each solve phase per execution
times the events the call ran, plus the stream section's loops (keyframe in, shift, marginal, out).
Prints per keyframe csim and model cycles, their ratio, and the update latency at the plan's clock
(model estimates), then the agreement of the streamed estimate with the native fixed-lag stream.

    python bench/bench_stream_cycles.py [--keyframes N] [--window W | --incremental K]
                                        [--scalar float|double]
"""

from __future__ import annotations

import argparse
import dataclasses
import re
import subprocess
import tempfile
import warnings

import numpy as np

from fgc.app.specs import example
from fgc.app.streaming import compile_stream, keyframe_result, one_step_solver
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends.cost.operators import normalise_bind
from fgc_backends.hls.config import DesignOptions, HlsConfig
from fgc_backends.hls.plan.stream import WindowUpdateModel
from fgc_backends.hls.streaming import OnChipFixedLagStream, OnChipIncrementalStream
from fgc_backends.native.streaming import FixedLagStream, IncrementalStream


def counted(stream: OnChipFixedLagStream, estimates_at_end: bool = False
            ) -> list[tuple[int, dict]]:
    """(cycles, events) per keyframe of a counting build of the stream's testbench (the inputs
    its last :meth:`run` wrote); ``estimates_at_end``: the kept estimates asked for after the
    last update only (else after every update)."""
    folder, name = stream.project.directory, stream.project.name
    stream.phases = []  # per keyframe: csim cycles per plan phase
    stream.estimates = []  # per keyframe (incremental): the kept estimates asked for (op 3)
    kernels = sorted(p.name for p in folder.glob("*.cpp") if not p.name.startswith("tb_"))
    subprocess.run(["g++", "-std=c++17", "-O1", "-DFGC_COUNT_CYCLES", "-Wno-unknown-pragmas",
                    "-I", "csim_include", "-I", "include", f"tb_{name}.cpp", *kernels,
                    "-o", "tb_count"], cwd=folder, check=True)
    mode = "--stream-estimates-at-end" if estimates_at_end else "--stream"
    out = subprocess.run(["./tb_count", mode, "data.txt", "stream.txt", "count.txt"],
                         cwd=folder, check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        m = re.match(r"^cycles (\d+) (\d+)(.*)$", line)
        if m:
            events = {k: int(v) for k, v in re.findall(r"(\S+)=(\d+)", m.group(3))}
            stream.phases.append({k[6:]: v for k, v in events.items() if k.startswith("phase:")})
            events = {k: v for k, v in events.items() if not k.startswith("phase:")}
            rows.append((int(m.group(2)), events))
        m = re.match(r"^estimates (\d+) (\d+)(.*)$", line)
        if m:
            events = {k: int(v) for k, v in re.findall(r"(\S+)=(\d+)", m.group(3))}
            stream.estimates.append((int(m.group(2)), events))
    return rows


def measure(keyframes: int, window: int, scalar: str, incremental: int | None = None,
            batch_every=None, one_step: bool = False, qr_rows: int = 1,
            units: int | None = None, design=None):
    """``design``: a DesignOptions (root_wave, allocation, bind; its qr_rows is ``qr_rows``)."""
    graph = example("lio").build(N=keyframes)
    # one_step: ISAM2's policy, one Gauss-Newton step an update (fgc.app.streaming.one_step)
    solver = one_step_solver() if one_step else None
    if units is not None:  # n_u Update units (the Program's solver setting)
        solver = dataclasses.replace(solver or SolverConfig(), units=units)
    out = tempfile.mkdtemp(prefix="fgc-stream-cycles-")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a double design over the part's DSP still simulates
        if incremental:
            program = compile_stream(graph, solver, incremental=incremental,
                                     batch_every=batch_every, name="lio_stream")
            stream = OnChipIncrementalStream(graph, program, scalar, out_dir=out,
                                             qr_rows=qr_rows, design=design)
        else:
            program = compile_stream(graph, solver, window=window, name="lio_stream")
            stream = OnChipFixedLagStream(graph, program, window, scalar, out_dir=out,
                                          qr_rows=qr_rows, design=design)
        data = problem_data(graph, program)
        result = stream.run(data)
        model = WindowUpdateModel(stream.layout, HlsConfig(scalar=scalar, qr_rows=qr_rows)
                                  if design is None else HlsConfig(
                                      scalar=scalar, design=dataclasses.replace(
                                          design, qr_rows=qr_rows)))
    rows = []
    for record, (cycles, events) in zip(result.updates, counted(stream), strict=True):
        ev = dict(events)
        # the marginal's or the batch store's own linearisation (when LM moved after its last
        # one), in their terms
        ev.setdefault("relinearize", 0)
        # a batch step's sweep passes linearise the window too: priced in the sweep's terms
        ev["linearize"] = ev.get("linearize", 0) - ev["relinearize"] - ev.get("sweep", 0)
        if record["mode"] == "batch" and model.batch is not None and not model.reuses(ev):
            ev["solve"] = ev.get("solve", 0) - 1  # the batch store's elimination, in its term
        price = model.price(record["keyframe"], record["iterations"], ev, record["status"])
        rows.append((record, cycles, price))
    # the kept keyframes' estimates, asked for after every update (op 3, not the update's)
    stream.estimate_rows = [(cycles, model.price_estimates(record["keyframe"], events))
                            for record, (cycles, events) in zip(result.updates, stream.estimates,
                                                               strict=True)
                            ] if stream.estimates else []
    return graph, program, data, result, rows, stream


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--keyframes", type=int, default=30)
    ap.add_argument("--window", type=int, default=10)
    ap.add_argument("--scalar", choices=("float", "double"), default="float")
    ap.add_argument("--batch-every", metavar="J,J,...", type=lambda t: tuple(
        int(v) for v in t.split(",")), help="batch steps of the incremental plan (keyframes)")
    ap.add_argument("--incremental", type=int, metavar="K",
                    help="the incremental plan on chip (newest K keyframes, the kept Bayes net) "
                         "instead of the fixed-lag window")
    ap.add_argument("--one-step", action="store_true",
                    help="ISAM2's update policy: one Gauss-Newton step per update (default: LM "
                         "to convergence)")
    ap.add_argument("--qr-rows", type=int, choices=(1, 2), default=1,
                    help="the QR Update units' rows a cycle (HlsConfig qr_rows; default 1)")
    ap.add_argument("--units", type=int, help="n_u Update units (default: the Program's)")
    ap.add_argument("--root-wave", action="store_true",
                    help="the design with the root step in a wavefront behind its children "
                         "(HlsConfig root_wave; two unit sets)")
    ap.add_argument("--allocation", help="factor datapaths' ALLOCATION, e.g. add=2,mul=3,div=1 "
                    "('default': the defaults)")
    ap.add_argument("--bind", help="the operators' binding, e.g. add=fabric (HlsConfig.bind)")
    ap.add_argument("--retire-special", type=int, choices=(1, 2, 3), default=None,
                    help="special-function instances of each retraction datapath (HlsConfig "
                         "retire_special; default: the design's, 1)")
    ap.add_argument("--data-width", type=int, choices=(32, 64), default=32,
                    help="bits a beat of the streaming top's data port (HlsConfig data_width: "
                         "64 = two float words a beat; default 32)")
    args = ap.parse_args()
    design = None
    if (args.root_wave or args.allocation or args.bind or args.retire_special
            or args.data_width != 32):
        alloc = tuple((k, int(v)) for k, v in (item.split("=") for item in
                                                args.allocation.split(","))) \
            if args.allocation and args.allocation != "default" else None
        bind = normalise_bind(tuple(tuple(item.split("=")) for item in args.bind.split(","))) \
            if args.bind else ()
        design = DesignOptions(root_wave=args.root_wave, allocation=alloc, bind=bind,
                               retire_special=args.retire_special,
                               data_width=args.data_width)
    graph, program, data, result, rows, stream = measure(args.keyframes, args.window, args.scalar,
                                                    args.incremental, args.batch_every,
                                                    args.one_step, args.qr_rows, args.units,
                                                    design)
    mode = (f"incremental K = {args.incremental}" + (
        f", batch at {','.join(map(str, args.batch_every))}" if args.batch_every else "")
        if args.incremental else f"fixed-lag W = {args.window}")
    policy = ", one Gauss-Newton step an update" if args.one_step else ""
    rows_note = f", QR Update units {args.qr_rows} rows a cycle" if args.qr_rows > 1 else ""
    rows_note += ", the root in a wavefront" if args.root_wave else ""
    if args.retire_special:
        rows_note += f", {args.retire_special} special-function instance(s) a retraction"
    rows_note += f", data port {args.data_width} bits a beat" if args.data_width != 32 else ""
    print(f"LIO N = {args.keyframes}, {mode}, {args.scalar} design{policy}{rows_note} "
          f"(on chip, model estimates at {rows[0][2].clock_mhz:g} MHz)")
    print(f"{'keyframe':>8} {'mode':>11} {'iters':>5} {'csim cycles':>12} {'model cycles':>12} "
          f"{'csim/model':>10} {'model ms':>9}")
    ratios = []
    for record, cycles, price in rows:
        ratios.append(cycles / price.cycles)
        print(f"{record['keyframe']:>8} {record['mode']:>11} {record['iterations']:>5} "
              f"{cycles:>12,} "
              f"{price.cycles:>12,} {cycles / price.cycles:>10.3f} {price.latency_ms:>9.3f}")
    lat = [p.latency_ms for _, _, p in rows]
    print(f"csim/model {min(ratios):.3f} … {max(ratios):.3f}; update latency median "
          f"{np.median(lat):.3f} ms, p99 {np.percentile(lat, 99):.3f} ms (model estimate)")
    if stream.estimate_rows:
        print("the kept keyframes' estimates asked for after each update (op 3: the walk if the "
              "update left them stale, the words out; not part of the update):")
        print(f"{'keyframe':>8} {'csim cycles':>12} {'model cycles':>12} {'csim/model':>10}")
        for (record, _, _), (cycles, price) in zip(rows, stream.estimate_rows, strict=True):
            # (nothing kept yet: no copy, no walk, no words: 0 cycles both)
            ratio = f"{cycles / price.cycles:>10.3f}" if price.cycles else f"{'-':>10}"
            print(f"{record['keyframe']:>8} {cycles:>12,} {price.cycles:>12,} {ratio}")
    native = (IncrementalStream(graph, program) if args.incremental
              else FixedLagStream(graph, program, args.window)).run(data)
    worst = 0.0
    for a, b in zip(result.updates, native.updates, strict=True):
        ua, ub = keyframe_result(program, a), keyframe_result(program, b)
        worst = max(worst, max(float(np.linalg.norm(ub.values[k].local(v)))
                               for k, v in ua.values.items()))
    print(f"on chip vs the native {mode} stream, worst tangent-space distance over every "
          f"keyframe's estimate: {worst:.2e}")


if __name__ == "__main__":
    main()
