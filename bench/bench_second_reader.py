"""The plan's price beside the second reader's (issue 32): emit each design, read the emitted
C++ back with :mod:`fgc_backends.hls.reader` (what Vitis would instantiate: operators per
pipelined loop, every call site its own module; II as the memories and recurrences allow) and
print, per design, the plan's DSP / BRAM36 / cycles per iteration beside the reader's DSP lower
bound and its count of loops whose declared II the text cannot meet.

    python bench/bench_second_reader.py            # LIO N=30 (QR) and imu_window N=50 (Cholesky)
    python bench/bench_second_reader.py --quick    # LIO N=8, imu_window N=10, fewer designs
    python bench/bench_second_reader.py --stream   # also paper A's on-chip stream design

The on-chip stream design (bench_papers.paper_a_stream's setting: LIO, incremental K = 3, batch
steps at keyframes 5/15/25) is compared per part: the window kernel, the batch kernel and the
stream section (fgc_stream.h's functions that the stream top calls, each read as a top, the
batch kernel they reach taken out), the plan's ``WindowModel.resources()`` parts beside them.

Model estimates (no vendor tool here): the reader's DSP is a lower bound on what Vitis binds.
"""

from __future__ import annotations

import argparse
import re
import tempfile
import time
from pathlib import Path

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.plan import DEFAULT_ALLOCATION, PlanOptions, build_plan, plan_cost
from fgc_backends.hls.reader import check, check_dsp, emitted_files, read_design
from fgc_backends.hls.reader.design import _design, _Reader

# the files of the code around the units (issue 32's kernel helper); the QR unit's headers
# (fgc_qr.h, fgc_eliminate.h's stacking) and the Cholesky cascade's (fgc_cpe.h) are counted apart
AROUND = ("fgc_lm_units.h", "fgc_backsub.h")
# the units priced in their headers (a second Cholesky cascade's CPEs: cpe_set1)
OWN_HEADERS = re.compile(r"qr\d+_(?:evaluate|update)|cpe(?:_set\d+)?")


def _dsp_of(tab) -> dict[str, int]:
    return {"add": tab.add.dsp, "mul": tab.mul.dsp, "div": tab.div.dsp, "sqrt": tab.sqrt.dsp,
            "special": tab.special.dsp}


def around_dsp(cost) -> int:
    """The plan's DSP of the units around the QR units and the Cholesky cascade (the factor
    datapaths, gradient / HGC, back-substitution, state update, LM control)."""
    return sum(d for unit, d in cost.dsp_by_unit if not OWN_HEADERS.fullmatch(unit))


def measure(program, config: HlsConfig, out: Path) -> dict:
    emit(program, out, config)
    plan = build_plan(program, PlanOptions.for_config(config, program))
    cost = plan_cost(plan)
    files, top = emitted_files(out)
    precision = "float64" if config.scalar == "double" else "float32"
    tab = plan.target.ops(precision)  # the design's part and clock, as the plan prices it
    design = read_design(files, top, tab.add.latency)
    issues = check(design.reached_loops)
    mine = [i for i in issues if i.file in AROUND or i.file == f"{program.name}.cpp"]
    dsp_of = _dsp_of(tab)
    around_files = (*AROUND, f"{program.name}.cpp")
    return dict(plan_dsp=cost.dsp, plan_bram36=cost.bram36, plan_cycles=cost.cycles,
                reader_dsp=design.dsp(dsp_of),
                plan_around=around_dsp(cost), reader_around=design.dsp(dsp_of, around_files),
                dsp_ok=not check_dsp(design, cost.dsp, _dsp_of(tab)),
                ii_short=sum(i.rule == "ii_ports" for i in issues),
                recurrences=sum(i.rule == "ii_recurrence" for i in issues),
                around=len(mine),
                others=sorted({f"{i.file}:{i.line}" for i in issues if i not in mine}),
                worst=max((r.ii_bound / r.ii for r in design.reached_loops if r.ii_known),
                          default=1.0))


def section_tops(reader) -> list[str]:
    """The stream section's functions the stream top (fgc_stream.h's ``stream_call``) calls."""
    call = reader.functions.get("stream_call")
    if call is None:
        return []
    names = dict.fromkeys(re.findall(r"\b(\w+)\s*<\s*CFG\s*>\s*\(", call.text))
    return [n for n in names if n in reader.functions
            and reader.functions[n].file == "fgc_stream.h"]


def measure_stream(n: int, out: Path) -> dict:
    """Paper A's on-chip stream design at N = ``n``: the plan's DSP per part (window kernel,
    batch kernel, stream section) beside the reader's, and the reader's II-short / carried
    loops. The reader's window kernel is the whole design's reading less the batch kernel's
    translation unit and the stream section's tops (what they instantiate apart from the batch
    kernel: the kernels' functions they call from their own call sites included)."""
    import fgc_backends
    from fgc.app import streaming

    graph = example("lio").build(N=n)
    solver = SolverConfig(precision="float32", linear="qr")
    program = streaming.compile_stream(graph, solver, incremental=3,
                                       batch_every=tuple(b for b in (5, 15, 25) if b < n))
    pricer = streaming.WindowPricer(streaming.stream_program(graph, program))
    res = pricer.model.resources()
    hls = fgc_backends.load("hls")
    hls.emit(streaming.stream_program(graph, program, None), out, hls.Config(scalar="float"))
    files, top = emitted_files(out)
    tab = pricer.model.plan.ops
    dsp_of = _dsp_of(tab)
    reader = _Reader(files, tab.add.latency)
    design = _design(reader, top)
    window_cpp = f"{top.removesuffix('_stream')}.cpp"
    batch_cpp = next((k for k, _ in files if k.endswith(".cpp") and k != window_cpp), None)
    batch = design.unit_dsp(dsp_of, batch_cpp) if batch_cpp else 0
    section = 0
    for name in section_tops(reader):
        if name in reader.functions:
            part = _design(reader, name, window_cpp)
            section += part.dsp(dsp_of) - (part.unit_dsp(dsp_of, batch_cpp) if batch_cpp else 0)
    total = design.dsp(dsp_of)
    issues = check(design.reached_loops)
    plan_parts = {k: d for k, (d, _) in res["parts"].items()}
    modules = dict(design.modules)
    return dict(plan_dsp=res["dsp"], reader_dsp=total,
                parts=[("window kernel", plan_parts.get("window kernel", 0),
                        total - batch - section),
                       ("batch kernel", plan_parts.get("batch kernel", 0), batch),
                       ("stream section", plan_parts.get("stream section", 0), section)],
                ii_short=sum(i.rule == "ii_ports" for i in issues),
                recurrences=sum(i.rule == "ii_recurrence" for i in issues),
                issues=[str(i) for i in issues],
                copies={k: modules.get(k, 0) for k in ("eliminate_all", "qr_update",
                                                       "keyframe_local", "keyframe_retract",
                                                       "retract_all", "so3_log")})


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="small problems, fewer designs")
    parser.add_argument("--stream", action="store_true",
                        help="also paper A's on-chip stream design (LIO N=30, or 8 with --quick)")
    parser.add_argument("--stream-only", action="store_true", help="the stream design alone")
    args = parser.parse_args(argv)
    lio_n, imu_n = (8, 10) if args.quick else (30, 50)
    units = (1, 4) if args.quick else (1, 4, 8, 32)
    cpes = (5, 20) if args.quick else (5, 20, 80)
    doubled = tuple((k, 2 * v) for k, v in DEFAULT_ALLOCATION)
    rows = []
    stream = None
    if args.stream_only:
        units, cpes = (), ()
    with tempfile.TemporaryDirectory() as tmp:
        if args.stream or args.stream_only:
            stream = measure_stream(lio_n, Path(tmp) / "stream")
        lio = example("lio")
        for n_u in units:
            for alloc in (None, doubled):
                program = compile_graph(lio.build(N=lio_n), name="lio",
                                        solver=SolverConfig(units=n_u))
                config = HlsConfig(allocation=alloc)
                t0 = time.perf_counter()
                m = measure(program, config, Path(tmp) / f"lio_{n_u}_{bool(alloc)}")
                rows.append((f"LIO N={lio_n} QR n_u={n_u}" + (" ALLOCATION x2" if alloc else ""),
                             m, time.perf_counter() - t0))
        imu = example("imu_window")
        for cpe in cpes:
            program = compile_graph(imu.build(N=imu_n), name="imu",
                                    solver=SolverConfig(linear="cholesky", cpe=cpe))
            for sets in (1, 2):  # one cascade, two side by side (fgc_cascades.h)
                t0 = time.perf_counter()
                m = measure(program, HlsConfig(unit_sets=sets), Path(tmp) / f"imu_{cpe}_{sets}")
                rows.append((f"imu_window N={imu_n} Cholesky #CPE={cpe}"
                             + (" x2 cascades" if sets == 2 else ""), m,
                             time.perf_counter() - t0))
    print(f"{'design':42s} {'plan DSP':>9s} {'reader DSP':>10s} {'ratio':>6s} "
          f"{'BRAM36':>7s} {'cycles/it':>10s} {'II short':>8s} {'carried':>7s} "
          f"{'worst II':>8s} {'check_dsp':>9s} {'around':>6s} {'plan/reader DSP around':>22s}")
    others = set()
    for name, m, _ in rows:
        print(f"{name:42s} {m['plan_dsp']:9d} {m['reader_dsp']:10d} "
              f"{m['reader_dsp'] / max(1, m['plan_dsp']):6.2f} {m['plan_bram36']:7.1f} "
              f"{m['plan_cycles']:10d} {m['ii_short']:8d} {m['recurrences']:7d} "
              f"{m['worst']:7.1f}x {'pass' if m['dsp_ok'] else 'FAIL':>9s} {m['around']:6d} "
              f"{m['plan_around']:>10d} / {m['reader_around']:<9d}")
        others |= set(m["others"])
    print("model estimates: plan = fgc's accelerator plan; reader = what the emitted text "
          "instantiates (a lower bound); 'II short': pipelined loops whose memories cannot give "
          "the declared II; 'carried': loops with a read-modify-write Vitis must assume carried; "
          "'worst II': the largest ratio of the II the text allows to the declared II; "
          "'check_dsp': the reader's check that the plan prices at least the text's DSP; "
          "'around': II-short or carried loops in the kernel around the units (the kernel, "
          "fgc_lm_units.h, fgc_backsub.h); 'plan/reader DSP around': the plan's units other "
          "than the QR units and CPEs against the reader's DSP of the functions defined in "
          "those files")
    if others:
        print("II-short / carried loops in the units' own headers: " + ", ".join(sorted(others)))
    if stream is not None:
        print(f"\npaper A's on-chip stream design (LIO N={lio_n}, K=3): plan {stream['plan_dsp']} "
              f"DSP, reader {stream['reader_dsp']} DSP; II short {stream['ii_short']}, "
              f"carried {stream['recurrences']}")
        print(f"{'part':16s} {'plan DSP':>9s} {'reader DSP':>10s}  plan >= reader")
        for part, plan, read in stream["parts"]:
            print(f"{part:16s} {plan:9d} {read:10d}  {'yes' if plan >= read else 'NO'}")
        print("module copies the text instantiates (every call site its own): " +
              ", ".join(f"{k} {v}" for k, v in stream["copies"].items()))
        for issue in stream["issues"]:
            print("  " + issue)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
