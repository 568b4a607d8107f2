"""LM's path on one problem, simulator against C simulation, try by try (fgc issue 33: "C
simulation = simulator on every example" and an honest per-solve latency).

Paper B's problem (imu_window N = 50, LM, Cholesky) in float32 takes 14 iterations in the
simulator and 42 linearisations with 47 retries in the C simulation of the design paper B's row
prices (#CPE 20, two cascades). This bench shows where the two paths part and why:

1. both runs traced: each linearisation (cost, μ) and each try (μ, not positive definite, or
   ‖δ‖, predicted decrease, trial cost, accepted or not). The trace lines are printed by copies
   of the emitted files (the simulator's ``fgc_sim_optimizer.py`` / ``fgc_sim_linear.py``, the
   design's ``include/fgc_lm.h`` / ``include/fgc_cpe.h``) with ``fprintf``/``print`` lines added
   in this bench's temporary folder; fgc's sources and the emitted design are not changed, and
   each insertion must match its anchor or the bench stops;
2. the first solve at the initial values, (H + μI) δ = g at μ = 10 and 1 from the simulator's
   float32 rows: in float64, in float32, and in float32 from rows moved by at most one ulp
   (what a different rounding of the factor kernels gives): how much float32 rounding alone
   moves δ, and whether the root step stays positive definite;
3. the final states against the float64 optimum (the simulator's float64 QR solve) and each
   other: largest position and rotation distance, and the remaining whitened step in σ.

    python bench/bench_solve_path.py                     # N = 50, #CPE 20 x2 (about 3 min)
    python bench/bench_solve_path.py --n 20 --cpe 5 --sets 1
    python bench/bench_solve_path.py --linear-precision float64   # the mixed design
"""

from __future__ import annotations

import argparse
import contextlib
import io
import runpy
import subprocess
import sys
import tempfile
import warnings
from pathlib import Path

import numpy as np

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.datafile import problem_data, write_data
from fgc.ir.program import SolverConfig
from fgc_backends.cfamily.results import keyed, read_result
from fgc_backends.hls import HlsConfig
from fgc_backends.hls import emit as hls_emit
from fgc_backends.sim.emitter import emit as sim_emit
from fgc_backends.sim.runner import remaining_step, run

imu_window = example("imu_window")


def _insert(path: Path, anchor: str, text: str, before: bool = False) -> None:
    """Put ``text`` after (or before) the one occurrence of ``anchor`` in ``path``."""
    source = path.read_text()
    if source.count(anchor) != 1:
        raise SystemExit(f"bench_solve_path: {path.name} changed: the anchor {anchor!r} "
                         f"occurs {source.count(anchor)} times (once expected)")
    path.write_text(source.replace(anchor, text + anchor if before else anchor + text))


# ---- the simulator, traced -------------------------------------------------------------------

SIM_LIN = '''
        print(f"LIN {it} {float(cost)!r} {float(mu)!r}", file=__import__("sys").stderr)'''
SIM_TRY = '''
            print(f"TRY {float(mu)!r} {float(numpy.linalg.norm(delta))!r} {predicted!r} "
                  f"{float(new)!r}", file=__import__("sys").stderr)'''
SIM_NPD = '''
            print(f"NPD {mu!r} {st.index} {exc.column}", file=__import__("sys").stderr)'''


def sim_trace(program, data, folder: Path) -> tuple[list[str], dict]:
    """The emitted simulator's run on ``data`` with trace lines; (lines, result dict)."""
    files = sim_emit(program, folder)
    write_data(data, folder / "data.txt")
    opt, lin = folder / "fgc_sim_optimizer.py", folder / "fgc_sim_linear.py"
    _insert(opt, '\n        band = max(limits["resolution"] * cost, noise)', SIM_LIN)
    _insert(opt, "\n            new = problem.cost(x_new)", SIM_TRY)
    _insert(lin, "\n        except NotPositiveDefinite as exc:", SIM_NPD)
    done = subprocess.run([sys.executable, str(files[0]), "data.txt", "result.json"],
                          cwd=folder, capture_output=True, text=True, check=True)
    import json
    return done.stderr.splitlines(), json.loads((folder / "result.json").read_text())


# ---- the C simulation, traced ----------------------------------------------------------------

CS_LIN = '''
        std::fprintf(stderr, "LIN %d %.9g %.9g\\n", it, (double)cost, (double)mu[0]);'''
CS_TRY = '''
            std::fprintf(stderr, "TRY %.9g %.9g %.9g %.9g\\n", (double)mu[0],
                         (double)CFG::root(d2), (double)predicted, (double)trial);'''
CS_FAIL = '''
        if (!solved) std::fprintf(stderr, "NPD %.9g\\n", (double)mu[0]);'''


def csim_trace(program, data, config: HlsConfig, folder: Path) -> tuple[list[str], Path]:
    """The emitted design's C simulation on ``data`` with trace lines; (lines, result file)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # designs over the part still simulate
        project = hls_emit(program, folder, config)
    write_data(data, folder / "data.txt")
    lm = folder / "include" / "fgc_lm.h"
    _insert(lm, "namespace fgc_lm {", "#include <cstdio>\n", before=True)
    _insert(lm, "\n        ++it;", CS_LIN)
    _insert(lm, "\n            const T trial = CFG::cost_trial();", CS_TRY)
    _insert(lm, "\n        if (!solved && !(mu[0] > T(0))) return", CS_FAIL, before=True)
    name = project.name
    subprocess.run(["g++", "-std=c++17", "-O2", "-ffp-contract=off", "-Wno-unknown-pragmas",
                    "-I", "csim_include", "-I", "include", f"tb_{name}.cpp", f"{name}.cpp",
                    "-o", "tb_trace"], cwd=folder, check=True)
    done = subprocess.run(["./tb_trace", "data.txt", "result.txt"], cwd=folder,
                          capture_output=True, text=True, check=True)
    return done.stderr.splitlines(), folder / "result.txt"


# ---- the two traces side by side -------------------------------------------------------------

def iterations(lines: list[str]) -> list[dict]:
    """Per linearisation: cost, μ at its start, the tries (μ, 'npd' or (‖δ‖, predicted,
    trial))."""
    out: list[dict] = []
    for line in lines:
        word, *rest = line.split()
        if word == "LIN":
            out.append({"it": int(rest[0]), "cost": float(rest[1]), "mu": float(rest[2]),
                        "tries": []})
        elif word == "TRY" and out:
            mu, d, pred, trial = map(float, rest)
            out[-1]["tries"].append((mu, (d, pred, trial)))
        elif word == "NPD" and out:
            out[-1]["tries"].append((float(rest[0]), "npd"))
    return out


def _tries(its: list[dict], k: int) -> str:
    if k >= len(its):
        return ""
    parts = []
    for mu, what in its[k]["tries"]:
        parts.append(f"μ={mu:g} npd" if what == "npd"
                     else f"μ={mu:g} |δ|={what[0]:.3g} → {what[2]:.4g}")
    return f"{its[k]['cost']:.6g}: " + ", ".join(parts or ["(stopped)"])


def side_by_side(sim: list[dict], csim: list[dict]) -> None:
    print(f"{'it':>3}  {'simulator: cost at X: tries (μ, |δ| → trial cost)':60} C simulation")
    for k in range(max(len(sim), len(csim))):
        print(f"{k + 1:3d}  {_tries(sim, k):60} {_tries(csim, k)}")
    for name, its in (("simulator", sim), ("C simulation", csim)):
        npd = sum(what == "npd" for it in its for _, what in it["tries"])
        tried = sum(what != "npd" for it in its for _, what in it["tries"])
        print(f"{name}: {len(its)} linearisations, {npd + tried} solves, {npd} of them not "
              f"positive definite (LM grows μ), {tried} trial steps")


# ---- the first solve under float32 rounding --------------------------------------------------

def first_solve(folder: Path, mus=(10.0, 1.0), samples: int = 6, seed: int = 1) -> None:
    """(H + μI) δ = g at the initial values from the simulator's float32 rows: float64 solve,
    float32 solve, and float32 solves of rows each moved by at most one ulp."""
    module = next(folder.glob("*_sim.py"))
    sys.path.insert(0, str(folder))
    try:
        ns = runpy.run_path(str(module), run_name="bench_solve_path")
    finally:
        sys.path.remove(str(folder))
    lib, spec = ns["LIB"], ns["PROBLEM"]
    problem = lib.optimizer.Problem(spec, lib.runtime.read_data(str(folder / "data.txt"),
                                                                spec["structure"]),
                                    "float32", lib)
    abs_, _, _ = problem.linearize(problem.x0)
    flat = np.concatenate([ab.reshape(-1) for ab in abs_])

    def solve(rows, mu):
        try:  # (the copy's trace lines are not this part's: they go nowhere)
            with contextlib.redirect_stderr(io.StringIO()):
                conds = lib.linear.eliminate(problem.plan, rows, mu, "cholesky")
        except lib.linear.SingularError as exc:
            return None, str(exc)
        return lib.linear.back_substitute(problem.plan, spec["back_substitution"], conds,
                                          problem.n, rows.dtype).astype(np.float64), ""

    rng = np.random.default_rng(seed)
    moved = []
    for _ in range(samples):
        step = rng.integers(-1, 2, size=flat.size).astype(np.float32)
        moved.append((flat + step * np.spacing(flat)).astype(np.float32))
    print("\nthe first solve at the initial values, (H + μI) δ = g from the simulator's float32 "
          "rows [J | r]:")
    for mu in mus:
        ref, why = solve(flat.astype(np.float64), mu)
        if ref is None:
            print(f"  μ={mu:g}: float64 solve singular ({why})")
            continue
        line = [f"  μ={mu:g}: float64 |δ| {np.linalg.norm(ref):.4f}; float32"]
        for k, rows in enumerate([flat, *moved]):
            d, _ = solve(rows, mu)
            tag = "" if k == 0 else f" 1-ulp #{k}"
            if d is None:
                line.append(f"{tag} not PD")
                continue
            off = np.linalg.norm(d - ref) / np.linalg.norm(ref)
            line.append(f"{tag} |δ| {np.linalg.norm(d):.4f} ({off:.0%} off)")
        print(",".join(line))


# ---- the answers -----------------------------------------------------------------------------

def _distance(a: dict, b: dict) -> tuple[float, float]:
    """Largest position distance (m) and rotation angle (rad) over the Pose3 variables."""
    dp = dr = 0.0
    for key, v in a.items():
        w = b[key]
        if hasattr(v, "t") and hasattr(v, "r"):
            dp = max(dp, float(np.linalg.norm(np.asarray(v.t) - np.asarray(w.t))))
            rel = np.asarray(v.r.R).T @ np.asarray(w.r.R)
            dr = max(dr, float(np.arccos(np.clip((np.trace(rel) - 1) / 2, -1, 1))))
    return dp, dr


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=50)
    ap.add_argument("--cpe", type=int, default=20)
    ap.add_argument("--sets", type=int, default=2, help="cascades side by side (1 or 2)")
    ap.add_argument("--linear-precision", default=None, choices=(None, "float64"),
                    help="float64: the mixed design (float32, a float64 linear solver)")
    args = ap.parse_args(argv)
    graph = imu_window.build(N=args.n)
    solver = SolverConfig(method="lm", linear="cholesky", cpe=args.cpe, precision="float32",
                          linear_precision=args.linear_precision)
    program = compile_graph(graph, solver, name="path")
    data = problem_data(graph, program)
    config = HlsConfig(scalar="float", unit_sets=args.sets if args.sets > 1 else None)
    tmp = Path(tempfile.mkdtemp(prefix="fgc-path-"))
    (tmp / "sim").mkdir()
    sim_lines, sim_result = sim_trace(program, data, tmp / "sim")
    cs_lines, cs_file = csim_trace(program, data, config, tmp / "hls")
    print(f"imu_window N={args.n} LM Cholesky float32"
          + (" (float64 linear solver)" if args.linear_precision else "")
          + f", #CPE {args.cpe} x{args.sets} ({tmp})")
    side_by_side(iterations(sim_lines), iterations(cs_lines))
    if not args.linear_precision:
        first_solve(tmp / "sim")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        qr = compile_graph(graph, SolverConfig(method="lm", linear="qr", precision="float64"),
                           name="path")
        optimum = run(qr, problem_data(graph, qr))
        sim = run(program, data)
    raw = read_result(cs_file, program, data, "float")
    cs = keyed(raw, program)
    print(f"\nthe answers (float64 optimum: simulator, float64 QR, {optimum.iterations} "
          f"iterations, cost {optimum.final_error:.3g}):")
    for name, res, storage in (("simulator", sim, sim.storage),
                               ("C simulation", cs, dict(raw.values))):
        dp, dr = _distance(optimum.user_values, res.user_values)
        sig = remaining_step(program, data, storage)
        print(f"  {name:13} {res.status} ({res.reason}) after {res.iterations} iterations, "
              f"cost {res.final_error:.4g}: {dp * 100:.2f} cm / {dr * 1e3:.2f} mrad from the "
              f"optimum, remaining step {sig:.3f} σ")
    dp, dr = _distance(sim.user_values, cs.user_values)
    print(f"  C simulation against the simulator: {dp * 100:.2f} cm / {dr * 1e3:.2f} mrad "
          "(issue 33's bound: 1 cm / 1 mrad)")
    if sim.warnings:
        print("  simulator: " + "; ".join(sim.warnings))


if __name__ == "__main__":
    main()
