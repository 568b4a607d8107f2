"""The streaming IR: a chain Program, the policy that feeds it keyframe by keyframe, and the slot
layout every backend's window reads (:func:`fgc.compiler.stream.compile_stream` builds it).

- :class:`FixedLag` ``(window)``: after each keyframe the newest W keyframes are held; the one
  leaving is marginalised into a dense Gaussian prior on the window.
- :class:`Incremental` ``(k, batch_every)``: each keyframe re-eliminates the newest K clusters
  on the kept Bayes net (paper A); batch steps re-eliminate all.

A backend runs a :class:`StreamProgram` through the contract's ``stream`` (``fgc_backends``):
the simulator from ``program`` alone, the C-family backends on *template* windows
(:class:`fgc.compiler.stream.WindowTemplate`) filled per update from ``graph``'s numbers, placed
by the :class:`SlotLayout`. A new policy is a frozen class here, its plan in the compiler and
its update loop in each backend's ``stream``.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import ClassVar

from fgc.errors import FgcError
from fgc.frontend.dsl import Graph
from fgc.ir.program import Program


class StreamError(FgcError):
    """A stream a backend's template window cannot run (keyframes of different kinds, a factor
    between non-consecutive keyframes, a singular marginal, a template that does not hold a
    window's factors)."""


@dataclass(frozen=True)
class FixedLag:
    """A fixed-lag window of ``window`` keyframes (W ≥ 1)."""

    window: int
    mode: ClassVar[str] = "fixed-lag"

    def __post_init__(self):
        if isinstance(self.window, bool) or not isinstance(self.window, int) or self.window < 1:
            raise FgcError(f"--window {self.window}: the window must hold at least 1 keyframe")


@dataclass(frozen=True)
class Incremental:
    """The incremental plan: the newest ``k`` clusters re-eliminated per keyframe, batch steps at
    ``batch_every`` (a period, a tuple of keyframes, or None)."""

    k: int
    batch_every: int | tuple[int, ...] | None = None
    mode: ClassVar[str] = "incremental"


Policy = FixedLag | Incremental


def policy_dict(policy: Policy) -> dict:
    """``policy`` as plain data (its ``mode`` and fields: ``{"mode": "fixed-lag", "window": 3}``):
    what the emitted simulator, which runs without fgc, reads."""
    return {"mode": policy.mode, **asdict(policy)}


@dataclass(frozen=True)
class Update:
    """One keyframe's update as a template window sees it: keyframe ``keyframe``, a batch step
    or not, the oldest keyframe ``first`` its window holds (a factor reaching further back moves
    it back)."""

    keyframe: int
    batch: bool
    first: int

    @property
    def size(self) -> int:
        return self.keyframe - self.first + 1


@dataclass(frozen=True)
class SlotLayout:
    """What every backend's template window reads about slots, backend-independent.

    ``clusters``: the keyframes' variable keys (the Program's clusters); ``cluster_of`` /
    ``position``: a key's keyframe and its place in it; ``spans``: per graph factor its oldest
    and newest keyframe; ``updates``: every keyframe's update (:class:`Update`); ``sizes``: the
    template windows the updates need, smallest first (fixed-lag: W + 1; incremental: the
    steady window, then each larger batch step's); ``refusal``: why no template window can run
    this chain (None when one can), so a backend refuses before it starts."""

    clusters: tuple[tuple[str, ...], ...]
    cluster_of: dict = field(compare=False)
    position: dict = field(compare=False)
    spans: tuple[tuple[int, int], ...]
    updates: tuple[Update, ...]
    sizes: tuple[int, ...]
    refusal: str | None

    def check(self, who: str, error: type[FgcError] = StreamError) -> None:
        """``error`` naming ``who`` when the chain cannot run on a template window."""
        if self.refusal is not None:
            raise error(f"{who} cannot stream this chain: {self.refusal}")


@dataclass(frozen=True)
class StreamProgram:
    """A chain's stream: ``program`` (the chain, compiled with the policy: an
    :class:`Incremental` one carries its plan in ``program.schedule.incremental``), ``policy``,
    ``slots`` and ``graph`` (the measurements and initial values each update's window is filled
    from). The template windows are compiled by the backends that run on them
    (:class:`fgc.compiler.stream.WindowTemplate`, of the sizes ``slots.sizes``)."""

    program: Program
    policy: Policy
    graph: Graph = field(compare=False, repr=False)
    slots: SlotLayout = field(compare=False, repr=False)

    @property
    def window(self) -> int | None:
        """The fixed-lag window W (None for an incremental stream)."""
        return self.policy.window if isinstance(self.policy, FixedLag) else None

    @property
    def incremental(self) -> bool:
        return isinstance(self.policy, Incremental)

    @property
    def mode(self) -> str:
        return self.policy.mode
