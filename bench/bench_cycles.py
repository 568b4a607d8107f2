"""The cycle-counting C simulation against the cost model (fgc issue 18, item 5), per phase.

For each example and configuration: emit the HLS accelerator, build its testbench with
-DFGC_COUNT_CYCLES (the counters of backends/hls/include/fgc_cycles.h: every loop of the QR unit
sets, the Cholesky cascade and back-substitution, and every loop of the kernel around them - the
factor datapaths, the gradient pass or HGC, stacking and commit or assembly and store, the state
update, LM control, the top's copies and the rounding-noise pass - reports trip, II and depth as
it runs, under the plan phase it belongs to) and run it on the example's data;
fgc_cycles::phase_totals() applies the plan's arithmetic to what ran.

The model's figure for a phase is the plan's (backends/hls/plan/, the design the config emits:
PlanOptions.for_config) cycles of one execution of that phase times the number of times the run
executed it: the linearisations, linear solves, retractions, cost passes, rounding-noise passes
and calls the counting build counted (FGC_EVENT). So the comparison checks the cycles per
execution, not how many iterations the solver took. Gauss-Newton, float32 Program, float design.

    python bench/bench_cycles.py
    python bench/bench_cycles.py --only Cholesky    # the configurations whose name holds it
"""

from __future__ import annotations

import re
import subprocess
import tempfile
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph  # noqa: E402
from fgc.ir.datafile import problem_data, write_data  # noqa: E402
from fgc.ir.program import SolverConfig  # noqa: E402
from fgc_backends.hls import HlsConfig, emit  # noqa: E402
from fgc_backends.hls.emitter import accel_plan  # noqa: E402
from fgc_backends.hls.plan import PHASE_TRIGGER as TRIGGER  # noqa: E402
from fgc_backends.hls.plan import phase_cycles  # noqa: E402
from fgc_backends.hls.plan import phase_group as group  # noqa: E402

imu_window = example("imu_window")
lio = example("lio")
pose_graph = example("pose_graph")

COUNT_MAIN = r"""
#include <cstdio>
#include <cstring>
#include "fgc_cycles.h"
struct Dump {
    Dump() { fgc_cycles::state(); }
    ~Dump() {
        std::printf("total %ld\n", fgc_cycles::total());
        for (const auto& kv : fgc_cycles::phase_totals())
            std::printf("phase %s %ld\n", kv.first.empty() ? "-" : kv.first.c_str(), kv.second);
        for (const auto& kv : fgc_cycles::events())
            std::printf("event %s %ld\n", kv.first.c_str(), kv.second);
    }
} dump_at_exit;
"""


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


def measure(name, graph, solver, config: HlsConfig | None = None):
    """(phases, events): per phase group (csim cycles, model cycles) of one run of the design
    ``config`` emits (default: the float design), and the run's event counts; the total is the
    sum over the groups."""
    program = compile_graph(graph, solver, name="cyc")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # designs over the part's DSP still simulate
        folder = Path(tempfile.mkdtemp(prefix="fgc-cycles-"))
        project = emit(program, folder, config or HlsConfig(scalar="float"))
    out = counting_run(project, graph, program, COUNT_MAIN)
    counted = {k: int(v) for k, v in re.findall(r"^phase (\S+) (\d+)$", out, re.M)}
    events = {k: int(v) for k, v in re.findall(r"^event (\S+) (\d+)$", out, re.M)}
    total = int(re.search(r"^total (\d+)$", out, re.M).group(1))
    if sum(counted.values()) != total or "-" in counted:
        raise RuntimeError(f"{name}: records outside a phase or phases not adding up: {out}")
    plan = accel_plan(program, project.config)
    per: dict[str, int] = {}
    for ph in plan.phases:
        per[group(ph.name)] = per.get(group(ph.name), 0) + phase_cycles(ph)
    phases = {}
    for g in sorted(set(per) | set(counted)):
        runs = events.get(TRIGGER[g], 0) if g in TRIGGER else 0
        phases[g] = (counted.get(g, 0), per.get(g, 0) * runs)
    return phases, events


ORDER = ("setup", "factor_jacobian", "gradient", "hgc", "hgc_beside", "qr_stack", "qr",
         "qr_commit", "assemble", "cholesky", "reassemble", "recholesky", "store", "backsub",
         "state_update", "factor_cost",
         "lm_iteration", "lm_control", "lm_accept", "lm_restore", "rounding_noise")


def cases():
    out = []
    for ordering in ("serial", "two-ended"):
        for units in (1, 4, 8):
            out.append((f"LIO N=30 QR {ordering} n_u={units}", lio.build(N=30),
                        SolverConfig(method="gn", linear="qr", ordering=ordering,
                                     units=units, precision="float32")))
    # the streaming QR unit (--qr-unit stream, fgc_qr_stream.h): n_u reflection stages
    for units in (4, 8):
        out.append((f"LIO N=30 QR two-ended n_u={units} stream", lio.build(N=30),
                    SolverConfig(method="gn", linear="qr", ordering="two-ended", units=units,
                                 precision="float32"),
                    HlsConfig(scalar="float", qr_unit="stream")))
    # the Householder unit's Update units two rows a cycle (HlsConfig qr_rows=2, FGC_QR_TWO_ROWS)
    for ordering, units in (("serial", 4), ("two-ended", 4), ("two-ended", 8)):
        out.append((f"LIO N=30 QR {ordering} n_u={units} two rows", lio.build(N=30),
                    SolverConfig(method="gn", linear="qr", ordering=ordering, units=units,
                                 precision="float32"),
                    HlsConfig(scalar="float", qr_rows=2)))
    # N = 20: at N = 50 undamped float32 Gauss-Newton stops singular inside its first solve
    for cpe in (5, 20, 80):
        out.append((f"imu_window N=20 Cholesky #CPE={cpe}", imu_window.build(N=20),
                    SolverConfig(method="gn", linear="cholesky", cpe=cpe,
                                 precision="float32")))
    # the fastest LIO design that fits (issue 33): the HGC's two lanes on a 21-row block
    out.append(("LIO N=30 Cholesky #CPE=15", lio.build(N=30),
                SolverConfig(method="gn", linear="cholesky", cpe=15, precision="float32")))
    # two cascades side by side (unit_sets=2, fgc_cascades.h): LIO's fastest design that fits,
    # and imu_window's with a cascade of three rounds a step
    out.append(("LIO N=30 Cholesky #CPE=15 x2", lio.build(N=30),
                SolverConfig(method="gn", linear="cholesky", cpe=15, precision="float32"),
                HlsConfig(scalar="float", unit_sets=2)))
    out.append(("imu_window N=20 Cholesky #CPE=5 x2", imu_window.build(N=20),
                SolverConfig(method="gn", linear="cholesky", cpe=5, precision="float32"),
                HlsConfig(scalar="float", unit_sets=2)))
    # back-substitution two lanes wide (backsub_lanes=2: COND cyclic over two banks, four
    # words a cycle into a lane, the triangle two rows a cycle), one cascade and two
    out.append(("LIO N=30 Cholesky #CPE=15 backsub x2 lanes", lio.build(N=30),
                SolverConfig(method="gn", linear="cholesky", cpe=15, precision="float32"),
                HlsConfig(scalar="float", backsub_lanes=2)))
    out.append(("imu_window N=20 Cholesky #CPE=20 x2 backsub x2 lanes", imu_window.build(N=20),
                SolverConfig(method="gn", linear="cholesky", cpe=20, precision="float32"),
                HlsConfig(scalar="float", unit_sets=2, backsub_lanes=2)))
    # two words a cycle through the cascade (cascade_lanes=2, fgc_cpe.h's STREAM_WORDS): one cascade
    # at #CPE = 80 (one round a step), two at #CPE = 5 (three rounds a step, the later ones
    # read back from H two words a cycle)
    out.append(("imu_window N=20 Cholesky #CPE=80 L2", imu_window.build(N=20),
                SolverConfig(method="gn", linear="cholesky", cpe=80, precision="float32"),
                HlsConfig(scalar="float", cascade_lanes=2)))
    out.append(("imu_window N=20 Cholesky #CPE=5 x2 L2", imu_window.build(N=20),
                SolverConfig(method="gn", linear="cholesky", cpe=5, precision="float32"),
                HlsConfig(scalar="float", unit_sets=2, cascade_lanes=2)))
    # paper B's 80 CPEs: two cascades of 40, two words a cycle (a step's 15 pivots: the round
    # leaves each cascade at its last pivot's CPE, the 25 after it idle)
    out.append(("imu_window N=20 Cholesky #CPE=40 x2 L2", imu_window.build(N=20),
                SolverConfig(method="gn", linear="cholesky", cpe=40, precision="float32"),
                HlsConfig(scalar="float", unit_sets=2, cascade_lanes=2)))
    # and with the HGC's third Gram lane (hgc_third_lane: the IMU Grams 166 words an instance)
    out.append(("imu_window N=20 Cholesky #CPE=40 x2 L2 lane C", imu_window.build(N=20),
                SolverConfig(method="gn", linear="cholesky", cpe=40, precision="float32"),
                HlsConfig(scalar="float", unit_sets=2, cascade_lanes=2, hgc_third_lane=True)))
    # back-substitution by columns (backsub_lanes=4: a loader and a process per end of the
    # chain, the state update fed by both), one cascade and two; a chain's default design takes
    # them (backsub_lanes auto), so the cases above with the default config run them too, and
    # the one-lane slot design is measured on a chain here (and on the tree below)
    out.append(("LIO N=30 Cholesky #CPE=15 backsub one lane", lio.build(N=30),
                SolverConfig(method="gn", linear="cholesky", cpe=15, precision="float32"),
                HlsConfig(scalar="float", backsub_lanes=1)))
    out.append(("LIO N=30 Cholesky #CPE=15 backsub columns", lio.build(N=30),
                SolverConfig(method="gn", linear="cholesky", cpe=15, precision="float32"),
                HlsConfig(scalar="float", backsub_lanes=4)))
    out.append(("imu_window N=20 Cholesky #CPE=20 x2 backsub columns", imu_window.build(N=20),
                SolverConfig(method="gn", linear="cholesky", cpe=20, precision="float32"),
                HlsConfig(scalar="float", unit_sets=2, backsub_lanes=4)))
    # a general tree (not a chain): steps with several children and many factors (30 Pose2,
    # 60 factors), with the HGC beside the elimination (the default) and before it
    for beside in (True, False):
        out.append((f"pose_graph w100_30 Cholesky #CPE=5{'' if beside else ' hgc before'}",
                    pose_graph.build(dataset="w100_30.g2o"),
                    SolverConfig(method="gn", linear="cholesky", cpe=5, precision="float32"),
                    HlsConfig(scalar="float", hgc_beside=beside)))
    return out


def main(argv=None) -> None:
    import argparse
    ap = argparse.ArgumentParser(description="The cycle-counting C simulation against the plan, "
                                 "per phase, on every configuration (about 10 minutes idle).")
    ap.add_argument("--only", default="", metavar="WORD",
                    help="only the configurations whose name holds WORD (e.g. Cholesky)")
    ap.add_argument("--list", action="store_true", help="print the configurations' names and exit")
    args = ap.parse_args(argv)
    only = args.only
    selected = [case for case in cases() if only in case[0]]
    if args.list:
        print("\n".join(case[0] for case in selected))
        return
    if not selected:
        ap.error(f"--only {only!r}: no configuration's name holds it (--list shows them)")
    summary = []
    for name, graph, solver, *config in selected:
        phases, events = measure(name, graph, solver, *config)
        print(f"{name}   (runs: " + ", ".join(f"{k} {v}" for k, v in sorted(events.items()))
              + ")")
        print(f"  {'phase':16} {'csim cycles':>12} {'model cycles':>12} {'csim/model':>10}")
        for g in sorted(phases, key=lambda g: (ORDER.index(g) if g in ORDER else 99, g)):
            c, m = phases[g]
            if c or m:
                ratio = f"{c / m:10.3f}" if m else f"{'-':>10}"
                print(f"  {g:16} {c:12,d} {m:12,d} {ratio}")
        c = sum(v[0] for v in phases.values())
        m = sum(v[1] for v in phases.values())
        print(f"  {'total':16} {c:12,d} {m:12,d} {c / m:10.3f}", flush=True)
        summary.append((name, c, m))
    print()
    print(f"{'configuration':42} {'csim cycles':>12} {'model cycles':>12} {'csim/model':>10}")
    for name, c, m in summary:
        print(f"{name:42} {c:12,d} {m:12,d} {c / m:10.3f}")


if __name__ == "__main__":
    main()
