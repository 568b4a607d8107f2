"""GTSAM oracles for keyframe-by-keyframe smoothing: what fgc's incremental and fixed-lag updates
are compared with after every keyframe (``fgc verify --incremental / --window``, the tests, the
streaming benchmark).

- :func:`isam2_per_keyframe`: ``gtsam.ISAM2`` fed each keyframe's factors, optionally with fgc's
  incremental policy (older variables held, the factors across the window's edge kept linear).
- :func:`fixed_lag_per_keyframe`: ``gtsam.BatchFixedLagSmoother`` (LM to convergence per
  update) or ``gtsam.IncrementalFixedLagSmoother`` (ISAM2 inside) with timestamps = keyframe
  index and lag W − 1, so that after each update it holds the newest W keyframes as fgc's window
  of W does.

Keyframes are the Program's schedule clusters (``program.schedule.clusters``: the variable keys
per keyframe, as strings); a factor belongs to the keyframe of its newest variable.
"""

from __future__ import annotations

import time

import numpy as np

from fgc.errors import FgcError
from fgc.frontend.dsl import Graph
from fgc.interop.to_gtsam import GtsamProblem, _gtsam, value_from_gtsam, value_to_gtsam


def _cluster_spans(graph: Graph, clusters) -> list[list[int]]:
    cluster_of = {key: c for c, keys in enumerate(clusters) for key in keys}
    return [[cluster_of[str(k)] for k in f.keys] for f in graph.factors]


def _graph_keys(graph: Graph) -> dict:
    return {str(k): k for k in graph.variables}


def _at(values, kind: str, key: int):
    """The GTSAM value at ``key`` of an fgc variable of type ``kind``."""
    return {"Pose3": values.atPose3, "ImuBias": values.atConstantBias}.get(
        kind, values.atVector)(key)


def _read(graph: Graph, problem: GtsamProblem, estimate, keys) -> dict:
    """{str key: fgc value} of ``keys`` (fgc graph keys) from GTSAM Values."""
    out = {}
    for k in keys:
        var = graph.variables[k]
        out[str(k)] = value_from_gtsam(var.type, _at(estimate, var.type.__name__,
                                                     problem.keys[k]))
    return out


def linear_at(graph: Graph, problem: GtsamProblem, factor, lin):
    """``factor`` linearised (whitened) at ``lin``, as a factor of the local coordinates
    s_i = Log(x̄_i⁻¹ x_i): error Σ A_i·s_i − b with Jacobians A_i·∂s_i/∂δ_i — fgc's τ (GTSAM's
    LinearContainerFactor keeps A_i, which is not the derivative of its error)."""
    gtsam = _gtsam()
    a, b = factor.linearize(lin).jacobian()
    keys = list(factor.keys())
    graph_key = {k: key for key, k in problem.keys.items()}
    kinds = [graph.variables[graph_key[k]].type.__name__ for k in keys]
    if not set(kinds) <= {"Pose3", "ImuBias", "Vector3"}:
        raise FgcError(f"the ISAM2 oracle's kept linear factors support Pose3, ImuBias and "
                       f"Vector3 variables, not {kinds}")

    def read(kind, values, key):
        value = _at(values, kind, key)
        return value.vector() if kind == "ImuBias" else value

    bars = [read(kind, lin, k) for kind, k in zip(kinds, keys, strict=True)]
    cols = np.cumsum([0] + [6 if kind != "Vector3" else 3 for kind in kinds])

    def error(this, values, jacobians):
        r = -b
        for i, (kind, key, bar) in enumerate(zip(kinds, keys, bars, strict=True)):
            if kind == "Pose3":
                shift = gtsam.Pose3.Logmap(bar.between(values.atPose3(key)))
                jac = gtsam.Pose3.LogmapDerivative(shift)
            else:
                shift, jac = read(kind, values, key) - bar, np.eye(len(bar))
            block = a[:, cols[i]:cols[i + 1]]
            r = r + block @ shift
            if jacobians is not None:
                jacobians[i] = block @ jac
        return r

    return gtsam.CustomFactor(gtsam.noiseModel.Unit.Create(a.shape[0]), keys, error)


def _isam2_params(factorization: str = "QR"):
    gtsam = _gtsam()
    params = gtsam.ISAM2Params()
    params.setFactorization(factorization)
    params.setRelinearizeThreshold(0.0)
    params.relinearizeSkip = 1
    gauss_newton = gtsam.ISAM2GaussNewtonParams()
    gauss_newton.setWildfireThreshold(0.0)
    params.setOptimizationParams(gauss_newton)
    return params


def isam2_per_keyframe(graph: Graph, problem: GtsamProblem, clusters, windows=None,
                       tol: float = 1e-11, settle: bool = True) -> list[dict]:
    """ISAM2 (QR, relinearising every variable it may, full back-substitution) keyframe by
    keyframe; returns the estimate after each keyframe ({str key: fgc value}) for the variables
    that have arrived.

    ``windows`` holds per keyframe (first, batch) — fgc's incremental policy — or None — plain
    ISAM2. With a window, the variables of clusters before ``first`` are held (noRelinKeys) and
    the factors reaching across into the window are kept linear at the estimate before the
    keyframe (:func:`linear_at`), as fgc keeps them inside τ; batch steps hold nothing and
    restore the nonlinear factors. Each keyframe: update, then update() until no variable moves
    by ``tol``; ``settle`` False: one update per keyframe (one Gauss-Newton step relinearising
    every variable it may: the one-step policy, ``SolverConfig.one_step``), the factors across
    the window's edge then kept linear at ISAM2's linearisation point (where the update before
    linearised them, as the one-step stream stores its τ and kept conditionals).
    """
    gtsam = _gtsam()
    isam = gtsam.ISAM2(_isam2_params())
    keys = _graph_keys(graph)
    spans = _cluster_spans(graph, clusters)
    slot, linear, estimates = {}, set(), []
    for c, cluster in enumerate(clusters):
        first, batch = (0, True) if windows is None else windows[c]
        factors, values, remove, added = gtsam.NonlinearFactorGraph(), gtsam.Values(), [], []
        for i, span in enumerate(spans):
            if max(span) == c:
                if not (batch or min(span) >= first):
                    raise FgcError(f"keyframe {c}: factor {i} reaches before the window")
                factors.add(problem.graph.at(i))
                added.append(i)
            elif i in slot and (not batch and min(span) < first) != (i in linear):
                remove.append(slot[i])
                linear.symmetric_difference_update({i})
                factors.add(linear_at(graph, problem, problem.graph.at(i),
                                      isam.calculateEstimate() if settle
                                      else isam.getLinearizationPoint())
                            if i in linear else problem.graph.at(i))
                added.append(i)
        for key in cluster:
            values.insert(problem.keys[keys[key]],
                          value_to_gtsam(graph.variables[keys[key]].initial))
        held = None
        if not batch:
            held = gtsam.KeyList()
            for key in (key for old in clusters[:first] for key in old):
                held.push_back(problem.keys[keys[key]])
        result = isam.update(factors, values, remove, None, held, None, False)
        slot.update(zip(added, result.getNewFactorsIndices(), strict=True))
        estimate = isam.calculateEstimate()
        for _ in range(100 if settle else 0):
            isam.update(gtsam.NonlinearFactorGraph(), gtsam.Values(), [], None, held, None,
                        False)
            previous, estimate = estimate, isam.calculateEstimate()
            if np.max(np.abs(previous.localCoordinates(estimate).vector())) < tol:
                break
        else:
            if settle:
                raise FgcError(f"ISAM2 did not settle at keyframe {c}")
        estimates.append(_read(graph, problem, estimate,
                               [keys[key] for old in clusters[:c + 1] for key in old]))
    return estimates


def fixed_lag_per_keyframe(graph: Graph, problem: GtsamProblem, clusters, window: int,
                           kind: str = "batch", timings: list | None = None,
                           estimates: bool = True) -> list[dict]:
    """GTSAM's fixed-lag smoother keyframe by keyframe: ``kind`` "batch"
    (``BatchFixedLagSmoother``: LM to a 1e-12 relative error decrease, 100 iterations, per
    update) or "incremental" (``IncrementalFixedLagSmoother``: one ISAM2 update per keyframe,
    relinearising every variable). Timestamps are keyframe indices and the lag W − 1: after
    the update of keyframe j it holds keyframes j − W + 1 … j, the older ones marginalised
    (after the update's optimisation) into linear factors. Returns, per keyframe, the
    estimate of the window ({str key: fgc value}; empty dicts when ``estimates`` is False);
    each update's wall time (seconds) is appended to ``timings`` if given."""
    gtsam = _gtsam()
    if window < 1:
        raise FgcError(f"the fixed-lag window must be >= 1 keyframe, got {window}")
    if kind == "batch":
        params = gtsam.LevenbergMarquardtParams()
        params.setRelativeErrorTol(1e-12)
        params.setAbsoluteErrorTol(1e-14)
        params.setMaxIterations(100)
        smoother = gtsam.BatchFixedLagSmoother(float(window - 1), params)
    elif kind == "incremental":
        smoother = gtsam.IncrementalFixedLagSmoother(float(window - 1), _isam2_params())
    else:
        raise FgcError(f"fixed-lag smoother kind {kind!r}: expected 'batch' or 'incremental'")
    keys = _graph_keys(graph)
    spans = _cluster_spans(graph, clusters)
    out = []
    for c, cluster in enumerate(clusters):
        factors, values = gtsam.NonlinearFactorGraph(), gtsam.Values()
        stamps = {}
        for i, span in enumerate(spans):
            if max(span) == c:
                if min(span) < c - window:
                    raise FgcError(f"keyframe {c}: factor {i} reaches keyframe {min(span)}, "
                                   f"already marginalised by a window of {window}")
                factors.add(problem.graph.at(i))
        for key in cluster:
            k = problem.keys[keys[key]]
            values.insert(k, value_to_gtsam(graph.variables[keys[key]].initial))
            stamps[k] = float(c)
        t0 = time.perf_counter()
        smoother.update(factors, values, stamps)
        if timings is not None:
            timings.append(time.perf_counter() - t0)
        if estimates:
            estimate = smoother.calculateEstimate()
            held = [keys[key] for old in clusters[max(0, c - window + 1):c + 1] for key in old]
            out.append(_read(graph, problem, estimate, held))
        else:
            out.append({})
    return out


def per_keyframe_distance(updates, estimates: list[dict]) -> list[float]:
    """Per keyframe, the largest tangent-space distance between fgc's update estimates (the
    ``values`` of each record of ``SimResult.updates``) and another estimate of the same
    variables."""
    return [max(float(np.linalg.norm(other[k].local(v))) for k, v in update["values"].items())
            for update, other in zip(updates, estimates, strict=True)]
