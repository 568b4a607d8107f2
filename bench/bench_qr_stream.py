"""The streaming QR unit (--qr-unit stream, include/fgc_qr_stream.h) beside paper A's
(householder, include/fgc_qr.h) on LIO N=30 (two-ended, LM, float32, the xc7z045 at 143 MHz):
per n_u, the plan's cycles per iteration and in the QR levels, DSP (all and the QR units'),
BRAM36, and the second reader's DSP of the emitted design (what the text instantiates: every
pipelined loop's operators, every call site its own module; a lower bound) beside the plan's.

    python bench/bench_qr_stream.py              # n_u 4, 8, 16, 32
    python bench/bench_qr_stream.py --quick      # LIO N=8, n_u 4 and 8, no reader

Model estimates (no vendor tool here).
"""

from __future__ import annotations

import argparse
import tempfile
import warnings
from pathlib import Path

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.plan import PlanOptions, build_plan, plan_cost
from fgc_backends.hls.reader import check, emitted_files, read_design


def _dsp_of(tab) -> dict[str, int]:
    return {"add": tab.add.dsp, "mul": tab.mul.dsp, "div": tab.div.dsp, "sqrt": tab.sqrt.dsp,
            "special": tab.special.dsp}


def measure(program, unit: str, out: Path | None) -> dict:
    config = HlsConfig(qr_unit=unit)
    plan = build_plan(program, PlanOptions.for_config(config, program))
    cost = plan_cost(plan)
    row = dict(cycles=cost.cycles, ms=cost.latency_ms,
               qr=sum(c for name, c in cost.phase_cycles if name.startswith("qr_level")),
               dsp=cost.dsp, qr_dsp=sum(d for name, d in cost.dsp_by_unit
                                        if name.startswith("qr")),
               bram36=cost.bram36, reader_dsp=None, issues=None)
    if out is not None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # designs over the part still emit
            emit(program, out, config)
        files, top = emitted_files(out)
        tab = plan.target.ops("float32")
        design = read_design(files, top, tab.add.latency)
        row["reader_dsp"] = design.dsp(_dsp_of(tab))
        row["issues"] = sum(1 for i in check(design.loops)
                            if "qrs_" in i.message or "fgc_qr_stream" in i.message)
    return row


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="LIO N=8, n_u 4 and 8, no reader")
    args = parser.parse_args(argv)
    n, units = (8, (4, 8)) if args.quick else (30, (4, 8, 16, 32))
    graph = example("lio").build(N=n)
    print(f"LIO N={n}, two-ended, LM, float32, xc7z045 @ 143 MHz")
    print(f"{'n_u':>3s} {'unit':12s} {'cycles/it':>9s} {'ms/it':>6s} {'QR levels':>9s} "
          f"{'DSP':>5s} {'QR DSP':>6s} {'BRAM36':>6s} {'reader DSP':>10s} {'unit issues':>11s}")
    with tempfile.TemporaryDirectory() as tmp:
        for n_u in units:
            program = compile_graph(graph, SolverConfig(method="lm", linear="qr",
                                                        ordering="two-ended",
                                                        precision="float32", units=n_u),
                                    name="lio")
            for unit in ("householder", "stream"):
                out = None if args.quick else Path(tmp) / f"lio_{n_u}_{unit}"
                r = measure(program, unit, out)
                reader = "-" if r["reader_dsp"] is None else f"{r['reader_dsp']:,}"
                issues = "-" if r["issues"] is None else str(r["issues"])
                print(f"{n_u:3d} {unit:12s} {r['cycles']:9,d} {r['ms']:6.3f} {r['qr']:9,d} "
                      f"{r['dsp']:5d} {r['qr_dsp']:6d} {r['bram36']:6.1f} {reader:>10s} "
                      f"{issues:>11s}", flush=True)
    print("model estimates: plan = fgc's accelerator plan (QR DSP: its QR units' operators); "
          "reader = the second reader's DSP of the emitted text (a lower bound); unit issues: "
          "the reader's II findings in fgc_qr_stream.h")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
