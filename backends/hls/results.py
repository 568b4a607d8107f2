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
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fgc.errors import DataError
from fgc.program import Program

RESULT_MAGIC = "FGCRESULT 1"
STATUSES = ("converged", "max_iterations", "failed")
REASONS = ("gradient", "step", "predicted_decrease", "absolute_error", "relative_decrease",
           "max_iterations", "non_finite", "singular", "cost_increased", "lambda_limit")


@dataclass(frozen=True)
class HlsResult:
    """Final estimate per variable, iterations, errors, status.

    ``values``: key → array of the variable's storage (C simulation, ``NativeSolver.run``), or
    key → fgc value from :func:`fgc_backends.hls.native.run`, which then keeps the arrays in
    ``storage`` (the simulator's ``SimResult`` layout: one result type across backends)."""

    values: dict
    iterations: int
    initial_error: float
    final_error: float
    status: str
    reason: str
    storage: dict[str, np.ndarray] | None = None

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


def read_result(path: str | Path, program: Program) -> HlsResult:
    """Parse the testbench's result file for ``program``; errors name the file and line."""
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
    return result_from_arrays(program, np.array(x),
                              (float(fields["INITIAL_ERROR"]), float(fields["FINAL_ERROR"])),
                              int(fields["ITERATIONS"]), STATUSES.index(fields["STATUS"]),
                              REASONS.index(fields["REASON"]))
