"""The result of a C simulation or native run, and the testbench's result-file format.

The testbench writes (numbers with ``%.17g``, so doubles read back exactly)::

    FGCRESULT 2
    STATUS <converged | max_iterations | failed>
    REASON <why it stopped: the simulator's reason names>
    ITERATIONS <n>
    INITIAL_ERROR <e0>
    FINAL_ERROR <e>
    VARIABLES <n>
    <key> <storage_dim> <v> ...    one line per variable, Program.variables order

``<key>`` is the variable's key token (:func:`fgc_backends.cfamily.names.key_tokens`: an integer key
as its digits, other keys sanitised), from a table the emitter generates; :func:`read_result`
checks each against the Program and returns the values under the graph's keys as well
(``HlsResult.keyed_values``: integer keys as ``int``).

**Reference.** Beside the data file, :func:`write_reference` puts the simulator's float64 result
for the same Program and data (``reference.txt``; same layout, header ``FGCREFERENCE 1
<structure fingerprint>``, then ``STATUS``, ``FINAL_ERROR``, ``VARIABLES`` and the keyed lines):
the testbench compares its own result with it and exits 4 on a mismatch. Version 2 adds
``ERROR_FLOOR <f>`` after ``FINAL_ERROR``: how much the cost rises when the reference state
is rounded to the design's scalar (:func:`error_floor`; 0 for double), how far above the
float64 optimum's cost a state held in float (or ap_fixed) can be expected to rest; the
testbench's final-error tolerance for such a design adds ``ERROR_FLOOR_FACTOR`` times it.

Statuses and reasons are the simulator's (``fgc_backends.sim``), by the same names; the C++
kernel reports them as indices into these tuples.

**float32 verdict.** The kernel's stopping rules cannot tell that a float32 state is too coarse
for the data's noise (positions near 1e6 m, σ = 1e-9): :func:`judge_precision` checks it on the
host after the run, never in the synthesisable kernel. It evaluates every factor's whitened
Jacobian in float64 at the returned solution (the Program's block kernels, through the
simulator's float64 linearisation) and ρ with :func:`fgc.ir.conditioning.resolution`, the
simulator's formula; ρ ≥ 1 turns "converged" into status "failed", reason "precision_limit",
with a :class:`fgc.ir.conditioning.PrecisionLimitWarning` — the simulator's verdict.
"""

from __future__ import annotations

import hashlib
import runpy
import tempfile
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

import fgc_backends
from fgc.errors import DataError
from fgc.interop.estimates import values_from_storage
from fgc.ir import conditioning, frame
from fgc.ir.codes import REASONS, STATUSES
from fgc.ir.datafile import ProblemData
from fgc.ir.program import Program
from fgc.ir.result import SolveResult
from fgc_backends.cfamily.names import key_tokens, token_key
from fgc_backends.cfamily.scalars import fixed_format

RESULT_MAGIC = "FGCRESULT 2"
REFERENCE_MAGIC = "FGCREFERENCE 2"
# a float (ap_fixed) state rests a few units in the last place from the float64 optimum: its
# cost may exceed the optimum's by this many times the cost of the optimum rounded to the scalar
# (the cost grows with the square of the state's distance: 10 ≈ three units in the last place)
ERROR_FLOOR_FACTOR = 10.0
REFERENCE_FILE = "reference.txt"
PRECISION_LIMIT = "precision_limit"  # a host-side verdict (judge_precision), not a kernel reason


@dataclass(frozen=True)
class HlsResult(SolveResult):
    """Final estimate per variable, iterations, errors, status.

    ``values``: key → array of the variable's storage (C simulation, ``NativeSolver.run``), or
    key → fgc value from the backends' ``run`` (:func:`keyed`), which then keeps the arrays in
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
    # the storage arrays under the graph's keys, read from a keyed result file (integer keys as
    # int: fgc.names.token_key); None when the result did not come from a file
    keyed_values: dict | None = None
    keys: dict = field(default_factory=dict)  # Program variable key → the user's key (run())


def keyed(result: HlsResult, program: Program) -> HlsResult:
    """``result`` (storage arrays as ``values``) as the backend contract's ``run`` returns it:
    ``values`` fgc values by Program key, the arrays in ``storage``, ``keys`` to the graph's."""
    return replace(result, values=values_from_storage(program, result.values),
                   storage=result.values, keys={v.key: v.user_key for v in program.variables})


def result_from_arrays(program: Program, x: np.ndarray, errors, iterations: int, status: int,
                       reason: int) -> HlsResult:
    """Assemble a result from the flat storage vector (in the Program's local frame, as the
    kernel holds it) and the kernel's report; the values are in world coordinates."""
    values, pos = {}, 0
    for v in program.variables:
        values[v.key] = np.array(x[pos:pos + v.storage_dim], dtype=np.float64)
        pos += v.storage_dim
    return HlsResult(frame.to_world(program, values), int(iterations), float(errors[0]),
                     float(errors[1]), STATUSES[status], REASONS[reason])


def read_result(path: str | Path, program: Program, data: ProblemData | None = None,
                scalar: str | None = None) -> HlsResult:
    """Parse the testbench's result file for ``program``; errors name the file and line. With
    the run's ``data`` and C++ ``scalar``, the result carries :func:`judge_precision`'s
    verdict."""
    path = Path(path)
    lines = path.read_text().splitlines()
    if not lines or lines[0] != RESULT_MAGIC:
        raise DataError(f"{path}:1: expected '{RESULT_MAGIC}' (not a result file of this fgc)")
    fields = {}
    for number, key in enumerate(("STATUS", "REASON", "ITERATIONS", "INITIAL_ERROR",
                                  "FINAL_ERROR", "VARIABLES"), start=1):
        parts = lines[number].split() if number < len(lines) else []
        if len(parts) != 2 or parts[0] != key:
            raise DataError(f"{path}:{number + 1}: expected '{key} <value>'")
        fields[key] = parts[1]
    if int(fields["VARIABLES"]) != len(program.variables):
        raise DataError(f"{path}:7: {fields['VARIABLES']} variables, the Program has "
                        f"{len(program.variables)}: not a result file of this Program")
    if fields["STATUS"] not in STATUSES or fields["REASON"] not in REASONS:
        raise DataError(f"{path}: unknown status {fields['STATUS']!r} or reason "
                        f"{fields['REASON']!r}")
    x, keyed = _keyed_lines(path, lines, 7, program)
    result = result_from_arrays(program, np.array(x),
                                (float(fields["INITIAL_ERROR"]), float(fields["FINAL_ERROR"])),
                                int(fields["ITERATIONS"]), STATUSES.index(fields["STATUS"]),
                                REASONS.index(fields["REASON"]))
    result = replace(result, keyed_values={key: result.values[v.key] for key, v in  # world
                                           zip(keyed, program.variables, strict=True)})
    if data is None or scalar is None:
        return result
    return judge_precision(program, data, result, scalar)


def _keyed_lines(path: Path, lines: list[str], first: int, program: Program
                 ) -> tuple[list[float], dict]:
    """The flat storage and {graph key: array} of the ``<key> <storage_dim> <v> ...`` lines
    from ``lines[first]`` on; each key token must be the Program's (errors name the line)."""
    x, keyed = [], {}
    tokens = key_tokens(v.key for v in program.variables)
    for i, (v, token) in enumerate(zip(program.variables, tokens, strict=True)):
        number = first + i
        parts = lines[number].split() if number < len(lines) else []
        if len(parts) < 2 or parts[0] != token:
            raise DataError(f"{path}:{number + 1}: expected the line of variable {token!r}, "
                            f"found {parts[0] if parts else 'nothing'!r}")
        try:
            values = [float(p) for p in parts[2:]]
            count = int(parts[1])
        except ValueError:
            raise DataError(f"{path}:{number + 1}: variable {token!r}: malformed numbers") \
                from None
        if count != v.storage_dim or len(values) != count:
            raise DataError(f"{path}:{number + 1}: variable {token!r} ({v.type_name}) needs "
                            f"{v.storage_dim} numbers, the line has {len(values)}")
        x += values
        keyed[token_key(token, v.key)] = np.array(values, dtype=np.float64)
    return x, keyed


def reference_run(program: Program, data: ProblemData):
    """The simulator's float64 run of ``program`` on ``data``: the testbench's reference
    (the simulator defines what the hardware computes; float64 so that a float accelerator is
    judged against the optimum, not against another float32 rounding). The simulator is
    reached through the registry: this layer imports no backend."""
    return fgc_backends.load("sim").run(program, data, precision="float64")


def error_floor(program: Program, data: ProblemData, reference, scalar: str) -> float:
    """How much the cost (float64, the simulator's) rises when ``reference``'s state is rounded
    to the C++ ``scalar``: 0 for double; float rounds each stored entry to float32,
    ap_fixed<W,I> to its grid of 2^-(W-I). How far above the float64 optimum's cost a state
    held in that scalar can be expected to rest (imu_window N = 50: the optimum's 1e-19 becomes
    9.3e-3 in float), so the testbench's final-error check does not ask a float design for a
    cost its state cannot represent."""
    costs = fgc_backends.load("sim").costs
    if scalar == "double" or reference.final_error is None:
        return 0.0
    fmt = fixed_format(scalar)
    rounded, local = {}, frame.to_local(program, dict(reference.storage))  # the design's state
    for v in program.variables:
        x = np.asarray(local[v.key], dtype=np.float64).ravel()
        if fmt is None:
            rounded[v.key] = x.astype(np.float32).astype(np.float64)
        else:
            step = 2.0 ** -(fmt[0] - fmt[1])
            rounded[v.key] = np.round(x / step) * step
    at_reference, at_rounded = costs(program, data, [dict(reference.storage),
                                                     frame.to_world(program, rounded)])
    floor = at_rounded - at_reference  # what the rounding adds to the optimum's cost
    return floor if np.isfinite(floor) and floor > 0 else 0.0


def write_reference(path: str | Path, program: Program, reference,
                    floor: float = 0.0) -> Path:
    """Write ``reference`` (a simulator result of ``program``: ``storage``, ``final_error``,
    ``status``) as the testbench's reference file, with the design's ``floor``
    (:func:`error_floor`); returns the path."""
    path = Path(path)
    if reference.status not in STATUSES:
        raise DataError(f"reference status {reference.status!r} is not one of {STATUSES}")
    if not (np.isfinite(floor) and floor >= 0):
        raise DataError(f"reference error floor {floor!r} is not a finite number ≥ 0")
    tokens = key_tokens(v.key for v in program.variables)
    local = frame.to_local(program, dict(reference.storage))  # the testbench's frame
    error = float("nan") if reference.final_error is None else float(reference.final_error)
    out = [f"{REFERENCE_MAGIC} {program.structure_fingerprint}", f"STATUS {reference.status}",
           f"FINAL_ERROR {error!r}", f"ERROR_FLOOR {float(floor)!r}",
           f"VARIABLES {len(program.variables)}"]
    for v, token in zip(program.variables, tokens, strict=True):
        values = np.asarray(local[v.key], dtype=np.float64).ravel()
        if values.size != v.storage_dim or not np.all(np.isfinite(values)):
            raise DataError(f"reference value of variable {v.key!r} is not {v.storage_dim} "
                            "finite numbers")
        out.append(" ".join([token, str(v.storage_dim), *(repr(float(x)) for x in values)]))
    path.write_text("\n".join(out) + "\n")
    return path


def judge_precision(program: Program, data: ProblemData, result: HlsResult,
                    scalar: str) -> HlsResult:
    """``result`` (storage arrays as ``values``) of a run in C++ ``scalar`` on ``data``, with
    the float32 verdict: ρ at the returned solution; ρ ≥ 1 warns
    (:class:`fgc.ir.conditioning.PrecisionLimitWarning`, the simulator's text) and a "converged"
    result becomes status "failed", reason "precision_limit". Double runs, and runs that ended
    singular or non-finite (as in the simulator), are returned unchanged; so are fixed-point
    scalars, whose resolution is not a relative eps (not judged)."""
    precision = conditioning.SCALAR_PRECISION.get(scalar)
    if precision in (None, "float64") or result.reason in ("singular", "non_finite"):
        return result
    local = frame.to_local(program, result.values)  # the state as the solver held it
    storage = [np.asarray(local[v.key], dtype=np.float64) for v in program.variables]
    if not all(np.all(np.isfinite(v)) for v in storage):
        return result
    rho, index = conditioning.resolution(whitened_jacobians(program, data, storage), storage,
                                         [v.dim for v in program.variables], precision)
    if rho < conditioning.RESOLUTION_LIMIT:
        return _judge_distance(program, data, replace(result, resolution=rho), precision)
    spec = program.variables[index]
    text = conditioning.precision_limit_message(spec.key, spec.type_name, rho, precision)
    conditioning.warn(text, conditioning.PrecisionLimitWarning)
    status, reason = result.status, result.reason
    if status == "converged":
        status, reason = "failed", PRECISION_LIMIT
    return replace(result, status=status, reason=reason, resolution=rho, message=text,
                   warnings=(*result.warnings, text))


def _judge_distance(program: Program, data: ProblemData, result: HlsResult,
                    precision: str) -> HlsResult:
    """A converged ``result`` more than ``conditioning.STEP_LIMIT`` σ from the float64 optimum
    (``fgc_backends.sim.remaining_step``, the simulator's verdict) fails with reason
    "precision_limit" and a :class:`fgc.ir.conditioning.PrecisionLimitWarning`."""
    import fgc_backends  # the simulator through the registry: this layer imports no backend

    if result.status != "converged":
        return result
    sigmas = fgc_backends.load("sim").remaining_step(program, data, dict(result.values))
    if sigmas is None or sigmas < conditioning.STEP_LIMIT:
        return result
    text = conditioning.remaining_step_message(sigmas, precision)
    conditioning.warn(text, conditioning.PrecisionLimitWarning)
    return replace(result, status="failed", reason=PRECISION_LIMIT, message=text,
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
        sim = fgc_backends.load("sim")  # the contract's emit, through the registry
        with tempfile.TemporaryDirectory(prefix="fgc-judge-") as tmp:
            files = sim.emit(program, Path(tmp), sim.Config())
            _LINEARIZERS[key] = runpy.run_path(str(files[0]), run_name="fgc_judge_problem")
    _BY_ID[id(program)] = (program, _LINEARIZERS[key])
    return _LINEARIZERS[key]


def whitened_jacobians(program: Program, data: ProblemData, storage: list[np.ndarray]
                       ) -> list[tuple[np.ndarray, np.ndarray]]:
    """Every factor block's whitened Jacobian rows at ``storage`` (one array per variable),
    evaluated in float64 by the Program's own block kernels (the simulator's linearisation; the
    emitted simulator is kept per Program for the process), paired with their global tangent
    columns: the ``parts`` of :func:`fgc.ir.conditioning.resolution`."""
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
