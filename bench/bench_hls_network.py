"""The emitted HLS accelerator's process network per option, beside the plan's.

LIO N = 30 (QR, two-ended: two unit sets) for n_u ∈ {1, 4, 8} and imu_window N = 50 (Cholesky)
for #CPE ∈ {5, 20, 80}: the processes and streams of the linear solver and of
back-substitution (the kernel's backsub_level region: one unit per unit set), read back from
the emitted kernel and its unit header (``fgc_backends.hls.network.counts``), and the plan's
(``plan.process_network``). Every project is linted inside ``emit``.

    FGC_CACHE_DIR=... python bench/bench_hls_network.py [--out DIR]
"""

from __future__ import annotations

import argparse
import tempfile
from pathlib import Path

from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends.hls import HlsConfig, emit  # noqa: E402
from fgc_backends.hls.emitter import accel_plan  # noqa: E402
from fgc_backends.hls.network import counts  # noqa: E402
from fgc_backends.hls.plan import process_network  # noqa: E402

imu_window = example("imu_window")
lio = example("lio")

CASES = (("LIO N=30, QR", lambda: lio.build(N=30), "qr", "units", (1, 4, 8)),
         ("imu_window N=50, Cholesky", lambda: imu_window.build(N=50), "cholesky", "cpe",
          (5, 20, 80)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=None, help="keep the projects here")
    args = parser.parse_args()
    root = args.out or Path(tempfile.mkdtemp(prefix="fgc-hls-network-"))
    print(f"{'example':28} {'option':9} {'ordering':10} {'processes':>9} {'streams':>8} "
          f"{'plan':>9}")
    for label, build, linear, option, values in CASES:
        graph = build()
        for value in values:
            program = compile_graph(graph, SolverConfig(linear=linear, **{option: value}),
                                    name="net")
            project = emit(program, root / f"{linear}_{option}{value}", HlsConfig())
            kernel = (project.directory / "net.cpp").read_text()
            unit = "fgc_qr.h" if linear == "qr" else "fgc_cpe.h"
            header = (project.directory / "include" / unit).read_text()
            backsub = (project.directory / "include" / "fgc_backsub.h").read_text()
            procs, streams = counts(kernel, header, backsub)
            plan_procs, plan_streams = process_network(accel_plan(program, HlsConfig()))
            print(f"{label:28} {option}={value:<4} {program.schedule.ordering:10} {procs:9d} "
                  f"{streams:8d} {len(plan_procs):4d}/{len(plan_streams):<4d}")


if __name__ == "__main__":
    main()
