"""Trajectory accuracy of the simulator's solution (float32 and float64) against GTSAM's LM optimum
on examples/lio.py, in evo's conventions: ATE (no alignment) and RPE (translation, delta 1 frame).

    python bench/bench_trajectory.py [--n 200]
"""

from __future__ import annotations

import argparse
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

from fgc.app.specs import example  # noqa: E402

lio = example("lio")

from fgc.app.metrics import ate, rpe  # noqa: E402
from fgc.app.run_report import gtsam_optimize  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.interop.to_gtsam import to_gtsam, values_from_gtsam  # noqa: E402
from fgc.ir.datafile import problem_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends import sim  # noqa: E402


def poses(values: dict, n: int) -> list:
    return [(float(i), values[f"x{i}"]) for i in range(n)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=200)
    args = parser.parse_args()
    graph = lio.build(N=args.n)
    problem = to_gtsam(graph)
    ref = poses(values_from_gtsam(graph, problem, gtsam_optimize(problem)[0]), args.n)
    print(f"LIO N={args.n}: simulator vs GTSAM LM optimum (metres)")
    print(f"{'precision':<10}{'ATE rmse':>12}{'ATE max':>12}{'RPE rmse':>12}{'RPE max':>12}")
    for precision in ("float64", "float32"):
        program = compile_graph(graph, SolverConfig(precision=precision))
        result = sim.run(program, problem_data(graph, program))
        est = poses({k: result.values[k] for k in result.values}, args.n)
        a, r = ate(est, ref), rpe(est, ref, delta=1)
        print(f"{precision:<10}{a.rmse:>12.3e}{a.max:>12.3e}{r.rmse:>12.3e}{r.max:>12.3e}")


if __name__ == "__main__":
    main()
