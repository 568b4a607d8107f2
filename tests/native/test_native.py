"""The native backend (``fgc_backends.native``): the solver as a CPU program, built on this
machine with ``-O3 -march=native`` but no FMA and called through ctypes.

- its project is a CPU program: kernel, header, C entry points and Makefile, no testbench and no
  synthesis script; ``fgc compile --backend native`` and ``fgc run --backend native`` use it;
- its library meets the simulator's numbers to 1e-9 in double, as the HLS C simulation does (two
  different programs since the HLS backend emits its dataflow design);
- the build holds no fused multiply-add (the Makefile's objdump check);
- bad options and bad arrays are refused with clear errors.
"""

from __future__ import annotations

import json
import platform
import re
import runpy
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from fgc.app.cli import main
from fgc.compile import compile_graph
from fgc.errors import DataError
from fgc.ir.datafile import problem_data, write_data
from fgc.ir.program import SolverConfig
from fgc_backends import native, sim
from fgc_backends.native import NativeConfig, NativeConfigError, NativeSolver

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "hls"))

from test_hls_csim import (  # noqa: E402
    CASES,
    F64_TOL,
    _check_against_reference,
    case_params,
    relative_worst,
    robust_chain,
)

from fgc.app.specs import example  # noqa: E402

lio = example("lio")
pose_graph = example("pose_graph")

BEACONS = str(ROOT / "examples" / "range_beacons.py")


def _program(name: str, case):
    build, linear, scalar, *wide = case
    graph = build()
    solver = SolverConfig(linear=linear, precision="float32" if wide else "float64",
                          linear_precision=wide[0] if wide else None)
    program = compile_graph(graph, solver, name=name)
    return program, problem_data(graph, program), scalar


# imu_window (float QR) and pose3example (double QR; lio keeps double QR) are heavy: ~25 s each
@pytest.mark.parametrize("name", case_params(("imu_window", "pose3example")))
def test_native_library_gives_the_csim_numbers(name, tmp_path):
    """The native CPU program and the accelerator's C simulation are different programs (SIMD
    lanes and step patterns against the dataflow units): both meet the simulator's numbers to
    the precision's tolerance on the same cases, so each other's. The C simulation's half is
    tests/hls/test_hls_csim.py's test_csim_matches_the_simulator (same CASES, same check): built
    here again it only cost time."""
    program, data, scalar = _program(name, CASES[name])
    reference = sim.run(program, data, precision="float64")
    project = native.emit(program, tmp_path / "native", NativeConfig(scalar=scalar))
    native.make(project)
    result = NativeSolver.load(program, project).run(data)
    _check_against_reference(name, program, result, reference, scalar)


def test_native_run_api_builds_once_and_agrees():
    graph = pose_graph.build()
    program = compile_graph(graph, SolverConfig(linear="qr"), name="w100_native")
    data = problem_data(graph, program)
    first = native.run(program, data)
    assert native.load(program) is native.load(program)  # cached per content hash
    reference = sim.run(program, data, precision="float64")
    assert relative_worst(first.storage, reference.storage) <= F64_TOL
    assert type(first.values["x1"]) is type(reference.values["x1"])  # geometry, as sim's
    # solve() on flat arrays: the results are new arrays each call (the library writes into
    # the solver's own buffers), and arrays the kernel would misread are refused
    solver = native.load(program)
    x, d = solver.flatten(data)
    out1, errors1, info1 = solver.solve(x, d)
    out2, _, _ = solver.solve(x + 0.0, d)
    assert out1 is not out2 and not np.shares_memory(out1, out2)
    np.testing.assert_array_equal(out1, out2)
    np.testing.assert_array_equal(out1, np.concatenate([first.storage[k.key] for k in
                                                        program.variables]))
    assert errors1[1] == first.final_error and info1[0] == first.iterations
    for bad, what in [(x[:-1], "x"), (x.astype(np.float32), "x"), (d[::2], "factor data"),
                      (list(d), "factor data")]:
        args = (bad, d) if what == "x" else (x, bad)
        with pytest.raises(DataError, match=f"{what} must be a C-contiguous float64 array"):
            solver.solve(*args)


def _sim_problem(program, data, folder):
    """The emitted simulator's Problem for ``data`` in float64 (its cost and linearize)."""
    files = sim.emit(program, folder)
    write_data(data, folder / "data.txt")
    ns = runpy.run_path(str(files[0]), run_name="fgc_sim_probe")
    lib = ns["LIB"]
    return lib.optimizer.Problem(ns["PROBLEM"], lib.runtime.read_data(str(folder / "data.txt")),
                                 "float64", lib)


@pytest.mark.parametrize("case", ["robust", "lio"])
def test_cost_and_rounding_noise_match_the_simulator(case, tmp_path):
    """The kernel's cost and its rounding noise (the band try_steps grants a step that does not
    lower the cost) against the simulator's at the initial values and at a random point near
    them: every noise kind and robust loss (robust chain), the fused IMU block with its constant
    tail rows (LIO). 1e-10 relative: the two sum in different orders."""
    graph = robust_chain() if case == "robust" else lio.build(N=10)
    program = compile_graph(graph, SolverConfig(linear="cholesky"), name=f"probe_{case}")
    data = problem_data(graph, program)
    solver = native.load(program)
    problem = _sim_problem(program, data, tmp_path)
    x0, d = solver.flatten(data)
    rng = np.random.default_rng(11)
    tangent = 1e-3 * rng.standard_normal(problem.n)
    for x in (x0, problem.retract(x0, tangent)):
        cost, band = solver.probe(np.ascontiguousarray(x), d)
        _, _, noise_sim = problem.linearize(x)
        assert cost == pytest.approx(float(problem.cost(x)), rel=1e-10)
        assert band == pytest.approx(noise_sim, rel=1e-10)
        assert 0 < band < 1e-9 * cost  # float64 rounding of x moves the cost by a few ulp


def _disassembly(library: Path) -> str:
    return subprocess.run(["objdump", "-d", str(library)], capture_output=True, text=True,
                          check=True).stdout


@pytest.mark.skipif(platform.machine() not in ("x86_64", "AMD64") or not shutil.which("objdump"),
                    reason="the fused multiply-add check is for x86 builds")
def test_native_build_holds_no_fused_multiply_add(tmp_path, monkeypatch):
    """The Makefile checks the native library for fused multiply-adds (GCC 12 emits vfmaddsub
    under AVX-512 whatever -mno-fma says) and builds it again without AVX-512 if it has any;
    a library that still has them is refused. FUSED (the pattern checked for) is set here to
    one the first build matches, to take both branches on any x86 host. Built with the
    project's own flags (-O3: the vectoriser's code), not the suite's -O0 (tests/conftest.py)."""
    monkeypatch.delenv("FGC_NATIVE_FLAGS", raising=False)
    graph = robust_chain()
    program = compile_graph(graph, SolverConfig(linear="qr"), name="fused")
    project = native.emit(program, tmp_path / "p", NativeConfig(scalar="double"))
    library = project.library
    assert library == project.directory / "libfused.so"
    native.make(project)
    assert not re.search(r"\bvfn?m(add|sub)", _disassembly(library))
    wide = "avx512f" in Path("/proc/cpuinfo").read_text()
    # every AVX-512 build uses zmm registers; the build again without AVX-512 none
    again = subprocess.run(["make", "-s", "-B", "native", r"FUSED=%zmm"], cwd=project.directory,
                           capture_output=True, text=True, check=True)
    assert ("built again with -mno-avx512f" in again.stdout) == wide, again.stdout
    assert "%zmm" not in _disassembly(library)
    data = problem_data(graph, program)
    solved = NativeSolver.load(program, project).run(data)
    reference = sim.run(program, data, precision="float64")
    assert abs(solved.final_error - reference.final_error) <= \
        F64_TOL * max(1.0, reference.final_error)
    # a pattern every build matches (any VEX instruction): refused, and no library is left
    refused = subprocess.run(["make", "-s", "-B", "native", r"FUSED=\bv[a-z]"],
                             cwd=project.directory, capture_output=True, text=True, check=False)
    assert refused.returncode != 0
    assert "still holds fused multiply-adds" in refused.stdout + refused.stderr
    assert not library.exists()


# what `fgc run examples/range_beacons.py --backend native --json` returned before the native
# solver became its own backend (float32, the default; x86-64 with AVX-512: the lanes and the
# vector width do not change the numbers); x19 since a norm's derivative is x / |x| (GTSAM's
# norm2, issue 34 item 5) instead of x · |x|⁻¹: float32 rounding, 1e-6 m
BEFORE_SPLIT = {"final_error": 12.30312728881836, "iterations": 4, "reason": "step",
                "status": "converged", "x19": [10.125077247619629, 12.728758811950684,
                                               -0.3288435637950897, 0.9443843364715576],
                "b1": [-4.999850749969482, 7.999110221862793]}


def test_native_project_is_a_cpu_program_and_fgc_run_is_unchanged(tmp_path, capsys):
    """``fgc compile --backend native`` writes a CPU program (no testbench, no tcl, no csim
    target; the HLS project no longer carries the native wrapper), and ``fgc run --backend
    native`` returns exactly what it returned before the split."""
    nat, hw = tmp_path / "native", tmp_path / "hls"
    assert main(["compile", BEACONS, "--backend", "native", "--out", str(nat), "-q"]) == 0
    assert main(["compile", BEACONS, "--backend", "hls", "--out", str(hw), "-q"]) == 0
    assert sorted(p.name for p in nat.iterdir()) == [
        "Makefile", "data.txt", "include", "native_range_beacons.cpp", "program.json",
        "range_beacons.cpp", "range_beacons.h"]
    assert sorted(p.name for p in (nat / "include").iterdir()) == ["fgc_lm.h"]  # shared LM
    assert "native_range_beacons.cpp" not in {p.name for p in hw.iterdir()}
    makefile = (nat / "Makefile").read_text()
    assert "csim" not in makefile and "tb_" not in makefile and "native:" in makefile
    assert "A CPU program, not a hardware design" in (nat / "range_beacons.cpp").read_text()
    assert "A CPU program" not in (hw / "range_beacons.cpp").read_text()
    capsys.readouterr()
    out = tmp_path / "run.json"
    code = main(["run", BEACONS, "--backend", "native", "--json", str(out)])
    line = capsys.readouterr().out
    # the final error evaluated in float64 at the returned state, the float32 design's own
    # figure (unchanged by the split) beside it
    assert line.startswith(f"fgc run {BEACONS} (native): converged (step), 4 iterations, final "
                           "error 12.30312667 ")
    assert "the float32 design's own figure 12.30312729)" in line
    report = json.loads(out.read_text())
    assert code == 0 and report["backend"] == "native"
    for field in ("final_error", "iterations", "reason", "status"):
        assert report[field] == BEFORE_SPLIT[field], field
    for key in ("x19", "b1"):
        assert report["values"][key]["value"] == BEFORE_SPLIT[key], key


@pytest.mark.parametrize("argv, needle", [
    (["run", BEACONS, "--part", "xc7z020clg400-1"], "--part applies to fgc compile --backend hls"),
    (["compile", BEACONS, "--backend", "native", "--out", "x", "--part", "xc7z020clg400-1"],
     "--part applies to fgc compile --backend hls"),
    (["run", BEACONS, "--backend", "sim", "--scalar", "double"],
     "--scalar applies to --backend native or hls"),
])
def test_hardware_options_the_native_backend_has_none_of(argv, needle, capsys, tmp_path,
                                                         monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert needle in err and len(err.strip().splitlines()) == 1


def test_bad_native_options_raise_native_config_errors(tmp_path):
    program = compile_graph(lio.build(N=3), SolverConfig(), name="bad")
    for config, needle in [(NativeConfig(scalar="int"), "expected 'float', 'double'"),
                           (NativeConfig(lanes=3), "lanes must be"),
                           (NativeConfig(scalar="double", linear_scalar="float"), "narrower"),
                           (NativeConfig(host_flags=("-O3;rm",)), "a Makefile would interpret"),
                           (NativeConfig(max_step_columns=4), "NativeConfig.max_step_columns")]:
        with pytest.raises(NativeConfigError, match=re.escape(needle)):
            native.emit(program, tmp_path, config)


def test_native_build_failure_is_one_line_naming_the_log(tmp_path):
    program = compile_graph(lio.build(N=3), SolverConfig(), name="r")
    project = native.emit(program, tmp_path, NativeConfig(scalar="double"))
    source = project.directory / "r.cpp"
    source.write_text(source.read_text() + "\nthis is not C++;\n")
    with pytest.raises(native.NativeBuildError) as info:
        native.make(project)
    message = str(info.value)
    assert "\n" not in message and "internal error" in message
    assert str(project.directory / "build.log") in message


def test_host_flags_keep_the_rounding():
    x86 = native.host_flags("x86_64")
    assert "-march=native" in x86 and "-mno-fma" in x86 and "-mprefer-vector-width=512" in x86
    assert native.host_flags("aarch64") == ("-O3",)


def test_lanes_do_not_change_the_numbers(tmp_path, monkeypatch):
    """Instances side by side in SIMD lanes make exactly the scalar calls: the same numbers.
    So does the suite's quicker build (FGC_NATIVE_FLAGS=-O0 after the project's -O3,
    tests/conftest.py): the same operations in the same order, no fused multiply-add."""
    graph = robust_chain()
    program = compile_graph(graph, SolverConfig(linear="qr"), name="lanes")
    data = problem_data(graph, program)
    results = []
    for lanes, flags in ((1, "-O0"), (None, "-O0"), (None, None)):
        if flags is None:
            monkeypatch.delenv("FGC_NATIVE_FLAGS", raising=False)
        else:
            monkeypatch.setenv("FGC_NATIVE_FLAGS", flags)
        project = native.emit(program, tmp_path / f"{lanes}{flags}",
                              NativeConfig(scalar="double", lanes=lanes))
        native.make(project)
        results.append(NativeSolver.load(program, project).run(data))
    for other in results[1:]:
        assert other.final_error == results[0].final_error
        for key, value in results[0].values.items():
            np.testing.assert_array_equal(other.values[key], value)
