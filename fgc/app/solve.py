"""A dense reference solver over fgc's own linearisation (Gauss-Newton / Levenberg-Marquardt).

This is the plain-NumPy definition of the optimisation the accelerator backends perform: it uses
only fgc's derived kernels (never GTSAM) and stacks one dense system, so it suits graphs up to a
few thousand tangent dimensions. The simulator backend is checked against it and against GTSAM.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fgc.compiler.derive import derive
from fgc.errors import FgcError
from fgc.frontend.dsl import Graph
from fgc.frontend.geometry import LieGroup
from fgc.ir.program import SolverConfig

MAX_DENSE_DIM = 20000


@dataclass(frozen=True)
class SolverOptions:
    """Options of :func:`optimize`; tolerances are GTSAM's names and meanings."""

    method: str = SolverConfig.method  # "lm" or "gn"; defaults: the backends' (SolverConfig)
    max_iterations: int = SolverConfig.max_iterations
    relative_error_tol: float = SolverConfig.relative_error_tol
    absolute_error_tol: float = SolverConfig.absolute_error_tol
    lambda_initial: float = SolverConfig.lambda_initial
    lambda_factor: float = SolverConfig.lambda_factor
    lambda_upper_bound: float = SolverConfig.lambda_upper_bound


@dataclass(frozen=True)
class Solution:
    values: dict
    error: float
    initial_error: float
    iterations: int
    converged: bool


def linearize(graph: Graph, values: dict) -> tuple[np.ndarray, np.ndarray, dict]:
    """Whitened dense system (A, b) of the whole graph at ``values``; ``offsets`` maps each key
    to its first column. Robust noise models are reweighted as in GTSAM."""
    from fgc.interop.to_gtsam import linearize_factor  # shares the exact GTSAM-style whitening

    offsets, col = {}, 0
    for k, var in graph.variables.items():
        offsets[k] = col
        col += var.type.dim
    if col > MAX_DENSE_DIM:
        raise FgcError(f"graph has {col} tangent dimensions; the dense reference solver handles "
                       f"at most {MAX_DENSE_DIM}")
    rows_a, rows_b = [], []
    for f in graph.factors:
        a_f, b_f = linearize_factor(f, [values[k] for k in f.keys])
        a = np.zeros((a_f.shape[0], col))
        pos = 0
        for k in f.keys:
            d = graph.variables[k].type.dim
            a[:, offsets[k]:offsets[k] + d] = a_f[:, pos:pos + d]
            pos += d
        rows_a.append(a)
        rows_b.append(b_f)
    return np.vstack(rows_a), np.concatenate(rows_b), offsets


def total_error(graph: Graph, values: dict) -> float:
    """Σ of factor errors (GTSAM's ``graph.error``), robust losses included."""
    total = 0.0
    for f in graph.factors:
        r = derive(f.type).evaluate_residual([values[k] for k in f.keys], f.measured)
        total += f.noise.error(r)
    if not np.isfinite(total):
        raise FgcError("the graph error is not finite at the current estimate")
    return total


def _retract(graph: Graph, values: dict, delta: np.ndarray, offsets: dict) -> dict:
    out: dict = {}
    for k, var in graph.variables.items():
        d = var.type.dim
        v: LieGroup = values[k]
        out[k] = v.retract(delta[offsets[k]:offsets[k] + d])
    return out


def optimize(graph: Graph, options: SolverOptions | None = None) -> Solution:
    """Optimise ``graph`` from its initial values; stops like GTSAM's optimisers."""
    opts = options or SolverOptions()
    if opts.method not in ("lm", "gn"):
        raise FgcError(f"unknown solver method {opts.method!r}; use 'lm' or 'gn'")
    values = {k: v.initial for k, v in graph.variables.items()}
    err0 = err = total_error(graph, values)
    lam, it, converged = opts.lambda_initial, 0, False
    while it < opts.max_iterations and not converged:
        it += 1
        a, b, offsets = linearize(graph, values)
        h, g = a.T @ a, a.T @ b
        while True:
            damped = h + lam * np.eye(h.shape[0]) if opts.method == "lm" else h
            try:
                delta = np.linalg.solve(damped, g)
            except np.linalg.LinAlgError:
                raise FgcError("the linear system is singular: is every variable constrained "
                               "(gauge fixed by a prior)?") from None
            trial = _retract(graph, values, delta, offsets)
            new_err = total_error(graph, trial)
            if opts.method == "gn" or new_err <= err:
                break
            lam *= opts.lambda_factor
            if lam > opts.lambda_upper_bound:
                return Solution(values, err, err0, it, converged=True)
        lam = max(lam / opts.lambda_factor, 1e-20)
        decrease = err - new_err
        values, err_prev, err = trial, err, new_err
        converged = (err <= opts.absolute_error_tol
                     or abs(decrease) <= opts.relative_error_tol * max(err_prev, 1e-300))
    return Solution(values, err, err0, it, converged)


# --------------------------------------------------------------------------------------------
# one-call API: fgc.solve(graph), fgc.verify(graph)
# --------------------------------------------------------------------------------------------
# ``fgc/__init__.py`` exports these two as ``fgc.solve`` and ``fgc.verify`` (so the attribute
# ``fgc.solve`` is this function, not this module; import the module's other names with
# ``from fgc.app.solve import optimize``).


def _program(graph: Graph, config, options: dict, name: str):
    from fgc.compile import compile_graph
    from fgc.ir.datafile import problem_data
    if config is not None and options:
        raise FgcError(f"pass either a SolverConfig or solver options, not both "
                       f"(got config and {sorted(options)})")
    if config is None:
        try:
            config = SolverConfig(**options)
        except TypeError as exc:
            raise FgcError(f"unknown solver option: {exc}") from None
    program = compile_graph(graph, config, name=name)
    return program, problem_data(graph, program)


def solve(graph: Graph, config=None, backend: str = "sim", name: str = "problem",
          **options):
    """Compile ``graph`` and solve it with the accelerator simulator (``backend="sim"``) or the
    generated native C++ solver (``"native"``) or the HLS accelerator's C simulation
    (``"hls"``; any registered backend): ``fgc.compile.compile_graph`` +
    ``problem_data`` + the backend's ``run``, in one call.

    In: an ``fgc.Graph``; a :class:`fgc.ir.program.SolverConfig` or its fields as keywords
    (``precision="float32"``, ``linear="cholesky"``, …; default: LM, QR, float64). Out: the
    backend's result: ``.values`` (final estimate by ``str(key)``), ``.status``
    ("converged", "max_iterations", "failed"), ``.iterations``, ``.final_error``.
    """
    from fgc_backends import load, names

    if backend not in names():
        raise FgcError(f"backend must be one of {', '.join(map(repr, names()))}, got {backend!r}")
    program, data = _program(graph, config, options, name)
    return load(backend).run(program, data)  # native: a CPU program, the clock is moot


def verify(graph: Graph, config=None, name: str = "problem", **options) -> dict:
    """Solve ``graph`` with the simulator and with GTSAM's LM (tight tolerances) and compare,
    as ``fgc verify`` does. In: as :func:`solve` (default float64). Out: the report dict:
    ``passed``, ``max_state_error``, ``max_rotation_error``, ``max_translation_error``,
    ``fgc_final_error``, ``gtsam_final_error``, ``iterations``, … and ``summary`` (the lines
    ``fgc verify`` prints). Needs the ``gtsam`` package."""
    from fgc.app.run_report import verify_report
    from fgc_backends import load

    program, data = _program(graph, config, options, name)
    return verify_report(graph, program, data, load("sim"))
