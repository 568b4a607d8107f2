"""Incremental smoothing plans over a chain (the LIO accelerator's window scheme).

When cluster j arrives, only the newest ``window`` clusters are re-eliminated; the older part of the
Bayes net and the factor it passes up are kept. Re-elimination runs oldest to newest so that the
root stays at the newest cluster: a middle root (two-ended elimination) would put the arriving
cluster's conditional below older ones and force a re-elimination of the whole newer half. Batch
updates re-eliminate every cluster present, in the same serial direction, so that the incremental
updates after them can reuse their Bayes net.
"""

from __future__ import annotations

from collections.abc import Sequence

from fgc.compiler.schedule.ir import IncrementalPlan, IncrementalUpdate


def plan_incremental(
    num_clusters: int, window: int, batch_every: int | Sequence[int] | None = None
) -> IncrementalPlan:
    """Plan one update per arriving cluster ``0 … num_clusters-1``.

    ``window`` (>= 1) is the number of newest clusters an incremental update re-eliminates.
    ``batch_every`` is either a period ``b`` (batch at arrivals b, 2b, 3b, …) or an explicit list of
    arrival indices (the LIO paper batches at steps 5, 15 and 25). Raises ``ValueError`` on a
    non-positive window or period, or a batch index outside the chain.
    """
    if window < 1:
        raise ValueError(f"incremental_k must be >= 1, got {window}")
    batches = _batch_keyframes(num_clusters, batch_every)
    updates = []
    for j in range(num_clusters):
        first = 0 if j in batches else max(0, j - window + 1)
        updates.append(
            IncrementalUpdate(
                keyframe=j,
                mode="batch" if j in batches else "incremental",
                clusters=tuple(range(first, j + 1)),
                kept=first,
            )
        )
    return IncrementalPlan(window=window, batch_keyframes=batches, updates=tuple(updates))


def _batch_keyframes(num_clusters: int, batch_every: int | Sequence[int] | None) -> tuple[int, ...]:
    """Arrival indices of batch updates, sorted and checked."""
    if batch_every is None:
        return ()
    if isinstance(batch_every, int):
        if batch_every < 1:
            raise ValueError(f"batch_every must be >= 1, got {batch_every}")
        return tuple(range(batch_every, num_clusters, batch_every))
    batches = tuple(sorted(set(batch_every)))
    outside = [j for j in batches if not 0 <= j < num_clusters]
    if outside:
        raise ValueError(f"batch steps {outside} lie outside the chain's {num_clusters} clusters")
    return batches
