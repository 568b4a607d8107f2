"""The accelerator plan's data model: loops, processes, phases, units, memories, channels.

A loop takes ``(trip - 1) * ii + depth`` cycles (0 when ``trip == 0``), repeated ``repeat`` times;
a process runs its loops one after another; a phase is a DATAFLOW region or a sequence of
processes (:func:`fgc_backends.hls.plan.cost.phase_cycles`). Units hold allocated operators,
memories are placed in BRAM or LUTRAM by size. :class:`AcceleratorPlan` is what the assembly
(:mod:`fgc_backends.hls.plan.assemble`) returns and :class:`Cost` what the pricer
(:func:`fgc_backends.hls.plan.cost.plan_cost`) makes of it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from fgc.errors import FgcError
from fgc_backends.cost.operators import OperatorTable
from fgc_backends.hls.target import Target

if TYPE_CHECKING:  # options import the model
    from fgc_backends.hls.plan.options import PlanOptions

BRAM18_BITS = 18 * 1024

PORTS = 2  # words a cycle a copy moves through a memory's two ports (accel.cpp.jinja's PORTS)

LUTRAM_MAX_BITS = 1024  # memories up to this size go to LUTRAM / registers (design)


class PlanError(FgcError):
    """The plan cannot be built for these options."""


@dataclass(frozen=True)
class Loop:
    name: str
    trip: int
    ii: int
    depth: int
    repeat: int = 1

    @property
    def cycles(self) -> int:
        return self.repeat * ((self.trip - 1) * self.ii + self.depth if self.trip > 0 else 0)


@dataclass(frozen=True)
class Process:
    name: str
    unit: str
    loops: tuple[Loop, ...]

    @property
    def cycles(self) -> int:
        return sum(lp.cycles for lp in self.loops)

    @property
    def fill(self) -> int:
        return self.loops[0].depth if self.loops else 0

PHASE_PER = ("iteration", "call", "rejection", "stream", "beside")


@dataclass(frozen=True)
class Phase:
    name: str
    dataflow: bool
    processes: tuple[Process, ...]
    linear: bool = False  # part of the linear-equation solver
    # how often it runs: "iteration" (once an iteration: in Cost.cycles), "call" (once per
    # accelerator call: the top's copies in and out), "rejection" (when a trial step does not
    # lower the cost: the rounding-noise pass), "stream" (the on-chip stream section's loops, once
    # per update that runs them: plan/stream.py), "beside" (the HGC producer's region beside the
    # elimination: priced inside the phase hgc_beside, units/cholesky.py's _beside); all but the
    # first are in Cost.other_cycles
    per: str = "iteration"


@dataclass(frozen=True)
class Unit:
    name: str
    role: str
    instances: int
    operators: tuple[tuple[str, int], ...]  # kind -> allocated instances in one unit
    extra_dsp: int = 0
    # the precision its operators are priced in when not the plan's (a mixed design's linear
    # solver: "float64" beside float32 datapaths); "" = the plan's working precision
    precision: str = ""


@dataclass(frozen=True)
class Memory:
    name: str
    words: int
    width: int
    banks: int

    @property
    def bram18(self) -> int:
        if self.words * self.width <= LUTRAM_MAX_BITS:
            return 0
        per_bank = math.ceil(self.words / self.banks)
        # a BRAM18 is 512 × 36 or 1024 × 18 (wider words use several side by side)
        width_blocks = math.ceil(self.width / 36)
        return self.banks * width_blocks * math.ceil(per_bank / 512)

    @property
    def kind(self) -> str:
        return "lutram" if self.bram18 == 0 else "bram"


@dataclass(frozen=True)
class Channel:
    name: str
    kind: str  # "stream" (FIFO), or "pingpong" (two buffers: region j writes one while it reads
    # the other, which region j - 1 wrote; the next region swaps them)
    depth: int
    width: int
    producer: str
    consumer: str


@dataclass(frozen=True)
class AcceleratorPlan:
    program: str
    linear: str
    precision: str
    clock_mhz: float
    options: PlanOptions
    units: tuple[Unit, ...]
    memories: tuple[Memory, ...]
    channels: tuple[Channel, ...]
    phases: tuple[Phase, ...]
    ops: OperatorTable = field(repr=False)

    @property
    def target(self) -> Target:
        """The part (``options.part``), clock and operator binding (``options.bind``) this
        plan is priced for."""
        return Target(self.options.part, self.clock_mhz, self.options.bind)

    def unit(self, name: str) -> Unit:
        return next(u for u in self.units if u.name == name)


@dataclass(frozen=True)
class Cost:
    cycles: int  # one iteration
    phase_cycles: tuple[tuple[str, int], ...]
    linear_cycles: int
    dsp: int
    lut: int
    ff: int
    bram36: float
    clock_mhz: float
    fits: bool
    over: tuple[str, ...]  # resources over the part's capacity
    dsp_by_unit: tuple[tuple[str, int], ...] = ()  # (unit, DSP of all its instances)
    words: int = 0  # words the plan's memories hold (channels not counted)
    other_cycles: tuple[tuple[str, int], ...] = ()  # phases not run every iteration (Phase.per)

    @property
    def latency_ms(self) -> float:
        return self.cycles / (self.clock_mhz * 1e3)
