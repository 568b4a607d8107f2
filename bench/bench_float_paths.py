"""A float design's C simulation against the float32 and float64 simulator, and how far each
float32 answer is from the float64 optimum: per pair the largest position, rotation (the
chordal measure the testbench uses, and acos of the trace beside it) and other-entry
difference; per answer its float64 cost, its distance from the optimum in sigma (the whitened
length of the float64 Gauss-Newton step from it, ``sim.remaining_step``) and how far its
rotation matrices are from orthonormal. The float32 simulator's accepted iterations are printed
(error, lambda), so two runs that part ways show where.

    FGC_CACHE_DIR=... python bench/bench_float_paths.py [--example imu_window] [--N 20]
        [--linear cholesky|qr] [--spread K]

--spread K: the float32 simulator's first solve (at the initial values, lambda_initial) K times,
its whitened rows each moved by about one float32 rounding (relative 2^-23 N(0, 1), fixed
seed): how far each step is from the float64 step (relative), and how many break down.

imu_window N = 20, LM, float32 Cholesky (2026-12-07): C simulation 6 iterations, simulator 84;
they differ by 3.2 mm / 0.275 mrad (acos: 1.06 mrad) / 3.1e-3, each 0.06 sigma from the
optimum (float64 cost 0.0019 / 0.0016); the simulator's matrices up to 2.6e-6 off orthonormal,
the C simulation's 3.3e-7 (98 s on 2 loaded cores).
"""

from __future__ import annotations

import argparse
import runpy
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "hls"))

from test_hls_csim import pose_errors  # noqa: E402

from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.datafile import problem_data, write_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends import sim  # noqa: E402
from fgc_backends.hls import HlsConfig, emit, run_csim  # noqa: E402


def acos_rotation(program, a: dict, b: dict) -> float:
    """The largest 3 × 3 rotation angle by acos((trace(RaᵀRb) − 1) / 2) (the old measure)."""
    worst = 0.0
    for v in program.variables:
        if v.type_name in ("Pose3", "Rot3"):
            ra = np.asarray(a[v.key], float)[:9].reshape(3, 3)
            rb = np.asarray(b[v.key], float)[:9].reshape(3, 3)
            worst = max(worst, float(np.arccos(np.clip((np.trace(ra.T @ rb) - 1) / 2, -1, 1))))
    return worst


def orthonormality(program, values: dict) -> float:
    """The largest ‖RᵀR − I‖_F over the 3 × 3 rotations of ``values``."""
    worst = 0.0
    for v in program.variables:
        if v.type_name in ("Pose3", "Rot3"):
            r = np.asarray(values[v.key], float)[:9].reshape(3, 3)
            worst = max(worst, float(np.linalg.norm(r.T @ r - np.eye(3))))
    return worst


def first_step_spread(program, data, runs: int) -> tuple[list[float], int]:
    """(relative distances of the float32 first steps from the float64 one, breakdowns) over
    ``runs`` one-rounding perturbations of the float32 rows (see the module's --spread)."""
    with tempfile.TemporaryDirectory(prefix="fgc-paths-sim-") as tmp:
        module = sim.emit(program, tmp)[0]
        namespace = runpy.run_path(str(module), run_name="fgc_sim_problem")
        lib, spec = namespace["LIB"], namespace["PROBLEM"]
        write_data(data, Path(tmp) / "data.txt")
        rows = lib.runtime.read_data(str(Path(tmp) / "data.txt"), spec["structure"])
        p64, p32 = (lib.optimizer.Problem(spec, rows, dtype, lib)
                    for dtype in ("float64", "float32"))
    mu = program.solver.lambda_initial
    reference = p64.solve(p64.linearize(p64.x0)[0], mu)
    abs32 = p32.linearize(p32.x0)[0]
    rng = np.random.default_rng(0)
    spread, broken = [], 0
    for _ in range(runs):
        moved = [(ab * (1 + 2.0 ** -23 * rng.standard_normal(ab.shape))).astype(np.float32)
                 for ab in abs32]
        try:
            step = p32.solve(moved, mu).astype(float)
        except lib.linear.SingularError:
            broken += 1
            continue
        spread.append(float(np.linalg.norm(step - reference) / np.linalg.norm(reference)))
    return spread, broken


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--example", default="imu_window")
    parser.add_argument("--N", type=int, default=20)
    parser.add_argument("--linear", choices=("cholesky", "qr"), default="cholesky")
    parser.add_argument("--spread", type=int, default=0, metavar="K")
    args = parser.parse_args(argv)
    graph = example(args.example).build(N=args.N)
    program = compile_graph(graph, SolverConfig(linear=args.linear, precision="float32"),
                            name="paths")
    data = problem_data(graph, program)
    f64 = sim.run(program, data, precision="float64")
    print(f"float32 simulator ({args.example} N={args.N}, LM, {args.linear}):")
    f32 = sim.run(program, data, precision="float32", progress=lambda r: print(
        f"  iteration {r['iteration']:3d}: error {r['error']:.9g}, lambda {r['lambda']:.0e}"))
    project = emit(program, tempfile.mkdtemp(prefix="fgc-paths-"), HlsConfig(scalar="float"))
    csim = run_csim(project, program, data, reference=False)
    answers = {"csim": csim.values, "sim32": f32.storage, "sim64": f64.storage}
    for name, result in (("csim", csim), ("sim32", f32), ("sim64", f64)):
        print(f"{name}: {result.status} ({result.reason}) after {result.iterations} iterations, "
              f"error {result.initial_error:.9g} -> {result.final_error:.9g}")
    for a, b in (("csim", "sim32"), ("csim", "sim64"), ("sim32", "sim64")):
        pos, rot, vec = pose_errors(program, answers[a], answers[b])
        print(f"{a} vs {b}: position {pos:.2e} m, rotation {rot:.2e} rad (acos "
              f"{acos_rotation(program, answers[a], answers[b]):.2e}), other {vec:.2e}")
    for name in ("csim", "sim32"):
        cost = sim.costs(program, data, [answers[name]])[0]
        sigma = sim.remaining_step(program, data, answers[name])
        print(f"{name}: float64 cost {cost:.3g}, {sigma:.3g} sigma from the optimum, rotations "
              f"{orthonormality(program, answers[name]):.1e} off orthonormal")
    if args.spread:
        spread, broken = first_step_spread(program, data, args.spread)
        print(f"first float32 step of the simulator, rows moved by one rounding ({args.spread} "
              f"runs): {broken} broke down; the others {min(spread, default=0):.1%} ... "
              f"{max(spread, default=0):.1%} from the float64 step (median "
              f"{float(np.median(spread)) if spread else 0:.1%})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
