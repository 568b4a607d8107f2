"""Where paper A's on-chip update goes, term by term (issue 33): LIO N = 30 on KITTI, K = 3, batch
steps at keyframes 5 / 15 / 25, one Gauss-Newton step an update (ISAM2's policy), float32 QR.
The simulator runs the stream once; each update is priced by the emitted design's plan
(``WindowPricer``: model estimates at 143 MHz) and the largest terms of the chosen keyframes are
printed, then the median and p99 per update.

    python bench/bench_update_terms.py                      # n_u 4, two unit sets, ALLOCATION 2/3/1
    python bench/bench_update_terms.py --units 4 --sets 2 --allocation add=2,mul=3,div=1 \\
        --keyframes 5,14,25 --top 25
    python bench/bench_update_terms.py --qr-rows 2        # the Update units two rows a cycle
    python bench/bench_update_terms.py --units 8 --allocation default --bind add=fabric
                                        # adders bound to fabric (run_hls.tcl's config_op)
    python bench/bench_update_terms.py --root-wave          # the root step in a wavefront
    python bench/bench_update_terms.py --retire-special 2   # two special-function instances a
                                        # retraction (HlsConfig retire_special: the retire's II)
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_papers as b  # noqa: E402

from fgc.app import streaming  # noqa: E402
from fgc_backends.cost.operators import bind_label, parse_bind  # noqa: E402
from fgc_backends.hls import HlsConfig  # noqa: E402


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--units", type=int, default=4, help="n_u (default 4)")
    ap.add_argument("--sets", type=int, default=2, help="unit sets (default 2)")
    ap.add_argument("--allocation", default="add=2,mul=3,div=1",
                    help="factor datapaths' ALLOCATION, or 'default' (default add=2,mul=3,div=1)")
    ap.add_argument("--bind", default="default",
                    help="the operators' binding, e.g. add=fabric,mul=meddsp (HlsConfig.bind; "
                    "default: Vitis's, fulldsp adders and maxdsp multipliers)")
    ap.add_argument("--root-wave", action="store_true",
                    help="the root step in a wavefront behind its children (HlsConfig "
                         "root_wave; two unit sets)")
    ap.add_argument("--retire-special", type=int, choices=(1, 2, 3), default=None,
                    help="special-function instances of each retraction datapath (HlsConfig "
                         "retire_special; default: the design's, 1)")
    ap.add_argument("--keyframes", default="5,14,25", help="keyframes whose terms are printed")
    ap.add_argument("--top", type=int, default=25, help="terms printed per keyframe")
    ap.add_argument("--qr-rows", type=int, choices=(1, 2), default=1,
                    help="rows a cycle through each QR Update unit (HlsConfig qr_rows; default 1)")
    ap.add_argument("--data-width", type=int, choices=(32, 64), default=32,
                    help="bits a beat of the streaming top's data port (HlsConfig data_width: "
                         "64 = two float words a beat; default 32)")
    args = ap.parse_args(argv)
    shown = {int(k) for k in args.keyframes.split(",") if k.strip()}
    graph, program, sp = b.paper_a_window(b.Config(), units=args.units)
    updates = b.stream_updates(graph, program, sp)
    pricer = streaming.WindowPricer(sp, config=HlsConfig(
        scalar="float", unit_sets=args.sets, allocation=b.parse_allocation(args.allocation),
        qr_rows=args.qr_rows, bind=parse_bind(args.bind), root_wave=args.root_wave,
        retire_special=args.retire_special, data_width=args.data_width))
    res = pricer.model.resources()
    wave = ", the root in a wavefront" if args.root_wave else ""
    if args.retire_special:
        wave += f", {args.retire_special} special-function instance(s) a retraction"
    wave += f", data port {args.data_width} bits a beat" if args.data_width != 32 else ""
    print(f"n_u {args.units}, {args.sets} unit set(s), {args.qr_rows} row(s) a cycle{wave}, "
          f"ALLOCATION {args.allocation}, operators bound {bind_label(parse_bind(args.bind))}: "
          f"{res['dsp']:,} DSP / {res['bram36']:g} BRAM36 / {res['lut']:,} LUT / "
          f"{res['ff']:,} FF by the plan (model estimates): "
          + ("fits " if res["fits"] else f"OVER ({', '.join(res['over'])}) ") + res["part"])
    latency = []
    for u in updates:
        price = pricer.price(u)
        latency.append(price.latency_ms)
        if u.keyframe not in shown:
            continue
        print(f"keyframe {u.keyframe} ({price.mode}): {price.cycles:,} cycles")
        for t in sorted(price.terms, key=lambda t: -abs(t.cycles))[:args.top]:
            print(f"   {t.name:28s} {t.cycles:9,} = {t.each:,} x {t.times}"
                  + ("  (assumed)" if t.assumed else ""))
    print(f"per update: median {np.median(latency):.3f} ms, "
          f"p99 {np.percentile(latency, 99):.3f} ms")


if __name__ == "__main__":
    main()
