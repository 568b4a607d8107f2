"""The schedule stage's output: frozen, JSON-round-trippable dataclasses.

A :class:`Schedule` is a Bayes tree in elimination order. Each :class:`EliminationStep` is one node
of it: a partial QR of the stacked factor rows touching its frontal variables, giving the
conditional p(frontals | separator) (a row block of R) and a new factor on the separator that is
handed to the parent step. ``levels`` lists the steps that may run at the same time.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from fgc.compiler.schedule.serialize import JsonDataclass

UpdateMode = Literal["batch", "incremental"]


@dataclass(frozen=True)
class EliminationStep(JsonDataclass):
    """One frontal elimination, i.e. one node of the Bayes tree.

    - ``frontals`` / ``frontal_dims``: variables eliminated here, in elimination order.
    - ``separator`` / ``separator_dims``: the later-eliminated variables the conditional depends
      on, in elimination order (GTSAM calls them the conditional's parents).
    - ``parent_dims``: per frontal, the total dimension of the later variables (later frontals of
      this step included) its rows of R are structurally coupled to — the width of its
      conditional's parent block in GTSAM's sequential Bayes net. Smaller than the rest of the
      block when a frontal does not touch every later frontal and separator variable.
    - ``factors``: indices into ``GraphStructure.factors`` of the original factors entering here
      (each factor enters the step of its first-eliminated variable).
    - ``children``: steps whose new factor enters here.
    - ``rows``: stacked rows entering the partial QR (factor rows plus children's new factors);
      the stacked matrix has ``frontal_dim + separator_dim`` columns (plus the right-hand side).
    - ``new_factor_rows``: rows of the factor on the separator handed to ``parent``.
    - ``fill_edges``: variable pairs first connected by eliminating this step's frontals.
    - ``parent``: index of the parent step, ``None`` at a root.
    - ``level``: height above the leaves; steps of equal level run in parallel.
    - ``clusters``: chain clusters eliminated here (empty on general graphs).
    """

    index: int
    frontals: tuple[str, ...]
    frontal_dims: tuple[int, ...]
    separator: tuple[str, ...]
    separator_dims: tuple[int, ...]
    parent_dims: tuple[int, ...]
    factors: tuple[int, ...]
    children: tuple[int, ...]
    rows: int
    new_factor_rows: int
    fill_edges: tuple[tuple[str, str], ...]
    parent: int | None
    level: int
    clusters: tuple[int, ...]

    @property
    def frontal_dim(self) -> int:
        """Scalar columns eliminated here."""
        return sum(self.frontal_dims)

    @property
    def separator_dim(self) -> int:
        """Scalar columns of the separator."""
        return sum(self.separator_dims)

    @property
    def r_nonzeros(self) -> int:
        """Structural non-zeros of this step's rows of R, frontal variable by frontal variable.

        Each frontal of dimension d contributes a d×d upper triangle and d × its parent width;
        this is what GTSAM's ``eliminateSequential`` stores and what a QR that skips known zeros
        computes.
        """
        return sum(
            d * (d + 1) // 2 + d * p
            for d, p in zip(self.frontal_dims, self.parent_dims, strict=True)
        )

    @property
    def dense_r_nonzeros(self) -> int:
        """Entries of the step's R block stored densely: f(f+1)/2 + f·s for f frontal, s separator.

        Equals :attr:`r_nonzeros` when the frontals are nested (each couples to all later
        frontals and the whole separator), as on chain keyframes and fundamental supernodes.
        """
        d = self.frontal_dim
        return d * (d + 1) // 2 + d * self.separator_dim


@dataclass(frozen=True)
class IncrementalUpdate(JsonDataclass):
    """What the backend does when chain cluster ``keyframe`` arrives.

    ``clusters`` are re-eliminated in the listed order (oldest first, so the root stays at the
    newest cluster); the conditionals of the ``kept`` older clusters and the factor they pass up
    are reused unchanged. A ``batch`` update re-eliminates every cluster present.
    """

    keyframe: int
    mode: UpdateMode
    clusters: tuple[int, ...]
    kept: int


@dataclass(frozen=True)
class IncrementalPlan(JsonDataclass):
    """Incremental smoothing over a chain: one update per arriving cluster, in arrival order.

    ``window`` is the number of newest clusters an incremental update re-eliminates (the LIO
    accelerator uses 3); ``batch_keyframes`` lists the arrivals that trigger a full batch step.
    """

    window: int
    batch_keyframes: tuple[int, ...]
    updates: tuple[IncrementalUpdate, ...]


@dataclass(frozen=True)
class Schedule(JsonDataclass):
    """An elimination schedule: structure class, ordering, Bayes tree, parallel levels.

    - ``structure_class``: ``"chain"`` or ``"general"``.
    - ``ordering``: the ordering used (``"auto"`` resolved to a concrete name).
    - ``clusters``: the chain's clusters (variable keys) in chain order; empty if general.
    - ``steps``: the Bayes tree's nodes in a valid sequential elimination order.
    - ``levels``: step indices grouped by level, leaves first; a level's steps are independent.
    - ``incremental``: the incremental plan, if one was asked for.
    """

    structure_class: Literal["chain", "general"]
    ordering: str
    clusters: tuple[tuple[str, ...], ...]
    steps: tuple[EliminationStep, ...]
    levels: tuple[tuple[int, ...], ...]
    incremental: IncrementalPlan | None

    @property
    def order(self) -> tuple[str, ...]:
        """Variable keys in sequential elimination order."""
        return tuple(key for step in self.steps for key in step.frontals)

    @property
    def num_sequential_steps(self) -> int:
        """Steps that must run one after another: the tree's height in levels."""
        return len(self.levels)

    @property
    def back_substitution(self) -> tuple[tuple[int, ...], ...]:
        """Levels in back-substitution order: roots first, then outwards to the leaves."""
        return tuple(reversed(self.levels))

    @property
    def roots(self) -> tuple[int, ...]:
        """Steps without a parent (one per connected component)."""
        return tuple(step.index for step in self.steps if step.parent is None)

    @property
    def r_nonzeros(self) -> int:
        """Total fill: structural scalar non-zeros of R, summed over steps (GTSAM's count)."""
        return sum(step.r_nonzeros for step in self.steps)

    @property
    def dense_r_nonzeros(self) -> int:
        """Total fill with every step's R block stored densely."""
        return sum(step.dense_r_nonzeros for step in self.steps)

    @property
    def num_fill_edges(self) -> int:
        """Total fill: variable pairs connected by elimination that no factor connected."""
        return sum(len(step.fill_edges) for step in self.steps)

    def describe(self) -> str:
        """A readable table, one line per level: which frontals are eliminated, and from what."""
        lines = [
            f"{self.structure_class} graph, {self.ordering} ordering: {len(self.steps)} steps in "
            f"{self.num_sequential_steps} levels, R non-zeros {self.r_nonzeros}"
        ]
        for number, level in enumerate(self.levels):
            parts = []
            for index in level:
                step = self.steps[index]
                separator = ",".join(step.separator) or "-"
                parts.append(f"[{','.join(step.frontals)} | {separator}] rows={step.rows}")
            lines.append(f"  level {number}: " + "  ".join(parts))
        return "\n".join(lines)
