"""The native solver in ap_fixed<W,I> against float64: the largest error of the estimate.

For the Pose2 loop example (examples/pose2_loop.py, the fixed-point tests' problem) and each
linear solver, the native library is built in ``ap_fixed<W,I>`` (LM's damping bound lowered to
1e4 so that it fits ±2^(I-1)) and in ``double``; each is compared with the simulator's float64
solution: the largest absolute difference of any stored entry (x, y, cos θ, sin θ), and the
relative difference of the final cost. Needs hls4ml's ap_types headers
(``pip install --no-deps hls4ml``).

    python bench/bench_fixed.py [--scalar "ap_fixed<40,16>"] [-p n=8]
"""

from __future__ import annotations

import argparse

import numpy as np

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import native, sim


def worst(program, result, reference) -> float:
    return max(float(np.max(np.abs(result.storage[v.key] - reference.storage[v.key])))
               for v in program.variables)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scalar", default="ap_fixed<40,16>")
    ap.add_argument("--lambda-upper-bound", type=float, default=1e4)
    ap.add_argument("-n", type=int, default=8, help="poses on the loop")
    args = ap.parse_args(argv)
    graph = example("pose2_loop").build(n=args.n)
    print(f"Pose2 loop, {args.n} poses; max |estimate - float64 simulator| over every stored "
          "entry, and the final cost's relative difference")
    print(f"{'linear':9s} {'scalar':18s} {'status':10s} {'iter':>4s} {'max error':>10s} "
          f"{'cost rel':>10s}")
    for linear in ("cholesky", "qr"):
        program = compile_graph(graph, SolverConfig(linear=linear,
                                                    lambda_upper_bound=args.lambda_upper_bound),
                                name=f"fx_bench_{linear}")
        data = problem_data(graph, program)
        reference = sim.run(program, data, precision="float64")
        for scalar in (args.scalar, "double"):
            config = native.NativeConfig(scalar=scalar)
            result = native.run(program, data, config)
            rel = abs(result.final_error - reference.final_error) / reference.final_error
            print(f"{linear:9s} {scalar:18s} {result.status:10s} {result.iterations:4d} "
                  f"{worst(program, result, reference):10.3g} {rel:10.3g}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
