"""The emitted Cholesky design (issue 33: the HGC streamed from the factor datapaths, the
assembly beside the #CPE cascade) on LIO N=30 (#CPE 5 / 10 / 15 / 20 / 80) and paper B's
imu_window N=50 (#CPE 5 / 20 / 40 / 80 / 120), each with one cascade and with two side by side
(HlsConfig unit_sets=2, fgc_cascades.h): per design the plan's cycles per LM iteration
and their phase groups, ms per iteration and per solve (5 LM iterations, GTSAM's count on
imu_window), the plan's DSP beside the second reader's (bench_second_reader.measure: the
emitted C++ read back), BRAM36, the plan's fit verdict on the xc7z045 and the linear solver's
share.

    python bench/bench_cholesky.py
    python bench/bench_cholesky.py --cascades 2    # the two-cascade designs only
    python bench/bench_cholesky.py --lanes 1 2     # each also two words a cycle through the
                                                   # cascade (HlsConfig.cascade_lanes)
    python bench/bench_cholesky.py --before        # the HGC before the elimination (one
                                                   # cascade: hgc_beside off)
    python bench/bench_cholesky.py --backsub-lanes 2   # back-substitution two lanes wide

Model estimates at 143 MHz, float32 (no vendor tool here).
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_second_reader import measure  # noqa: E402

from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends.hls import HlsConfig  # noqa: E402
from fgc_backends.hls.emitter import accel_plan  # noqa: E402
from fgc_backends.hls.plan import plan_cost, plan_groups  # noqa: E402

CASES = [("lio", 30, c) for c in (5, 10, 15, 20, 80)] + [("imu_window", 50, c)
                                                          for c in (5, 20, 40, 80, 120)]
GROUPS = ("factor_jacobian", "hgc", "hgc_beside", "assemble", "cholesky", "backsub")


def main() -> None:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cascades", type=int, nargs="+", choices=(1, 2), default=(1, 2))
    parser.add_argument("--lanes", type=int, nargs="+", choices=(1, 2), default=(1,),
                        help="words a cycle through each cascade (HlsConfig.cascade_lanes)")
    parser.add_argument("--before", action="store_true",
                        help="every block type's HGC before the elimination (hgc_beside off)")
    parser.add_argument("--backsub-lanes", type=int, choices=(1, 2), default=1,
                        help="HlsConfig.backsub_lanes: back-substitution's width")
    args = parser.parse_args()
    for (ex, n, cpe), sets, lanes in ((c, k, la) for c in CASES for k in args.cascades
                                      for la in args.lanes):
        program = compile_graph(example(ex).build(N=n), SolverConfig(
            method="lm", linear="cholesky", cpe=cpe, precision="float32"), name=f"{ex}{cpe}")
        config = HlsConfig(scalar="float", unit_sets=sets, hgc_beside=not args.before,
                           backsub_lanes=args.backsub_lanes, cascade_lanes=lanes)
        plan = accel_plan(program, config)
        cost, groups = plan_cost(plan), plan_groups(plan)
        with tempfile.TemporaryDirectory() as d:
            read = measure(program, config, Path(d) / "design")
        ms = cost.cycles / cost.clock_mhz / 1e3
        print(f"{ex} N={n} #CPE={cpe} x{sets}{' L2' if lanes == 2 else ''}: "
              f"{cost.cycles:,} cycles/iteration, "
              f"{ms:.3f} ms/iteration, "
              f"{5 * ms:.2f} ms/solve (5 it.), DSP plan {cost.dsp} reader {read['reader_dsp']}, "
              f"BRAM36 {cost.bram36}, fits (plan) {cost.fits}, linear share "
              f"{cost.linear_cycles / cost.cycles:.3f}; "
              + ", ".join(f"{g} {groups[g]:,}" for g in GROUPS if g in groups), flush=True)


if __name__ == "__main__":
    main()
