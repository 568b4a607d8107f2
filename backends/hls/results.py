"""The result of a C simulation or native run, and the testbench's result-file format.

The testbench writes (numbers with ``%.17g``, so doubles read back exactly)::

    FGCRESULT 1
    STATUS <converged | max_iterations | failed>
    REASON <why it stopped: the simulator's reason names>
    ITERATIONS <n>
    INITIAL_ERROR <e0>
    FINAL_ERROR <e>
    VARIABLES <n>
    <storage_dim> <v> ...          one line per variable, Program.variables order

Statuses and reasons are the simulator's (``fgc_backends.sim``), by the same names; the C++
kernel reports them as indices into these tuples.

**float32 verdict.** The kernel's stopping rules cannot tell that a float32 state is too coarse
for the data's noise (positions near 1e6 m, σ = 1e-9): :func:`judge_precision` checks it on the
host after the run, never in the synthesisable kernel. It evaluates every factor's whitened
Jacobian in float64 at the returned solution (the Program's block kernels, through the
simulator's float64 linearisation) and ρ with :func:`fgc.conditioning.resolution`, the
simulator's formula; ρ ≥ 1 turns "converged" into status "failed", reason "precision_limit",
with a :class:`fgc.conditioning.PrecisionLimitWarning` — the simulator's verdict.
"""

from __future__ import annotations

import hashlib
import runpy
import tempfile
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from fgc import conditioning
from fgc.datafile import ProblemData
from fgc.errors import DataError
from fgc.program import Program

RESULT_MAGIC = "FGCRESULT 1"
STATUSES = ("converged", "max_iterations", "failed")
REASONS = ("gradient", "step", "predicted_decrease", "absolute_error", "relative_decrease",
           "max_iterations", "non_finite", "singular", "cost_increased", "lambda_limit")
PRECISION_LIMIT = "precision_limit"  # a host-side verdict (judge_precision), not a kernel reason


@dataclass(frozen=True)
class HlsResult:
    """Final estimate per variable, iterations, errors, status.

    ``values``: key → array of the variable's storage (C simulation, ``NativeSolver.run``), or
    key → fgc value from :func:`fgc_backends.native.run`, which then keeps the arrays in
    ``storage`` (the simulator's ``SimResult`` layout: one result type across backends)."""

    values: dict
    iterations: int
    initial_error: float
    final_error: float
    status: str
    reason: str
    storage: dict[str, np.ndarray] | None = None
    resolution: float | None = None  # ρ at the solution (judge_precision; None: not judged)
    message: str = ""  # why the run failed, in words (empty when it converged)
    warnings: tuple[str, ...] = ()  # texts of the fgc warnings the verdict issued

    @property
    def converged(self) -> bool:
        return self.status == "converged"


def result_from_arrays(program: Program, x: np.ndarray, errors, iterations: int, status: int,
                       reason: int) -> HlsResult:
    """Assemble a result from the flat storage vector and the kernel's report."""
    values, pos = {}, 0
    for v in program.variables:
        values[v.key] = np.array(x[pos:pos + v.storage_dim], dtype=np.float64)
        pos += v.storage_dim
    return HlsResult(values, int(iterations), float(errors[0]), float(errors[1]),
                     STATUSES[status], REASONS[reason])


def read_result(path: str | Path, program: Program, data: ProblemData | None = None,
                scalar: str | None = None) -> HlsResult:
    """Parse the testbench's result file for ``program``; errors name the file and line. With
    the run's ``data`` and C++ ``scalar``, the result carries :func:`judge_precision`'s
    verdict."""
    path = Path(path)
    lines = path.read_text().splitlines()
    fields = {}
    for number, key in enumerate(("STATUS", "REASON", "ITERATIONS", "INITIAL_ERROR",
                                  "FINAL_ERROR", "VARIABLES"), start=1):
        parts = lines[number].split() if number < len(lines) else []
        if len(parts) != 2 or parts[0] != key:
            raise DataError(f"{path}:{number + 1}: expected '{key} <value>'")
        fields[key] = parts[1]
    if lines[0] != RESULT_MAGIC or int(fields["VARIABLES"]) != len(program.variables):
        raise DataError(f"{path}: not a result file of this Program")
    x = []
    for line in lines[7:7 + len(program.variables)]:
        numbers = line.split()
        x += [float(v) for v in numbers[1:]]
    result = result_from_arrays(program, np.array(x),
                                (float(fields["INITIAL_ERROR"]), float(fields["FINAL_ERROR"])),
                                int(fields["ITERATIONS"]), STATUSES.index(fields["STATUS"]),
                                REASONS.index(fields["REASON"]))
    if data is None or scalar is None:
        return result
    return judge_precision(program, data, result, scalar)


def judge_precision(program: Program, data: ProblemData, result: HlsResult,
                    scalar: str) -> HlsResult:
    """``result`` (storage arrays as ``values``) of a run in C++ ``scalar`` on ``data``, with
    the float32 verdict: ρ at the returned solution; ρ ≥ 1 warns
    (:class:`fgc.conditioning.PrecisionLimitWarning`, the simulator's text) and a "converged"
    result becomes status "failed", reason "precision_limit". Double runs, and runs that ended
    singular or non-finite (as in the simulator), are returned unchanged; so are fixed-point
    scalars, whose resolution is not a relative eps (not judged)."""
    precision = conditioning.SCALAR_PRECISION.get(scalar)
    if precision in (None, "float64") or result.reason in ("singular", "non_finite"):
        return result
    storage = [np.asarray(result.values[v.key], dtype=np.float64) for v in program.variables]
    if not all(np.all(np.isfinite(v)) for v in storage):
        return result
    rho, index = conditioning.resolution(whitened_jacobians(program, data, storage), storage,
                                         [v.dim for v in program.variables], precision)
    if rho < conditioning.RESOLUTION_LIMIT:
        return replace(result, resolution=rho)
    spec = program.variables[index]
    text = conditioning.precision_limit_message(spec.key, spec.type_name, rho, precision)
    conditioning.warn(text, conditioning.PrecisionLimitWarning)
    status, reason = result.status, result.reason
    if status == "converged":
        status, reason = "failed", PRECISION_LIMIT
    return replace(result, status=status, reason=reason, resolution=rho, message=text,
                   warnings=(*result.warnings, text))


_LINEARIZERS: dict[str, dict] = {}  # Program JSON hash → the emitted simulator's namespace
_BY_ID: dict[int, tuple[Program, dict]] = {}  # id → (Program, namespace): skips hashing the JSON


def _linearizer(program: Program) -> dict:
    """The emitted simulator of ``program`` (its namespace), emitted once per Program content."""
    known = _BY_ID.get(id(program))
    if known is not None and known[0] is program:
        return known[1]
    key = hashlib.sha256(program.to_json().encode()).hexdigest()
    if key not in _LINEARIZERS:
        from fgc_backends.sim.config import SimConfig
        from fgc_backends.sim.emitter import emit

        with tempfile.TemporaryDirectory(prefix="fgc-judge-") as tmp:
            files = emit(program, Path(tmp), SimConfig())
            _LINEARIZERS[key] = runpy.run_path(str(files[0]), run_name="fgc_judge_problem")
    _BY_ID[id(program)] = (program, _LINEARIZERS[key])
    return _LINEARIZERS[key]


def whitened_jacobians(program: Program, data: ProblemData, storage: list[np.ndarray]
                       ) -> list[tuple[np.ndarray, np.ndarray]]:
    """Every factor block's whitened Jacobian rows at ``storage`` (one array per variable),
    evaluated in float64 by the Program's own block kernels (the simulator's linearisation; the
    emitted simulator is kept per Program for the process), paired with their global tangent
    columns: the ``parts`` of :func:`fgc.conditioning.resolution`."""
    namespace = _linearizer(program)
    lib = namespace["LIB"]
    rows = ([(np.asarray(v, dtype=np.float64), i + 1) for i, v in enumerate(storage)],
            [(np.asarray(f, dtype=np.float64), i + 1) for i, f in enumerate(data.factors)])
    # no elimination schedule: only the linearisation is needed (the plan costs as much again)
    spec = {**namespace["PROBLEM"], "steps": ()}
    problem = lib.optimizer.Problem(spec, rows, "float64", lib)
    abs_, _, _ = problem.linearize(problem.x0)
    return [(ab[..., :-1], block.columns) for block, ab in zip(problem.blocks, abs_,
                                                                strict=True)]
