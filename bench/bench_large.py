"""Large GTSAM data files: fgc's native solver against GTSAM's LM, side by side in one process.

For each file (read from GTSAM's example data, as ``fgc run FILE`` reads it) the script reports
fgc's compile time, the native build/load time (a cached build loads in milliseconds; a first
build runs g++), and then times the solve alone on both sides: fgc's ``NativeSolver.solve`` and
GTSAM's ``LevenbergMarquardtOptimizer`` (construction to ``optimize()``; its default
multifrontal Cholesky, and its COLAMD ordering computed inside the timed call as a user's run
does; ``--gtsam-ordering-untimed`` passes it precomputed). Both run the same LM (λ₀ 1e-5, factor
10, relative/absolute error tolerances of fgc's ``SolverConfig``) for at most ``--iterations``
iterations; each side's best of ``--repeat`` runs counts. The final errors are both evaluated by
GTSAM on its own graph (fgc's result inserted as GTSAM values), so one yardstick judges them.

    python bench/bench_large.py [--files w10000.graph sphere2500.txt ...] [--linear cholesky qr]
                                [--iterations 100] [--repeat 3]

Prints one line per (file, fgc linear solver): wall and CPU times in seconds, their ratios
GTSAM / fgc (> 1: fgc is faster), iterations of each side and the two final errors. Both sides run
on one thread in this process: on a shared machine the CPU-time ratio is the steadier one.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

import gtsam  # noqa: E402
from datasets import fgc_error_in_gtsam  # noqa: E402  (bench/datasets.py)

from fgc.app.specs import load_spec  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.errors import FgcError  # noqa: E402
from fgc.interop.to_gtsam import to_gtsam  # noqa: E402
from fgc.ir.datafile import problem_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends import native  # noqa: E402
from fgc_backends.cfamily.results import result_from_arrays  # noqa: E402

FILES = ("w10000.graph", "sphere2500.txt", "victoria_park.txt", "w20000.txt")


def gtsam_lm(problem, solver: SolverConfig, ordering=None):
    params = gtsam.LevenbergMarquardtParams()
    if ordering is not None:
        params.setOrdering(ordering)
    params.setRelativeErrorTol(solver.relative_error_tol)
    params.setAbsoluteErrorTol(solver.absolute_error_tol)
    params.setlambdaInitial(solver.lambda_initial)
    params.setlambdaFactor(solver.lambda_factor)
    params.setlambdaUpperBound(solver.lambda_upper_bound)
    params.setMaxIterations(solver.max_iterations)
    optimizer = gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params)
    result = optimizer.optimize()
    return result, optimizer.iterations()


def best(fn, args, repeat: int):
    """(fastest wall time, fastest CPU time of this process, the last run's output). Both
    sides solve on one thread in this process, so on a machine shared with other work the CPU
    time is the steadier figure (wall time counts the waits for a core)."""
    out, fastest, cpu = None, float("inf"), float("inf")
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        out = fn(*args)
        fastest = min(fastest, time.perf_counter() - t0)
        cpu = min(cpu, time.process_time() - c0)
    return fastest, cpu, out


def bench_file(name: str, linears, iterations: int, repeat: int, ordering_untimed: bool):
    t0 = time.perf_counter()
    graph = load_spec(gtsam.findExampleDataFile(name), {})
    t_read = time.perf_counter() - t0
    problem = to_gtsam(graph)
    ordering = (gtsam.Ordering.Colamd(gtsam.VariableIndex(problem.graph))
                if ordering_untimed else None)
    for linear in linears:
        solver = SolverConfig(linear=linear, max_iterations=iterations)
        t0 = time.perf_counter()
        program = compile_graph(graph, solver, name=Path(name).stem)
        t_compile = time.perf_counter() - t0
        t0 = time.perf_counter()
        built = native.load(program)
        t_build = time.perf_counter() - t0
        x, d = built.flatten(problem_data(graph, program))
        widest = max(s.frontal_dim + s.separator_dim for s in program.schedule.steps)
        t_fgc, c_fgc, (x_out, errors, info) = best(built.solve, (x, d), repeat)
        t_gtsam, c_gtsam, (values, it_gtsam) = best(gtsam_lm, (problem, solver, ordering), repeat)
        result = result_from_arrays(program, x_out, errors, *info)
        e_fgc = fgc_error_in_gtsam(graph, problem, result)
        e_gtsam = problem.graph.error(values)
        print(f"{name:<19}{linear:<9}{t_read:>6.1f}{t_compile:>8.1f}{t_build:>7.1f}{widest:>6}"
              f"{t_fgc:>9.3f}{t_gtsam:>9.3f}{t_gtsam / t_fgc:>7.1f}x"
              f"{c_fgc:>9.3f}{c_gtsam:>10.3f}{c_gtsam / c_fgc:>9.1f}x{result.iterations:>5}"
              f"{it_gtsam:>5}{e_fgc:>17.10g}{e_gtsam:>17.10g}", flush=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--files", nargs="+", default=list(FILES))
    parser.add_argument("--linear", nargs="+", default=["cholesky", "qr"])
    parser.add_argument("--iterations", type=int, default=100)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--gtsam-ordering-untimed", action="store_true",
                        help="compute GTSAM's COLAMD ordering before timing (fgc's is compiled)")
    args = parser.parse_args()
    print(f"{'file':<19}{'linear':<9}{'read':>6}{'compile':>8}{'build':>7}{'width':>6}"
          f"{'fgc s':>9}{'gtsam s':>9}{'ratio':>8}{'fgc cpu':>9}{'gtsam cpu':>10}{'cpu ratio':>10}"
          f"{'it':>5}{'it_g':>5}"
          f"{'error fgc':>17}{'error gtsam':>17}")
    for name in args.files:
        try:
            bench_file(name, args.linear, args.iterations, args.repeat,
                       args.gtsam_ordering_untimed)
        except FgcError as exc:  # a file fgc cannot read as it is: say so, go on
            print(f"{name:<19}not benchmarked: {exc}", flush=True)


if __name__ == "__main__":
    main()
