"""Reports behind ``fgc simulate`` and ``fgc verify``: plain dicts (JSON-able) with a summary.

Backends are passed in (never imported here), so fgc stays independent of any backend.
"""

from __future__ import annotations

import dataclasses
import time
from importlib import import_module
from pathlib import Path

import numpy as np

from fgc.dsl import Graph
from fgc.geometry import Pose2, Pose3, Rot2, Rot3

# float64 must reproduce GTSAM's optimum; float32 is the hardware type (issue 4's bounds)
STATE_TOL_F64 = 1e-6
ROT_TOL_F32, POS_TOL_F32 = 1e-3, 1e-2


def _values_by_key(graph: Graph, result_values: dict) -> dict:
    return {k: result_values[str(k)] for k in graph.variables}


def state_errors(graph: Graph, ours: dict, theirs: dict) -> dict:
    """Largest tangent-space distance, rotation angle (rad) and translation (m, for poses and
    points) between two value sets of ``graph``'s variables."""
    tangent = rot = pos = 0.0
    for k in graph.variables:
        a, b = theirs[k], ours[k]
        tangent = max(tangent, float(np.linalg.norm(a.local(b))))
        if isinstance(a, (Pose3, Pose2)):
            pos = max(pos, float(np.linalg.norm(np.asarray(a.t, float) - np.asarray(b.t, float))))
            rot = max(rot, _angle(a.r, b.r))
        elif isinstance(a, (Rot3, Rot2)):
            rot = max(rot, _angle(a, b))
        else:
            pos = max(pos, float(np.linalg.norm(a.local(b))))
    return {"max_state_error": tangent, "max_rotation_error": rot,
            "max_translation_error": pos}


def _angle(a, b) -> float:
    return float(np.linalg.norm(np.atleast_1d(a.local(b))))


def gtsam_optimize(problem, linear: str = "qr"):
    """GTSAM's LM with tight tolerances. The oracle uses GTSAM's multifrontal QR whatever fgc
    solves with: the optimum does not depend on the linear solver, and GTSAM's Cholesky stalls on
    badly scaled problems (IMU window N ≥ 50: 100 iterations, error 1e-6, where QR reaches 1e-20
    in 5)."""
    import gtsam

    params = gtsam.LevenbergMarquardtParams()
    params.setLinearSolverType("MULTIFRONTAL_QR" if linear == "qr" else "MULTIFRONTAL_CHOLESKY")
    params.setRelativeErrorTol(1e-12)
    params.setAbsoluteErrorTol(1e-14)
    params.setMaxIterations(100)
    optimizer = gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params)
    result = optimizer.optimize()
    return result, int(optimizer.iterations())


def verify_report(graph: Graph, program, data, sim) -> dict:
    """Simulator vs GTSAM's LM (same tight tolerances), linearisation check, verdict."""
    from fgc.verify import linearization_error, to_gtsam, values_from_gtsam

    result = sim.run(program, data)
    t0 = time.perf_counter()
    problem = to_gtsam(graph)
    gres, giters = gtsam_optimize(problem)
    gtsam_s = time.perf_counter() - t0
    ours = _values_by_key(graph, result.values)
    errors = state_errors(graph, ours, values_from_gtsam(graph, problem, gres))
    fgc_err = float(problem.graph.error(to_gtsam(graph, ours).values))
    gtsam_err = float(problem.graph.error(gres))
    rel = abs(fgc_err - gtsam_err) / max(gtsam_err, 1e-12)
    precision = program.solver.precision
    if precision == "float64":
        passed = errors["max_state_error"] <= STATE_TOL_F64 and (rel <= 1e-6 or gtsam_err < 1e-12)
    else:
        passed = (errors["max_rotation_error"] <= ROT_TOL_F32
                  and errors["max_translation_error"] <= POS_TOL_F32)
    report = {"variables": len(graph.variables), "factors": len(graph.factors),
              "precision": precision, "linear_precision": program.solver.les_precision,
              "linear": program.solver.linear, "ordering": program.schedule.ordering,
              "status": result.status,
              "linearization_error": linearization_error(graph), **errors,
              "fgc_final_error": fgc_err, "gtsam_final_error": gtsam_err,
              "relative_final_error_difference": rel, "iterations": result.iterations,
              "gtsam_iterations": giters, "fgc_solve_seconds": result.solve_seconds,
              "gtsam_seconds": gtsam_s, "passed": bool(passed and result.converged)}
    report["summary"] = _verify_summary(report)
    report["_result_values"] = result.values  # popped by the CLI (--values, --marginals)
    return report


def _precision_text(r: dict) -> str:
    """"float32", or "float32 (float64 linear solver)" for the mixed design."""
    les = r["linear_precision"]
    return r["precision"] + (f" ({les} linear solver)" if les != r["precision"] else "")


def _verify_summary(r: dict) -> list[str]:
    tol = (f"tolerance {STATE_TOL_F64:g}" if r["precision"] == "float64"
           else f"float32 bounds {ROT_TOL_F32:g} rad / {POS_TOL_F32:g} m")
    return [
        f"fgc verify: {r['variables']} variables, {r['factors']} factors, simulator "
        f"{_precision_text(r)} {r['linear']} {r['ordering']} vs GTSAM LM (QR)",
        f"  linearisation vs GTSAM (max rel. diff)  {r['linearization_error']:.2e}",
        f"  final error: fgc {r['fgc_final_error']:.10g}  GTSAM {r['gtsam_final_error']:.10g}",
        f"  max state difference: tangent {r['max_state_error']:.2e}, rotation "
        f"{r['max_rotation_error']:.2e} rad, translation {r['max_translation_error']:.2e} m "
        f"({tol})",
        f"  iterations: fgc {r['iterations']} ({r['status']}), GTSAM {r['gtsam_iterations']}",
        "  PASSED" if r["passed"] else "  FAILED",
    ]


def simulate_report(graph: Graph, program, data, sim, plot_dir: str | None = None) -> dict:
    """Run the simulator, then the cost model for the iterations it took."""
    cost_model = import_module(f"{sim.__name__}.cost")  # the backend's own cost model
    result = sim.run(program, data)
    cost = cost_model.estimate(program, iterations=max(result.iterations, 1))
    storage = program.storage
    report = {
        "status": result.status, "reason": result.reason, "iterations": result.iterations,
        "initial_error": result.initial_error, "final_error": result.final_error,
        "precision": program.solver.precision,
        "linear_precision": program.solver.les_precision, "cycles": cost.cycles,
        "clock_mhz": cost.clock_mhz, "latency_ms": cost.latency_ms,
        "cycles_by_unit": dataclasses.asdict(cost.solve),
        "resources": dataclasses.asdict(cost.resources), "energy_mj": cost.energy_mj,
        "power_w": cost.power_w,
        "storage": {"dense_words": storage.dense_words, "stored_words": storage.steps[-1].words,
                    "steps": [dataclasses.asdict(s) for s in storage.steps]},
        "simulator_solve_seconds": result.solve_seconds,
    }
    if plot_dir:
        report["plots"] = _plots(Path(plot_dir), graph, result, report)
    report["summary"] = _simulate_summary(report, len(graph.variables))
    report["_result_values"] = result.values  # popped by the CLI (--values, --marginals)
    return report


def _plots(out: Path, graph: Graph, result, report: dict) -> list[str]:
    from fgc import plots

    out.mkdir(parents=True, exist_ok=True)
    steps = [(s["name"], s["words"]) for s in report["storage"]["steps"]]
    files = [plots.plot_latency_breakdown(out / "latency.png", report["cycles_by_unit"]),
             plots.plot_storage_steps(out / "storage.png", report["storage"]["dense_words"],
                                      steps)]
    values = _values_by_key(graph, result.values)
    if any(isinstance(v, (Pose3, Pose2)) for v in values.values()):
        files.append(plots.plot_trajectory(out / "trajectory.png", values))
    return [str(f) for f in files]


def _simulate_summary(r: dict, n_vars: int) -> list[str]:
    res = r["resources"]
    return [
        f"fgc simulate: {n_vars} variables, {_precision_text(r)}: {r['status']} after "
        f"{r['iterations']} iterations, error {r['initial_error']:.6g} → {r['final_error']:.10g}",
        f"  accelerator: {r['cycles']:,} cycles = {r['latency_ms']:.3f} ms at "
        f"{r['clock_mhz']:g} MHz, energy {r['energy_mj']:.3f} mJ ({r['power_w']:.2f} W)",
        f"  resources: {res['dsp']} DSP, {res['bram']:g} BRAM36, {res['lut']:,} LUT, "
        f"{res['ff']:,} FF",
        f"  storage: {r['storage']['stored_words']:,} words "
        f"(dense {r['storage']['dense_words']:,})",
    ]
