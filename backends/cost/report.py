"""The cost model's output: frozen dataclasses, JSON-able through :meth:`CostReport.to_dict`."""

from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass, fields

import numpy as np

from .cholesky import CholeskyTiming
from .kernels import BlockTiming
from .qr import QrTiming


@dataclass(frozen=True)
class UnitCycles:
    """Cycles by unit along the critical path of one iteration (or a whole solve).

    - ``factor_jacobian`` / ``factor_cost``: the factor block in residual + Jacobian mode and in
      residual + cost mode.
    - ``hessian``: what the HGC adds after the factor block (they stream into each other);
      0 on the QR path.
    - ``factorization``: partial-QR steps, or the Cholesky cascade (Lz = g included).
    - ``back_substitution``: the Bayes net's back-substitution, or Lᵀδ = z.
    - ``state_update``: retract of every variable.
    - ``control``: phase handshakes and the trust-region decision.
    """

    factor_jacobian: int = 0
    factor_cost: int = 0
    hessian: int = 0
    factorization: int = 0
    back_substitution: int = 0
    state_update: int = 0
    control: int = 0

    @property
    def total(self) -> int:
        """All units in sequence."""
        return sum(getattr(self, f.name) for f in fields(self))

    @property
    def linear_solve(self) -> int:
        """The linear-equation solver's share (paper B's LES): factorization + substitution."""
        return self.factorization + self.back_substitution

    def scaled(self, k: int) -> UnitCycles:
        """Every unit × ``k``."""
        return UnitCycles(*(k * getattr(self, f.name) for f in fields(self)))

    def __add__(self, other: UnitCycles) -> UnitCycles:
        return UnitCycles(*(getattr(self, f.name) + getattr(other, f.name)
                            for f in fields(self)))


@dataclass(frozen=True)
class Resources:
    """FPGA resources: DSP48E1 slices, BRAM36 (halves are BRAM18s), LUTs, flip-flops."""

    dsp: int = 0
    bram: float = 0.0
    lut: int = 0
    ff: int = 0

    def __add__(self, other: Resources) -> Resources:
        return Resources(self.dsp + other.dsp, self.bram + other.bram, self.lut + other.lut,
                         self.ff + other.ff)

    def scaled(self, k: float) -> Resources:
        """Resources of ``k`` copies (LUT/FF/DSP rounded up)."""
        return Resources(int(np.ceil(self.dsp * k)), self.bram * k, int(np.ceil(self.lut * k)),
                         int(np.ceil(self.ff * k)))


@dataclass(frozen=True)
class Utilization:
    """Fractions of the device's resources (1.0 = full)."""

    dsp: float
    bram: float
    lut: float
    ff: float

    @property
    def fits(self) -> bool:
        """True if every resource is within the device."""
        return max(self.dsp, self.bram, self.lut, self.ff) <= 1.0


@dataclass(frozen=True)
class UnitResources:
    """Resources by unit (see :class:`UnitCycles` for the units)."""

    factor: Resources
    hessian: Resources
    linear_solver: Resources
    back_substitution: Resources
    state_update: Resources
    control: Resources
    memory: Resources

    @property
    def total(self) -> Resources:
        out = Resources()
        for f in fields(self):
            out = out + getattr(self, f.name)
        return out


@dataclass(frozen=True)
class MemoryWords:
    """Words of on-chip storage (``word_bits`` each), from the storage plan and the schedule.

    ``linear_system`` is the compressed A/b (QR) or H/g (Cholesky) of the storage plan's last
    step; ``dense_linear_system`` is the same system stored densely (for comparison, not
    allocated); ``factor`` is R and its right-hand side (QR) or L's fill beyond H (Cholesky, L
    overwrites H in place); ``state`` the current and trial values; ``vectors`` δ and the
    triangular solve's intermediate; ``measurements`` the factors' run-time data.
    ``linear_bits`` is the word of the linear solver's memories (the system, the factor and
    the vectors; wider than ``word_bits`` in the mixed design).
    """

    word_bits: int
    linear_system: int
    dense_linear_system: int
    factor: int
    state: int
    vectors: int
    measurements: int
    linear_bits: int

    @property
    def total(self) -> int:
        """Words allocated (the dense system excluded)."""
        return (self.linear_system + self.factor + self.state + self.vectors
                + self.measurements)


@dataclass(frozen=True)
class CostReport:
    """Cycles, latency, resources, power, energy and memory of one Program's accelerator."""

    program: str
    method: str
    linear: str
    precision: str
    clock_mhz: float
    units: int  # n_u Update units per QR block (QR path)
    cpe: int  # Cholesky process elements (Cholesky path)
    iterations: int  # accepted steps (each relinearises)
    rejected: int  # rejected LM steps (solve again, evaluate cost, no relinearisation)
    iteration: UnitCycles  # one accepted iteration
    rejected_step: UnitCycles  # one rejected LM step
    solve: UnitCycles  # the whole solve
    factor_blocks: tuple[BlockTiming, ...]  # Jacobian-mode pipeline of each block type
    linear_detail: QrTiming | CholeskyTiming
    resources_by_unit: UnitResources
    resources: Resources
    utilization: Utilization  # fractions of the device
    memory: MemoryWords
    power_w: float
    linear_precision: str  # the linear solver's (wider than ``precision`` when mixed)

    @property
    def cycles(self) -> int:
        """Cycles of the whole solve."""
        return self.solve.total

    @property
    def latency_ms(self) -> float:
        """Whole solve in milliseconds at ``clock_mhz``."""
        return self.solve.total / (self.clock_mhz * 1e3)

    @property
    def iteration_latency_ms(self) -> float:
        return self.iteration.total / (self.clock_mhz * 1e3)

    @property
    def linear_solve_fraction(self) -> float:
        """Share of the solve spent in the linear-equation solver (paper B: 82.4 % average)."""
        return self.solve.linear_solve / self.solve.total if self.solve.total else 0.0

    @property
    def energy_mj(self) -> float:
        """Energy of the whole solve in millijoules (power × latency)."""
        return self.power_w * self.latency_ms

    def to_dict(self) -> dict:
        """Plain JSON-able dict: every field plus the derived totals."""
        out = _plain(dataclasses.asdict(self))
        out["linear_detail"]["kind"] = type(self.linear_detail).__name__
        for name in ("iteration", "rejected_step", "solve"):
            out[name]["total"] = getattr(self, name).total
            out[name]["linear_solve"] = getattr(self, name).linear_solve
        out["memory"]["total"] = self.memory.total
        out.update(cycles=self.cycles, latency_ms=self.latency_ms,
                   iteration_latency_ms=self.iteration_latency_ms,
                   linear_solve_fraction=self.linear_solve_fraction, energy_mj=self.energy_mj)
        return out

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), indent=1, sort_keys=True) + "\n"

    def summary(self) -> str:
        """A few readable lines: latency, split by unit, resources, power, energy (all of them
        model estimates, and labelled so)."""
        s = self.solve
        parts = ", ".join(f"{f.name} {getattr(s, f.name) / s.total:.1%}"
                          for f in fields(s) if getattr(s, f.name))
        r = self.resources
        les = (f" ({self.linear_precision} linear solver)"
               if self.linear_precision != self.precision else "")
        return (f"{self.program}: {self.method}/{self.linear} {self.precision}{les}, "
                f"{self.iterations} it + {self.rejected} rejected: {self.latency_ms:.3f} ms "
                f"({self.cycles} cycles @ {self.clock_mhz:g} MHz; model estimate)\n"
                f"  split: {parts}\n"
                f"  DSP {r.dsp}, BRAM36 {r.bram:g}, LUT {r.lut}, FF {r.ff}; "
                f"{self.power_w:.3f} W, {self.energy_mj:.3f} mJ (model estimate)")


def _plain(x):
    """numpy scalars → Python numbers, tuples → lists, recursively."""
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, np.generic):
        return x.item()
    return x
