"""The self-checking testbench, keyed result files and the Vitis script of an emitted project.

- ``make csim`` compares the kernel's result with ``reference.txt`` (the simulator's float64 run,
  written beside the data) and fails (testbench exit 4) on a corrupted reference; without one it
  says the result is unchecked and succeeds;
- ``result.txt`` names every value by its variable's key token; reading it back gives the
  graph's keys (integer keys as ``int``) and refuses a file whose keys are not the Program's;
- ``run_hls.tcl`` adds only ``include/`` (fgc's unit headers; Vitis's own ``ap_fixed.h`` /
  ``hls_stream.h`` are used), has one clock (the cost model's), the part, and passes the
  reference to ``csim_design``.
"""

from __future__ import annotations

import dataclasses
import re
import subprocess

import numpy as np
import pytest

import fgc
from fgc import Pose2, Pose3, Rot3
from fgc.compile import compile_graph
from fgc.errors import DataError
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import sim
from fgc_backends.cfamily.names import key_token, key_tokens, token_key
from fgc_backends.cfamily.results import (
    ERROR_FLOOR_FACTOR,
    error_floor,
    read_result,
    write_reference,
)
from fgc_backends.hls import HlsConfig, emit, run_csim
from fgc_backends.hls.build import HlsBuildError


def chain(n: int = 6, keys=None) -> fgc.Graph:
    """A Pose2 odometry chain with a prior; keys ``keys`` (default the ints 0 … n-1)."""
    keys = list(range(n)) if keys is None else keys
    g = fgc.Graph()
    for i, k in enumerate(keys):
        g.add_variable(k, Pose2(i * 1.0 + 0.1, 0.05 * i, 0.02 * i))
    g.add(PriorFactor(keys[0], Pose2(0.0, 0.0, 0.0), noise.isotropic(3, 0.1)))
    for a, b in zip(keys, keys[1:], strict=False):
        g.add(BetweenFactor(a, b, Pose2(1.0, 0.0, 0.05), noise.isotropic(3, 0.2)))
    return g


@pytest.fixture(scope="module")
def project(tmp_path_factory):
    graph = chain()
    program = compile_graph(graph, SolverConfig(linear="cholesky"), name="chk")
    out = tmp_path_factory.mktemp("chk")
    proj = emit(program, out, HlsConfig(scalar="double"))
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = run_csim(proj, program, data, reference)
    return proj, program, data, reference, result


def _tb(proj, *args) -> subprocess.CompletedProcess:
    return subprocess.run([f"./tb_{proj.name}", *args], cwd=proj.directory, capture_output=True,
                          text=True, check=False)


def test_testbench_passes_on_the_right_reference(project):
    proj, *_ = project
    done = _tb(proj, "data.txt", "result.txt", "reference.txt")
    assert done.returncode == 0, done.stderr
    assert "matches the reference" in done.stdout


def test_a_corrupted_reference_fails_make_csim(project):
    proj, program, data, reference, _ = project
    key = program.variables[3].key
    storage = dict(reference.storage)
    storage[key] = storage[key] + np.array([0.0, 1e-6, 0.0, 0.0])  # 1 µm: far above 1e-9
    bad = dataclasses.replace(reference, storage=storage)
    with pytest.raises(HlsBuildError, match="make csim failed"):
        run_csim(proj, program, data, bad)
    log = (proj.directory / "build.log").read_text()
    assert "MISMATCH: variable 3 entry 1" in log
    write_reference(proj.directory / "reference.txt", program, bad)
    assert _tb(proj, "data.txt", "result.txt", "reference.txt").returncode == 4
    # the final error is compared as well
    write_reference(proj.directory / "reference.txt", program,
                    dataclasses.replace(reference, final_error=reference.final_error + 1e-6))
    done = _tb(proj, "data.txt", "result.txt", "reference.txt")
    assert done.returncode == 4 and "MISMATCH: final error" in done.stderr
    # and the status, in double
    write_reference(proj.directory / "reference.txt", program,
                    dataclasses.replace(reference, status="max_iterations"))
    done = _tb(proj, "data.txt", "result.txt", "reference.txt")
    assert done.returncode == 4 and "MISMATCH: status converged" in done.stderr


def test_a_reference_of_another_structure_is_refused(project):
    proj, program, *_ = project
    ref = proj.directory / "reference.txt"
    write_reference(ref, program, project[3])
    lines = ref.read_text().splitlines()
    ref.write_text("\n".join([lines[0][:-4] + "beef", *lines[1:]]) + "\n")
    done = _tb(proj, "data.txt", "result.txt", "reference.txt")
    assert done.returncode == 2 and "not a reference file of this structure" in done.stderr
    ref.write_text("\n".join([*lines[:6], "x9 4 0 0 1 0", *lines[7:]]) + "\n")
    done = _tb(proj, "data.txt", "result.txt", "reference.txt")
    assert done.returncode == 2 and "expected '1 4 <numbers>'" in done.stderr


def test_without_a_reference_the_testbench_says_so(project):
    proj, program, data, _, _ = project
    result = run_csim(proj, program, data, reference=False)
    assert result.converged
    done = _tb(proj, "data.txt", "result.txt", "missing.txt")
    assert done.returncode == 0 and "no reference file missing.txt" in done.stdout


def test_result_file_is_keyed_and_int_keys_come_back_as_ints(project):
    proj, program, _, reference, result = project
    lines = (proj.directory / "result.txt").read_text().splitlines()
    assert lines[0] == "FGCRESULT 2"
    assert [line.split()[0] for line in lines[7:]] == [str(i) for i in range(6)]
    assert list(result.keyed_values) == list(range(6))
    for v in program.variables:
        np.testing.assert_allclose(result.keyed_values[int(v.key)], reference.storage[v.key],
                                   atol=1e-9)
    # a file whose keys are not the Program's is refused, naming the line
    path = proj.directory / "bad_result.txt"
    path.write_text("\n".join([*lines[:9], "7 " + lines[9].split(" ", 1)[1], *lines[10:]]))
    with pytest.raises(DataError, match=r"bad_result.txt:10: expected the line of variable '2'"):
        read_result(path, program)
    path.write_text("\n".join([*lines[:9], lines[9] + " 1.0", *lines[10:]]))
    with pytest.raises(DataError, match=r":10: variable '2' \(Pose2\) needs 4 numbers"):
        read_result(path, program)


def test_key_tokens_are_safe_unique_and_read_back():
    assert key_token("17") == "17" and key_token("-3") == "-3"
    assert key_token("x1") == "x1"
    assert key_token('a"b\\c*/d\n') == "a_b_c__d_"
    assert key_token("1x") == "k_1x"  # never reads back as an integer
    tokens = key_tokens(["a b", "a_b", "a+b", "17", ""])
    assert tokens == ("a_b", "a_b~1", "a+b", "17", "k_")
    assert len(set(tokens)) == len(tokens)
    assert all(re.fullmatch(r"[A-Za-z0-9_.:+~-]+", t) for t in tokens)
    assert token_key("17", "17") == 17 and token_key("x1", "x1") == "x1"


def test_string_keys_keep_their_names_in_the_result(tmp_path):
    keys = ["x0", "x 1", "x_1", "x2"]
    graph = chain(4, keys)
    program = compile_graph(graph, SolverConfig(linear="cholesky"), name="chk_str")
    proj = emit(program, tmp_path, HlsConfig(scalar="double"))
    result = run_csim(proj, program, problem_data(graph, program))
    assert list(result.keyed_values) == keys
    tb = (tmp_path / "tb_chk_str.cpp").read_text()
    assert '"x_1",\n    "x_1~2",' in tb


def test_tcl_uses_vitis_headers_one_clock_and_the_reference(tmp_path):
    program = compile_graph(chain(3), SolverConfig(linear="cholesky", clock_mhz=200.0),
                            name="chk_tcl")
    proj = emit(program, tmp_path / "p", HlsConfig(scalar="double", clock_ns=5.0))
    tcl = (proj.directory / "run_hls.tcl").read_text()
    code = [line.strip() for line in tcl.splitlines() if not line.startswith("#")]
    # the unit headers the kernel includes by name (fgc_qr.h, fgc_lm.h, ...) are found in
    # include/; no other include path, so Vitis's own ap_fixed.h / hls_stream.h are used
    assert 'set cflags "-std=c++14 -Iinclude"' in code
    flags = [line.replace("-Iinclude", "") for line in code]
    assert not any("-I" in line or "isystem" in line or "ap_types" in line for line in flags)
    assert "csim_include" not in tcl
    included = {h for h in re.findall(r'#include "(fgc_\w+\.h)"', (proj.directory /
                                                                   "chk_tcl.cpp").read_text())}
    assert included and all((proj.directory / "include" / h).is_file() for h in included)
    assert code.count("create_clock -period 5 -name default") == 1
    assert sum("create_clock" in line for line in code) == 1
    assert "set_part {xc7z045ffg900-2}" in code
    assert 'csim_design -argv "data.txt result.txt reference.txt"' in code
    assert "add_files -tb reference.txt" in code
    makefile = (proj.directory / "Makefile").read_text()
    assert "./tb_chk_tcl $(DATA) $(RESULT) $(REFERENCE)" in makefile


def test_float_testbench_measures_a_3x3_rotation_by_its_chord(tmp_path):
    # A 3x3 rotation's angle from the chord |R - R_ref|_F, not acos((trace(R_ref^T R) - 1) / 2):
    # the same rotation whose matrix is 1e-6 off orthonormal (84 float retractions left 1.4e-6
    # on imu_window N = 20's float32 simulator) read 1.7 mrad through acos, a mismatch; the
    # chord reads 1.7e-6. A rotation 0.9 mrad off passes, 1.1 mrad off does not.
    g = fgc.Graph()
    for i in range(4):
        g.add_variable(i, Pose3.Expmap(np.r_[0.1 * i, -0.05 * i, 0.2 * i, i, 0.3 * i, 0.1]))
    g.add(PriorFactor(0, Pose3.Expmap(np.r_[0, 0, 0, 0, 0, 0.1]), noise.isotropic(6, 0.1)))
    for i in range(3):
        g.add(BetweenFactor(i, i + 1, Pose3.Expmap(np.r_[0.1, -0.05, 0.25, 1.0, 0.3, 0.0]),
                            noise.isotropic(6, 0.2)))
    program = compile_graph(g, SolverConfig(linear="qr"), name="chk_rot3")
    proj = emit(program, tmp_path, HlsConfig(scalar="float"))
    data = problem_data(g, program)
    reference = sim.run(program, data, precision="float64")
    key = program.variables[2].key
    out = np.asarray(run_csim(proj, program, data, reference).values[key], float)
    rotation = out[:9].reshape(3, 3)

    def check(r_ref: np.ndarray) -> subprocess.CompletedProcess:
        storage = {**reference.storage, key: np.r_[r_ref.reshape(-1), out[9:]]}
        write_reference(tmp_path / "reference.txt", program,
                        dataclasses.replace(reference, storage=storage))
        return _tb(proj, "data.txt", "result.txt", "reference.txt")

    def turned(angle: float) -> np.ndarray:
        return rotation @ Rot3.Expmap(angle * np.array([2.0, -1.0, 2.0]) / 3).R

    done = check(rotation * (1 - 1e-6))
    assert done.returncode == 0, done.stderr
    assert check(turned(0.0009)).returncode == 0
    done = check(turned(0.0011))
    assert done.returncode == 4 and "variable 2: rotation differs from the reference by 0.0011" \
        in done.stderr
    # a matrix that is no rotation reads far off, as any rotation as far off does
    done = check(2 * rotation)
    assert done.returncode == 4 and "variable 2: rotation differs" in done.stderr


def test_fgc_compile_writes_the_reference_beside_the_data(tmp_path):
    from pathlib import Path

    from fgc.app.cli import main

    spec = str(Path(__file__).resolve().parents[2] / "examples" / "range_beacons.py")
    out = tmp_path / "prj"
    assert main(["compile", spec, "--backend", "hls", "--scalar", "double", "--out",
                 str(out), "-q"]) == 0
    reference = (out / "reference.txt").read_text().splitlines()
    assert reference[0].startswith("FGCREFERENCE 2 ") and reference[1] == "STATUS converged"
    assert reference[3] == "ERROR_FLOOR 0.0"  # a double design rests at the optimum
    done = subprocess.run(["make", "-s", "csim"], cwd=out, capture_output=True, text=True,
                          check=False)
    assert done.returncode == 0, done.stderr
    assert "matches the reference" in done.stdout


def test_float_testbench_tolerates_1cm_1mrad_and_no_more(tmp_path):
    graph = chain()
    program = compile_graph(graph, SolverConfig(linear="qr"), name="chk_f32")
    proj = emit(program, tmp_path, HlsConfig(scalar="float"))
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    run_csim(proj, program, data, reference)
    key = program.variables[4].key

    def check(dx: float, dtheta: float) -> subprocess.CompletedProcess:
        x, y, c, s = reference.storage[key]
        a = np.arctan2(s, c) + dtheta
        storage = {**reference.storage, key: np.array([x + dx, y, np.cos(a), np.sin(a)])}
        write_reference(tmp_path / "reference.txt", program,
                        dataclasses.replace(reference, storage=storage))
        return _tb(proj, "data.txt", "result.txt", "reference.txt")

    assert check(0.005, 0.0005).returncode == 0
    # the final error: within 1e-2 x max(1, reference) + 10 x the cost of the reference rounded
    # to float, no more
    floor = error_floor(program, data, reference, "float")
    assert 0 < floor < 1e-2
    allowed = 1e-2 * max(1.0, reference.final_error) + ERROR_FLOOR_FACTOR * floor
    result = read_result(proj.directory / "result.txt", program)
    for shift, code in ((0.5, 0), (2.0, 4)):
        write_reference(tmp_path / "reference.txt", program, dataclasses.replace(
            reference, final_error=result.final_error - shift * allowed), floor)
        done = _tb(proj, "data.txt", "result.txt", "reference.txt")
        assert done.returncode == code, done.stderr
    assert "MISMATCH: final error" in done.stderr
    lines = (tmp_path / "reference.txt").read_text().splitlines()
    (tmp_path / "reference.txt").write_text("\n".join([*lines[:3], "ERROR_FLOOR -1",
                                                       *lines[4:]]) + "\n")
    done = _tb(proj, "data.txt", "result.txt", "reference.txt")
    assert done.returncode == 2 and "a finite number >= 0" in done.stderr
    done = check(0.02, 0.0)
    assert done.returncode == 4 and "MISMATCH: variable 4 entry 0" in done.stderr
    done = check(0.0, 0.002)
    assert done.returncode == 4 and "variable 4: rotation differs from the reference by 0.002" \
        in done.stderr
