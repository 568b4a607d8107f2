"""Deterministic output: every shipped example, compiled for every registered backend, gives
byte-identical files (the Program's JSON, the data file and every emitted source) twice in one
process (the second time from a warm derivation cache) and in two processes with different
``PYTHONHASHSEED`` s, each starting from its own empty cache.

Set iteration order, sympy's hash-dependent term order and dictionary order of unhashed keys are
the usual ways for a compiler to drift between runs; a change that lets one of them into an
output file fails here, naming the example, backend and file.

The default run covers the Pose2 graph and the custom factor (range_beacons); ``-m heavy`` adds
Pose3, LIO and the IMU window, whose cold derivations take minutes for two processes. Their
emitted code is also held by the golden tests (tests/golden/ holds pose3example, LIO and the IMU
window for every backend, written by another process with another hash seed), and Pose3 across
hash seeds by tests/hls/test_hls.py (the HLS design), tests/compiler/test_compile.py (the
Program) and the double native build below. (With Pose3 the default case took 52.5 s of CPU,
without it 27.5 s, 2026-12-07.)
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from fgc_backends import names

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = {  # small sizes: the derivations, which dominate, do not depend on them
    "lio": ["examples/lio.py", "-p", "N=6"],
    "imu_window": ["examples/imu_window.py", "-p", "N=6", "--linear", "cholesky"],
    "pose2": ["examples/pose_graph.py", "-p", "dataset=w100.graph"],
    "pose3": ["examples/pose_graph.py", "-p", "dataset=pose3example.txt"],
    "range_beacons": ["examples/range_beacons.py", "-p", "steps=6"],
}
SCRIPT = """
import sys
from fgc.app.cli import main
from fgc_backends import names
out, cases = sys.argv[1], eval(sys.argv[2])
for run in ("cold", "warm"):
    for name, argv in cases.items():
        for backend in names():
            code = main(["compile", *argv, "--backend", backend,
                         "--out", f"{out}/{run}/{name}/{backend}"])
            assert code == 0, (name, backend, code)
"""


def _files(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file()}


@pytest.mark.parametrize("chosen", [
    pytest.param(["pose2", "range_beacons"], id="pose2-and-custom-factor"),
    pytest.param(sorted(EXAMPLES), id="every-example", marks=pytest.mark.heavy),
])
def test_examples_are_byte_identical_across_runs_and_hash_seeds(tmp_path, chosen):
    cases = {name: EXAMPLES[name] for name in chosen}
    outputs = {}
    for seed in ("1", "2"):
        env = dict(os.environ, PYTHONHASHSEED=seed, FGC_CACHE_DIR=str(tmp_path / f"cache{seed}"))
        out = tmp_path / f"seed{seed}"
        subprocess.run([sys.executable, "-c", SCRIPT, str(out), repr(cases)], cwd=ROOT,
                       env=env, check=True, capture_output=True, text=True)
        cold, warm = _files(out / "cold"), _files(out / "warm")
        assert cold.keys() == warm.keys()
        for name in cold:
            assert cold[name] == warm[name], f"{name}: cold and warm cache differ (seed {seed})"
        outputs[seed] = cold
    assert outputs["1"].keys() == outputs["2"].keys()
    for name, text in outputs["1"].items():
        assert text == outputs["2"][name], f"{name}: differs between PYTHONHASHSEED 1 and 2"
    examples = {n.split("/")[0] for n in outputs["1"]}
    assert examples == set(cases)
    for name in cases:  # every backend, the Program and the data file of each
        got = {n.split("/", 2)[1] for n in outputs["1"] if n.startswith(f"{name}/")}
        assert got == set(names()), name
        assert f"{name}/sim/program.json" in outputs["1"], name


def test_a_double_native_build_with_the_stream_host_code_is_byte_identical(tmp_path):
    """The examples above compile in float32, whose native build has no stream host code; a
    float64 Pose3 graph's native build holds it (fgc_kept_walk, fgc_local_jacobian and the Log
    kernels printed for them) and is byte-identical under two hash seeds, each from an empty
    cache."""
    outputs = {}
    for seed in ("1", "2"):
        env = dict(os.environ, PYTHONHASHSEED=seed, FGC_CACHE_DIR=str(tmp_path / f"cache{seed}"))
        out = tmp_path / f"seed{seed}"
        subprocess.run([sys.executable, "-m", "fgc.app.cli", "compile", *EXAMPLES["pose3"],
                        "--precision", "float64", "--backend", "native", "--out", str(out)],
                       cwd=ROOT, env=env, check=True, capture_output=True, text=True)
        outputs[seed] = _files(out)
    assert outputs["1"] == outputs["2"]
    kernel = outputs["1"]["pose_graph.cpp"].decode()
    assert "kept_walk(" in kernel and "void local_0(" in kernel and "so3_log(" in kernel
