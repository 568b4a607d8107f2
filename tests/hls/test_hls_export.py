"""``run_hls.tcl`` ends by exporting the IP for Vivado (issue 35): the whole flow by default,
``FGC_HLS_STEPS`` for a part of it (a csim-only run exports nothing). Vitis HLS is not needed:
the script runs in ``tclsh`` with its Vitis commands stubbed to log their calls."""

from __future__ import annotations

import os
import shutil
import subprocess

import pytest

import fgc
from fgc import Pose2
from fgc.compile import compile_graph
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig, emit

VITIS = ("open_project", "set_top", "add_files", "open_solution", "set_part", "create_clock",
         "csim_design", "csynth_design", "cosim_design", "export_design")
STUBS = "".join(f'proc {c} {{args}} {{ puts "{c} $args" }}\n' for c in VITIS)


@pytest.fixture(scope="module")
def tcl(tmp_path_factory) -> str:
    graph = fgc.Graph()
    for i in range(3):
        graph.add_variable(f"x{i}", Pose2(float(i), 0.0, 0.0))
    graph.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), noise.isotropic(3, 0.1)))
    for i in range(1, 3):
        graph.add(BetweenFactor(f"x{i - 1}", f"x{i}", Pose2(1.0, 0.0, 0.0),
                                noise.isotropic(3, 0.1)))
    program = compile_graph(graph, SolverConfig(), name="ip")
    out = tmp_path_factory.mktemp("ip")
    emit(program, out, HlsConfig(scalar="double"))
    return (out / "run_hls.tcl").read_text()


def _run(tcl: str, tmp_path, steps: str | None) -> subprocess.CompletedProcess:
    if shutil.which("tclsh") is None:
        pytest.skip("tclsh is not installed")
    script = tmp_path / "run.tcl"
    script.write_text(STUBS + tcl)
    env = {k: v for k, v in os.environ.items() if k != "FGC_HLS_STEPS"}
    if steps is not None:
        env["FGC_HLS_STEPS"] = steps
    return subprocess.run(["tclsh", str(script)], capture_output=True, text=True, env=env,
                          timeout=60, check=False)


def _flow(done: subprocess.CompletedProcess) -> list[str]:
    return [line.split()[0] for line in done.stdout.splitlines()
            if line.split()[0] in VITIS[6:]]


def test_the_default_flow_ends_by_exporting_the_ip(tcl, tmp_path):
    done = _run(tcl, tmp_path, None)
    assert done.returncode == 0, done.stderr
    assert _flow(done) == ["csim_design", "csynth_design", "cosim_design", "export_design"]
    export = done.stdout.splitlines()[-1]
    assert export == 'export_design -format ip_catalog -rtl verilog -display_name {fgc ip_top}'


def test_a_csim_only_run_exports_nothing(tcl, tmp_path):
    done = _run(tcl, tmp_path, "csim")
    assert done.returncode == 0, done.stderr
    assert _flow(done) == ["csim_design"]
    done = _run(tcl, tmp_path, "csim csynth export")
    assert _flow(done) == ["csim_design", "csynth_design", "export_design"]


@pytest.mark.parametrize("steps, says", [("export", "needs csynth"),
                                         ("csim synth", "unknown step 'synth'")])
def test_steps_that_cannot_run_are_refused_by_name(tcl, tmp_path, steps, says):
    done = _run(tcl, tmp_path, steps)
    assert done.returncode == 2 and says in done.stderr and _flow(done) == []
