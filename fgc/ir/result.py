"""The result every backend's ``run`` returns (the backend contract, ``fgc_backends.CONTRACT``).

Each backend's result class derives from :class:`SolveResult` and has at least these fields:
``values`` (Program variable key → fgc value: ``Pose3``, ``Vector3``, …), ``storage`` (the same
as raw storage arrays, or None), ``status`` (one of ``fgc.ir.codes.STATUSES``), ``reason``,
``iterations``, ``initial_error``, ``final_error``, ``message`` (why a run failed, in words) and
``keys`` (Program key → the graph's own key). The simulator's ``SimResult`` adds timings, the
cost log and the conditioning diagnosis; ``HlsResult`` (HLS C simulation and native solver) the
precision verdict.
"""

from __future__ import annotations

FIELDS = ("values", "storage", "status", "reason", "iterations", "initial_error", "final_error",
          "message", "keys")


class SolveResult:
    """The shared behaviour of every backend's result (fields: :data:`FIELDS`)."""

    __slots__ = ()

    @property
    def user_values(self) -> dict:
        """``values`` by the graph's own keys (an int key is an int again)."""
        return {self.keys.get(k, k): v for k, v in self.values.items()}

    def gtsam_values(self, keys: dict | None = None):
        """The estimate as a ``gtsam.Values`` under the graph's own keys (an int stays that
        int, ``"x1"`` is ``gtsam.Symbol('x', 1)``; ``keys`` maps any other key):
        :func:`fgc.interop.to_gtsam.values_to_gtsam` of :attr:`user_values`."""
        from fgc.interop.to_gtsam import values_to_gtsam

        return values_to_gtsam(self.user_values, keys)

    @property
    def converged(self) -> bool:
        return self.status == "converged"
