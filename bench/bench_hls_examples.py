"""Every example through the HLS accelerator's C simulation, against the simulator.

Each example (examples/*.py, pose_graph on both of its datasets) in double with QR and with
Cholesky, and in float with QR: double must agree with the float64 simulator within 1e-9
relative (tests/hls/test_hls_csim.py's measure), float within 1 cm / 1 mrad / 1e-2.

    FGC_CACHE_DIR=... python bench/bench_hls_examples.py [example:linear:scalar ...]
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "hls"))

from test_hls_csim import pose_errors, relative_worst  # noqa: E402

from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.datafile import problem_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends import sim  # noqa: E402
from fgc_backends.hls import HlsConfig, emit, run_csim  # noqa: E402

imu_window = example("imu_window")
lio = example("lio")
pose_graph = example("pose_graph")
range_beacons = example("range_beacons")

EXAMPLES = {"lio_N10": lambda: lio.build(N=10), "imu_window_N20": lambda: imu_window.build(N=20),
            "pose_graph_w100": lambda: pose_graph.build(),
            "pose_graph_pose3example": lambda: pose_graph.build("pose3example.txt"),
            "range_beacons": lambda: range_beacons.build()}
CONFIGS = (("qr", "double"), ("cholesky", "double"), ("qr", "float"))


def main(only: list[str]) -> int:
    failed = 0
    for name, build in EXAMPLES.items():
        for linear, scalar in CONFIGS:
            if only and f"{name}:{linear}:{scalar}" not in only:
                continue
            graph = build()
            program = compile_graph(graph, SolverConfig(linear=linear, precision="float64"),
                                    name="ex")
            project = emit(program, tempfile.mkdtemp(prefix="fgc-hls-ex-"),
                           HlsConfig(scalar=scalar))
            data = problem_data(graph, program)
            start = time.perf_counter()
            result = run_csim(project, program, data)
            reference = sim.run(program, data, precision="float64")
            if scalar == "double":
                worst = relative_worst(result.values, reference.storage)
                ok = worst <= 1e-9 and result.status == reference.status
                what = f"worst relative {worst:.2e}"
            else:
                pos, rot, vec = pose_errors(program, result.values, reference.storage)
                ok = pos <= 1e-2 and rot <= 1e-3 and vec <= 1e-2
                what = f"pos {pos:.2e} m, rot {rot:.2e} rad, other {vec:.2e}"
            failed += not ok
            print(f"{name:24} {linear:8} {scalar:6} {'PASS' if ok else 'FAIL'}  {what}; "
                  f"csim {result.iterations} it {result.status}, sim {reference.iterations} it "
                  f"{reference.status} ({time.perf_counter() - start:.0f} s)", flush=True)
    return 1 if failed else 0


def _selection(argv: list[str]) -> list[str]:
    import argparse
    names = [f"{n}:{lin}:{sc}" for n in EXAMPLES for lin, sc in CONFIGS]
    ap = argparse.ArgumentParser(description="Every example through the HLS C simulation "
                                 "against the simulator (about 17 minutes idle).")
    ap.add_argument("only", nargs="*", metavar="EXAMPLE:LINEAR:SCALAR",
                    help="run only these (default: all): " + ", ".join(names))
    only = ap.parse_args(argv).only
    unknown = [o for o in only if o not in names]
    if unknown:
        ap.error(f"unknown selection {', '.join(unknown)} (one of: {', '.join(names)})")
    return only


if __name__ == "__main__":
    sys.exit(main(_selection(sys.argv[1:])))
