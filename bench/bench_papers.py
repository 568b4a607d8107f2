"""Paper reproduction: each published figure of paper A (LIO, ICCAD 2022) and paper B (IMU
window) beside fgc's figure for the same configuration, with why they differ.

fgc's hardware figures are the accelerator plan's arithmetic (``fgc_backends.hls.plan``:
``plan_cost(build_plan(...))``, model estimates at 143 MHz on the xc7z045); GTSAM's per-iteration
time is measured here, in this process (gtsam python wheel, LM, median of timed ``iterate()``
calls after one warm-up solve). Storage ratios are ``Program.storage`` (fgc/compiler/storage.py).

    FGC_CACHE_DIR=... python bench/bench_papers.py            # LIO N=30, IMU N=50 (≈ 1-2 min)
    FGC_CACHE_DIR=... python bench/bench_papers.py --small    # LIO N=5, IMU N=5 (a smoke run)
"""

from __future__ import annotations

import argparse
import re
import statistics
import time
from dataclasses import dataclass

from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends.hls.plan import (  # noqa: E402
    DEFAULT_ALLOCATION,
    PART_DSP,
    PlanOptions,
    build_plan,
    plan_cost,
    plan_power_w,
)

imu_window = example("imu_window")
lio = example("lio")


@dataclass(frozen=True)
class Row:
    paper: str
    figure: str
    published: str
    fgc: str
    why: str


@dataclass(frozen=True)
class Config:
    lio_n: int = 30
    imu_n: int = 50
    storage_ns: tuple[int, int] = (20, 80)
    units: tuple[int, ...] = (1, 2, 4, 8, 16, 32)
    alloc_scales: tuple[int, ...] = (1, 2, 4)
    cpes: tuple[int, ...] = (5, 20, 40, 80, 120)
    c123: tuple[int, ...] = (20, 40, 80)  # paper B's C1-C3 #CPE (backends/cost/params.py)
    gtsam_iterations: int = 5
    gtsam_repeats: int = 5


SMALL = Config(lio_n=5, imu_n=5, storage_ns=(4, 6), units=(1, 8), alloc_scales=(1,),
               cpes=(5, 20), c123=(20,), gtsam_iterations=2, gtsam_repeats=1)


def _cost(program, **options):
    return plan_cost(build_plan(program, PlanOptions.of(program, **options)))


def _scaled(scale: int) -> tuple[tuple[str, int], ...]:
    return tuple((k, n * scale) for k, n in DEFAULT_ALLOCATION)


def best_design(program, cfg: Config):
    """The lowest per-iteration latency over n_u × QR unit sets × factor-datapath ALLOCATION
    scale × Jacobian storage, among designs that fit the xc7z045: (options dict, Cost), and the
    number of designs tried."""
    widest = max(len(level) for level in program.schedule.levels)
    best, tried = None, 0
    for units in cfg.units:
        for sets in sorted({1, min(2, widest)}):
            for scale in cfg.alloc_scales:
                for storage in ("whitened", "raw"):
                    opts = dict(units=units, unit_sets=sets, allocation=_scaled(scale),
                                jacobian_storage=storage)
                    c = _cost(program, **opts)
                    tried += 1
                    if c.fits and (best is None or c.cycles < best[1].cycles):
                        best = ({**opts, "allocation": f"default × {scale}"}, c)
    return best, tried


def gtsam_ms_per_iteration(graph, cfg: Config) -> dict[str, tuple[float, float]]:
    """(median, fastest) wall time in ms of one GTSAM LM iteration (``iterate()``), per linear
    solver; the machine is shared, so the fastest is the least disturbed."""
    import gtsam

    from fgc.interop.to_gtsam import to_gtsam

    problem = to_gtsam(graph)
    out = {}
    for solver in ("MULTIFRONTAL_CHOLESKY", "MULTIFRONTAL_QR"):
        params = gtsam.LevenbergMarquardtParams()
        params.setLinearSolverType(solver)
        gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params).optimize()
        times = []
        for _ in range(cfg.gtsam_repeats):
            opt = gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params)
            for _ in range(cfg.gtsam_iterations):
                t0 = time.perf_counter()
                opt.iterate()
                times.append(time.perf_counter() - t0)
        out[solver] = (statistics.median(times) * 1e3, min(times) * 1e3)
    return out


def _reflections(program, opts) -> tuple[tuple[int, float], int]:
    """(reflections in the middle QR level's first process, mean cycles of one), and the
    depth of a dot product over that level's widest column."""
    from fgc_backends.hls.plan import dot_loop

    plan = build_plan(program, PlanOptions.of(
        program, **{k: v for k, v in opts.items() if k != "allocation"}))
    levels = [ph for ph in plan.phases if ph.name.startswith("qr_level")]
    loops = [lp for lp in levels[len(levels) // 2].processes[0].loops if "_reflection" in lp.name]
    mean = sum(lp.cycles for lp in loops) / max(len(loops), 1)
    return (len(loops), mean), dot_loop("d", 16, plan.ops).depth


def _levels(c) -> int:
    return sum(1 for name, _ in c.phase_cycles if name.startswith("qr_level"))


def _other(c) -> float:
    return 1 - c.linear_cycles / c.cycles


def _dominant(c) -> str:
    """The phase group (prefix before the level number) taking most of one iteration."""
    groups: dict[str, int] = {}
    for name, cycles in c.phase_cycles:
        key = re.sub(r"_level\d+$", "", name)
        groups[key] = groups.get(key, 0) + cycles
    name, cycles = max(groups.items(), key=lambda kv: kv[1])
    return f"{name} {cycles / c.cycles:.0%}"


def _res(c) -> str:
    return f"{c.dsp} DSP / {c.bram36:g} BRAM36 / {c.lut:,} LUT / {c.ff:,} FF"


def paper_a(cfg: Config) -> list[Row]:
    graph = lio.build(N=cfg.lio_n)
    progs = {o: compile_graph(graph, SolverConfig(method="gn", linear="qr", ordering=o,
                                                  precision="float32"))
             for o in ("two-ended", "serial")}
    rows = []
    best = {o: best_design(p, cfg) for o, p in progs.items()}
    (two_opts, two), tried = best["two-ended"]
    (ser_opts, ser), _ = best["serial"]
    same = {o: _cost(p, units=two_opts["units"]) for o, p in progs.items()}
    a = f"A (LIO N={cfg.lio_n})"
    rows.append(Row(a, "two-ended vs serial speed-up", "1.6×",
                    f"{same['serial'].cycles / same['two-ended'].cycles:.2f}× at n_u="
                    f"{two_opts['units']}; best vs best {ser.cycles / two.cycles:.2f}×",
                    f"two unit sets halve the sequential QR and back-substitution levels "
                    f"({_levels(same['serial'])} → {_levels(same['two-ended'])}); the factor "
                    "datapaths, gradient pass, state update and LM control "
                    f"({_other(same['two-ended']):.0%} of the two-ended iteration) and each "
                    "step's stacking and commit (one step after another) are not split, so the "
                    "speed-up stays under 2×; paper A's lower 1.6× suggests its non-eliminating "
                    "work weighs more than the plan's"))
    gt = gtsam_ms_per_iteration(graph, cfg)
    g_med = min(med for med, _ in gt.values())
    g_fast = min(fast for _, fast in gt.values())
    levels = sum(1 for name, _ in two.phase_cycles if name.startswith("qr_level"))
    qr_cycles = sum(c for name, c in two.phase_cycles if name.startswith("qr_level"))
    refl, dot_depth = _reflections(progs["two-ended"], two_opts)
    rows.append(Row(a, "best design vs GTSAM (per iteration)", "9.3× (16-core Intel)",
                    f"{g_fast / two.latency_ms:.2f}× against GTSAM's fastest iteration, "
                    f"{g_med / two.latency_ms:.2f}× against its median (GTSAM LM ms/iteration "
                    "here, median / fastest: "
                    + ", ".join(f"{k.split('_')[1].lower()} {m:.3f} / {f:.3f}"
                                for k, (m, f) in gt.items())
                    + f"; plan {two.latency_ms:.3f} ms, n_u={two_opts['units']}, "
                    f"{two_opts['unit_sets']} unit sets, ALLOCATION {two_opts['allocation']}, "
                    f"{two_opts['jacobian_storage']} Jacobians; best of {tried} designs)",
                    f"limited by {_dominant(two)} of the cycles ({levels} sequential QR levels"
                    f" × ~{qr_cycles // max(levels, 1):,} cycles; a step is {refl[0]} "
                    f"Householder reflections, one DATAFLOW region each, ~{refl[1]:.0f} cycles "
                    f"each, {dot_depth} of them the depth of one dot product - multiply + "
                    "adder tree at the documented add latency 11 - and the rest the batched "
                    "Updates' fold / scale and update pipelines and the column stream): within "
                    "a reflection the design overlaps what it can (the next pivot column is "
                    "updated and streamed to the Evaluate first; qr_finish's square root and "
                    "divide run under the next region's broadcast), but region j + 1 starts "
                    "only when region j has drained, so with n_u ≥ the columns more Update "
                    "units cannot shorten that chain; paper A's few hundred cycles a step "
                    "would need reflections pipelined into each other (a column taking "
                    "reflection j + 1 while others still take j), a design the plan does not "
                    "contain"))
    rows.append(Row(a, "parallel (two-ended) resources", "473 DSP / 163 BRAM36 / 184,990 LUT / "
                    "211,895 FF", _res(two) + " (best design)",
                    "operator DSP/LUT/FF are assumed (operators.py); the factor datapaths are "
                    "ALLOCATION-limited and their DSP dominate; BRAM counts only the plan's "
                    "memories (no AXI/DMA or HLS control overhead)"))
    rows.append(Row(a, "serial resources", "255 DSP / 88 BRAM36 / 99,733 LUT / 120,416 FF",
                    _res(ser) + f" (best serial, n_u={ser_opts['units']})",
                    "one unit set instead of two, same factor datapaths: the plan's factor "
                    "units are not halved as the paper's are"))
    st = progs["two-ended"].storage
    st_cost = {s: _cost(progs["two-ended"], units=two_opts["units"], jacobian_storage=s)
               for s in ("whitened", "raw")}
    words = {s: c.words for s, c in st_cost.items()}
    whiten = dict(st_cost["raw"].phase_cycles)["whiten_stack"]
    rows.append(Row(a, f"storage reduction, 3 steps, {cfg.lio_n} keyframes",
                    "15.5× / 19.0× / 56.3×",
                    " / ".join(f"{st.ratio(i):.1f}×" for i in (1, 2, 3))
                    + f"; plan memory words whitened {words['whitened']:,} → raw "
                    f"{words['raw']:,}, for +{whiten:,} whiten_stack cycles an iteration "
                    f"({st_cost['raw'].latency_ms / st_cost['whitened'].latency_ms - 1:+.1%})",
                    "fgc stores the whitened A = W·J: a full square-root information W mixes "
                    "rows and leaves no structural zeros to skip in step 3; the papers store raw "
                    "Jacobians (PlanOptions jacobian_storage='raw' prices that choice: fewer "
                    "words, a whiten_stack phase of multiply-accumulates; the whitened "
                    "default's own W·J is not priced by the plan, so raw's extra cycles are an "
                    "upper bound)"))
    return rows


def paper_b(cfg: Config) -> list[Row]:
    graph = imu_window.build(N=cfg.imu_n)
    prog = compile_graph(graph, SolverConfig(method="lm", linear="cholesky",
                                             precision="float32"))
    iters = _lm_iterations(graph)
    b = f"B (IMU N={cfg.imu_n})"
    rows = []
    lo, hi = cfg.cpes[0], cfg.cpes[-1]
    costs = {(c, h): _cost(prog, cpe=c, hessian_storage=h)
             for c in cfg.cpes for h in ("frontal", "dense", "blocked")}
    def solve(c, h):
        cost = costs[c, h]
        return f"{cost.latency_ms * iters:.2f} ms" + (
            "" if cost.fits else f" (does not fit: {', '.join(cost.over)})")

    rows.append(Row(b, f"solve at #CPE={lo} / {hi}", "171 ms (5) / 8.97 ms (120)",
                    " / ".join(solve(c, "frontal") for c in (lo, hi))
                    + " emitted (multifrontal: each step's frontal [H | g]); what-if whole-"
                    "matrix designs: dense H "
                    + " / ".join(solve(c, "dense") for c in (lo, hi)) + "; blocked H "
                    + " / ".join(solve(c, "blocked") for c in (lo, hi))
                    + f" ({iters} LM iterations, GTSAM's count on this problem)",
                    "the emitted design streams each elimination step's frontal matrix through "
                    "the cascade, one word a cycle per round, steps one after another; a pivot "
                    "no longer stalls the stream (about 14 cycles a CPE in float32), so a step "
                    "costs about its words and CPEs beyond its f pivots only pass words on "
                    "(docs/hls.md, 'The Cholesky cascade'); the what-if "
                    "designs stream H's whole trailing triangle (or its envelope); the paper's "
                    "iteration count and CPE pipeline are not known here"))
    cpe = build_plan(prog, PlanOptions.of(prog, cpe=lo)).unit("cpe")
    ops = build_plan(prog, PlanOptions.of(prog, cpe=lo)).ops
    per_cpe = sum(n * ops.op(k).dsp for k, n in cpe.operators) + cpe.extra_dsp
    rows.append(Row(b, "DSP per CPE", "6", str(per_cpe),
                    "per CPE an adder 2 + two multipliers 3 each (assumed DSP of the full-DSP "
                    "cores: its Update loop's x - h_i (h_c / d)); its tap's divide is LUT-only "
                    "and no square root is taken"))
    c123 = [c for c in cfg.c123 if (c, "dense") in costs] or list(cfg.c123)
    for c in c123:
        if (c, "dense") not in costs:
            costs[c, "dense"] = _cost(prog, cpe=c)
            costs[c, "blocked"] = _cost(prog, cpe=c, hessian_storage="blocked")
    rows.append(Row(b, "C1-C3 DSP share of 900", "30.9 % - 70.9 %",
                    ", ".join(f"#CPE={c} {costs[c, 'dense'].dsp / PART_DSP:.1%}"
                              + ("" if costs[c, "dense"].fits else " (does not fit)")
                              for c in c123),
                    "the plan's factor datapaths (one per block type, ALLOCATION-limited) and "
                    "16 HGC lanes add a fixed ~"
                    f"{costs[c123[0], 'dense'].dsp - per_cpe * c123[0]} DSP to the CPEs' "
                    f"{per_cpe} each; "
                    "paper B's factor units are smaller"))
    c1 = costs[(c123[0], "dense")]
    c1b = costs[(c123[0], "blocked")]
    rows.append(Row(b, "linear solve share of the time", "82.4 %",
                    f"{c1.linear_cycles / c1.cycles:.1%} dense H, "
                    f"{c1b.linear_cycles / c1b.cycles:.1%} blocked H at #CPE={c123[0]} (HGC + "
                    "cascade + triangular solve)",
                    "a dense cascade streams all of H's trailing triangle every round; the "
                    "blocked plan streams only H's envelope, so the factor phases weigh more"))
    rows.append(Row(b, "power C1 / C2 / C3", "2.293 / 2.956 / 3.759 W",
                    " / ".join(f"{plan_power_w(costs[c, 'dense']):.3f} W" for c in c123)
                    + f" (#CPE {', '.join(map(str, c123))})",
                    "not modelled by the plan: the sim model's static + per-resource power, "
                    "whose coefficients were fitted to these three figures (with the sim "
                    "model's resources), applied to the plan's resources - not a reproduction"))
    ratios = []
    for n in cfg.storage_ns:
        p = compile_graph(imu_window.build(N=n), SolverConfig(method="lm", linear="cholesky",
                                                              precision="float32"))
        dense_words = p.storage.dense_words
        blocked = _cost(p, hessian_storage="blocked").words
        ratios.append(f"N={n}: {p.storage.ratio(3):.1f}× (plan words dense "
                      f"{_cost(p).words:,} → blocked {blocked:,}; dense H+g {dense_words:,})")
    rows.append(Row(b, "Hessian storage reduction", "21.1× (N=20) / 82.8× (N=80)",
                    "; ".join(ratios),
                    "fgc's step 3 skips H's fixed zeros of the whitened Jacobians; the full IMU "
                    "square-root information fills the blocks the paper's raw Jacobians keep "
                    "sparse"))
    return rows


def _lm_iterations(graph) -> int:
    from fgc.app.run_report import gtsam_optimize
    from fgc.interop.to_gtsam import to_gtsam

    return max(1, gtsam_optimize(to_gtsam(graph), linear="qr")[1])


def table(cfg: Config = Config()) -> list[Row]:
    return paper_a(cfg) + paper_b(cfg)


def format_rows(rows: list[Row]) -> str:
    lines = []
    for r in rows:
        lines += [f"[{r.paper}] {r.figure}", f"    published: {r.published}",
                  f"    fgc:       {r.fgc}", f"    why:       {r.why}"]
    return "\n".join(lines)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--small", action="store_true", help="LIO N=5, IMU N=5: a smoke run")
    args = ap.parse_args(argv)
    cfg = SMALL if args.small else Config()
    print(format_rows(table(cfg)))


if __name__ == "__main__":
    main()
