"""run: emit a Program's simulator, run it on one data file, return the result as fgc values."""

from __future__ import annotations

import dataclasses
import json
import runpy
import subprocess
import sys
import tempfile
from collections.abc import Collection, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from fgc.errors import DataError, FgcError
from fgc.frontend import geometry
from fgc.frontend.geometry import LieGroup
from fgc.ir import conditioning, frame
from fgc.ir.datafile import ProblemData, check_structure, read_data, write_data
from fgc.ir.program import Program
from fgc.ir.result import SolveResult
from fgc.ir.stream import FixedLag, Incremental, Policy, policy_dict

from .config import SimConfig
from .emitter import RESULT_FORMAT, emit


@dataclass(frozen=True)
class SimResult(SolveResult):
    """What the simulator computed.

    ``values``/``storage``: the final estimate per Program variable key (``str`` of the graph's
    key; fgc values / raw storage arrays), ``keys`` the graph's key per variable key and
    ``user_values`` the values by the graph's keys (an int key stays an int); ``status`` is
    "converged", "max_iterations" or "failed" and ``reason`` says which stopping rule or failure
    (e.g. "relative_decrease", "lambda_limit", "singular", "precision_limit": float32 cannot
    place the state within its noise, never "converged");
    ``final_error`` is GTSAM's graph error at ``values`` (the last accepted point);
    ``cost_log`` holds the initial cost and the cost after each accepted step (incremental
    runs: the initial and the final cost of the whole graph); ``updates`` lists, for an
    incremental run, each keyframe's update (mode, first re-eliminated cluster, iterations,
    status, window cost, and under ``"values"`` the estimate after the update: fgc values by
    variable key, for the variables that have arrived).

    ``singular_variable`` is the key of the variable whose elimination pivot vanished (reason
    "singular", or LM's rank-deficient solution found by the diagnosis); ``condition`` the
    diagnosis' κ at the solution (rows and columns equilibrated, :mod:`fgc.ir.conditioning`);
    ``message`` says in words why a run failed or what its warnings are, ``warnings`` holds
    the texts of the :class:`fgc.ir.conditioning.FgcWarning` s the run issued.
    """

    values: dict[str, LieGroup]
    storage: dict[str, np.ndarray]
    status: str
    reason: str
    iterations: int
    initial_error: float | None
    final_error: float | None
    cost_log: tuple[float, ...]
    precision: str
    setup_seconds: float
    solve_seconds: float
    files: tuple[Path, ...]
    updates: tuple[dict, ...] | None = None
    singular_variable: str | None = None
    condition: float | None = None
    message: str = ""
    warnings: tuple[str, ...] = ()
    linear: str = "qr"
    linear_precision: str | None = None  # the linear solver's precision (None: ``precision``)
    keys: dict[str, int | str] = field(default_factory=dict)  # variable key → the user's key

    @property
    def float32_ok(self) -> bool | None:
        """Whether κ is below the float32 limit of this run's linear solver (None: unknown):
        of a float32 solver unless the run widened its linear solver beyond its precision."""
        mixed = self.linear_precision not in (None, self.precision)
        return conditioning.float32_ok(self.condition, self.linear,
                                       self.linear_precision if mixed else "float32")


def run(program: Program, data: ProblemData | str | Path, out_dir: str | Path | None = None,
        precision: str | None = None, config: SimConfig | None = None,
        in_process: bool = True, policy: Policy | None = None, progress=None) -> SimResult:
    """Emit ``program``'s simulator into ``out_dir`` (a temporary directory if None), run it on
    ``data`` (a ProblemData, written next to it as ``data.txt``, or a data file path) in this
    process (or as a subprocess) and read its result. ``precision`` overrides the Program's;
    ``policy`` (:mod:`fgc.ir.stream`) runs keyframe by keyframe: :class:`Incremental` along
    the Program's incremental plan, :class:`FixedLag` in a fixed-lag window of that many
    keyframes (the oldest marginalised into a prior; a chain Program, no incremental plan
    needed); the emitted simulator reads it as plain data (:func:`policy_dict`). ``progress``
    (in process only) is called with each keyframe's raw update record as it completes.

    Raises DataError when the data does not fit the Program (naming the line and factor), or
    were laid out for another structure (naming both structure fingerprints).
    """
    if out_dir is None:
        with tempfile.TemporaryDirectory(prefix="fgc-sim-") as tmp:
            return run(program, data, tmp, precision, config, in_process, policy, progress)
    out = Path(out_dir)
    files = tuple(emit(program, out, config))
    if isinstance(data, ProblemData):
        check_structure(data, program)
        data_path = out / "data.txt"
        write_data(data, data_path)
    else:
        data_path = Path(data)
    result_path = out / "result.json"
    _check_policy(program, policy)
    emitted = None if policy is None else policy_dict(policy)
    if in_process:
        raw = _run_in_process(program, files[0], data_path, result_path, precision, emitted,
                              progress)
    else:
        raw = _run_subprocess(files[0], data_path, result_path, precision, emitted)
        if raw["status"] == "data_error":
            error = DataError(raw["message"])
            error.factor, error.variable = raw["factor"], raw["variable"]
            raise DataError(_explain(program, error))
    result = _result(program, raw, files, config or SimConfig())
    if result.precision != "float64" and result.status == "converged" and policy is None:
        result = _judge_distance(program, data if isinstance(data, ProblemData) else
                                 read_data(data_path), result, config, out)
    return result


def remaining_step(program: Program, data: ProblemData, storage: dict,
                   config: SimConfig | None = None, emitted: str | Path | None = None
                   ) -> float | None:
    """How far, in σ, the state ``storage`` ({variable key: storage}, world coordinates) is from
    the optimum of ``program`` on ``data`` to first order: the whitened length ‖A·δ‖₂ of the
    float64 Gauss-Newton step δ from it (the simulator's float64 linearisation and elimination;
    ``emitted``: as :func:`linearize`). None when that system is singular or not finite."""
    problem = _float64_problem(program, data, config, emitted)
    x = next(_points(program, problem, [storage]))
    with np.errstate(all="ignore"):
        abs_, _, _ = problem.linearize(x)
        if not all(np.all(np.isfinite(ab)) for ab in abs_):
            return None
        try:
            delta = problem.solve(abs_, 0.0)
        except problem.lib.linear.SingularError:
            return None
        moved = [np.einsum("nmd,nd->nm", ab[..., :-1], delta[block.columns])
                 for block, ab in zip(problem.blocks, abs_, strict=True)]
    length = float(np.sqrt(sum(float(np.sum(m * m)) for m in moved)))
    return length if np.isfinite(length) else None


def _judge_distance(program: Program, data: ProblemData, result: SimResult,
                    config: SimConfig | None, emitted: Path) -> SimResult:
    """A converged low-precision ``result`` more than :data:`conditioning.STEP_LIMIT` σ from the
    float64 optimum (:func:`remaining_step`) fails with reason "precision_limit" and a
    :class:`conditioning.PrecisionLimitWarning` (:mod:`fgc.ir.conditioning`)."""
    sigmas = remaining_step(program, data, result.storage, config, emitted)
    if sigmas is None or sigmas < conditioning.STEP_LIMIT:
        return result
    text = conditioning.remaining_step_message(sigmas, result.precision)
    conditioning.warn(text, conditioning.PrecisionLimitWarning)
    return dataclasses.replace(result, status="failed", reason="precision_limit",
                               message=" ".join(filter(None, (result.message, text))),
                               warnings=(*result.warnings, text))


def linearize(program: Program, data: ProblemData, points: Sequence[dict | None],
              config: SimConfig | None = None, emitted: str | Path | None = None,
              factors: Collection[int] | None = None
              ) -> list[dict[int, tuple[np.ndarray, np.ndarray]]]:
    """The whitened linearisation of every graph factor as the emitted simulator computes it.

    Loads ``program``'s simulator (emitted into a temporary directory, or the one :func:`run`
    or :func:`emit` wrote into ``emitted`` with the same ``config``) and, at each point of
    ``points`` (``{variable key: storage array}``, None: the data's initial values), runs every
    block type's error + Jacobian kernel over all its instances exactly as the solver does (the
    printed, fused kernels; the run-time's whitening and robust reweighting), in float64. Per
    point: {graph factor index: (A, b)} for every factor (or those in ``factors``), A over the
    factor's own variables in its key order, b = −W·r (GTSAM's convention). ``fgc verify``
    checks the executed kernels through this."""
    problem = _float64_problem(program, data, config, emitted)
    results = []
    for x in _points(program, problem, points):
        with np.errstate(all="ignore"):
            results.append(_factor_rows(program, [b.linearize(x) for b in problem.blocks],
                                        None if factors is None else set(factors)))
    return results


def costs(program: Program, data: ProblemData, points: Sequence[dict | None],
          config: SimConfig | None = None, emitted: str | Path | None = None) -> list[float]:
    """The simulator's total cost (GTSAM's graph error, its cost-only mode, float64) of
    ``program`` on ``data`` at each of ``points`` (as :func:`linearize` takes them), without
    solving anything."""
    problem = _float64_problem(program, data, config, emitted)
    return [float(problem.cost(x)) for x in _points(program, problem, points)]


def _float64_problem(program: Program, data: ProblemData, config: SimConfig | None,
                     emitted: str | Path | None):
    """The emitted simulator's float64 Problem of ``program`` on ``data`` (emitted into a
    temporary directory when ``emitted`` is None, else loaded from it)."""
    check_structure(data, program)
    if emitted is None:
        with tempfile.TemporaryDirectory(prefix="fgc-sim-lin-") as tmp:
            emit(program, tmp, config)
            return _float64_problem(program, data, config, tmp)
    out = Path(emitted)
    module = out / (config or SimConfig()).files(program.name)[0][1]
    if not module.is_file():
        raise FgcError(f"{out}: no emitted simulator of problem '{program.name}' there")
    namespace = runpy.run_path(str(module), run_name="fgc_sim_problem")
    lib, spec = namespace["LIB"], namespace["PROBLEM"]
    with tempfile.TemporaryDirectory(prefix="fgc-sim-lin-") as tmp:
        data_path = Path(tmp) / "data.txt"
        write_data(data, data_path)
        try:
            return lib.optimizer.Problem(spec, lib.runtime.read_data(
                str(data_path), spec["structure"]), "float64", lib)
        except lib.runtime.SimDataError as exc:
            raise DataError(_explain(program, exc)) from None


def _points(program: Program, problem, points: Sequence[dict | None]):
    """Each point (``{variable key: storage array}`` in world coordinates, None: the data's
    initial values) as the problem's storage vector (in the Program's local frame)."""
    for point in points:
        if point is None:
            yield problem.x0
            continue
        local = frame.to_local(program, {v.key: point[v.key] for v in program.variables})
        yield np.concatenate([np.asarray(local[v.key], dtype=np.float64).reshape(-1)
                              for v in program.variables])


def _factor_rows(program: Program, abs_: list[np.ndarray], wanted: set[int] | None
                 ) -> dict[int, tuple[np.ndarray, np.ndarray]]:
    """Each block's [A | b] (instances, M, D + 1) cut into its member factors' (A, b) (only
    the graph factors in ``wanted``, if given)."""
    out: dict[int, tuple[np.ndarray, np.ndarray]] = {}
    seen = [0] * len(program.blocks)
    for spec in program.factors:
        block = program.blocks[spec.block]
        ab = abs_[spec.block][seen[spec.block]]
        seen[spec.block] += 1
        starts = np.concatenate([[0], np.cumsum(block.variable_dims)]).astype(int)
        for member, f in zip(block.members, spec.factors, strict=True):
            if wanted is not None and f not in wanted:
                continue
            if not member.positions:
                raise FgcError(f"block '{block.name}': the Program predates member positions; "
                               "recompile it")
            first, last = member.rows
            cols = np.concatenate([np.arange(starts[p], starts[p + 1])
                                   for p in member.positions])
            out[f] = (ab[first:last][:, cols].copy(), ab[first:last, -1].copy())
    return out


def _check_policy(program: Program, policy: Policy | None) -> None:
    """An incremental policy needs the Program's incremental plan; a fixed-lag window a chain
    of keyframes whose factors each fit in the window."""
    if policy is None:
        return
    if not isinstance(policy, FixedLag | Incremental):
        raise FgcError(f"the simulator runs the streaming policies of fgc.ir.stream, got "
                       f"{type(policy).__name__}")
    if isinstance(policy, Incremental):
        if program.schedule.incremental is None:
            raise FgcError("the Program has no incremental plan (compile with incremental_k)")
        return
    window = policy.window
    if program.schedule.structure_class != "chain":
        raise FgcError(f"a fixed-lag window needs a chain of keyframes; '{program.name}' is a "
                       f"{program.schedule.structure_class} graph")
    cluster_of = {k: c for c, keys in enumerate(program.schedule.clusters) for k in keys}
    for f in program.factors:
        spans = [cluster_of[k] for k in f.keys]
        if max(spans) - min(spans) > window:
            raise FgcError(f"a factor on {list(f.keys)} spans keyframes {min(spans)} to "
                           f"{max(spans)}: the oldest is marginalised before the newest arrives "
                           f"in a window of {window} keyframes")


def _run_in_process(program: Program, module: Path, data: Path, result: Path,
                    precision: str | None, policy: dict | None = None, progress=None) -> dict:
    namespace = runpy.run_path(str(module), run_name="fgc_sim_problem")
    try:
        return namespace["run"](str(data), str(result), precision, policy, progress)
    except namespace["LIB"].runtime.SimDataError as exc:
        raise DataError(_explain(program, exc)) from None


def _run_subprocess(module: Path, data: Path, result: Path, precision: str | None,
                    policy: dict | None = None) -> dict:
    cmd = [sys.executable, str(module), str(data), str(result)]
    if precision:
        cmd += ["--precision", precision]
    if policy is not None:
        cmd += ["--policy", json.dumps(policy)]
    result.unlink(missing_ok=True)
    proc = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if proc.returncode not in (0, 1, 2) or not result.is_file():
        raise FgcError(f"the simulator failed (exit {proc.returncode}):\n{proc.stderr.strip()}")
    return json.loads(result.read_text())


def _explain(program: Program, exc: Exception) -> str:
    """The simulator's data error, plus the factor or variable it concerns in the user's terms."""
    message = str(exc)
    factor, variable = getattr(exc, "factor", None), getattr(exc, "variable", None)
    if factor is not None and 0 <= factor < len(program.factors):
        spec = program.factors[factor]
        message += (f" [factor block '{program.blocks[spec.block].name}' on variables "
                    f"{list(spec.keys)}, graph factors {list(spec.factors)}]")
    if variable is not None and 0 <= variable < len(program.variables):
        spec = program.variables[variable]
        message += f" [variable '{spec.key}' ({spec.type_name})]"
    return message


def read_result(program: Program, path: str | Path, config: SimConfig | None = None,
                files: tuple[Path, ...] = ()) -> SimResult:
    """The result file an emitted simulator of ``program`` wrote (``python <name>_sim.py DATA
    RESULT.json``) as a :class:`SimResult`: values keyed by variable as :func:`run` returns
    them. Raises FgcError naming the file if it is not such a result, is for another Program's
    variables, or records a data error."""
    path = Path(path)
    try:
        raw = json.loads(path.read_text())
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise FgcError(f"{path}: cannot read the simulator's result: {exc}") from None
    if not isinstance(raw, dict) or raw.get("format") != RESULT_FORMAT:
        have = raw.get("format") if isinstance(raw, dict) else None
        raise FgcError(f"{path}: not an fgc simulator result of format '{RESULT_FORMAT}' "
                       f"(format {have!r})")
    if raw["status"] == "data_error":
        raise DataError(f"{path}: the simulator refused its data: {raw['message']}")
    return _result(program, raw, files, config or SimConfig(), where=str(path))


def _keyed(program: Program, values: dict, where: str, complete: bool = True
           ) -> dict[str, np.ndarray]:
    """Program key → storage from a result's keyed values ({str(key): {"key", "type",
    "value"}}), each checked against the Program's variable (key, int-ness, type, size);
    ``complete``: every variable must have one."""
    if not isinstance(values, dict):
        raise FgcError(f"{where}: the result's values are not keyed by variable")
    out = {}
    for spec in program.variables:
        entry = values.get(spec.key)
        if entry is None:
            if complete:
                raise FgcError(f"{where}: the result has no value for variable {spec.key!r}")
            continue
        entry = entry if isinstance(entry, dict) else {}
        key, number = entry.get("key"), np.asarray(entry.get("value", ()), dtype=np.float64)
        if (type(key) is not type(spec.user_key) or key != spec.user_key
                or entry.get("type") != spec.type_name or number.shape != (spec.storage_dim,)):
            raise FgcError(f"{where}: the result's value for variable {spec.key!r} is "
                           f"{entry.get('type')!r} key {key!r} of {number.size} numbers; the "
                           f"Program has {spec.type_name} key {spec.user_key!r} of "
                           f"{spec.storage_dim} (another Program's result?)")
        out[spec.key] = number
    extra = sorted(set(values) - {v.key for v in program.variables})
    if extra:
        raise FgcError(f"{where}: the result has values for variables the Program does not "
                       f"have: {extra[:5]}")
    return out


def _values(program: Program, storage: dict[str, np.ndarray]) -> dict[str, LieGroup]:
    types = {v.key: v for v in program.variables}
    return {k: geometry.type_named(types[k].type_name, types[k].dim).from_storage(arr)
            for k, arr in storage.items()}


def _result(program: Program, raw: dict, files: tuple[Path, ...],
            config: SimConfig, where: str = "the simulator") -> SimResult:
    storage = frame.to_world(program, _keyed(program, raw["values"], where))
    values = _values(program, storage)
    singular, messages, warned = _explain_outcome(program, raw, config)
    return SimResult(values, storage, raw["status"], raw["reason"], raw["iterations"],
                     raw["initial_error"], raw["final_error"], tuple(raw["cost_log"]),
                     raw["precision"], raw["setup_seconds"], raw["solve_seconds"], files,
                     _updates(program, raw.get("incremental"), where),
                     singular, raw.get("condition"), " ".join(messages), tuple(warned),
                     raw.get("linear", program.solver.linear), raw.get("linear_precision"),
                     {v.key: v.user_key for v in program.variables})


def _updates(program: Program, raw: list[dict] | None, where: str
             ) -> tuple[dict, ...] | None:
    """An incremental run's update records, each estimate as fgc values by variable key (only
    the variables that have arrived)."""
    if raw is None:
        return None
    return tuple({**update, "values": _values(program, frame.to_world(program, _keyed(
        program, update["values"], where, complete=False)))} for update in raw)


def _explain_outcome(program: Program, raw: dict, config: SimConfig
                     ) -> tuple[str | None, list[str], list[str]]:
    """(key of the singular variable, messages, texts of the warnings issued) of a raw result:
    failures in words, an undetermined variable by name, float32 conditioning."""
    messages, warned, key = [], [], None
    if raw["status"] == "failed" and raw["reason"] in _FAILURES:
        messages.append(_FAILURES[raw["reason"]].format(
            iterations=raw["iterations"], cost=raw["final_error"],
            bound=program.solver.lambda_upper_bound))
    info = raw.get("singular")
    if info is not None and 0 <= info["variable"] < len(program.variables):
        spec = program.variables[info["variable"]]
        key = spec.key
        tolerance = (config.pivot_tolerance_float32 if raw["precision"] == "float32"
                     and raw["reason"] == "singular" else config.pivot_tolerance_float64)
        text = conditioning.rank_deficient_message(key, spec.type_name, info["component"],
                                                   info["ratio"], tolerance)
        messages.append(text)
        if raw["status"] != "failed":
            conditioning.warn(text, conditioning.RankDeficientWarning)
            warned.append(text)
    limit = raw.get("resolution")
    if limit is not None and limit["rho"] >= 1.0 and 0 <= limit["variable"] < len(
            program.variables):
        spec = program.variables[limit["variable"]]
        text = conditioning.precision_limit_message(spec.key, spec.type_name, limit["rho"],
                                                    raw["precision"])
        conditioning.warn(text, conditioning.PrecisionLimitWarning)
        messages.append(text)
        warned.append(text)
    text = conditioning.warn_if_ill_conditioned(raw.get("condition"), raw["linear"],
                                                raw["precision"], raw.get("linear_precision"))
    if text:
        messages.append(text)
        warned.append(text)
    return key, messages, warned


_FAILURES = {
    "singular": "Gauss-Newton stopped after {iterations} iterations: the linear system is "
                "singular (last accepted cost {cost}).",
    "lambda_limit": "Levenberg-Marquardt gave up after {iterations} iterations: no step lowered "
                    "the cost before the damping passed {bound:g} (last accepted cost {cost}).",
    "precision_limit": "the solver stopped after {iterations} iterations (cost {cost}), but "
                       "its working precision cannot resolve the state to the data's noise: "
                       "not converged.",
    "non_finite": "the cost or linearisation became non-finite after {iterations} iterations "
                  "(last finite cost {cost}); check the initial values and noise models.",
}
