"""The accelerator plan's cost (backends/hls/plan/) beside today's model and the papers.

LIO N = 30 (GN + QR, float32, two-ended and serial, n_u ∈ {1, 4, 8}) and imu_window N = 50
(LM + Cholesky, float32, #CPE ∈ {5, 20, 80}); per-iteration latency in ms at 143 MHz, DSP,
BRAM36, LUT, FF. ``today`` is ``fgc_backends.cost.estimate`` (one accepted iteration).
Paper figures are whole-solve or whole-design numbers, printed for scale, not per iteration.

    FGC_CACHE_DIR=... python bench/bench_plan.py
"""

from __future__ import annotations

import dataclasses

from fgc.app.specs import example

imu_window = example("imu_window")
lio = example("lio")

from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends.cost import estimate  # noqa: E402
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost  # noqa: E402

PAPERS = {
    "lio": "paper A: two-ended 1.6x faster than serial; parallel 473 DSP / 163 BRAM36 / "
           "184,990 LUT / 211,895 FF; serial 255 / 88 / 99,733 / 120,416",
    "imu": "paper B N=50: #CPE=5 -> 171 ms, #CPE=120 -> 8.97 ms (whole solve); 6 DSP per CPE",
}


def row(label, program, **opts) -> float:
    program = dataclasses.replace(program, solver=dataclasses.replace(program.solver, **opts))
    plan = build_plan(program, PlanOptions.of(program))
    c = plan_cost(plan)
    today = estimate(program, 1)
    r = today.resources
    fits = "fits" if c.fits else "DOES NOT FIT (" + ",".join(c.over) + ")"
    print(f"{label:28s} plan {c.latency_ms:8.3f} ms  {c.dsp:4d} DSP {c.bram36:6.1f} BRAM36 "
          f"{c.lut:7d} LUT {c.ff:7d} FF {fits:10s} | today {today.iteration_latency_ms:8.3f} ms "
          f"{r.dsp:4d} DSP {r.bram:6.1f} BRAM36")
    if opts.get("units") == 1 or opts.get("cpe") == 5:
        print("      DSP by unit: " + ", ".join(f"{n} {d}" for n, d in c.dsp_by_unit if d))
    return c.latency_ms


def main() -> None:
    graph = lio.build(N=30)
    print("LIO N=30, GN + QR, float32")
    ms = {}
    for ordering in ("two-ended", "serial"):
        p = compile_graph(graph, SolverConfig(method="gn", linear="qr", ordering=ordering,
                                              precision="float32"))
        for u in (1, 4, 8):
            ms[ordering, u] = row(f"  {ordering} n_u={u}", p, units=u)
    print("  plan serial / two-ended: " + ", ".join(
        f"n_u={u} {ms['serial', u] / ms['two-ended', u]:.2f}x" for u in (1, 4, 8)))
    print("  " + PAPERS["lio"])
    p = compile_graph(imu_window.build(N=50),
                      SolverConfig(method="lm", linear="cholesky", precision="float32"))
    print("imu_window N=50, LM + Cholesky, float32")
    for c in (5, 20, 80):
        row(f"  #CPE={c}", p, cpe=c)
    print("  " + PAPERS["imu"])


if __name__ == "__main__":
    main()
