"""Solves started at coincident points (issue 34 item 5): fgc's backends against GTSAM.

The three graphs of tests/test_singular_start.py (a Pose2 + Point2 bearing-range problem whose
landmark starts at the pose observing it, a Point2 ranged from three beacons starting on one
of them with a custom distance factor, a Point3 ranged from four Pose3 starting at one of them
with a custom Pose3 range), solved by each backend from those starts and by GTSAM's LM with its
own factors (BearingRangeFactor2D, RangeFactor2, RangeFactor3D). Prints per backend its status,
iterations, final error, the final error's difference from GTSAM's (relative) and the largest
storage-entry difference of the states. The HLS C simulation in float does not build for a
graph without rotations (a known testbench limit, tests/test_optimum_start.py): skipped there.

    python bench/bench_singular.py                                 # sim, native, hls; 64 and 32
    python bench/bench_singular.py --backends sim64,sim32
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests"))

from test_singular_start import GRAPHS, _gtsam_optimum, _solve  # noqa: E402

BACKENDS = ("sim64", "sim32", "native64", "native32", "hls64", "hls32")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backends", default=",".join(BACKENDS))
    args = parser.parse_args()
    for name, build in GRAPHS.items():
        graph = build()
        error, optimum = _gtsam_optimum(graph)
        print(f"{name}: GTSAM's LM (its own factors) -> final error {error:.12g}")
        for backend in args.backends.split(","):
            kind, bits = backend[:-2], backend[-2:]
            if backend == "hls32" and name == "beacon-distance":
                print(f"  {backend:9s} skipped (float testbench without rotations)")
                continue
            t0 = time.perf_counter()
            r = _solve(graph, kind, "float64" if bits == "64" else "float32")
            values = getattr(r, "keyed_values", None) or r.values
            states = max(float(np.abs(np.asarray(
                v if isinstance(v, np.ndarray) else v.storage_array())
                - optimum[k].storage_array()).max()) for k, v in values.items())
            print(f"  {backend:9s} {r.status} ({r.reason}) after {r.iterations} iterations, "
                  f"final error {r.final_error:.12g}, rel. diff "
                  f"{abs(r.final_error - error) / error:.2e}, max state diff {states:.2e} "
                  f"({time.perf_counter() - t0:.1f} s)")


if __name__ == "__main__":
    main()
