"""The accelerator cost model against the papers' published figures, and its curves.

Paper B (IMU window, LM + Cholesky, ZC706 at 143 MHz, float32): whole-solve latency at N = 50 with
5 and 120 CPEs, the 19.1× between them, "N = 20 under 1 ms", the linear solve's 82.4 % share and
the Vivado power of the built designs C1–C3. The three Cholesky stream models of
``CostParams.cholesky_stream`` are compared, each at the assumed 8 iterations and at the
iteration count that fits the two N = 50 points best. Paper A (LIO chain, GN + QR): latency
against n_u Update units, serial and two-ended elimination, and the speed-up between them.

    python bench/bench_cost_model.py [--lio-n 30] [--params]
"""

from __future__ import annotations

import argparse
import dataclasses
import math

import numpy as np

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import Program, SolverConfig
from fgc_backends.cost import CostParams, CostReport, describe, estimate
from fgc_backends.cost import calibration as cal

imu_window = example("imu_window")
lio = example("lio")

DESIGNS = tuple((p.name, p.cpe) for p in cal.PAPER_B_POWER)


def with_solver(program: Program, **changes) -> Program:
    return dataclasses.replace(program, solver=dataclasses.replace(program.solver, **changes))


def imu_program(n: int) -> Program:
    config = SolverConfig(method="lm", linear="cholesky", precision="float32")
    return compile_graph(imu_window.build(N=n), config)


def split(report: CostReport) -> str:
    s = report.solve
    return ", ".join(f"{f.name} {getattr(s, f.name) / s.total:.1%}"
                     for f in dataclasses.fields(s) if getattr(s, f.name))


# --------------------------------------------------------------------------------------------
# paper B
# --------------------------------------------------------------------------------------------


def calibration(imu50: Program) -> None:
    print(f"paper B, N = 50, LM + Cholesky, float32, {cal.PAPER_B_ITERATIONS} iterations "
          f"(defaults: cholesky_stream={CostParams().cholesky_stream!r})")
    reports = {}
    for point in cal.PAPER_B_LATENCY:
        r = estimate(with_solver(imu50, cpe=point.cpe), cal.PAPER_B_ITERATIONS)
        reports[point.cpe] = r
        err = cal.relative_error(r.latency_ms, point.ms)
        print(f"  #CPE {point.cpe:>3}: model {r.latency_ms:8.2f} ms, paper {point.ms:7.2f} ms "
              f"({err:+.1%}); linear solve {r.linear_solve_fraction:.1%}")
        print(f"      split: {split(r)}")
    lo, hi = (reports[p.cpe].latency_ms for p in cal.PAPER_B_LATENCY)
    paper = cal.PAPER_B_LATENCY[0].ms / cal.PAPER_B_LATENCY[1].ms
    print(f"  ratio 5 → 120 CPEs: model {lo / hi:.1f}×, paper {paper:.1f}×")


def stream_models(imu50: Program, imu20: Program) -> None:
    print("\nCholesky stream models (per-iteration cycles scaled by the iteration count):")
    print(f"  {'stream':<9}{'ratio':>7}{'K fit':>7}  {'@K=8: 5 CPE':>12}{'120 CPE':>9}"
          f"{'N=20 C3':>9}   {'@K fit: 5 CPE':>13}{'120 CPE':>9}{'N=20 C3':>9}")
    for stream in ("whole", "trailing", "dense"):
        params = CostParams(cholesky_stream=stream)
        per_it = [estimate(with_solver(imu50, cpe=p.cpe), 1, params).latency_ms
                  for p in cal.PAPER_B_LATENCY]
        n20 = estimate(with_solver(imu20, cpe=80), 1, params).latency_ms
        # least squares in log space: the K that balances the two relative errors
        k_fit = math.exp(np.mean([math.log(p.ms / t)
                                  for p, t in zip(cal.PAPER_B_LATENCY, per_it, strict=True)]))
        row = [f"{t * k:9.2f}" for k in (cal.PAPER_B_ITERATIONS, k_fit) for t in (*per_it, n20)]
        print(f"  {stream:<9}{per_it[0] / per_it[1]:6.1f}×{k_fit:7.2f}  {row[0]:>12}{row[1]}"
              f"{row[2]}   {row[3]:>13}{row[4]}{row[5]}")
    print("  paper:   19.1×           171.00     8.97    < 1 ms")


def linear_share(programs: dict[int, Program]) -> None:
    shares = []
    for n, program in programs.items():
        row = []
        for name, cpe in DESIGNS:
            r = estimate(with_solver(program, cpe=cpe), cal.PAPER_B_ITERATIONS)
            shares.append(r.linear_solve_fraction)
            row.append(f"{name} {r.latency_ms:8.3f} ms ({r.linear_solve_fraction:.1%})")
        print(f"  N = {n:>2}: " + "   ".join(row))
    print(f"  linear-solve share, average over C1–C3 × N: model {np.mean(shares):.1%}, paper "
          f"{cal.PAPER_B_LINEAR_SOLVE_SHARE:.1%}")


def power(imu80: Program) -> None:
    print(f"\npower of the built designs (N = {cal.PAPER_B_MAX_N}, 143 MHz):")
    dynamic = []
    for point in cal.PAPER_B_POWER:
        r = estimate(with_solver(imu80, cpe=point.cpe), cal.PAPER_B_ITERATIONS)
        u, t = r.utilization, r.resources
        dynamic.append(r.power_w - CostParams().power_static_w)
        print(f"  {point.name} ({point.cpe:>2} CPEs): model {r.power_w:.3f} W, Vivado "
              f"{point.watts:.3f} W ({cal.relative_error(r.power_w, point.watts):+.1%}); "
              f"DSP {t.dsp} ({u.dsp:.0%}) BRAM36 {t.bram:g} ({u.bram:.0%}) LUT {t.lut} "
              f"({u.lut:.0%}) FF {t.ff} ({u.ff:.0%}); {r.energy_mj:.2f} mJ per solve")
    a = np.c_[np.ones(len(dynamic)), dynamic]
    (static, scale), *_ = np.linalg.lstsq(a, [p.watts for p in cal.PAPER_B_POWER], rcond=None)
    print(f"  least-squares refit: static {static:.3f} W, dynamic × {scale:.3f} "
          "(defaults were set from this fit)")


def precision(imu50: Program) -> None:
    print("\nfloat64 against float32 (N = 50, C1):")
    for p in ("float32", "float64"):
        r = estimate(with_solver(imu50, cpe=20, precision=p), cal.PAPER_B_ITERATIONS)
        t = r.resources
        print(f"  {p}: {r.latency_ms:8.2f} ms, DSP {t.dsp}, LUT {t.lut}, FF {t.ff}, "
              f"BRAM36 {t.bram:g}, {r.power_w:.3f} W, fits: {r.utilization.fits}")


# --------------------------------------------------------------------------------------------
# paper A
# --------------------------------------------------------------------------------------------


def lio_curves(n: int) -> None:
    graph = lio.build(N=n)
    programs = {o: compile_graph(graph, SolverConfig(method="gn", linear="qr", ordering=o,
                                                     precision="float32"))
                for o in ("serial", "two-ended")}
    print(f"\npaper A, LIO chain N = {n}, GN + QR, float32: one iteration (ms)")
    print(f"  {'n_u':>4}{'serial':>10}{'two-ended':>11}{'speed-up':>10}   two-ended split")
    speedups = []
    for units in (1, 2, 4, 8):
        r = {o: estimate(with_solver(p, units=units), 1) for o, p in programs.items()}
        s = r["serial"].latency_ms / r["two-ended"].latency_ms
        speedups.append(s)
        print(f"  {units:>4}{r['serial'].latency_ms:10.3f}{r['two-ended'].latency_ms:11.3f}"
              f"{s:9.2f}×   {split(r['two-ended'])}")
    print(f"  average speed-up {np.mean(speedups):.2f}×, paper A "
          f"{cal.PAPER_A_TWO_ENDED_SPEEDUP}× (measured, on average)")
    for o, p in programs.items():
        t = estimate(with_solver(p, units=8), 1).resources
        print(f"  {o} n_u = 8: DSP {t.dsp}, BRAM36 {t.bram:g}, LUT {t.lut}, FF {t.ff}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lio-n", type=int, default=30, help="LIO keyframes (default 30)")
    parser.add_argument("--params", action="store_true", help="print the CostParams table")
    args = parser.parse_args()
    if args.params:
        print(describe(CostParams) + "\n")
    imu = {n: imu_program(n) for n in (20, 50, cal.PAPER_B_MAX_N)}
    calibration(imu[50])
    stream_models(imu[50], imu[20])
    print(f"\nlatency of C1–C3, {cal.PAPER_B_ITERATIONS} iterations:")
    linear_share(imu)
    power(imu[cal.PAPER_B_MAX_N])
    precision(imu[50])
    lio_curves(args.lio_n)


if __name__ == "__main__":
    main()
