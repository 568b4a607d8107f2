"""Thorough property run and float32 honesty: fgc against GTSAM on many random factor graphs, and
the float32 solution of each shipped example against its float64 solution.

``property`` draws ``--examples`` random graphs from ``tests/strategies.py`` (hypothesis, fixed
seed: the same graphs every run), solves each with the simulator in float64 and with GTSAM's LM
in the same process, and prints the verdicts (match / mismatch / excluded / failed, see
``strategies.Outcome``), every case that is not a match, and the time fgc and GTSAM took in
total. ``--native N`` also runs N random data sets through the native library.

``float32`` solves each example in float64 and float32 with QR and Cholesky (and Cholesky with a
float64 linear solver, the mixed design) and prints the
largest rotation and translation difference, the diagnosed condition number κ (rows and
columns equilibrated), the float32 limit for the solver and whether fgc warned.

    python bench/bench_property.py property [--examples 500] [--native 60] [--seed 7]
    python bench/bench_property.py float32
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))

from fgc.app.specs import example  # noqa: E402

imu_window = example("imu_window")
lio = example("lio")
pose_graph = example("pose_graph")
import strategies  # noqa: E402
from hypothesis import HealthCheck, Phase, given, seed, settings  # noqa: E402

from fgc.app.run_report import state_errors  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.conditioning import float32_kappa_limit  # noqa: E402
from fgc.ir.datafile import problem_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends import sim  # noqa: E402


def run_property(examples: int, strategy, judge, seed_value: int) -> tuple[Counter, list, float]:
    """Judge ``examples`` recipes drawn from ``strategy``; (verdicts, non-matches, seconds)."""
    counts, odd = Counter(), []
    settings_ = settings(max_examples=examples, deadline=None, database=None,
                         phases=(Phase.generate,), suppress_health_check=list(HealthCheck))

    @seed(seed_value)
    @settings_
    @given(strategy)
    def one(spec):
        try:
            outcome = judge(spec)
        except Exception as exc:  # a crash is a finding: count it, keep going
            counts["error"] += 1
            odd.append(f"error: {type(exc).__name__}: {exc}; {spec}")
            return
        counts[outcome.verdict] += 1
        if outcome.verdict != "match":
            odd.append(outcome.describe())

    t0 = time.perf_counter()
    one()
    return counts, odd, time.perf_counter() - t0


def timed_compare(spec) -> strategies.Outcome:
    """:func:`strategies.compare`, timing fgc (compile + simulate) and GTSAM separately."""
    t0 = time.perf_counter()
    graph = strategies.build(spec)
    program = compile_graph(graph, strategies.solver(spec))
    result = sim.run(program, problem_data(graph, program))
    t1 = time.perf_counter()
    reference = strategies.gtsam_optimum(graph)
    TIMES["fgc"] += t1 - t0
    TIMES["gtsam"] += time.perf_counter() - t1
    keys = {str(k): k for k in graph.variables}
    values = {keys[k]: v for k, v in result.values.items()}
    return strategies.judge(spec, graph, values, (result.status, result.reason), reference)


TIMES: Counter = Counter()


def native_judge(spec) -> strategies.Outcome:
    outcome, gap = strategies.compare_native(spec)
    if gap > 1e-6:
        return strategies.Outcome(spec, "mismatch", gap, outcome.fgc_error,
                                  outcome.gtsam_error, outcome.status, "native vs simulator")
    return outcome


def print_run(title: str, counts: Counter, odd: list, seconds: float) -> None:
    total = sum(counts.values())
    print(f"{title}: {total} graphs in {seconds:.0f} s — " +
          ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    for line in odd:
        print("  ", line)


def cmd_property(args) -> int:
    counts, odd, seconds = run_property(args.examples, strategies.graph_specs(max_poses=14),
                                        timed_compare, args.seed)
    print_run("simulator vs GTSAM LM (float64; state ≤ 1e-6 where errors agree to 1e-6)",
              counts, odd, seconds)
    print(f"   time: fgc compile+simulate {TIMES['fgc']:.1f} s, GTSAM LM {TIMES['gtsam']:.1f} s")
    bad = counts["mismatch"] + counts["failed"] + counts["error"]
    if args.native:
        ncounts, nodd, nseconds = run_property(args.native, strategies.native_specs(),
                                               native_judge, args.seed)
        print_run("native library vs GTSAM LM (and vs the simulator ≤ 1e-6)", ncounts, nodd,
                  nseconds)
        bad += ncounts["mismatch"] + ncounts["failed"] + ncounts["error"]
    return 1 if bad else 0


# --------------------------------------------------------------------------------------------
# float32 honesty
# --------------------------------------------------------------------------------------------

EXAMPLES = (("pose3example", lambda: pose_graph.build("pose3example.txt")),
            ("w100", lambda: pose_graph.build("w100.graph")),
            ("imu_window N=20", lambda: imu_window.build(N=20)),
            ("imu_window N=50", lambda: imu_window.build(N=50)),
            ("imu_window N=80", lambda: imu_window.build(N=80)),
            ("lio N=30", lambda: lio.build(N=30)),
            ("lio N=100", lambda: lio.build(N=100)))


def float32_row(name: str, graph, linear: str, wide: bool = False) -> str:
    """One row; ``wide``: the mixed design (float32 with a float64 linear solver)."""
    program = compile_graph(graph, SolverConfig(linear=linear))
    data = problem_data(graph, program)
    f64 = sim.run(program, data)
    run32 = program
    if wide:
        run32 = compile_graph(graph, SolverConfig(linear=linear, precision="float32",
                                                  linear_precision="float64"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        f32 = sim.run(run32, data, precision="float32")
    keys = {str(k): k for k in graph.variables}
    errors = state_errors(graph, {keys[k]: v for k, v in f32.values.items()},
                          {keys[k]: v for k, v in f64.values.items()})
    label = linear + ("+f64" if wide else "")
    limit = float32_kappa_limit(linear, "float64" if wide else "float32")
    return (f"{name:16s} {label:12s} {errors['max_rotation_error']:10.1e} "
            f"{errors['max_translation_error']:10.1e} {f64.condition:10.3g} "
            f"{limit:8.2g} {'yes' if caught else 'no':>6s}  {f32.status}")


def cmd_float32(_args) -> int:
    print("float32 against float64 (max over variables; translation part also for vectors);")
    print("cholesky+f64: the mixed design, float32 with a float64 linear solver")
    print(f"{'example':16s} {'linear':12s} {'rot (rad)':>10s} {'trans (m)':>10s} "
          f"{'kappa':>10s} {'limit':>8s} {'warned':>6s}  float32 status")
    for name, build in EXAMPLES:
        graph = build()
        for linear, wide in (("qr", False), ("cholesky", False), ("cholesky", True)):
            print(float32_row(name, graph, linear, wide), flush=True)
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    prop = sub.add_parser("property", help="many random graphs against GTSAM")
    prop.add_argument("--examples", type=int, default=500)
    prop.add_argument("--native", type=int, default=0, help="random data sets, native path")
    prop.add_argument("--seed", type=int, default=7)
    prop.set_defaults(func=cmd_property)
    f32 = sub.add_parser("float32", help="float32 vs float64 on the examples, with κ")
    f32.set_defaults(func=cmd_float32)
    args = parser.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())
