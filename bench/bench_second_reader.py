"""The plan's price beside the second reader's (issue 32): emit each design, read the emitted
C++ back with :mod:`fgc_backends.hls.reader` (what Vitis would instantiate: operators per
pipelined loop, every call site its own module; II as the memories and recurrences allow) and
print, per design, the plan's DSP / BRAM36 / cycles per iteration beside the reader's DSP lower
bound and its count of loops whose declared II the text cannot meet: for its memories' ports,
a carried recurrence, or the ALLOCATION limits in scope (operations an iteration of a kind above
instances x II); and the ``DEPENDENCE ... inter false`` claims the text refutes (an element
read and written again P iterations later) or cannot prove (a data-dependent address). Every
loop the new rules flag is printed below the table.

    python bench/bench_second_reader.py            # LIO N=30 (QR) and imu_window N=50 (Cholesky)
    python bench/bench_second_reader.py --quick    # LIO N=8, imu_window N=10, fewer designs
    python bench/bench_second_reader.py --stream   # also paper A's on-chip stream design
    python bench/bench_second_reader.py --stream-only [--lm]  # that design alone
    python bench/bench_second_reader.py --stream-only --bind add=fabric  # the operators bound

The on-chip stream design (bench_papers.paper_a_stream's setting: LIO, incremental K = 3, batch
steps at keyframes 5/15/25, one Gauss-Newton step an update: each batch step a sweep through the
window kernel; ``--lm``: LM to convergence, with its batch kernel), the default design and the
smallest the stream search holds, is compared per part: the window kernel (its own top's
reading), the batch kernel (LM) and the stream section (the rest of the stream top's reading),
the plan's ``WindowModel.resources()`` parts beside them.

Model estimates (no vendor tool here): the reader's DSP is a lower bound on what Vitis binds.
"""

from __future__ import annotations

import argparse
import dataclasses
import re
import tempfile
import time
from pathlib import Path

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.plan import DEFAULT_ALLOCATION, PlanOptions, build_plan, plan_cost
from fgc_backends.hls.reader import (
    check,
    check_dsp,
    dsp_table,
    emitted_files,
    emitted_ops,
    read_design,
)
from fgc_backends.hls.reader.depth import check_depths, datapath_depths, table_latency
from fgc_backends.hls.reader.design import _design, _Reader

# the rules issue 32's second-reader task added (their findings are printed, not only counted)
NEW_RULES = ("ii_allocation", "dependence_false", "dependence_unproven")
# the files of the code around the units (issue 32's kernel helper); the QR unit's headers
# (fgc_qr.h, fgc_eliminate.h's stacking) and the Cholesky cascade's (fgc_cpe.h) are counted apart
AROUND = ("fgc_lm_units.h", "fgc_backsub.h")
# the units priced in their headers (a second Cholesky cascade's CPEs: cpe_set1)
OWN_HEADERS = re.compile(r"qr\d+_(?:evaluate|update)|cpe(?:_set\d+)?")


def _dsp_of(tab) -> dict[str, int]:
    return {"add": tab.add.dsp, "mul": tab.mul.dsp, "div": tab.div.dsp, "sqrt": tab.sqrt.dsp,
            "special": tab.special.dsp}


def _bind_arg(text: str):
    from fgc_backends.cost.operators import BindError, parse_bind

    try:
        return parse_bind(text)
    except BindError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def around_dsp(cost) -> int:
    """The plan's DSP of the units around the QR units and the Cholesky cascade (the factor
    datapaths, gradient / HGC, back-substitution, state update, LM control)."""
    return sum(d for unit, d in cost.dsp_by_unit if not OWN_HEADERS.fullmatch(unit))


def depth_reading(files, name: str, ops_of, precision: str, plan, program) -> tuple[dict, list]:
    """The factor datapath functions of the kernel ``<name>.cpp`` as deep as the reader
    schedules their text (reader.depth) beside the depth their plan loops are priced with
    (``plan.report.datapath_depths``): ({function: (read, priced)}, check_depths' issues)."""
    from fgc_backends.hls.plan.report import datapath_depths as priced_depths

    kernel = [(k, t) for k, t in files if k == f"{name}.cpp"]
    read = datapath_depths(kernel, table_latency(ops_of(precision)))
    priced = priced_depths(plan, program)
    return ({k: (read.get(k), v) for k, v in priced.items()},
            [str(i) for i in check_depths(read, priced, f"{name}.cpp")])


def measure(program, config: HlsConfig, out: Path) -> dict:
    from fgc_backends.hls.emitter import for_program

    config = for_program(program, config)  # the design emitted: a float64 solver when mixed
    emit(program, out, config)
    plan = build_plan(program, PlanOptions.for_config(config, program))
    cost = plan_cost(plan)
    files, top = emitted_files(out)
    precision = "float64" if config.scalar == "double" else "float32"
    tab = plan.target.ops(precision)  # the design's part and clock, as the plan prices it
    design = read_design(files, top, tab.add.latency)
    issues = check(design.reached_loops)
    strict = check(design.reached_loops, strict=True)
    mine = [i for i in issues if i.file in AROUND or i.file == f"{program.name}.cpp"]
    # a mixed design's L operators in L's table; every table bound as run_hls.tcl binds it
    # (config_op), read from the text, not the plan
    dsp_of = dsp_table(emitted_ops(out), precision)
    around_files = (*AROUND, f"{program.name}.cpp")
    _, deeper = depth_reading(files, program.name, emitted_ops(out), precision, plan, program)
    return dict(plan_dsp=cost.dsp, plan_bram36=cost.bram36, plan_cycles=cost.cycles,
                reader_dsp=design.dsp(dsp_of),
                plan_around=around_dsp(cost), reader_around=design.dsp(dsp_of, around_files),
                dsp_ok=not check_dsp(design, cost.dsp, dsp_of),
                ii_short=sum(i.rule == "ii_ports" for i in issues),
                recurrences=sum(i.rule == "ii_recurrence" for i in issues),
                allocation=sum(i.rule == "ii_allocation" for i in issues),
                false_claims=sum(i.rule == "dependence_false" for i in issues),
                unproven=sum(i.rule == "dependence_unproven" for i in strict),
                findings=[str(i) for i in strict if i.rule in NEW_RULES],
                around=len(mine),
                others=sorted({f"{i.file}:{i.line}" for i in issues if i not in mine}),
                deeper=deeper,
                worst=max((r.ii_bound / r.ii for r in design.reached_loops if r.ii_known),
                          default=1.0))


def measure_stream(n: int, out: Path, config=None, units: int | None = None,
                   batch: tuple[int, ...] = (5, 15, 25),
                   solver: SolverConfig | None = None) -> dict:
    """Paper A's on-chip stream design at N = ``n``: the plan's DSP per part (window kernel,
    batch kernel, stream section) beside the reader's, and the reader's II-short / carried
    loops. The reader's window kernel is what the window kernel's own top (``<name>_top``: its
    LM, units and datapaths once) instantiates, its batch kernel what the stream top reaches in
    the batch kernel's translation unit, and its stream section the rest of the stream top's
    reading: every copy the stream's own code adds (the marginal's QR set, the kept net's Log /
    retraction datapaths, tau's loops, a kernel function called from a second site).
    ``config``: the design's HlsConfig (unit sets, ALLOCATION; default the default design),
    ``units``: n_u (default the Program's), ``batch``: the batch keyframes (those below n),
    ``solver``: the stream's SolverConfig (default float32 QR, LM to convergence)."""
    import fgc_backends
    from fgc.app import streaming

    graph = example("lio").build(N=n)
    solver = solver or SolverConfig(precision="float32", linear="qr")
    if units is not None:
        solver = dataclasses.replace(solver, units=units)
    program = streaming.compile_stream(graph, solver, incremental=3,
                                       batch_every=tuple(b for b in batch if b < n))
    hls = fgc_backends.load("hls")
    config = dataclasses.replace(config, scalar="float") if config else hls.Config(scalar="float")
    pricer = streaming.WindowPricer(streaming.stream_program(graph, program), config=config)
    res = pricer.model.resources()
    hls.emit(streaming.stream_program(graph, program, None), out, config)
    files, top = emitted_files(out)
    tab = pricer.model.plan.ops
    dsp_of = _dsp_of(emitted_ops(out)("float32"))  # as run_hls.tcl binds it (config_op)
    reader = _Reader(files, tab.add.latency)
    design = _design(reader, top)
    name = top.removesuffix("_stream")
    window_cpp = f"{name}.cpp"
    batch_cpp = next((k for k, _ in files if k.endswith(".cpp") and k != window_cpp), None)
    batch = design.unit_dsp(dsp_of, batch_cpp) if batch_cpp else 0
    window = _design(reader, f"{name}_top").dsp(dsp_of)
    total = design.dsp(dsp_of)
    issues = check(design.reached_loops, strict=True)
    depths, deeper = depth_reading(files, name, emitted_ops(out), "float32", pricer.model.plan,
                                   pricer.model.layout.template)
    plan_parts = {k: d for k, (d, _) in res["parts"].items()}
    modules = dict(design.modules)
    return dict(plan_dsp=res["dsp"], reader_dsp=total, plan_bram36=res["bram36"],
                plan_lut=res["lut"], plan_ff=res["ff"], plan_fits=res["fits"],
                plan_units=res["units"], duplicated=pricer.model.duplicated(),
                parts=[("window kernel", plan_parts.get("window kernel", 0), window),
                       *((("batch kernel", plan_parts.get("batch kernel", 0), batch),)
                         if batch_cpp or "batch kernel" in plan_parts else ()),
                       ("stream section", plan_parts.get("stream section", 0),
                        total - batch - window)],
                ii_short=sum(i.rule == "ii_ports" for i in issues),
                recurrences=sum(i.rule == "ii_recurrence" for i in issues),
                allocation=sum(i.rule == "ii_allocation" for i in issues),
                false_claims=sum(i.rule == "dependence_false" for i in issues),
                unproven=sum(i.rule == "dependence_unproven" for i in issues),
                issues=[str(i) for i in issues], depths=depths, deeper=deeper,
                copies={k: modules.get(k, 0) for k in ("eliminate_all", "linearize_all",
                                                       "back_substitute_at", "qr_update",
                                                       "keyframe_pass", "kept_matvec",
                                                       "write_tau", "so3_log")})


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="small problems, fewer designs")
    parser.add_argument("--stream", action="store_true",
                        help="also paper A's on-chip stream design (LIO N=30, or 8 with --quick)")
    parser.add_argument("--stream-only", action="store_true", help="the stream design alone")
    parser.add_argument("--lm", action="store_true",
                        help="the stream's solver LM to convergence (its batch kernel) instead "
                             "of paper A's one-step policy (batch steps as sweeps)")
    parser.add_argument("--stream-design", metavar="N_U,SETS[,ADD,MUL,DIV[,ROWS]][,wave]",
                        action="append", default=[], help="one more stream design (repeatable): "
                        "n_u, unit sets, the factor datapaths' ALLOCATION limits and the QR "
                        "Update units' rows a cycle (e.g. 8,1,2,3,1 or 4,2,2,3,1,2), 'wave' last "
                        "for the root step in a wavefront (root_wave)")
    parser.add_argument("--bind", type=_bind_arg, default=(), metavar="KIND=IMPL,…",
                        help="every design's operator binding (HlsConfig.bind; run_hls.tcl's "
                        "config_op, which the reader reads back), e.g. add=fabric,mul=meddsp")
    parser.add_argument("--data-width", type=int, choices=(32, 64), default=32,
                        help="every stream design's data port, bits a beat (HlsConfig "
                        "data_width: 64 = two float words a beat; default 32)")
    args = parser.parse_args(argv)
    bind = args.bind
    width = {"data_width": args.data_width} if args.data_width != 32 else {}
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
            # paper A's setting as bench_papers.paper_a_stream runs it: float32 QR, one
            # Gauss-Newton step an update (its batch steps sweep the window: one set of units),
            # or (--lm) LM to convergence with its batch kernel; the default design and the
            # smallest of the stream search (n_u 1, one unit set, ALLOCATION 1 / 1 / 1)
            from fgc.app.streaming import one_step_solver

            solver = SolverConfig(precision="float32", linear="qr")
            solver = solver if args.lm else one_step_solver(solver)
            stream = measure_stream(lio_n, Path(tmp) / "stream", HlsConfig(bind=bind, **width),
                                    solver=solver)
            smallest = measure_stream(lio_n, Path(tmp) / "smallest",
                                      HlsConfig(unit_sets=1, allocation=(
                                          ("add", 1), ("mul", 1), ("div", 1)), bind=bind,
                                          **width), 1,
                                      solver=solver)
            streams = [("default design", stream),
                       ("smallest searched (n_u 1, one unit set, ALLOCATION 1/1/1)", smallest)]
            for i, spec in enumerate(args.stream_design):
                fields = spec.split(",")
                wave = fields[-1] == "wave"  # HlsConfig root_wave (the root in a wavefront)
                v = [int(x) for x in fields[:-1 if wave else None]]
                alloc = tuple(zip(("add", "mul", "div"), v[2:5], strict=True)) if len(v) > 2 \
                    else None
                qr_rows = v[5] if len(v) > 5 else 1
                label = (f"n_u {v[0]}, {v[1]} unit set(s), ALLOCATION "
                         + ("/".join(map(str, v[2:5])) if alloc else "default")
                         + (f", {qr_rows} rows a cycle" if qr_rows > 1 else "")
                         + (", root wave" if wave else ""))
                streams.append((label, measure_stream(
                    lio_n, Path(tmp) / f"design{i}", HlsConfig(unit_sets=v[1], allocation=alloc,
                                                              qr_rows=qr_rows, bind=bind,
                                                              root_wave=wave, **width),
                    v[0], solver=solver)))
        lio = example("lio")
        for n_u in units:
            for alloc in (None, doubled):
                program = compile_graph(lio.build(N=lio_n), name="lio",
                                        solver=SolverConfig(units=n_u))
                config = HlsConfig(allocation=alloc, bind=bind)
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
                m = measure(program, HlsConfig(unit_sets=sets, bind=bind),
                            Path(tmp) / f"imu_{cpe}_{sets}")
                rows.append((f"imu_window N={imu_n} Cholesky #CPE={cpe}"
                             + (" x2 cascades" if sets == 2 else ""), m,
                             time.perf_counter() - t0))
    print(f"{'design':42s} {'plan DSP':>9s} {'reader DSP':>10s} {'ratio':>6s} "
          f"{'BRAM36':>7s} {'cycles/it':>10s} {'II short':>8s} {'carried':>7s} "
          f"{'alloc':>5s} {'false dep':>9s} {'unproven':>8s} "
          f"{'worst II':>8s} {'check_dsp':>9s} {'around':>6s} {'plan/reader DSP around':>22s}")
    others = set()
    deeper: set[str] = set()
    findings: dict[str, list[str]] = {}
    for name, m, _ in rows:
        print(f"{name:42s} {m['plan_dsp']:9d} {m['reader_dsp']:10d} "
              f"{m['reader_dsp'] / max(1, m['plan_dsp']):6.2f} {m['plan_bram36']:7.1f} "
              f"{m['plan_cycles']:10d} {m['ii_short']:8d} {m['recurrences']:7d} "
              f"{m['allocation']:5d} {m['false_claims']:9d} {m['unproven']:8d} "
              f"{m['worst']:7.2f}x {'pass' if m['dsp_ok'] else 'FAIL':>9s} {m['around']:6d} "
              f"{m['plan_around']:>10d} / {m['reader_around']:<9d}")
        others |= set(m["others"])
        deeper |= set(m["deeper"])
        for finding in m["findings"]:
            findings.setdefault(finding, []).append(name)
    print("model estimates: plan = fgc's accelerator plan; reader = what the emitted text "
          "instantiates (a lower bound); 'II short': pipelined loops whose memories cannot give "
          "the declared II; 'carried': loops with a read-modify-write Vitis must assume carried; "
          "'alloc': loops whose ALLOCATION limits cannot issue an iteration's operations "
          "within the declared II (ops of a kind > instances x II); 'false dep': "
          "'DEPENDENCE inter false' claims the text refutes (a partial sum met again P "
          "iterations later); 'unproven': such claims on a data-dependent address (not a "
          "failure: the text cannot tell); "
          "'worst II': the largest ratio of the II the text allows to the declared II; "
          "'check_dsp': the reader's check that the plan prices at least the text's DSP; "
          "'around': II-short or carried loops in the kernel around the units (the kernel, "
          "fgc_lm_units.h, fgc_backsub.h); 'plan/reader DSP around': the plan's units other "
          "than the QR units and CPEs against the reader's DSP of the functions defined in "
          "those files")
    if others:
        print("II-short / carried loops in the units' own headers: " + ", ".join(sorted(others)))
    if rows:  # reader.depth: the factor datapaths' text no deeper than their plan loops
        print("factor datapaths whose text schedules deeper than the plan's loop depth: "
              + (", ".join(sorted(deeper)) if deeper else "none"))
    if findings:
        print("\nthe ALLOCATION / DEPENDENCE rules' findings (loop, figures; the designs they "
              "are in):")
        for finding, names in sorted(findings.items()):
            print(f"  {finding}\n      in: {'; '.join(names)}")
    if stream is not None:
        policy = "LM to convergence" if args.lm else "one Gauss-Newton step an update"
        for label, st in streams:
            print(f"\npaper A's on-chip stream design (LIO N={lio_n}, K=3, {policy}), {label}"
                  + (f", operators bound {','.join(f'{k}={v}' for k, v in bind)}" if bind else "")
                  + ": "
                  f"plan {st['plan_dsp']} DSP / {st['plan_bram36']:g} BRAM36, reader "
                  f"{st['reader_dsp']} DSP: DSP = max(plan, reader) = "
                  f"{max(st['plan_dsp'], st['reader_dsp'])} "
                  + ("fits" if max(st['plan_dsp'], st['reader_dsp']) <= 900 else "over")
                  + f" the xc7z045's 900 DSP (LUT {st['plan_lut']:,}, FF {st['plan_ff']:,} by "
                  "the plan: " + ("fit" if st["plan_fits"] else "OVER")
                  + f"); II short {st['ii_short']}, carried {st['recurrences']}, alloc "
                  f"{st['allocation']}, false dep {st['false_claims']}, unproven {st['unproven']}")
            print(f"{'part':16s} {'plan DSP':>9s} {'reader DSP':>10s}  plan >= reader")
            for part, plan, read in st["parts"]:
                print(f"{part:16s} {plan:9d} {read:10d}  {'yes' if plan >= read else 'NO'}")
            if st["duplicated"]:
                print("what the window and batch kernels each hold (plan DSP; the two never "
                      "run at once):")
                for unit, where in st["duplicated"].items():
                    print(f"  {unit:18s} " + ", ".join(f"{part} {d}" for part, d in where.items()))
            print("factor datapath depth, text (reader) / plan loop: " + ", ".join(
                f"{k} {r}/{p}" for k, (r, p) in st["depths"].items())
                  + f"; deeper than the plan: {len(st['deeper'])}")
            for issue in st["deeper"]:
                print("  " + issue)
            print("module copies the text instantiates (every call site its own): " +
                  ", ".join(f"{k} {v}" for k, v in st["copies"].items()))
            for issue in st["issues"]:
                print("  " + issue)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
