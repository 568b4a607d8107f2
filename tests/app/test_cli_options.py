"""Global and hardware options of the ``fgc`` command line: --version, -q/-v, derivation progress,
--clock/--part/--scalar (one clock for the cost model and run_hls.tcl), "model estimate" labels,
``fgc metrics``, and the one-call Python API ``fgc.solve`` / ``fgc.verify``.

GTSAM comparison (``fgc.verify``): float64 simulator within 1e-6 tangent distance of GTSAM's LM,
the same tolerance ``fgc verify`` applies.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.app.cli import derive_with_progress, main

ROOT = Path(__file__).resolve().parents[2]
BEACONS = str(ROOT / "examples" / "range_beacons.py")


def _beacons_graph():
    from fgc.app.specs import example

    range_beacons = example("range_beacons")
    return range_beacons.build(steps=8)


def test_version(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--version"])
    assert exc.value.code == 0
    assert capsys.readouterr().out.strip() == f"fgc {fgc.__version__}"


@pytest.mark.parametrize("argv", [["-q", "simulate", BEACONS], ["simulate", BEACONS, "-q"]])
def test_quiet_prints_only_the_result_line(argv, capsys):
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert out.count("\n") == 1 and out.startswith("fgc simulate: 22 variables, float32: "
                                                   "converged")


def test_quiet_verify_prints_the_verdict(capsys):
    assert main(["verify", BEACONS, "-q", "-p", "steps=8"]) == 0
    assert capsys.readouterr().out == f"fgc verify {BEACONS}: PASSED\n"


def test_verbose_adds_stage_timings_on_stderr_only(capsys):
    assert main(["simulate", BEACONS]) == 0
    plain = capsys.readouterr()
    assert main(["-v", "simulate", BEACONS]) == 0
    verbose = capsys.readouterr()
    assert verbose.out == plain.out  # stdout stays deterministic
    for stage in ("load spec", "compile", "simulate"):
        assert f"fgc: {stage}: " in verbose.err
    assert plain.err == ""


def test_progress_line_only_for_cold_derivations(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("FGC_CACHE_DIR", str(tmp_path / "cache"))

    @fgc.factor(name="CliProgressProbe")
    def probe(p: fgc.Point2, *, target: fgc.Point2):
        return p - target

    graph = fgc.Graph()
    graph.add_variable("p", fgc.Point2(1.0, 2.0))
    graph.add(probe("p", target=fgc.Point2(0.0, 0.0), noise=fgc.noise.isotropic(2, 1.0)))
    assert derive_with_progress(graph, show=True) == 1
    assert "fgc: deriving factor CliProgressProbe (1/1, not cached" in capsys.readouterr().err
    assert derive_with_progress(graph, show=True) == 0  # now cached: silent
    assert capsys.readouterr().err == ""


def test_quiet_never_shows_progress():
    from argparse import Namespace

    from fgc.app.cli import _show_progress

    assert not _show_progress(Namespace(quiet=True, verbose=0))
    assert _show_progress(Namespace(quiet=False, verbose=1))


def test_clock_reaches_the_cost_model_and_run_hls_tcl(tmp_path, capsys):
    assert main(["simulate", BEACONS, "--clock", "7ns", "--json", str(tmp_path / "s.json")]) == 0
    assert json.loads((tmp_path / "s.json").read_text())["clock_mhz"] == pytest.approx(1000 / 7)
    out = tmp_path / "hls"
    assert main(["compile", BEACONS, "--backend", "hls", "--out", str(out), "--clock", "200MHz",
                 "--part", "xczu9eg-ffvb1156-2-e", "--scalar", "double", "-q"]) == 0
    tcl = (out / "run_hls.tcl").read_text()
    assert "create_clock -period 5 -name default" in tcl
    assert "set_part {xczu9eg-ffvb1156-2-e}" in tcl
    program = json.loads((out / "program.json").read_text())
    assert program["solver"]["clock_mhz"] == 200.0
    assert program["solver"]["precision"] == "float64"  # implied by --scalar double
    assert "typedef double T;" in (out / "range_beacons.h").read_text()


def test_emit_takes_the_programs_clock_and_rejects_a_second_one(tmp_path):
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends import hls

    program = compile_graph(_beacons_graph(), SolverConfig(clock_mhz=200.0), name="beacons")
    with pytest.raises(hls.HlsConfigError, match=r"clock mismatch: .* 200 MHz .*clock_ns=7"):
        hls.emit(program, tmp_path, hls.HlsConfig(scalar="double", clock_ns=7.0))
    hls.emit(program, tmp_path, hls.HlsConfig(scalar="double", clock_ns=5.0))  # agrees
    # no period given: the Program's clock (SolverConfig.clock_mhz) is the design's
    hls.emit(program, tmp_path / "own", hls.HlsConfig(scalar="double"))
    assert "create_clock -period 5 " in (tmp_path / "own" / "run_hls.tcl").read_text()


@pytest.mark.parametrize("argv, needle", [
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--scalar", "ap_fixed<0,0>"],
     "width W=0"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--scalar", "ap_fixed<2000,10>"],
     "width W=2000"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--scalar", "ap_fixed<16,20>"],
     "integer bits I=20"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--scalar", "int"],
     "expected 'float', 'double' or 'ap_fixed<W,I>'"),
    (["simulate", BEACONS, "--clock", "5GHz"], "expected a frequency like 143MHz"),
    (["simulate", BEACONS, "--clock", "0"], "must be positive"),
    (["simulate", BEACONS, "--clock", "5000MHz"], "outside 1 MHz"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--part", "a;b"], "plain part name"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--scalar", "double",
      "--precision", "float32"], "--scalar double contradicts --precision float32"),
    (["compile", BEACONS, "--out", "x", "--scalar", "float"],
     "--scalar applies to --backend hls or native only"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--allocation", "mul=0"],
     "'mul=0': expected KIND=N"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--allocation", "fma=4"],
     "'fma=4': expected KIND=N with KIND one of add, mul"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--allocation", "mul=4,mul=8"],
     "mul is given twice"),
    (["compile", BEACONS, "--out", "x", "--allocation", "mul=4"],
     "--allocation applies to --backend hls only (not sim)"),
    (["compile", BEACONS, "--backend", "native", "--out", "x", "--unit-sets", "2"],
     "--unit-sets applies to --backend hls only (not native)"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--unit-sets", "9"],
     "unit_sets must be 1 … 8"),
    (["report", BEACONS, "--iterations", "1", "--scalar", "ap_fixed<32,16>"],
     "the HLS dataflow design is float or double only"),
    (["report", BEACONS, "--iterations", "1", "--unit-sets", "9"], "unit_sets must be 1 … 8"),
    (["report", BEACONS, "--iterations", "1", "--part", "xc9z999"], "fgc knows no capacities"),
    (["simulate", BEACONS, "--incremental", "3", "--allocation", "mul=4"],
     "--allocation shapes the batch design"),
    (["compile", BEACONS, "--backend", "native", "--out", "x", "--qr-unit", "stream"],
     "--qr-unit applies to --backend hls only (not native)"),
    (["simulate", BEACONS, "--incremental", "3", "--qr-unit", "stream"],
     "--qr-unit shapes the batch design"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--hgc-before"],
     "--hgc-before applies to Cholesky designs (--linear cholesky); a qr design has no HGC"),
    (["compile", BEACONS, "--backend", "native", "--out", "x", "--linear", "cholesky",
      "--hgc-before"], "--hgc-before applies to --backend hls only (not native)"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--linear", "cholesky",
      "--linear-precision", "float64", "--hgc-before"],
     "its HGC runs before the elimination already"),
    (["report", BEACONS, "--iterations", "1", "--hgc-before"],
     "--hgc-before applies to Cholesky designs"),
    (["simulate", BEACONS, "--incremental", "3", "--linear", "cholesky", "--hgc-before"],
     "--hgc-before shapes the batch design"),
    (["run", BEACONS, "--backend", "sim", "--window", "3", "--linear", "cholesky",
      "--hgc-before"], "--hgc-before shapes the batch Cholesky design"),
    (["compile", BEACONS, "--backend", "hls", "--out", "x", "--backsub-lanes", "3"],
     "'3': expected auto, 1, 2 or 4"),
    (["compile", BEACONS, "--backend", "native", "--out", "x", "--backsub-lanes", "2"],
     "--backsub-lanes applies to --backend hls only (not native)"),
    (["report", BEACONS, "--iterations", "1", "--backsub-lanes", "4"],
     "backsub_lanes 4 (back-substitution by columns"),
    (["simulate", BEACONS, "--incremental", "3", "--backsub-lanes", "2"],
     "--backsub-lanes shapes the batch design"),
    (["report", BEACONS, "--incremental", "3", "--backsub-lanes", "1"],
     "--backsub-lanes shapes the batch design"),
    (["run", BEACONS, "--backend", "sim", "--window", "3", "--backsub-lanes", "4"],
     "the stream's design (--window / --incremental) back-substitutes one lane"),
])
def test_bad_hardware_options_exit_2_with_one_line(argv, needle, capsys, tmp_path,
                                                   monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert needle in err and err.count("\n") == 1, err


def test_modelled_figures_are_labelled(capsys):
    assert main(["simulate", BEACONS]) == 0
    out = capsys.readouterr().out
    assert "accelerator (model estimate): " in out and "resources (model estimate): " in out
    assert main(["report", BEACONS, "--iterations", "3"]) == 0
    out = capsys.readouterr().out
    # the verdict either way (range_beacons no longer fits as issue 32 re-prices it)
    verdict = re.compile(r"(?:fits|does NOT fit) xc7z045.*\(model estimate\)")
    assert verdict.search(out)
    assert "Modelled cycles by phase (whole solve; model estimate, accelerator plan)" in out
    assert main(["report", BEACONS, "--iterations", "3", "-q"]) == 0
    line = capsys.readouterr().out
    assert line.count("\n") == 1 and verdict.search(line)
    assert line.rstrip().endswith("xc7z045 (model estimate)")


def _helix(n: int = 15):
    from fgc.frontend.geometry import Pose3, Rot3

    return [(0.1 * i, Pose3(Rot3.Expmap(np.array([0.1, -0.2, 0.4 * i])),
                            np.array([3 * np.cos(0.4 * i), 3 * np.sin(0.4 * i), 0.2 * i])))
            for i in range(n)]


def test_metrics_command(tmp_path, capsys):
    """EST is REF with every orientation turned by 10° about a fixed body axis and every
    position moved by (0.3, 0, 0.4) m: ATE 0.5 m and 10° at every pose without alignment."""
    from fgc.app.metrics import ate, read_tum, rpe, write_tum
    from fgc.frontend.geometry import Pose3, Rot3

    ref = _helix()
    turn = Rot3.Expmap(np.radians(10.0) * np.array([1.0, 0.0, 0.0])).R
    est = [(t, Pose3(Rot3(p.r.R @ turn), p.t + np.array([0.3, 0.0, 0.4]))) for t, p in ref]
    ref_f, est_f = write_tum(tmp_path / "ref.tum", ref), write_tum(tmp_path / "est.tum", est)
    out = tmp_path / "m.json"
    assert main(["metrics", str(est_f), str(ref_f), "--json", str(out)]) == 0
    text = capsys.readouterr().out
    assert "ATE translation [  m]  rmse 0.5 " in text and "ATE rotation    [deg]  rmse 10 " in text
    res = json.loads(out.read_text())
    assert res["ate_translation"]["rmse"] == pytest.approx(0.5, rel=1e-12)
    assert res["ate_rotation"]["max"] == pytest.approx(10.0, rel=1e-12)
    assert res["ate_rotation"]["unit"] == "deg"
    assert main(["metrics", str(est_f), str(ref_f), "--align", "sim3", "--delta", "2",
                 "--all-pairs", "--json", str(out), "-q"]) == 0
    assert capsys.readouterr().out.startswith("ATE translation")
    res = json.loads(out.read_text())
    e, r = read_tum(est_f), read_tum(ref_f)
    want = rpe(e, r, delta=2, align="sim3", all_pairs=True, relation="rotation")
    assert res["rpe_rotation"]["rmse"] == pytest.approx(want.rmse, rel=1e-12)
    assert res["ate_translation"]["rmse"] == pytest.approx(ate(e, r, align="sim3").rmse,
                                                           rel=1e-12)
    assert res["alignment"]["scale"] == pytest.approx(want.alignment.scale)


def test_metrics_bad_input(tmp_path, capsys):
    bad = tmp_path / "bad.tum"
    bad.write_text("0 1 2 3\n")
    assert main(["metrics", str(bad), str(bad)]) == 2
    err = capsys.readouterr().err
    assert "bad.tum" in err and err.count("\n") == 1


def test_one_call_solve_and_verify():
    graph = _beacons_graph()
    result = fgc.solve(graph)
    assert result.status == "converged"
    report = fgc.verify(graph)
    assert report["passed"] and report["max_state_error"] <= 1e-6
    assert result.final_error == pytest.approx(report["gtsam_final_error"], rel=1e-6)
    f32 = fgc.solve(graph, precision="float32", linear="cholesky")
    assert f32.status == "converged"
    with pytest.raises(fgc.FgcError, match="unknown solver option"):
        fgc.solve(graph, precisionn="float32")
    with pytest.raises(fgc.FgcError, match="backend must be"):
        fgc.solve(graph, backend="fpga")


@pytest.mark.heavy
def test_one_call_native_follows_the_program_clock():
    """``fgc.solve(..., backend="native")`` at a non-default clock builds the C++ with that
    clock (no clock-mismatch error) and matches the float64 simulator to 1e-9 relative."""
    graph = _beacons_graph()
    sim = fgc.solve(graph)
    native = fgc.solve(graph, backend="native", clock_mhz=200.0)
    assert native.status == "converged"
    assert native.final_error == pytest.approx(sim.final_error, rel=1e-9)


def test_allocation_and_unit_sets_shape_the_emitted_design(tmp_path):
    """--allocation sets the heaviest block type's ALLOCATION limits (the others get their
    instance share, kinds not named keep the defaults) and --unit-sets the QR unit sets; the
    emitted pragmas and processes are the plan's for that HlsConfig."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends import hls
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.network import allocations

    lio = str(ROOT / "examples" / "lio.py")
    out = tmp_path / "lio"
    assert main(["compile", lio, "-p", "N=5", "--backend", "hls", "--out", str(out),
                 "--units", "2", "--unit-sets", "1", "--allocation", "mul=48,add=32",
                 "-q"]) == 0
    kernel = (out / "lio.cpp").read_text()
    found = allocations(kernel)
    program = compile_graph(example("lio").build(N=5), SolverConfig(units=2), name="lio")
    config = hls.HlsConfig(allocation=(("mul", 48), ("add", 32)), unit_sets=1)
    plan = accel_plan(program, config)
    from fgc_backends.hls.units.special_ops import printed_counts  # the plan's counts
    heavy = max(range(len(program.blocks)), key=lambda i: sum(
        printed_counts(program.blocks[i], "jacobian").values())
        * sum(f.block == i for f in program.factors))
    from fgc_backends.hls.units.datapath import factor_allocation  # the emitted limits
    limits = dict(factor_allocation(program, plan.options)[heavy])
    assert limits["mul"] == 48 and limits["add"] == 32 and limits["div"] == 4  # div: default
    # the printed limit is the multipliers the datapath's loop binds at its II, at most the
    # option's 48 (the plan's rule); a limit below that binding is printed as the limit
    (mul,) = [n for kind, op, n in found[f"factor_{heavy}"] if op == "fmul"]
    assert 4 < mul <= 48
    tight = tmp_path / "tight"
    assert main(["compile", lio, "-p", "N=5", "--backend", "hls", "--out", str(tight),
                 "--units", "2", "--unit-sets", "1", "--allocation", "mul=4,add=32", "-q"]) == 0
    assert ("operation", "fmul", 4) in allocations((tight / "lio.cpp").read_text())[
        f"factor_{heavy}"]
    assert "qr0_update1" in kernel and "qr1_" not in kernel  # one unit set, n_u = 2
    two = accel_plan(program, hls.HlsConfig())
    assert dict(factor_allocation(program, two.options)[heavy])["mul"] == 24


def test_report_prices_the_design_compile_emits(tmp_path, capsys):
    """fgc report / simulate with --scalar, --part, --allocation and --unit-sets price the plan
    of the design fgc compile --backend hls emits with the same flags (emitter.accel_plan)."""
    import json

    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends import hls
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.plan import plan_cost

    lio = str(ROOT / "examples" / "lio.py")
    flags = ["-p", "N=5", "--units", "2", "--iterations", "2"]
    design = ["--scalar", "double", "--unit-sets", "1", "--allocation", "mul=48,add=32",
              "--part", "xc7z020clg400-1"]
    assert main(["report", lio, *flags, "--json", str(tmp_path / "d.json"), "-q"]) == 0
    assert main(["report", lio, *flags, *design, "--json", str(tmp_path / "r.json"), "-q"]) == 0
    assert "does NOT fit xc7z020" in capsys.readouterr().out
    default = json.loads((tmp_path / "d.json").read_text())["cost"]
    priced = json.loads((tmp_path / "r.json").read_text())["cost"]
    program = compile_graph(example("lio").build(N=5),
                            SolverConfig(units=2, precision="float64"), name="lio")
    plan = accel_plan(program, hls.HlsConfig(scalar="double", unit_sets=1,
                                             allocation=(("mul", 48), ("add", 32)),
                                             part="xc7z020clg400-1"))
    cost = plan_cost(plan)
    assert priced["cycles"] == 2 * cost.cycles and priced["resources"]["dsp"] == cost.dsp
    assert priced["device"] == "xc7z020" and not priced["fits"]
    assert priced["cycles"] != default["cycles"] and priced["resources"] != default["resources"]


# heavy (about 25 s of CPU: three compiles and four reports of LIO): the width's plan and C
# simulation stay in the default run (tests/hls/test_plan.py, test_hls_csim.py,
# test_units_backsub.py), the CLI's pricing of a design in
# test_report_prices_the_design_compile_emits
@pytest.mark.heavy
def test_backsub_lanes_auto_by_default_and_as_given(tmp_path, capsys):
    """--backsub-lanes: auto (the default) is the design's automatic width, by columns on a
    chain (LIO N = 5), and fgc report prices and names that width; an explicit width is emitted
    and priced as given (byte-identical to emit with that HlsConfig)."""
    import json

    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends import hls
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.plan import plan_cost

    lio = str(ROOT / "examples" / "lio.py")
    flags = ["-p", "N=5", "--linear", "cholesky", "--precision", "float32", "-q"]
    for name, extra in (("default", []), ("auto", ["--backsub-lanes", "auto"]),
                        ("one", ["--backsub-lanes", "1"])):
        assert main(["compile", lio, *flags, "--backend", "hls", "--out",
                     str(tmp_path / name), *extra]) == 0
        assert main(["report", lio, *flags, "--iterations", "1", *extra, "--json",
                     str(tmp_path / f"{name}.json")]) == 0
    kernel = {n: (tmp_path / n / "lio.cpp").read_text() for n in ("default", "auto", "one")}
    assert kernel["default"] == kernel["auto"] and "#define FGC_BS_COLUMNS 1" in kernel["auto"]
    assert "FGC_BS_COLUMNS" not in kernel["one"]
    program = compile_graph(example("lio").build(N=5), SolverConfig(
        linear="cholesky", precision="float32"), name="lio")
    hls.emit(program, tmp_path / "api", hls.HlsConfig(scalar="float", backsub_lanes=1))
    assert (tmp_path / "api" / "lio.cpp").read_text() == kernel["one"]
    cost = {n: json.loads((tmp_path / f"{n}.json").read_text())["cost"]
            for n in ("default", "one")}
    assert cost["default"]["backsub_lanes"] == 4 and cost["one"]["backsub_lanes"] == 1
    for n, lanes in (("default", None), ("one", 1)):
        plan = accel_plan(program, hls.HlsConfig(scalar="float", backsub_lanes=lanes))
        assert cost[n]["iteration_cycles"] == plan_cost(plan).cycles
    assert cost["default"]["iteration_cycles"] < cost["one"]["iteration_cycles"]
    assert main(["report", lio, *flags[:-1], "--iterations", "1"]) == 0
    out = capsys.readouterr().out
    assert "back-substitution by columns, a process per end of the chain (backsub_lanes 4" \
        in out


def test_hgc_before_emits_and_prices_the_design_without_the_beside(tmp_path, capsys):
    """--hgc-before is DesignOptions.hgc_beside off: fgc compile emits the Cholesky design whose
    HGC regions all run before the elimination (byte-identical to emit with that HlsConfig, no
    cholesky_eliminate_beside), and fgc report prices that design's plan, not the default's."""
    import json

    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc.ir.program import SolverConfig
    from fgc_backends import hls
    from fgc_backends.hls.emitter import accel_plan
    from fgc_backends.hls.plan import plan_cost

    flags = ["--linear", "cholesky", "-q"]
    for name, extra in (("beside", []), ("before", ["--hgc-before"])):
        assert main(["compile", BEACONS, *flags, "--backend", "hls", "--out",
                     str(tmp_path / name), *extra]) == 0
        assert main(["report", BEACONS, *flags, "--iterations", "1", *extra, "--json",
                     str(tmp_path / f"{name}.json")]) == 0
    kernel = {n: (tmp_path / n / "range_beacons.cpp").read_text() for n in ("beside", "before")}
    assert "cholesky_eliminate_beside" in kernel["beside"]
    assert "cholesky_eliminate_beside" not in kernel["before"]
    program = compile_graph(example("range_beacons").build(), SolverConfig(linear="cholesky"),
                            name="range_beacons")
    hls.emit(program, tmp_path / "direct", hls.HlsConfig(hgc_beside=False))
    assert (tmp_path / "direct" / "range_beacons.cpp").read_text() == kernel["before"]
    cost = {n: json.loads((tmp_path / f"{n}.json").read_text())["cost"]
            for n in ("beside", "before")}
    for name, beside in (("beside", True), ("before", False)):
        plan = accel_plan(program, hls.HlsConfig(hgc_beside=beside))
        assert any(ph.name == "hgc_beside" for ph in plan.phases) == beside
        assert cost[name]["cycles"] == plan_cost(plan).cycles
    assert cost["before"]["cycles"] != cost["beside"]["cycles"]
