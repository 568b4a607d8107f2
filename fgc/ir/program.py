"""The Program IR: everything a backend needs to emit an accelerator for one problem *structure*.

A Program is frozen, JSON-serialisable (``to_json``/``from_json`` round-trip exactly) and checked
(``check_program``). It holds the block kernels as printer-agnostic sympy (stored as ``srepr``
text), the elimination schedule, the storage plan and the solver configuration. Measurements,
noise and initial values are *data*, read by the emitted program at run time; they are not here.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import json
from dataclasses import dataclass, field

import sympy as sp

from fgc.compiler.kernel import Kernel
from fgc.compiler.schedule import Schedule
from fgc.compiler.storage import StoragePlan, StorageStep
from fgc.errors import FgcError
from fgc.frontend.geometry import special
from fgc.ir.codes import ORDERINGS  # the one list (the schedule and the CLI read it)
from fgc.ir.frame import Frame

PROGRAM_VERSION = 1
METHODS, LINEAR_SOLVERS, PRECISIONS = ("gn", "lm"), ("qr", "cholesky"), ("float32", "float64")


class ProgramError(FgcError):
    """A Program (or a stage result feeding it) breaks an invariant."""


@dataclass(frozen=True)
class SolverConfig:
    """How the accelerator solves: GN/LM with paper B's stopping rules, QR or Cholesky, precision,
    unit counts (n_u Update units per partial-QR block, #CPE Cholesky process elements), clock.

    ``precision`` is the working precision of the whole accelerator; ``linear_precision`` (None:
    the same) widens the linear-equation solver alone (Hessian/gradient accumulation,
    elimination, back-substitution): float32 factor blocks, cost and state update with a
    float64 solver is the mixed design that ill-conditioned Cholesky problems need (the normal
    equations square the condition number).
    """

    method: str = "lm"
    linear: str = "qr"
    ordering: str = "auto"
    precision: str = "float64"
    linear_precision: str | None = None
    units: int = 4
    cpe: int = 20
    clock_mhz: float = 143.0
    max_iterations: int = 100  # k_max
    lambda_initial: float = 1e-5  # μ₀
    lambda_factor: float = 10.0
    eps_gradient: float = 1e-12  # ε1: stop when ‖g‖∞ < ε1
    eps_step: float = 1e-12  # ε2: stop when ‖δ‖ < ε2 (‖x‖ + ε2)
    relative_error_tol: float = 1e-12
    # LM's limits, one set for every backend (the simulator, the HLS design, the native solver
    # and the dense reference solver print or read these): stop once the cost is at most
    # absolute_error_tol; give up (failed / lambda_limit) when μ would pass lambda_upper_bound
    # after rejected steps; μ never falls below mu_min after accepted ones (damping stays on)
    absolute_error_tol: float = 1e-14
    lambda_upper_bound: float = 1e10
    mu_min: float = 1e-30
    incremental_k: int | None = None
    batch_every: tuple[int, ...] | int | None = None

    @property
    def one_step(self) -> bool:
        """ISAM2's update policy for a stream: one Gauss-Newton step an update (GN, k_max = 1);
        a stream's store is then the update's own factorisation at the point it linearised
        (``fgc.app.streaming.one_step_solver``)."""
        return self.method == "gn" and int(self.max_iterations) == 1

    def check(self) -> None:
        """Raise ProgramError naming the first invalid option."""
        choices = {"method": METHODS, "linear": LINEAR_SOLVERS, "precision": PRECISIONS,
                   "ordering": ORDERINGS}
        for name, allowed in choices.items():
            if getattr(self, name) not in allowed:
                raise ProgramError(f"solver option {name}={getattr(self, name)!r}: expected one "
                                   f"of {', '.join(allowed)}")
        if self.linear_precision is not None:
            if self.linear_precision not in PRECISIONS:
                raise ProgramError(f"solver option linear_precision={self.linear_precision!r}: "
                                   f"expected one of {', '.join(PRECISIONS)}")
            if PRECISIONS.index(self.linear_precision) < PRECISIONS.index(self.precision):
                raise ProgramError(f"solver option linear_precision={self.linear_precision} is "
                                   f"narrower than precision={self.precision}: the linear solver "
                                   "can only be widened")
        for name in ("units", "cpe", "max_iterations"):
            if int(getattr(self, name)) < 1:
                raise ProgramError(f"solver option {name} must be ≥ 1, got {getattr(self, name)}")
        for name in ("clock_mhz", "lambda_initial", "lambda_factor", "eps_gradient", "eps_step",
                     "lambda_upper_bound", "mu_min"):
            if not getattr(self, name) > 0:
                raise ProgramError(f"solver option {name} must be > 0, got {getattr(self, name)}")
        if not self.absolute_error_tol >= 0:
            raise ProgramError("solver option absolute_error_tol must be ≥ 0, got "
                               f"{self.absolute_error_tol}")
        if self.method == "lm" and not self.mu_min <= self.lambda_initial:
            raise ProgramError(f"solver option mu_min={self.mu_min:g} exceeds lambda_initial="
                               f"{self.lambda_initial:g}: LM's damping floor above its start")

    @property
    def les_precision(self) -> str:
        """The linear-equation solver's precision: ``linear_precision`` or else ``precision``."""
        return self.linear_precision or self.precision

    @property
    def mixed(self) -> bool:
        """Whether the linear solver is wider than the rest of the accelerator."""
        return self.les_precision != self.precision


# --------------------------------------------------------------------------------------------
# kernels as text
# --------------------------------------------------------------------------------------------


def _namespace() -> dict:
    ns = {name: getattr(sp, name) for name in dir(sp) if not name.startswith("_")}
    for cls in (*special.COEFFICIENT_FUNCTIONS.values(), *special.SO3_LOG_FUNCTIONS,
                *special.GUARD_FUNCTIONS):
        ns[cls.__name__] = cls
    return ns


@dataclass(frozen=True)
class KernelText:
    """A :class:`fgc.compiler.kernel.Kernel` as ``srepr`` strings (exact, printer-agnostic)."""

    inputs: tuple[str, ...]
    assignments: tuple[tuple[str, str], ...]
    outputs: tuple[str, ...]

    @classmethod
    def of(cls, kernel: Kernel) -> KernelText:
        return cls(tuple(sp.srepr(s) for s in kernel.inputs),
                   tuple((sp.srepr(x), sp.srepr(e)) for x, e in kernel.assignments),
                   tuple(sp.srepr(sp.sympify(e)) for e in kernel.outputs))

    def kernel(self) -> Kernel:
        """The kernel these strings spell. Parsed once per distinct text: a Kernel is frozen and
        its sympy expressions immutable, and an emitter asks for the same kernels many times
        (one LIO design parsed its 58 kernels' 33k expressions over again: half its emit time)."""
        return _parsed(self)


@functools.lru_cache(maxsize=512)
def _parsed(text: KernelText) -> Kernel:
    ns = _namespace()

    def parse(s: str):
        return eval(s, {"__builtins__": {}}, ns)  # noqa: S307 - srepr we wrote ourselves

    return Kernel(tuple(parse(s) for s in text.inputs),
                  tuple((parse(x), parse(e)) for x, e in text.assignments),
                  tuple(parse(e) for e in text.outputs))


# --------------------------------------------------------------------------------------------
# the program
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class VariableSpec:
    """A variable: ``key`` is the text of the graph's key (``str(k)``), ``int_key`` whether
    that key was an int, so that results written by a backend give the user's key back."""

    key: str
    type_name: str
    dim: int
    storage_dim: int
    int_key: bool = False

    @property
    def user_key(self) -> int | str:
        """The graph's key: an int again if it was one."""
        return int(self.key) if self.int_key else self.key


@dataclass(frozen=True)
class MemberSpec:
    """One member factor type of a block: its rows in the stacked residual and its data layout."""

    factor_type: str
    rows: tuple[int, int]
    noise_kind: str
    noise_params: int
    measurements: tuple[tuple[str, int], ...]  # (name, storage size), kernel input order
    # the block variable each of the factor's keys is, in the factor's key order (empty: a
    # Program that predates the field)
    positions: tuple[int, ...] = ()
    # whether any factor of this member may carry a robust loss (its data's robust code may be
    # non-zero): False lets a backend build no robust-loss datapath for it, and data with a
    # robust loss on such a member are refused (True: a Program that predates the field)
    robust: bool = True


@dataclass(frozen=True)
class BlockSpec:
    """A fused block type: variable types, members, both kernel modes, structure, op counts."""

    name: str
    variable_types: tuple[str, ...]
    variable_dims: tuple[int, ...]
    members: tuple[MemberSpec, ...]
    residual_dim: int
    structure: tuple[tuple[tuple[str, ...], ...], ...]
    ops_unshared: dict  # residual + Jacobian, every output its own expression tree (no CSE)
    ops_before: dict  # members CSE'd separately, summed
    ops_after: dict  # the fused kernel: shared General Calculation
    ops_cost: dict  # the fused cost-only kernel
    kernel: KernelText = field(repr=False)
    cost_kernel: KernelText = field(repr=False)


@dataclass(frozen=True)
class BlockInstance:
    """A block instance in the graph: its block type, variable keys and member factor indices."""

    block: int
    keys: tuple[str, ...]
    factors: tuple[int, ...]


@dataclass(frozen=True)
class Program:
    name: str
    variables: tuple[VariableSpec, ...]
    blocks: tuple[BlockSpec, ...]
    factors: tuple[BlockInstance, ...]
    schedule: Schedule
    storage: StoragePlan
    solver: SolverConfig
    max_variables: int
    version: int = PROGRAM_VERSION
    # float32: the local frame its data are written in (``fgc.ir.frame``; None: world
    # coordinates, and no ``frame`` entry in the JSON)
    frame: Frame | None = None

    # -- JSON --------------------------------------------------------------------------------
    def to_dict(self) -> dict:
        out = dataclasses.asdict(dataclasses.replace(self, schedule=None, storage=None,
                                                     frame=None))
        del out["frame"]
        if self.frame is not None:
            out["frame"] = self.frame.to_dict()
        out["schedule"] = self.schedule.to_dict()
        out["storage"] = dataclasses.asdict(self.storage)
        for v in out["variables"]:  # only an int key says so: str-keyed JSON is as before
            if not v["int_key"]:
                del v["int_key"]
        return out

    def to_json(self) -> str:
        """Canonical JSON (sorted keys): equal Programs give byte-identical text."""
        return self._canonical_json

    @functools.cached_property
    def _canonical_json(self) -> str:
        # once per Program: on a 10,000-pose graph to_dict takes seconds, and the fingerprint,
        # the native cache key and --out each want it
        return json.dumps(self.to_dict(), indent=1, sort_keys=True) + "\n"

    @classmethod
    def from_dict(cls, d: dict) -> Program:
        if d.get("version") != PROGRAM_VERSION:
            raise ProgramError(f"Program version {d.get('version')} is not {PROGRAM_VERSION}")
        storage = dict(d["storage"])
        storage["steps"] = tuple(StorageStep(**s) for s in storage["steps"])
        solver = dict(d["solver"])
        if isinstance(solver.get("batch_every"), list):
            solver["batch_every"] = tuple(solver["batch_every"])
        return cls(
            name=d["name"],
            variables=tuple(VariableSpec(**v) for v in d["variables"]),
            blocks=tuple(_block_from_dict(b) for b in d["blocks"]),
            factors=tuple(BlockInstance(f["block"], tuple(f["keys"]), tuple(f["factors"]))
                          for f in d["factors"]),
            schedule=Schedule.from_dict(d["schedule"]),
            storage=StoragePlan(**storage),
            solver=SolverConfig(**solver),
            max_variables=d["max_variables"],
            version=d["version"],
            frame=Frame.from_dict(d["frame"]) if d.get("frame") is not None else None,
        )

    @classmethod
    def from_json(cls, text: str) -> Program:
        return cls.from_dict(json.loads(text))

    # -- fingerprints ------------------------------------------------------------------------
    @functools.cached_property
    def structure_fingerprint(self) -> str:
        """Digest of what a data file's numbers mean: each variable's key and type, each block
        type's member factor types and data layout, and which keys each factor instance connects
        (in order) with its graph factor indices. Data files carry it and every reader refuses
        data of another structure: two graphs with the same counts but other connectivity have
        different fingerprints. Solver options and the schedule do not change the data layout
        (one data file serves every design of a structure), so they are in
        :attr:`fingerprint`, not here."""
        return _digest(structure_summary(self))

    @functools.cached_property
    def fingerprint(self) -> str:
        """Digest of the whole design: the structure (:attr:`structure_fingerprint`), the block
        kernels, the elimination orderings and schedule, the storage plan and every solver
        option (the Program's canonical JSON without its name). Same spec → same
        fingerprint."""
        d = json.loads(self.to_json())  # the same JSON text as to_dict()'s, from the cache
        d.pop("name")
        return _digest(d)


FINGERPRINT_CHARS = 16  # hex digits of SHA-256 (64 bits)


def _digest(obj) -> str:
    text = json.dumps(obj, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:FINGERPRINT_CHARS]


def structure_summary(p: Program) -> dict:
    """The fields :attr:`Program.structure_fingerprint` digests (JSON-serialisable); a local
    frame (``fgc.ir.frame``) changes what the data's positions mean, so it is digested too."""
    out = {
        "variables": [[v.key, v.type_name, v.dim, v.storage_dim] for v in p.variables],
        "blocks": [[b.variable_types, [[m.factor_type, m.rows, m.noise_kind, m.noise_params,
                                        m.measurements, m.positions, m.robust]
                                       for m in b.members]]
                   for b in p.blocks],
        "factors": [[f.block, f.keys, f.factors] for f in p.factors],
    }
    if p.frame is not None:
        out["frame"] = p.frame.to_dict()
    return out


def _tuples(x):
    return tuple(_tuples(v) for v in x) if isinstance(x, list) else x


def _block_from_dict(b: dict) -> BlockSpec:
    members = tuple(MemberSpec(m["factor_type"], tuple(m["rows"]), m["noise_kind"],
                               m["noise_params"], _tuples(m["measurements"]),
                               tuple(m.get("positions", ())), m.get("robust", True))
                    for m in b["members"])

    def text(k: dict) -> KernelText:
        return KernelText(tuple(k["inputs"]), _tuples(k["assignments"]), tuple(k["outputs"]))

    return BlockSpec(b["name"], tuple(b["variable_types"]), tuple(b["variable_dims"]), members,
                     b["residual_dim"], _tuples(b["structure"]), b["ops_unshared"],
                     b["ops_before"], b["ops_after"], b["ops_cost"], text(b["kernel"]),
                     text(b["cost_kernel"]))


# --------------------------------------------------------------------------------------------
# invariants
# --------------------------------------------------------------------------------------------


def check_program(p: Program) -> None:
    """Invariants between the stages; raises ProgramError naming what is inconsistent."""
    p.solver.check()
    keys = [v.key for v in p.variables]
    if len(set(keys)) != len(keys):
        raise ProgramError("duplicate variable keys in the Program")
    if len(keys) > p.max_variables:
        raise ProgramError(f"{len(keys)} variables exceed the compiled maximum {p.max_variables}")
    dims = {v.key: v.dim for v in p.variables}
    for f in p.factors:
        if not 0 <= f.block < len(p.blocks):
            raise ProgramError(f"factor instance {f.factors} refers to block {f.block}")
        block = p.blocks[f.block]
        if tuple(dims.get(k) for k in f.keys) != block.variable_dims:
            raise ProgramError(f"block '{block.name}' on keys {list(f.keys)}: variable "
                               f"dimensions do not match {block.variable_dims}")
    eliminated = sorted(k for s in p.schedule.steps for k in s.frontals)
    if eliminated != sorted(keys):
        raise ProgramError("the schedule does not eliminate every variable exactly once")
    for b in p.blocks:
        n_out = b.residual_dim * (1 + sum(b.variable_dims))
        if len(b.kernel.outputs) != n_out:
            raise ProgramError(f"block '{b.name}': kernel has {len(b.kernel.outputs)} outputs, "
                               f"expected {n_out}")
