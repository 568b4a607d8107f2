"""What the host-side float32 verdict adds to a native run.

``NativeSolver.run`` judges every float result on the host (``judge_precision``: the Program's
float64 linearisation at the returned solution and ρ, ``fgc.ir.conditioning.resolution``). This
script builds each shipped example's float32 native solver (not timed), then prints the best of
``--repeat`` warm calls of the bare solve (``NativeSolver.solve``) and of the verdict alone, and
the verdict's ρ.

    python bench/bench_judge.py [--repeat 20] [EXAMPLE ...]
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from fgc.app.cli import load_spec
from fgc.compile import compile_graph
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import native
from fgc_backends.cfamily.results import judge_precision, result_from_arrays

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def best(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("examples", nargs="*", default=["range_beacons", "lio", "pose_graph"])
    parser.add_argument("--repeat", type=int, default=20)
    args = parser.parse_args()
    for name in args.examples:
        graph = load_spec(str(EXAMPLES / f"{name}.py"), {})
        program = compile_graph(graph, SolverConfig(precision="float32"))
        data = problem_data(graph, program)
        solver = native.load(program)
        flat = solver.flatten(data)
        x, errors, info = solver.solve(*flat)
        raw = result_from_arrays(program, x, errors, *info)
        judged = judge_precision(program, data, raw, solver.project.config.scalar)  # warm
        solve = best(lambda: solver.solve(*flat), args.repeat)  # noqa: B023
        judge = best(lambda: judge_precision(program, data, raw, "float"), args.repeat)  # noqa: B023
        print(f"{name}: solve {solve * 1e3:.2f} ms, verdict {judge * 1e3:.2f} ms, "
              f"ρ = {judged.resolution:.3g}, {judged.status} ({judged.reason})")


if __name__ == "__main__":
    main()
