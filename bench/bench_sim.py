"""The simulator backend (emitted NumPy program, run in this process) against GTSAM's LM.

For each problem fgc compiles the graph and emits the simulator (not timed), loads the emitted
module once, and times its solve: ``solve`` is the optimisation alone (data already in memory),
``+setup`` adds reading the data file and building the index tables. GTSAM gets the same graph
through ``fgc.interop.to_gtsam.to_gtsam`` (not timed) and its ``LevenbergMarquardtOptimizer`` with
the same
tolerances is timed from construction to ``optimize()``. Best of ``--repeat`` runs each; the ratio
is fgc's solve over GTSAM's.

    python bench/bench_sim.py [--repeat 5] [--n 30 200 1000] [--linear qr cholesky]
        [--precision float64]
"""

from __future__ import annotations

import argparse
import runpy
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

from fgc.app.specs import example  # noqa: E402

lio = example("lio")

from fgc.compile import compile_graph  # noqa: E402
from fgc.interop.to_gtsam import to_gtsam  # noqa: E402
from fgc.ir.datafile import problem_data, write_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends import sim  # noqa: E402


def gtsam_lm(problem):
    import gtsam

    params = gtsam.LevenbergMarquardtParams()
    params.setRelativeErrorTol(1e-12)
    params.setAbsoluteErrorTol(1e-14)
    params.setMaxIterations(100)
    optimizer = gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params)
    return optimizer.optimize(), optimizer.iterations()


def best_of(fn, repeat: int):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def bench(n: int, linear: str, precision: str, repeat: int) -> str:
    graph = lio.build(N=n, keyframe_dt=None if n <= 469 else 0.4)  # 470 GPS fixes in the data
    program = compile_graph(graph, SolverConfig(linear=linear))
    problem = to_gtsam(graph)
    gtsam_s, (_, gtsam_it) = best_of(lambda: gtsam_lm(problem), repeat)
    with tempfile.TemporaryDirectory() as tmp:
        files = sim.emit(program, tmp)
        data = Path(tmp) / "data.txt"
        write_data(problem_data(graph, program), data)
        run = runpy.run_path(str(files[0]))["run"]
        runs = [run(str(data), None, precision) for _ in range(repeat)]
    solve = min(r["solve_seconds"] for r in runs)
    total = min(r["solve_seconds"] + r["setup_seconds"] for r in runs)
    r = runs[0]
    return (f"lio N={n:<4} {linear:<8} {precision}  fgc sim {solve * 1e3:8.1f} ms "
            f"(+setup {total * 1e3:7.1f} ms, {r['iterations']:3d} it, {r['status']})  "
            f"GTSAM {gtsam_s * 1e3:7.1f} ms ({gtsam_it:3d} it)  ratio {solve / gtsam_s:5.2f}x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--n", type=int, nargs="+", default=[30, 200, 1000])
    parser.add_argument("--linear", nargs="+", default=["qr", "cholesky"])
    parser.add_argument("--precision", default="float64", choices=("float32", "float64"))
    args = parser.parse_args()
    for n in args.n:
        for linear in args.linear:
            print(bench(n, linear, args.precision, args.repeat), flush=True)


if __name__ == "__main__":
    main()
