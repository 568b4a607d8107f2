"""The codes every stage and backend shares: one table per kind, read by the front end, the
data-file writer, the emitters and the result readers (a backend never types these out).

- Noise kinds: a member's noise model in the data file is its kind's index here followed by
  :func:`noise_param_count` parameters (isotropic: σ⁻¹; diagonal: the per-row σ⁻¹; full: the
  lower triangle of the square-root information, row by row).
- Robust codes: 0 none, then the index of the loss's kind + 1.
- Solver statuses and reasons: the index a kernel writes into ``info``; the names the results
  carry (the simulator's, the HLS C simulation's and the native solver's alike).
"""

from __future__ import annotations

NOISE_KINDS: tuple[str, ...] = ("isotropic", "diagonal", "full")
NOISE_CODES: dict[str, int] = {kind: code for code, kind in enumerate(NOISE_KINDS)}

ROBUST_KINDS: tuple[str, ...] = ("huber", "cauchy")
ROBUST_CODES: dict[str | None, int] = {None: 0} | {k: i + 1 for i, k in enumerate(ROBUST_KINDS)}

# elimination orderings a SolverConfig may ask for (fgc.compiler.schedule implements each):
# auto = two-ended on chains, min-degree otherwise; natural = declaration order (GTSAM's
# Ordering.Natural)
ORDERINGS: tuple[str, ...] = ("auto", "two-ended", "serial", "min-degree", "nested-dissection",
                              "natural")

STATUSES: tuple[str, ...] = ("converged", "max_iterations", "failed")
REASONS: tuple[str, ...] = ("gradient", "step", "predicted_decrease", "absolute_error",
                            "relative_decrease", "max_iterations", "non_finite", "singular",
                            "cost_increased", "lambda_limit")


def noise_param_count(kind: str, rows: int) -> int:
    """How many parameters a ``kind`` noise model of ``rows`` rows stores in the data file."""
    if kind == "isotropic":
        return 1
    if kind == "diagonal":
        return rows
    if kind == "full":
        return rows * (rows + 1) // 2
    raise ValueError(f"unknown noise kind {kind!r}; one of {NOISE_KINDS}")
