"""Golden tests: the examples' emitted projects (every backend) equal the files in tests/golden/.

Each case runs ``fgc compile`` as a user would and compares every emitted source file byte for
byte with the committed copy (``program.json``, ``data.txt`` and ``reference.txt`` are left out:
the first is checked by the Program's JSON round trip, the others hold measurements and the
simulator's numbers, not generated code). The simulator's run-time modules are not generated
either: they are copied from ``backends/sim/runtime/``, and
``test_emitted_sim_runtime_is_the_package_source`` holds each emitted copy to its source byte for
byte and ``golden/sim/runtime.sha256`` records the sources' digests, so the golden tests still
fail on any change of what a simulator runs. An
intended change of the emitted code is recorded with

    python -m pytest tests/test_golden.py --update-golden

and reviewed as a diff of tests/golden/ in the same commit.
"""

from __future__ import annotations

import difflib
import hashlib
from pathlib import Path

import pytest

from fgc.app.cli import main as cli_main
from fgc_backends import names
from fgc_backends.sim import SimConfig
from fgc_backends.sim.runtime import SHARED

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = Path(__file__).resolve().parent / "golden"
NOT_CODE = {"program.json", "data.txt", "reference.txt"}
SIM_RUNTIME = {p.name: p for p in SimConfig.runtime_files()}  # copied, not generated
CASES = {
    "lio": ["examples/lio.py", "-p", "N=8"],
    "imu_window": ["examples/imu_window.py", "-p", "N=8", "--linear", "cholesky"],
    "pose_graph": ["examples/pose_graph.py", "-p", "dataset=pose3example.txt"],
}


def _emitted(out: Path) -> dict[str, bytes]:
    # folders hold copied fixed headers (the HLS project's csim_include/ and include/), not
    # generated code
    return {p.name: p.read_bytes() for p in sorted(out.iterdir())
            if p.is_file() and p.name not in NOT_CODE and p.name not in SIM_RUNTIME}


def _first_difference(name: str, want: bytes, got: bytes) -> str:
    diff = difflib.unified_diff(want.decode().splitlines(), got.decode().splitlines(),
                                f"golden/{name}", f"emitted/{name}", n=1, lineterm="")
    return "\n".join(list(diff)[:20])


@pytest.mark.parametrize("backend", names())
@pytest.mark.parametrize("case", sorted(CASES))
def test_emitted_project_equals_golden(case, backend, tmp_path, request, monkeypatch):
    monkeypatch.chdir(ROOT)
    out = tmp_path / case
    spec, *params = CASES[case]
    assert cli_main(["compile", spec, *params, "--backend", backend, "--out", str(out)]) == 0
    emitted = _emitted(out)
    golden_dir = GOLDEN / backend / case
    if request.config.getoption("--update-golden"):
        golden_dir.mkdir(parents=True, exist_ok=True)
        for stale in golden_dir.iterdir():
            stale.unlink()
        for name, text in emitted.items():
            (golden_dir / name).write_bytes(text)
        pytest.skip(f"golden files of {backend}/{case} rewritten")
    assert golden_dir.is_dir(), f"no golden files: run pytest {__file__} --update-golden"
    golden = {p.name: p.read_bytes() for p in sorted(golden_dir.iterdir())}
    assert sorted(emitted) == sorted(golden), "emitted file names differ from the golden ones"
    for name, want in golden.items():
        assert emitted[name] == want, (
            f"{backend}/{case}/{name} differs from the golden copy (intended? rerun with "
            f"--update-golden):\n{_first_difference(name, want, emitted[name])}")


@pytest.mark.parametrize("case", sorted(CASES))
def test_emitted_sim_runtime_is_the_package_source(case, tmp_path, monkeypatch):
    monkeypatch.chdir(ROOT)
    out = tmp_path / case
    spec, *params = CASES[case]
    assert cli_main(["compile", spec, *params, "--backend", "sim", "--out", str(out)]) == 0
    source = sorted((ROOT / "backends" / "sim" / "runtime").glob("fgc_sim_*.py"))
    shared = [ROOT / "fgc" / "frontend" / "geometry" / f"{name}.py" for name in SHARED]
    assert sorted(SIM_RUNTIME) == sorted(p.name for p in source + shared), \
        "runtime/ and its module list differ"
    for path in source + shared:
        copy = out / path.name
        assert copy.is_file(), f"{case}: {path.name} was not emitted"
        assert copy.read_bytes() == path.read_bytes(), f"{case}: {path.name} is not a verbatim copy"


def test_sim_runtime_matches_its_recorded_digests(request):
    """The run-time's sources as golden/sim/runtime.sha256 records them: a change of the
    run-time is reviewed (``--update-golden``) like a change of the generated files."""
    record = GOLDEN / "sim" / "runtime.sha256"
    got = "".join(f"{hashlib.sha256(p.read_bytes()).hexdigest()}  {name}\n"
                  for name, p in sorted(SIM_RUNTIME.items()))
    if request.config.getoption("--update-golden"):
        record.write_text(got)
        pytest.skip("golden/sim/runtime.sha256 rewritten")
    assert record.is_file(), f"no recorded digests: run pytest {__file__} --update-golden"
    want = record.read_text()
    diff = _first_difference("runtime.sha256", want.encode(), got.encode())
    assert got == want, ("the simulator run-time changed (intended? rerun with "
                         f"--update-golden):\n{diff}")
