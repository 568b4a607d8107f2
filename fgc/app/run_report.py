"""Reports behind ``fgc simulate`` and ``fgc verify``: plain dicts (JSON-able) with a summary.

Backends are passed in (never imported here), so fgc stays independent of any backend.
"""

from __future__ import annotations

import dataclasses
import tempfile
import time
from importlib import import_module
from pathlib import Path

import numpy as np

from fgc.frontend.dsl import Graph
from fgc.frontend.geometry import Pose2, Pose3, Rot2, Rot3

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


def gtsam_optimize(problem, linear: str = "qr", max_iterations: int = 100):
    """GTSAM's LM with tight tolerances. The oracle uses GTSAM's multifrontal QR whatever fgc
    solves with: the optimum does not depend on the linear solver, and GTSAM's Cholesky stalls on
    badly scaled problems (IMU window N ≥ 50: 100 iterations, error 1e-6, where QR reaches 1e-20
    in 5)."""
    import gtsam

    params = gtsam.LevenbergMarquardtParams()
    params.setLinearSolverType("MULTIFRONTAL_QR" if linear == "qr" else "MULTIFRONTAL_CHOLESKY")
    params.setRelativeErrorTol(1e-12)
    params.setAbsoluteErrorTol(1e-14)
    params.setMaxIterations(max_iterations)
    optimizer = gtsam.LevenbergMarquardtOptimizer(problem.graph, problem.values, params)
    result = optimizer.optimize()
    return result, int(optimizer.iterations())


# Final errors agree when they differ by at most this, relative to GTSAM's (or when both are
# below ERROR_FLOOR, an exact fit).
ERROR_RTOL, ERROR_FLOOR = 1e-6, 1e-12
# float32: fgc's answer, evaluated in float64, may cost this much more than GTSAM's optimum:
# 1e-3 relative, or 0.5 absolute (½‖δ‖² of a 1σ offset in whitened units), whichever is larger
ERROR_RTOL_F32, ERROR_ATOL_F32 = 1e-3, 0.5


def status_text(status: str, reason: str | None) -> str:
    """A solve's status with its reason, once when they are the same word
    ("max_iterations", not "max_iterations (max_iterations)")."""
    return status if not reason or reason == status else f"{status} ({reason})"


def require_finite_start(graph: Graph, result) -> None:
    """Raise DataError naming the factor when the error at the initial values is not finite
    (the solver cannot start: bad input, exit 2)."""
    initial = getattr(result, "initial_error", None)
    if initial is not None and np.isfinite(initial):
        return
    from fgc.compiler.derive import derive
    from fgc.errors import DataError

    for f in graph.factors:
        vals = [graph.variables[k].initial for k in f.keys]
        with np.errstate(all="ignore"):
            r = np.asarray(derive(f.type).evaluate_residual(vals, f.measured), dtype=float)
        if not np.all(np.isfinite(r)):
            raise DataError(f"the error at the initial values is not finite: factor '{f.name}' "
                            f"on {list(f.keys)} has residual {r.tolist()}; change the initial "
                            "values or the residual function")
    raise DataError("the error at the initial values is not finite; check the initial values "
                    "and noise models")


def verify_report(graph: Graph, program, data, sim) -> dict:
    """Simulator vs GTSAM's LM (same tight tolerances and iteration limit), linearisation check
    per factor type, and a verdict with its reason."""
    from fgc.interop.to_gtsam import (
        EXECUTED_SAMPLE,
        executed_checks,
        linearization_checks,
        sample_factors,
        to_gtsam,
        values_from_gtsam,
        values_to_gtsam,
    )

    with tempfile.TemporaryDirectory(prefix="fgc-verify-") as emitted:
        result = sim.run(program, data, emitted)
        require_finite_start(graph, result)
        # the kernels the simulator executed, at the start and (if finite) at its answer
        finite = all(np.all(np.isfinite(v)) for v in result.storage.values())
        # (non-finite linearisations are judged below, by name: no numpy warning for them)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            executed = sim.linearize(program, data,
                                     [None, result.storage] if finite else [None],
                                     emitted=emitted, factors=sample_factors(graph))
    problem = to_gtsam(graph)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # built-in types are reported, not judged: a sample of them, as the executed check
        checks = linearization_checks(graph, problem=problem, builtin_sample=EXECUTED_SAMPLE)
    k_max = program.solver.max_iterations
    t0 = time.perf_counter()
    gres, giters = gtsam_optimize(problem, max_iterations=k_max)
    gtsam_s = time.perf_counter() - t0
    ours = _values_by_key(graph, result.values)
    errors = state_errors(graph, ours, values_from_gtsam(graph, problem, gres))
    # GTSAM's graph at fgc's answer: the same factors, so the same graph object with fgc's values
    # (converting the 64,312 factors of w10000.graph again cost seconds of a verify)
    from_fgc = dataclasses.replace(problem, values=values_to_gtsam(
        {k: ours.get(k, var.initial) for k, var in graph.variables.items()}, problem.keys))
    points = [("initial values", None, problem), ("final estimate", ours, from_fgc)]
    executed = executed_checks(graph, program, points[:len(executed)], executed)
    fgc_err = float(problem.graph.error(from_fgc.values))
    gtsam_err = float(problem.graph.error(gres))
    rel = abs(fgc_err - gtsam_err) / max(gtsam_err, ERROR_FLOOR)
    precision = program.solver.precision
    report = {"variables": len(graph.variables), "factors": len(graph.factors),
              "precision": precision, "linear_precision": program.solver.les_precision,
              "linear": program.solver.linear, "ordering": program.schedule.ordering,
              "status": result.status, "reason": result.reason, "max_iterations": k_max,
              "linearization_error": max((c.error for c in checks), default=0.0),
              "linearization_checks": [_check_dict(c) for c in checks],
              "executed_kernel_checks": [_executed_dict(c) for c in executed], **errors,
              "fgc_final_error": fgc_err, "gtsam_final_error": gtsam_err,
              "relative_final_error_difference": rel, "iterations": result.iterations,
              "gtsam_iterations": giters, "fgc_solve_seconds": result.solve_seconds,
              "gtsam_seconds": gtsam_s}
    report["fgc_message"] = getattr(result, "message", "")
    matched = _state_matches(report)
    if _limited(report) or (not matched and fgc_err <= gtsam_err
                            + ERROR_RTOL * max(gtsam_err, ERROR_FLOOR)):
        # at a limit, or fgc is at least as low: is its answer an optimum GTSAM's LM cannot
        # improve on (and stops at, within the limit)?
        restart, restart_iters = gtsam_optimize(from_fgc, max_iterations=k_max)
        report["gtsam_from_fgc_error"] = float(problem.graph.error(restart))
        report["gtsam_from_fgc_iterations"] = restart_iters
    bad = {c.factor_type for c in checks if c.custom and not c.passed} | {
        c.factor_type for c in executed if not c.passed}
    if bad or result.status == "failed":
        report["input_problem"] = input_problem(graph, bad or None)
    report["passed"], report["verdict"] = _verdict(report, checks, matched, executed)
    report["summary"] = _verify_summary(report)
    report["_result_values"] = result.values  # popped by the CLI (--values, --marginals)
    return report


def _check_dict(c) -> dict:
    return {"factor_type": c.factor_type, "factors": c.factors, "error": c.error,
            "tolerance": c.tolerance, "method": c.method, "passed": c.passed,
            "singular": c.singular, "sampled": c.sampled}


def _executed_dict(c) -> dict:
    return {"factor_type": c.factor_type, "block": c.block, "checked": c.checked,
            "factors": c.factors, "error": c.error, "where": c.where, "tolerance": c.tolerance,
            "reference": c.reference, "sampled": c.sampled, "passed": c.passed,
            "singular": c.singular}


def _state_tolerance(r: dict) -> str:
    if r["precision"] == "float64":
        return f"{STATE_TOL_F64:g}"
    return f"{ROT_TOL_F32:g} rad / {POS_TOL_F32:g} m"


def _state_distance(r: dict) -> str:
    if r["precision"] == "float64":
        return f"{r['max_state_error']:.2e}"
    return f"{r['max_rotation_error']:.2e} rad / {r['max_translation_error']:.2e} m"


def _errors_agree(r: dict) -> tuple[bool, str]:
    """Do the final errors (both evaluated by GTSAM in float64) agree, and the sentence that
    says to what."""
    fgc_err, gtsam_err = r["fgc_final_error"], r["gtsam_final_error"]
    both = f"final errors fgc {fgc_err:.10g}, GTSAM {gtsam_err:.10g}"
    if r["precision"] == "float64":
        if gtsam_err < ERROR_FLOOR:
            return True, (f"{both}; GTSAM's is below {ERROR_FLOOR:g} (an exact fit: no relative "
                          "comparison, the state distance decides)")
        ok = r["relative_final_error_difference"] <= ERROR_RTOL
        return ok, f"{both}, {'within' if ok else 'not within'} {ERROR_RTOL:g} relative"
    tol = max(ERROR_RTOL_F32 * gtsam_err, ERROR_ATOL_F32)
    ok = abs(fgc_err - gtsam_err) <= tol
    return ok, (f"{both} (both in float64), {'within' if ok else 'not within'} "
                f"max({ERROR_RTOL_F32:g} relative, {ERROR_ATOL_F32:g} absolute)")


def _state_matches(r: dict) -> bool:
    errors_agree = _errors_agree(r)[0]
    if r["precision"] == "float64":
        return r["max_state_error"] <= STATE_TOL_F64 and errors_agree
    return (r["max_rotation_error"] <= ROT_TOL_F32
            and r["max_translation_error"] <= POS_TOL_F32 and errors_agree)


def _at_limit(r: dict) -> list[str]:
    return (["fgc"] if r["status"] == "max_iterations" else []) + (
        ["GTSAM"] if r["gtsam_iterations"] >= r["max_iterations"] else [])


def _limited(r: dict) -> bool:
    return bool(_at_limit(r))


def _limits(r: dict) -> str:
    """Which side stopped at the iteration limit, as a clause ("" when neither did)."""
    hit = _at_limit(r)
    if not hit:
        return ""
    who = " and ".join(hit)
    return f"; {who} stopped at the iteration limit ({r['max_iterations']})"


def _fgc_status(r: dict) -> str:
    """fgc's own status in words: "fgc converged (step) after 5 iterations"."""
    status = {"max_iterations": "stopped at its iteration limit"}.get(
        r["status"], status_text(r["status"], r["reason"]))
    return f"fgc {status} after {_n(r['iterations'], 'iteration')}"


def input_problem(graph: Graph, factor_types: set | None = None) -> str | None:
    """The first factor (of ``factor_types``, default all) whose linearisation at the initial
    values is not finite, or whose derived Jacobians differ from central differences there but
    agree at a nearby point: a singular or non-differentiable point of its residual (a
    direction at 0, atan2 on its branch cut, ...), which is the input's problem, not the
    derivation's. Coincident points of a norm or a bearing are not: fgc derives GTSAM's
    convention there (``singular_at``). None when there is none."""
    from fgc.interop.to_gtsam import (
        FD_TOLERANCE,
        is_custom,
        linearization_checks,
        linearize_factor,
        singular_at,
    )

    rng = np.random.default_rng(0)
    for f in graph.factors:
        if factor_types is not None and f.type.name not in factor_types:
            continue
        values = [graph.variables[k].initial for k in f.keys]
        with np.errstate(all="ignore"):
            a, b = linearize_factor(f, values)
        on = f"factor '{f.name}' on {', '.join(repr(k) for k in f.keys)}"
        if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
            what = "residual" if not np.all(np.isfinite(b)) else "Jacobian"
            return (f"{on}: its {what} at the initial values is not finite (a singular point "
                    "of the residual, e.g. a direction x / |x| at x = 0); "
                    "change those initial values")
        if not is_custom(f.type) or singular_at(f, values):
            continue  # built-in, or at a singular point where GTSAM's convention applies
        here = _single(f, values)
        if linearization_checks(here)[0].error <= FD_TOLERANCE:
            continue
        nearby = [v.retract(1e-3 * rng.standard_normal(type(v).dim)) for v in values]
        if linearization_checks(_single(f, nearby))[0].error <= FD_TOLERANCE:
            return (f"{on}: at the initial values its derived Jacobians differ from central "
                    "differences, but agree at a nearby point, so the residual is not "
                    "differentiable there (e.g. atan2 on its branch cut); "
                    "change those initial values")
    return None


def _single(f, values) -> Graph:
    g = Graph()
    for k, v in zip(f.keys, values, strict=True):
        g.add_variable(k, v)
    return g.add(f)


def _verdict(r: dict, checks: list, matched: bool, executed: list = ()) -> tuple[bool, str]:
    """(passed, one line saying why). PASSED needs fgc's own solve to have ended (converged,
    or at its limit at an optimum GTSAM's LM cannot leave) and its answer to match GTSAM's or
    to be an optimum at least as good; the sentence names what was compared."""
    if r.get("input_problem"):
        return False, f"FAILED: an input problem, not a derivation error: {r['input_problem']}"
    bad = [c for c in checks if c.custom and not c.passed]
    if bad:
        c = max(bad, key=lambda c: c.error / c.tolerance)
        return False, (f"FAILED: fgc's linearisation of factor type '{c.factor_type}' differs "
                       f"from GTSAM's ({c.method}) by {c.error:.2e} > tolerance "
                       f"{c.tolerance:g}: the derived residual or Jacobians are wrong or stale")
    bad = [c for c in executed if not c.passed]
    if bad:
        c = max(bad, key=lambda c: c.error / c.tolerance)
        return False, (f"FAILED: the simulator's kernel for factor type '{c.factor_type}' (block "
                       f"'{c.block}') differs from {c.reference} by {c.error:.2e} > tolerance "
                       f"{c.tolerance:g} at the {c.where}: the executed (fused) kernel is wrong "
                       "or stale")
    dist = f"state distance {_state_distance(r)}"
    tol = _state_tolerance(r)
    fgc_err, gtsam_err = r["fgc_final_error"], r["gtsam_final_error"]
    errors = _errors_agree(r)[1]
    if r["status"] == "failed":
        message = f": {r['fgc_message']}" if r.get("fgc_message") else ""
        return False, (f"FAILED: fgc's own solve failed: {_fgc_status(r)}{message}; "
                       f"GTSAM's answer is not compared with a failed run ({dist}, {errors})")
    restart, iters = r.get("gtsam_from_fgc_error"), r.get("gtsam_from_fgc_iterations", 0)
    stays = restart is not None and restart >= fgc_err - ERROR_RTOL * max(fgc_err, ERROR_FLOOR)
    stops = iters < r["max_iterations"]
    if restart is not None:
        from_fgc = ("GTSAM's LM started from fgc's answer "
                    + (f"stays there ({restart:.10g} after {_n(iters, 'iteration')})" if stays
                       else f"lowers it to {restart:.10g} in {_n(iters, 'iteration')}")
                    + ("" if stops else ", stopping at the iteration limit again"))
    if _limited(r):
        who = " and ".join(_at_limit(r))
        limit = f"{who} stopped at the iteration limit ({r['max_iterations']})"
        if not (stays and stops):
            return False, (f"FAILED: not converged: {limit} and {from_fgc}, so fgc's answer is "
                           f"not shown to be an optimum ({_fgc_status(r)}; {dist}, {errors}); "
                           "raise --max-iterations")
        if matched:
            return True, (f"PASSED at the iteration limit: {limit}, but the answers match "
                          f"({dist} ≤ {tol}, {errors}) and {from_fgc}")
    if matched:
        return True, (f"PASSED: {_fgc_status(r)} and its answer matches GTSAM's: {dist} ≤ "
                      f"{tol}, {errors}")
    if restart is None:
        return False, (f"FAILED: {dist} > {tol} and GTSAM reached the lower error ({gtsam_err:.10g}"
                       f" < fgc {fgc_err:.10g}, relative difference "
                       f"{r['relative_final_error_difference']:.1e}); {_fgc_status(r)}")
    if not stays:
        return False, (f"FAILED: {dist} > {tol}; fgc's final error {fgc_err:.10g} is not above "
                       f"GTSAM's {gtsam_err:.10g}, but {from_fgc}, so fgc's answer is not an "
                       f"optimum ({_fgc_status(r)})")
    return True, (f"PASSED: fgc's optimum is at least as good as GTSAM's (final error fgc "
                  f"{fgc_err:.10g} ≤ GTSAM {gtsam_err:.10g}) and {from_fgc}; {dist} > {tol}; "
                  f"{_fgc_status(r)}{_limits(r)}")


def _n(count: int, noun: str) -> str:
    return f"{count} {noun}{'' if count == 1 else 's'}"


def _precision_text(r: dict) -> str:
    """"float32", or "float32 (float64 linear solver)" for the mixed design."""
    les = r["linear_precision"]
    return r["precision"] + (f" ({les} linear solver)" if les != r["precision"] else "")


def _singular_text(c: dict) -> str:
    n = c.get("singular", 0)
    return (f" ({n} at a singular point of the residual, e.g. coincident points: residual "
            "compared, Jacobian GTSAM's convention there, where none exists to compare)"
            if n else "")


def _verify_summary(r: dict) -> list[str]:
    tol = (f"tolerance {STATE_TOL_F64:g}" if r["precision"] == "float64"
           else f"float32 bounds {ROT_TOL_F32:g} rad / {POS_TOL_F32:g} m")
    from fgc.interop.to_gtsam import EXECUTED_SAMPLE

    lines = [
        f"fgc verify: {r['variables']} variables, {r['factors']} factors, simulator "
        f"{_precision_text(r)} {r['linear']} {r['ordering']} vs GTSAM LM (QR)",
    ]
    for c in r["linearization_checks"]:
        if c["method"].startswith("numerical"):
            lines.append(f"  custom factor verify '{c['factor_type']}': checked against "
                         f"{c['method']}, tolerance {c['tolerance']:g}; max rel. diff "
                         f"{c['error']:.2e} over {c['factors']} factors{_singular_text(c)}")
    executed = r.get("executed_kernel_checks", [])
    if executed:
        worst = max(c["error"] for c in executed)
        checked = sum(c["checked"] for c in executed)
        sampled = [c["factor_type"] for c in executed if c["sampled"]]
        sample = (f"; {EXECUTED_SAMPLE} evenly spaced factors per point of "
                  f"{', '.join(repr(n) for n in sampled)}" if sampled else "")
        lines.append(f"  executed kernels (simulator) vs numerical derivatives (custom) / fgc's "
                     f"per-factor derivation (built-in), at the initial values and the final "
                     f"estimate: max rel. diff {worst:.2e} over {checked} factor evaluations, "
                     f"tolerance {executed[0]['tolerance']:g}{sample}"
                     f"{_singular_text({'singular': sum(c['singular'] for c in executed)})}")
    builtin = [c for c in r["linearization_checks"] if not c["method"].startswith("numerical")]
    if builtin:
        worst = max(c["error"] for c in builtin)
        sampled = [c["factor_type"] for c in builtin if c.get("sampled")]
        sample = (f"; {EXECUTED_SAMPLE} evenly spaced factors of "
                  f"{', '.join(repr(n) for n in sampled)}" if sampled else "")
        lines.append(f"  linearisation vs GTSAM's own factors (max rel. diff)  {worst:.2e} "
                     "(reported, not judged: GTSAM's own Jacobians can be inexact, e.g. Pose2 at "
                     f"small non-zero rotation residuals{sample})")
    lines += [
        f"  final error: fgc {r['fgc_final_error']:.10g}  GTSAM {r['gtsam_final_error']:.10g}",
        f"  max state difference: tangent {r['max_state_error']:.2e}, rotation "
        f"{r['max_rotation_error']:.2e} rad, translation {r['max_translation_error']:.2e} m "
        f"({tol})",
        f"  iterations: fgc {r['iterations']} ({status_text(r['status'], r['reason'])}), "
        f"GTSAM {r['gtsam_iterations']} (limit {r['max_iterations']})",
    ]
    if "gtsam_from_fgc_error" in r:
        lines.append(f"  GTSAM LM started from fgc's answer: error {r['gtsam_from_fgc_error']:.10g}"
                     f" after {_n(r['gtsam_from_fgc_iterations'], 'iteration')}")
    lines.append(f"  {r['verdict']}")
    return lines


def plan_summary(program, iterations: int, options=None) -> dict:
    """The accelerator plan's hardware figures for ``iterations`` iterations of ``program``
    (``fgc_backends.hls.plan.plan_summary``: plan_cost of build_plan with ``options``, by
    default the Program's n_u, #CPE, clock and precision; the CLI passes the options of the
    design ``fgc compile --backend hls`` would emit with the same flags). Looked up by name, as
    the backends are, so fgc imports none."""
    return import_module("fgc_backends.hls.plan").plan_summary(program, iterations, options)


def simulate_report(graph: Graph, program, data, sim, plot_dir: str | None = None,
                    plan_options=None) -> dict:
    """Run the simulator, then cost the iterations it took with the accelerator plan
    (``plan_options``: the priced design, default the Program's)."""
    result = sim.run(program, data)
    require_finite_start(graph, result)
    cost = plan_summary(program, max(result.iterations, 1), plan_options)
    storage = program.storage
    report = {
        "status": result.status, "reason": result.reason, "iterations": result.iterations,
        "initial_error": result.initial_error, "final_error": result.final_error,
        "precision": program.solver.precision,
        "linear_precision": program.solver.les_precision, "cycles": cost["cycles"],
        "clock_mhz": cost["clock_mhz"], "latency_ms": cost["latency_ms"],
        "cycles_by_unit": cost["cycles_by_unit"], "cost_source": cost["source"],
        "resources": cost["resources"], "energy_mj": cost["energy_mj"],
        "power_w": cost["power_w"],
        "storage": {"dense_words": storage.dense_words, "stored_words": storage.steps[-1].words,
                    "plan_memory_words": cost["memory_words"],
                    "steps": [dataclasses.asdict(s) for s in storage.steps]},
        "simulator_solve_seconds": result.solve_seconds,
        "final_error_float64": float64_error(graph, result.values),
        "fits": cost["fits"], "device": cost["device"], "utilization": cost["utilization"],
    }
    if plot_dir:
        report["plots"] = _plots(Path(plot_dir), graph, result, report)
    report["summary"] = _simulate_summary(report, len(graph.variables))
    if plot_dir:
        names = ", ".join(Path(f).name for f in report["plots"])
        missing = ("" if len(report["plots"]) > 2 else "; no trajectory or attitude plot: the "
                   "graph has no Pose2/Pose3 or Rot2/Rot3 variables")
        report["summary"].append(f"  plots → {plot_dir}: {names}{missing}")
    report["_result_values"] = result.values  # popped by the CLI (--values, --marginals)
    return report


def _plots(out: Path, graph: Graph, result, report: dict) -> list[str]:
    """latency.png, storage.png and, for graphs with poses, trajectory.png: fgc's solution over
    GTSAM's LM solution (computed here: one GTSAM solve, milliseconds to a second or two for the
    shipped examples, cheap next to the simulator), the GPS fixes of the graph's GPSFactors and
    the landmarks (Point2 / Point3 variables: beacons too) of both; for rotation-only graphs,
    attitude.png (attitude over the variables, fgc and GTSAM)."""
    from fgc.app import plots
    out.mkdir(parents=True, exist_ok=True)
    steps = [(s["name"], s["words"]) for s in report["storage"]["steps"]]
    files = [out / "latency.png", out / "storage.png"]
    plots.plot_latency_breakdown(report["cycles_by_unit"], path=files[0])
    plots.plot_storage_steps(report["storage"]["dense_words"], steps, path=files[1])
    values = _values_by_key(graph, result.values)
    poses = any(isinstance(v, (Pose3, Pose2)) for v in values.values())
    rotations = any(isinstance(v, (Rot3, Rot2)) for v in values.values())
    if poses or rotations:
        from fgc.interop.to_gtsam import to_gtsam, values_from_gtsam

        problem = to_gtsam(graph)
        reference = values_from_gtsam(graph, problem, gtsam_optimize(problem)[0])
    if poses:
        gps = [np.asarray(getattr(f.measured["position"], "v", f.measured["position"]),
                          float).ravel() for f in graph.factors if f.type.name == "GPSFactor"]
        files.append(out / "trajectory.png")
        plots.plot_trajectory(values, reference, np.array(gps) if gps else None,
                              title="Trajectory (top view): fgc vs GTSAM LM", path=files[-1],
                              landmarks=values, gtsam_landmarks=reference)
    elif rotations:
        files.append(out / "attitude.png")
        plots.plot_attitude(values, reference, title="Attitude: fgc vs GTSAM LM",
                            path=files[-1])
    return [str(f) for f in files]


_RESOURCE_NAMES = (("dsp", "DSP"), ("bram", "BRAM36"), ("lut", "LUT"), ("ff", "FF"))


def fit_verdict(cost: dict) -> str:
    """"fits xc7z045" or "does NOT fit xc7z045: BRAM36 14.3× the device's" — the accelerator
    plan's verdict (``plan_summary``'s ``fits`` / ``utilization``), as ``fgc report`` and
    ``fgc simulate`` print it."""
    if cost["fits"]:
        return f"fits {cost['device']}"
    over = [f"{label} {cost['utilization'][key]:.3g}× the device's"
            for key, label in _RESOURCE_NAMES if cost["utilization"].get(key, 0.0) > 1.0]
    return f"does NOT fit {cost['device']}" + (f": {', '.join(over)}" if over else "")


def float64_error(graph: Graph, values: dict) -> float:
    """The graph's error Σ ½‖R r‖² (robust losses included; GTSAM's ``graph.error``) at
    ``values`` (graph key or its ``str`` → value), evaluated in float64 whatever precision the
    values were solved in: a float32 design's own cost figure is rounded and can lie below the
    true optimum. NaN when the state is not finite."""
    from fgc.compiler.derive import derive
    from fgc.interop.estimates import graph_values

    storage = {k: np.asarray(v.to_storage(), dtype=np.float64)
               for k, v in graph_values(graph, values).items()}
    if not all(np.all(np.isfinite(s)) for s in storage.values()):
        return float("nan")
    by_type: dict = {}
    for f in graph.factors:
        by_type.setdefault(f.type, []).append(f)
    total = 0.0
    for ftype, factors in by_type.items():  # one vectorised residual call per factor type
        d = derive(ftype)
        names = [b.name for b in d.measurements]
        inputs = np.array([np.concatenate([storage[k] for k in f.keys]
                                          + [np.ravel(f.measured[n]) for n in names])
                           for f in factors])
        total += _noise_error(factors, d.evaluate_residuals(inputs))
    return total


def _noise_error(factors: list, r: np.ndarray) -> float:
    """Σ of GTSAM's factor errors ½‖R r‖² (ρ(‖R r‖) for robust noise) over ``factors``."""
    info = np.stack([f.noise.sqrt_information for f in factors])
    with np.errstate(all="ignore"):
        e = np.linalg.norm(np.einsum("nij,nj->ni", info, r), axis=1)
    total = float(0.5 * np.sum(np.where([f.noise.robust is None for f in factors], e * e, 0.0)))
    return total + sum(float(f.noise.robust.loss(x)) for f, x in zip(factors, e, strict=True)
                       if f.noise.robust is not None)


def final_error_text(r: dict) -> str:
    """The float64 final error, and the design's own figure beside it when the design is not
    float64 (``r``: a report with ``final_error_float64``, ``final_error``, ``precision``)."""
    text = f"{_number(r['final_error_float64'], '.10g')} (float64 at the returned state"
    if r.get("precision", "float64") != "float64":
        text += f"; the {r['precision']} design's own figure {_number(r['final_error'], '.10g')}"
    return text + ")"


def _simulate_summary(r: dict, n_vars: int) -> list[str]:
    res = r["resources"]
    return [
        f"fgc simulate: {n_vars} variables, {_precision_text(r)}: "
        f"{status_text(r['status'], r['reason'])} after "
        f"{r['iterations']} iterations, error {_number(r['initial_error'], '.6g')} → "
        f"{final_error_text(r)}",
        f"  accelerator (model estimate): {r['cycles']:,} cycles = {r['latency_ms']:.3f} ms at "
        f"{r['clock_mhz']:g} MHz (accelerator plan), energy {r['energy_mj']:.3f} mJ "
        f"({r['power_w']:.2f} W: the sim model's power fit on the plan's resources)",
        f"  resources (model estimate): {res['dsp']} DSP, {res['bram']:g} BRAM36, "
        f"{res['lut']:,} LUT, {res['ff']:,} FF; {fit_verdict(r)}",
        f"  storage: {r['storage']['stored_words']:,} words "
        f"(dense {r['storage']['dense_words']:,}); plan memories "
        f"{r['storage']['plan_memory_words']:,} words (model estimate)",
    ]


def _number(x: float | None, fmt: str) -> str:
    return "not finite" if x is None or not np.isfinite(x) else format(x, fmt)
