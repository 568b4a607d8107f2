"""Paper B's scaling from 5 to 80 CPEs (issue 33 item 4) by the plan: imu_window N = 50, LM,
float32 at 143 MHz, back-substitution by columns (the default on a chain).

    python bench/bench_flight.py                 # #CPE 5 ... 120, one and two cascades (x2 C:
                                                 # hgc_third_lane), one and
                                                 # two words a cycle: cycles / iteration, DSP,
                                                 # BRAM36, fits; the 5 -> 80 CPEs ratios
    python bench/bench_flight.py --pieces        # #CPE 40 x2 L2 with the third Gram lane and
                                                 # steps in flight (what-if)

The what-if piece is the plan's arithmetic with a term replaced, not a design that is built:
``flight`` (a step enters its cascade as the first Schur-complement row of the step before on the
same end leaves that step's last pivot: the cascade's share of a region the interval, rows
0 ... f - 1 plus the f pivots' depth, not the whole round). Built since: the grams process
storing the two steps' first Grams side by side (fgc_cascades.h's cholesky_set_firsts) and the
HGC's third entries lane with two cascades (units/cholesky.py's gram_third: the IMU Grams at
the datapath's pace, 166 words an instance instead of 248)."""

from __future__ import annotations

import argparse
from dataclasses import replace

import fgc_backends.hls.units.cholesky as ch
from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig
from fgc_backends.hls.emitter import accel_plan
from fgc_backends.hls.plan import plan_cost
from fgc_backends.hls.plan.model import Loop

N = 50


def design(cpe: int, sets: int, lanes: int, third: bool = False):
    program = compile_graph(example("imu_window").build(N=N), SolverConfig(
        method="lm", linear="cholesky", cpe=cpe, precision="float32"), name=f"iw{cpe}")
    return plan_cost(accel_plan(program, HlsConfig(scalar="float", unit_sets=sets,
                                                   cascade_lanes=lanes, hgc_third_lane=third)))


def what_if(pieces: set[str]) -> None:
    """Replace the plan's terms named by ``pieces`` (module docstring) in units/cholesky.py."""
    cascades = ch.cascades_phases

    def phases(tables, order, dims, cpe, ops, timing, lanes=1, cond_banks=1,
               staged=frozenset()):
        out = []
        for ph in cascades(tables, order, dims, cpe, ops, timing, lanes, cond_banks, staged):
            procs = []
            for p in ph.processes:
                if "flight" in pieces and p.name.startswith("cascade"):
                    f, sep = dims[int(p.name[len("cascade"):])]
                    w = f + sep
                    if f <= cpe:  # one round: the next step after rows 0 ... f - 1, f pivots
                        waits = sum(ch.cpe_wait(q, w, ops, lanes) for q in range(f))
                        gap = (ch.cpe_vecs(0, w, lanes) - ch.cpe_vecs(f, w, lanes)
                               + ch.cpe_round_depth(f, cpe, ops, waits))
                        gap = max(gap, ch.cpe_vecs(0, w, lanes) + 1)
                        p = replace(p, loops=(p.loops[0], Loop("flight", 1, 1, gap)))
                procs.append(p)
            out.append(replace(ph, processes=tuple(procs)))
        return out

    ch.cascades_phases = phases


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pieces", action="store_true", help="the what-if pieces at #CPE 40 x2")
    args = ap.parse_args()
    if args.pieces:
        base = {"cpe": 40, "sets": 2, "lanes": 2}
        saved = ch.cascades_phases
        for pieces in [(), ("third",), ("flight",), ("third", "flight")]:
            what_if(set(pieces))
            cost = design(**base, third="third" in pieces)
            print(f"{'+'.join(pieces) or 'as built':24s} #CPE 40 x2 L2 {cost.cycles:7,d} cycles "
                  f"{88584 / cost.cycles:.2f}x the default #CPE 5 x1, {cost.dsp:,d} DSP",
                  flush=True)
            ch.cascades_phases = saved
        return
    table = {}
    for lanes in (1, 2):
        for cpe in (5, 20, 40, 80, 120):
            for sets, third in ((1, False), (2, False), (2, True)):
                cost = design(cpe, sets, lanes, third)
                table[cpe, sets + third, lanes] = cost
                print(f"#CPE {cpe:3d} x{sets}{' C' if third else '  '} L{lanes}: "
                      f"{cost.cycles:7,d} cycles, "
                      f"{cost.dsp:5,d} DSP, {cost.bram36:6.1f} BRAM36, "
                      f"{'fits' if cost.fits else 'over: ' + ','.join(cost.over)}", flush=True)
    default5 = table[5, 1, 1].cycles
    for lanes in (1, 2):
        for sets, cpe in ((1, 80), (2, 40), (3, 40)):
            c = table[cpe, sets, lanes].cycles
            same = table[5, 1, lanes].cycles
            name = "x2 + the third Gram lane" if sets == 3 else f"x{sets}"
            print(f"80 CPEs as #CPE {cpe} {name} L{lanes}: {default5 / c:.2f}x the default "
                  f"#CPE 5 x1 ({default5:,d}), {same / c:.2f}x #CPE 5 x1 L{lanes} ({same:,d})")


if __name__ == "__main__":
    main()
