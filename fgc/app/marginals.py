"""Marginal covariances of chosen variables at an estimate, from fgc's own linearisation.

The covariance of variable k is the k-block of (AᵀA)⁻¹, A the whitened Jacobian of the whole
graph at ``values`` (:func:`fgc.app.solve.linearize`: GTSAM's whitening and robust reweighting, and
each variable's tangent chart), which is what ``gtsam.Marginals(graph, values)
.marginalCovariance(key)`` returns. A is factored once (QR, so RᵀR = AᵀA without squaring
A's condition number; a rank-deficient A, e.g. a graph without a prior to fix the gauge, raises
FgcError) and only
the chosen blocks' columns of the inverse are solved for. GTSAM is never called.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from fgc.app.solve import linearize
from fgc.errors import FgcError
from fgc.frontend.dsl import Graph, Key


def marginal_covariances(graph: Graph, keys: Iterable[Key], values: dict | None = None
                         ) -> dict[Key, np.ndarray]:
    """{key: (dim × dim) marginal covariance} of ``keys`` at ``values`` (default: the initial
    values; pass a solve's result for the estimate's covariances)."""
    keys = list(keys)
    for k in keys:
        if k not in graph.variables:
            raise FgcError(f"marginals: the graph has no variable {k!r}")
    point = {k: (values[k] if values is not None and k in values else var.initial)
             for k, var in graph.variables.items()}
    a, _, offsets = linearize(graph, point)
    r = np.linalg.qr(a, mode="r")  # RᵀR = AᵀA without squaring A's condition number
    diag = np.abs(np.diag(r))
    if r.shape[0] < a.shape[1] or not diag.min() > 1e-12 * max(diag.max(), 1e-300):
        raise FgcError("marginals: the information matrix is singular (is every variable "
                       "constrained, the gauge fixed by a prior?)")
    lower = r.T
    out = {}
    for k in keys:
        o, d = offsets[k], graph.variables[k].type.dim
        e = np.zeros((a.shape[1], d))
        e[o:o + d] = np.eye(d)
        y = np.linalg.solve(lower, e)  # L y = E, then Lᵀ x = y (triangular, solved densely)
        x = np.linalg.solve(lower.T, y)
        block = x[o:o + d]
        out[k] = 0.5 * (block + block.T)
    return out


def parse_keys(text: str, graph: Graph) -> list[Key]:
    """``"x1,x2"`` → the graph's key objects (an int key matches its digits)."""
    by_text = {str(k): k for k in graph.variables}
    keys = []
    for item in (s.strip() for s in text.split(",")):
        if item not in by_text:
            raise FgcError(f"--marginals: the graph has no variable {item!r}")
        keys.append(by_text[item])
    return keys
