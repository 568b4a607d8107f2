"""float32 far from the origin: distance to GTSAM's float64 optimum, in σ, per backend.

A chain of ``--poses`` Pose2 or Pose3 poses (σ 1 cm per position axis, 5 mrad per rotation
axis; a prior on the first pose, noisy between factors, initial values perturbed) placed at
``--offsets`` metres from the origin on every axis, solved in float32 by the simulator, the HLS C
simulation (``--scalar float``) and the native solver (float), and by GTSAM's LM in float64.
Prints, per chain and offset, each backend's status and the largest |component| of the tangent
difference local(GTSAM's optimum, fgc's) divided by that component's σ (``dσ``). The goal is
dσ ≤ 1 wherever the run says "converged", and a failure that says why elsewhere.

``--no-frame`` compiles without the local frame (``compile_graph(..., local_frame=False)``): the
world-coordinate solve fgc did before, judged by the float32 resolution verdict alone.

    python bench/bench_frame.py                                  # sim, hls, native; both chains
    python bench/bench_frame.py --backends sim --no-frame        # the world-coordinate solve
"""

from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import fgc  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.frontend import noise  # noqa: E402
from fgc.frontend.factors import BetweenFactor, PriorFactor  # noqa: E402
from fgc.frontend.geometry import Pose2, Pose3, Rot3  # noqa: E402
from fgc.ir.datafile import problem_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402

SIGMA_T, SIGMA_R = 0.01, 0.005
OFFSETS = (0.0, 1e3, 1e4, 1e5, 1e6)


def chain(kind: str, offset: float, poses: int = 10, seed: int = 0) -> tuple[fgc.Graph, np.ndarray]:
    """The chain at ``offset`` and its per-tangent-component σ (the variable's tangent order)."""
    rng = np.random.default_rng(seed)
    graph = fgc.Graph()
    if kind == "pose2":
        sig = np.array([SIGMA_T, SIGMA_T, SIGMA_R])
        truth = [Pose2(offset + 1.0 * i, offset + 0.5 * np.sin(i), 0.1 * i) for i in range(poses)]
        between = noise.diagonal(sig)
        for i, pose in enumerate(truth):
            d = rng.normal(0, 1, 3) * [0.3, 0.3, 0.05]
            graph.add_variable(f"x{i}", pose.retract(d))
        graph.add(PriorFactor("x0", truth[0], noise.diagonal(sig)))
        for i in range(poses - 1):
            m = truth[i].between(truth[i + 1]).retract(rng.normal(0, 1, 3) * sig)
            graph.add(BetweenFactor(f"x{i}", f"x{i + 1}", m, between))
        return graph, sig
    sig = np.array([SIGMA_R] * 3 + [SIGMA_T] * 3)  # Pose3 tangent [ω, v]
    truth = [Pose3(Rot3.Expmap(np.array([0.02 * i, -0.01 * i, 0.1 * i])),
                   np.array([offset + 1.0 * i, offset + 0.5 * np.sin(i), offset + 0.1 * i]))
             for i in range(poses)]
    for i, pose in enumerate(truth):
        d = rng.normal(0, 1, 6) * [0.05, 0.05, 0.05, 0.3, 0.3, 0.3]
        graph.add_variable(f"x{i}", pose.retract(d))
    graph.add(PriorFactor("x0", truth[0], noise.diagonal(sig)))
    for i in range(poses - 1):
        m = truth[i].between(truth[i + 1]).retract(rng.normal(0, 1, 6) * sig)
        graph.add(BetweenFactor(f"x{i}", f"x{i + 1}", m, noise.diagonal(sig)))
    return graph, sig


def gtsam_optimum(graph: fgc.Graph) -> dict:
    """GTSAM's LM optimum (float64, tight tolerances, as ``fgc verify``) as fgc values."""
    from fgc.app.run_report import gtsam_optimize
    from fgc.interop.to_gtsam import to_gtsam, values_from_gtsam

    problem = to_gtsam(graph)
    optimum, _ = gtsam_optimize(problem)
    return values_from_gtsam(graph, problem, optimum)


def sigma_distance(graph: fgc.Graph, values: dict, reference: dict, sig: np.ndarray) -> float:
    """max over variables and tangent components of |local(reference, value)| / σ."""
    worst = 0.0
    for k in graph.variables:
        d = np.asarray(reference[k].local(values[str(k)]), dtype=np.float64).reshape(-1)
        worst = max(worst, float(np.max(np.abs(d) / sig)))
    return worst


def solve(graph: fgc.Graph, backend: str, frame: bool):
    """(status, reason, result) of a float32 solve of ``graph`` on ``backend``."""
    from fgc_backends import load

    program = compile_graph(graph, SolverConfig(precision="float32"), name="chain",
                            local_frame=frame)
    data = problem_data(graph, program)
    if backend == "hls":
        from fgc_backends.hls.config import HlsConfig

        config = HlsConfig(scalar="float")
    elif backend == "native":
        from fgc_backends.native.config import NativeConfig

        config = NativeConfig(scalar="float")
    else:
        config = None
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = load(backend).run(program, data, config)
    warned = [str(w.message) for w in caught
              if issubclass(w.category, fgc.ir.conditioning.FgcWarning)]
    return result, warned, program.frame


def measure(kinds, offsets, backends, frame: bool, poses: int = 10) -> list[dict]:
    rows = []
    for kind in kinds:
        for offset in offsets:
            graph, sig = chain(kind, offset, poses)
            reference = gtsam_optimum(graph)
            for backend in backends:
                result, warned, used = solve(graph, backend, frame)
                rows.append({"chain": kind, "offset": offset, "backend": backend,
                             "status": result.status, "reason": result.reason,
                             "sigma": sigma_distance(graph, result.values, reference, sig),
                             "warned": bool(warned), "origin": used.origin if used else None})
    return rows


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--chains", default="pose2,pose3")
    ap.add_argument("--offsets", default=",".join(f"{o:g}" for o in OFFSETS))
    ap.add_argument("--backends", default="sim,hls,native")
    ap.add_argument("--poses", type=int, default=10)
    ap.add_argument("--no-frame", action="store_true")
    args = ap.parse_args()
    rows = measure(args.chains.split(","), [float(x) for x in args.offsets.split(",")],
                   args.backends.split(","), not args.no_frame, args.poses)
    print(f"{'chain':6} {'offset':>8} {'backend':7} {'status':>15} {'reason':>20} "
          f"{'dσ':>8}  warned  origin")
    for r in rows:
        print(f"{r['chain']:6} {r['offset']:8.0e} {r['backend']:7} {r['status']:>15} "
              f"{r['reason']:>20} {r['sigma']:8.3g}  {'yes' if r['warned'] else 'no':6}  "
              f"{r['origin']}")


if __name__ == "__main__":
    main()
