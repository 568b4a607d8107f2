"""The cycle-counting C simulation against the cost model (fgc issue 18, item 5).

For each example and configuration: emit the HLS accelerator, build its testbench with
-DFGC_COUNT_CYCLES (the unit headers' counters, backends/hls/include/fgc_cycles.h: every loop of
the QR unit set, the Cholesky cascade and back-substitution reports trip, II and depth as it
runs) and run it on the example's data; fgc_cycles::total() applies the plan's arithmetic to what
ran. The model's figure is the plan's (backends/hls/plan.py) linear-solver phases the units
execute (QR levels or the Cholesky cascade, and back-substitution) per linear solve, times the
solves the run made. Gauss-Newton, so every solve is one iteration.

    python bench/bench_cycles.py

Only the units' loops are counted: the factor datapaths, stacking, commit, HGC, state update
and LM control have no counters yet, and are left out of both figures.
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "examples"))

import imu_window  # noqa: E402
import lio  # noqa: E402

from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.datafile import problem_data, write_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends.cfamily.results import read_result  # noqa: E402
from fgc_backends.hls import HlsConfig, emit  # noqa: E402
from fgc_backends.hls.emitter import accel_plan  # noqa: E402
from fgc_backends.hls.plan import phase_cycles  # noqa: E402

COUNT_MAIN = r"""
#include <cstdio>
#include <cstring>
#include "fgc_cycles.h"
struct Dump {
    Dump() { fgc_cycles::state(); }
    ~Dump() {
        std::printf("total %ld\n", fgc_cycles::total());
    }
} dump_at_exit;
"""
COUNTED = ("qr_level", "backsub_level", "cholesky")


def counting_run(project, graph, program, main: str) -> str:
    """Build ``project``'s testbench with the unit headers' counters on (-DFGC_COUNT_CYCLES)
    and ``main`` (C++ whose static object reads fgc_cycles at exit), run it on ``graph``'s data
    and return what it printed."""
    folder = project.directory
    write_data(problem_data(graph, program), folder / "data.txt")
    (folder / "count_main.cpp").write_text(main)
    subprocess.run(["g++", "-std=c++17", "-O1", "-DFGC_COUNT_CYCLES", "-Wno-unknown-pragmas",
                    "-I", "csim_include", "-I", "include", f"tb_{project.name}.cpp",
                    f"{project.name}.cpp", "count_main.cpp", "-o", "tb_count"], cwd=folder,
                   check=True)
    return subprocess.run(["./tb_count", "data.txt", "result.txt"], cwd=folder, check=True,
                          capture_output=True, text=True).stdout


def measure(name, graph, solver):
    program = compile_graph(graph, solver, name="cyc")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # designs over the part's DSP still simulate
        folder = Path(tempfile.mkdtemp(prefix="fgc-cycles-"))
        project = emit(program, folder, HlsConfig(scalar="float"))
    out = counting_run(project, graph, program, COUNT_MAIN)
    line = next(x for x in out.splitlines() if x.startswith("total "))
    total = int(line.split()[1])
    # Gauss-Newton: one linear solve an iteration; the run's iterations from its result file
    solves = read_result(folder / "result.txt", program).iterations
    plan = accel_plan(program, project.config)
    model = sum(phase_cycles(ph) for ph in plan.phases if ph.name.startswith(COUNTED))
    return solves, total, model * solves


def main() -> None:
    cases = []
    for units in (1, 4, 8):
        for ordering in ("serial", "two-ended"):
            cases.append((f"LIO N=30 QR {ordering} n_u={units}", lio.build(N=30),
                          SolverConfig(method="gn", linear="qr", ordering=ordering,
                                       units=units, precision="float32")))
    # N = 20: at N = 50 undamped float32 Gauss-Newton stops singular inside its first solve
    for cpe in (5, 20, 80):
        cases.append((f"imu_window N=20 Cholesky #CPE={cpe}", imu_window.build(N=20),
                      SolverConfig(method="gn", linear="cholesky", cpe=cpe,
                                   precision="float32")))
    print(f"{'configuration':42} {'solves':>6} {'csim cycles':>12} {'model cycles':>12} "
          f"{'csim/model':>10}")
    for name, graph, solver in cases:
        solves, counted, model = measure(name, graph, solver)
        print(f"{name:42} {solves:6d} {counted:12,d} {model:12,d} {counted / model:10.3f}",
              flush=True)


if __name__ == "__main__":
    main()
