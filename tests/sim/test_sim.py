"""The simulator backend: printer, emitted run-time, emission rules, solver behaviour, bad data.

Solutions are checked against GTSAM in ``test_sim_gtsam.py``; here the pieces are checked against
fgc's own numeric definitions (fgc.frontend.geometry) and the solver paths against each other.
"""

from __future__ import annotations

import ast
import dataclasses
import os
import runpy
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import fgc
from fgc.compile import compile_graph
from fgc.compiler.kernel import Kernel
from fgc.errors import DataError
from fgc.frontend import geometry
from fgc.frontend.factors import BetweenFactor, GPSFactor, PriorFactor
from fgc.frontend.geometry import Point3, Pose2, Pose3, Rot2, Rot3, lie_closed_forms, special
from fgc.ir.conditioning import RankDeficientWarning
from fgc.ir.datafile import problem_data, write_data
from fgc.ir.program import SolverConfig
from fgc.ir.stream import FixedLag, Incremental
from fgc_backends import load, sim
from fgc_backends.sim import types as sim_types
from fgc_backends.sim.printer import SimPrinter
from fgc_backends.sim.runtime import fgc_sim_runtime, fgc_sim_special

ROOT = Path(__file__).resolve().parents[2]

from fgc.app.specs import example  # noqa: E402

imu_window = example("imu_window")
pose_graph = example("pose_graph")

# (contextlib, ctypes: fgc_sim_linear's one_blas_thread sets OpenBLAS' thread count)
ALLOWED_IMPORTS = {"numpy", "argparse", "contextlib", "ctypes", "hashlib", "importlib",
                   "importlib.util", "json", "os", "sys", "time", "types"}


@pytest.fixture(scope="module")
def pose3():
    """pose3example compiled, its data, and the emitted simulator loaded in this process."""
    graph = pose_graph.build("pose3example.txt")
    program = compile_graph(graph)
    return graph, program, problem_data(graph, program)


@pytest.fixture(scope="module")
def emitted(pose3, tmp_path_factory):
    out = tmp_path_factory.mktemp("sim")
    files = sim.emit(pose3[1], out)
    return files, runpy.run_path(str(files[0]))


# --------------------------------------------------------------------------------------------
# printer
# --------------------------------------------------------------------------------------------


def _coefficient(name: str):
    return lambda t: special.coefficient(name, t)


def _run_printed(kernel: Kernel, x: np.ndarray, outputs=None) -> np.ndarray:
    printed = SimPrinter().kernel(kernel, "k", outputs)
    source = "def k(x):\n" + "".join(f"    {line}\n" for line in printed.lines)
    ns = {"numpy": np, "so3_log": None}
    ns.update({f"lie_{n}": _coefficient(n) for n in special.COEFFICIENT_FUNCTIONS})
    exec(source, ns)  # noqa: S102 - our own printed code
    return ns["k"](x)


def test_printed_kernel_keeps_float32_and_is_vectorised():
    a, b = sp.symbols("a b", real=True)
    t = sp.Symbol("_t0", real=True)
    kernel = Kernel((a, b), ((t, sp.sqrt(2) * a + sp.Rational(1, 3) * b**-2),),
                    (t, sp.Integer(0), special.lie_A(a * a), sp.pi * sp.sqrt(b)))
    x = np.array([[0.5, 1e-9, 3.0], [2.0, 4.0, 1.0]], dtype=np.float32)
    out = _run_printed(kernel, x)
    assert out.dtype == np.float32 and out.shape == (4, 3)
    assert np.allclose(out[0], np.sqrt(2) * x[0] + x[1] ** -2 / 3, rtol=1e-6)
    assert np.all(out[1] == 0)
    assert np.allclose(out[2], np.sin(x[0]) / x[0], rtol=1e-6)
    assert np.allclose(out[3], np.pi * np.sqrt(x[1]), rtol=1e-6)


def test_printer_computes_each_so3_log_once_and_selects_outputs():
    r = sp.symbols("r0:9", real=True)
    logs = [f(*r) for f in special.SO3_LOG_FUNCTIONS]
    kernel = Kernel(r, (), (logs[0] + logs[1], 2 * logs[2], logs[0]))
    printed = SimPrinter().kernel(kernel, "k", outputs=[1, 2])
    calls = [line for line in printed.lines if "so3_log(" in line]
    assert len(calls) == 1 and calls[0].startswith("w0_0, w0_1, w0_2 = so3_log(a0, a1,")
    assert printed.outputs == 2 and printed.lines[-2] == "out[1] = w0_0"


def test_printer_rejects_unknown_functions():
    a = sp.Symbol("a", real=True)
    with pytest.raises(sim.printer.PrintError, match="cannot print mystery"):
        SimPrinter().kernel(Kernel((a,), (), (sp.Function("mystery")(a),)), "k")


# --------------------------------------------------------------------------------------------
# the emitted run-time against fgc's geometry
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_runtime_coefficients_are_fgcs_bit_for_bit(emitted, dtype):
    """The problem module's Lie coefficients (the run-time's switch and series over fgc's own
    copied closed forms) give exactly fgc's numbers on both sides of the switch."""
    ns = emitted[1]
    t = np.concatenate([[0.0, 1e-16, 1e-8, 0.3, 3.99, 4.0, 4.01, 9.0, np.pi**2],
                        np.geomspace(1e-20, 40.0, 2000), np.linspace(0.0, 9.9, 2000)]).astype(dtype)
    assert sorted(ns["LIE"]) == sorted(special.COEFFICIENT_FUNCTIONS)
    for name in special.COEFFICIENT_FUNCTIONS:
        got = ns[f"lie_{name}"](t)  # the problem module's names, which its kernels call
        assert got.dtype == dtype
        np.testing.assert_array_equal(got, special.coefficient(name, t), err_msg=name)


def test_emitted_constants_are_fgcs_series(emitted):
    constants = emitted[1]["LIB"].constants
    assert constants.SERIES_BELOW == special.SERIES_BELOW
    assert {name: tuple(float(c) for c in reversed(coeffs))
                                for name, coeffs in special.SERIES.items()} == constants.SERIES


@pytest.mark.parametrize("theta", [0.0, 1e-8, 1e-4, 1.0, 2.5, np.pi - 1e-6, np.pi])
def test_runtime_so3_log_matches_fgc(theta):
    rng = np.random.default_rng(1)
    axes = rng.normal(size=(4, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    mats = np.array([Rot3.Expmap(a * theta).R for a in axes])
    got = np.stack(fgc_sim_special.so3_log(*mats.reshape(4, 9).T), -1)
    want = np.array([special.so3_log_numeric(m) for m in mats])
    if theta == np.pi:  # ±ω are the same rotation
        got = got * np.sign(np.sum(got * want, 1, keepdims=True))
    np.testing.assert_allclose(got, want, atol=1e-12)
    got32 = np.stack(fgc_sim_special.so3_log(*mats.astype(np.float32).reshape(4, 9).T), -1)
    assert got32.dtype == np.float32


def _printed_type_kernel(kernel: Kernel):
    """A variable type's kernel printed as the problem module prints it, over the run-time's
    special functions (lie_* from fgc's series, so3_log), as f(part, …) over instances."""
    printed = SimPrinter().kernel(kernel, "k")
    source = "def k(x):\n" + "".join(f"    {line}\n" for line in printed.lines)
    series = {name: tuple(float(c) for c in reversed(coeffs))
              for name, coeffs in special.SERIES.items()}
    ns = {"numpy": np, "so3_log": fgc_sim_special.so3_log}
    lie = fgc_sim_special.lie_functions(special.SERIES_BELOW, series, lie_closed_forms)
    ns.update({f"lie_{name}": f for name, f in lie.items()})
    exec(source, ns)  # noqa: S102 - our own printed code
    return fgc_sim_special.over_instances(ns["k"])


TYPES = [Pose3, Rot3, Pose2, Rot2, Point3, geometry.vector_type(3), geometry.ImuBias]


@pytest.mark.parametrize("cls", TYPES, ids=lambda c: c.__name__)
def test_printed_retract_and_local_match_fgc(cls):
    retract = _printed_type_kernel(sim_types.retract_kernel(cls))
    local = _printed_type_kernel(sim_types.local_kernel(cls))
    rng = np.random.default_rng(2)
    values = [cls.random(rng) for _ in range(5)]
    deltas = rng.normal(size=(5, cls.dim)) * np.array([1.0, 1e-9, 1e-5, 0.3, 2.0])[:, None]
    x = np.array([v.storage_array() for v in values])
    got = retract(x, deltas)
    moved = [v.retract(d) for v, d in zip(values, deltas, strict=True)]
    np.testing.assert_allclose(got, [m.storage_array() for m in moved], atol=1e-12)
    back = local(x, got)
    want = np.array([v.local(m) for v, m in zip(values, moved, strict=True)]).reshape(5, -1)
    np.testing.assert_allclose(back, want, atol=1e-9)
    np.testing.assert_allclose(back, deltas, atol=1e-9)  # Log(x⁻¹ (x ∘ Exp δ)) = δ
    x32, d32 = x.astype(np.float32), deltas.astype(np.float32)
    assert retract(x32, d32).dtype == np.float32 and local(x32, x32).dtype == np.float32


def test_problem_module_holds_each_variable_types_kernels(pose3, emitted):
    ns = emitted[1]
    types = ns["PROBLEM"]["types"]
    assert len(types) == 1 and ns["PROBLEM"]["retract_groups"] == ((0, (0, 1, 2, 3, 4)),)
    retract = fgc_sim_special.over_instances(types[0][0])
    rng = np.random.default_rng(3)
    x = np.array([Pose3.random(rng).storage_array() for _ in range(3)])
    d = rng.normal(size=(3, 6)) * 0.1
    want = [Pose3.from_storage(list(a)).retract(b).storage_array()
            for a, b in zip(x, d, strict=True)]
    np.testing.assert_allclose(retract(x, d), want, atol=1e-12)


def test_a_variable_type_fgc_does_not_know_is_refused(pose3):
    program = pose3[1]
    odd = dataclasses.replace(program.variables[0], type_name="Quaternion")
    bad = dataclasses.replace(program, variables=(odd, *program.variables[1:]))
    with pytest.raises(sim.EmitError, match="no retraction for variable type 'Quaternion'"):
        sim_types.variable_types(bad, sim.EmitError)


def test_emit_refuses_a_runtime_that_disagrees_with_the_data_format(pose3, tmp_path,
                                                                    monkeypatch):
    monkeypatch.setattr(fgc_sim_runtime, "DATA_MAGIC", "FGCDATA 0")
    with pytest.raises(sim.EmitError, match="data file's magic"):
        sim.emit(pose3[1], tmp_path)


# --------------------------------------------------------------------------------------------
# emission
# --------------------------------------------------------------------------------------------


def test_backend_is_registered_by_name():
    assert load("sim") is sim
    with pytest.raises(fgc.FgcError, match="unknown backend"):
        load("nope")


def test_emission_is_deterministic_labelled_and_numpy_only(pose3, emitted, tmp_path):
    files, _ = emitted
    again = sim.emit(pose3[1], tmp_path)
    assert [p.name for p in again] == [p.name for p in files]
    assert files[0].name == "fgc_problem_sim.py"
    runtime = {p.name: p for p in sim.SimConfig.runtime_files()}
    assert [p.name for p in files[2:]] == list(runtime)
    for a, b in zip(files, again, strict=True):
        text = a.read_text()
        assert text == b.read_text(), a.name
        if a.name in runtime:  # copied as it is
            assert a.read_bytes() == runtime[a.name].read_bytes(), a.name
        else:
            template = "sim.py.jinja" if a == files[0] else f"{a.name}.jinja"
            assert text.startswith(f"# generated from template {template} by fgc — do not "
                                   "edit\n")
        imported = set()
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.Import):
                imported |= {alias.name for alias in node.names}
            elif isinstance(node, ast.ImportFrom):
                imported.add(node.module)
        assert imported <= ALLOWED_IMPORTS, (a.name, imported - ALLOWED_IMPORTS)


def test_emission_is_independent_of_hash_seeds(tmp_path):
    code = ("import sys; from fgc.app.specs import example; pose_graph = example('pose_graph'); "
            "from fgc.compile import compile_graph; from fgc_backends import sim; "
            "sim.emit(compile_graph(pose_graph.build('w100.graph')), sys.argv[1])")
    for seed in ("1", "2"):
        subprocess.run([sys.executable, "-c", code, str(tmp_path / seed)], check=True,
                       env={**os.environ, "PYTHONHASHSEED": seed})
    for f in sorted((tmp_path / "1").iterdir()):
        assert f.read_bytes() == (tmp_path / "2" / f.name).read_bytes(), f.name


def test_user_names_never_reach_the_code(tmp_path):
    evil = "x'); import os; os.system('echo pwned') #"
    g = fgc.Graph()
    g.add_variable(evil, Pose2(0.1, 0.0, 0.0))
    g.add_variable("y\n\"\"\"", Pose2(1.0, 0.1, 0.2))
    g.add(PriorFactor(evil, Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    g.add(BetweenFactor(evil, "y\n\"\"\"", Pose2(1.0, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    program = compile_graph(g, name="bad name'); import os #")
    files = sim.emit(program, tmp_path)
    assert files[0].name == "bad_name____import_os_sim.py"
    for f in files:
        assert "pwned" not in f.read_text() and '"""\n"' not in f.read_text()
    result = sim.run(program, problem_data(g, program), tmp_path)
    assert result.converged and set(result.values) == {evil, "y\n\"\"\""}


# --------------------------------------------------------------------------------------------
# solving
# --------------------------------------------------------------------------------------------


def _tangent_distance(a: dict, b: dict) -> float:
    return max(float(np.linalg.norm(a[k].local(b[k]))) for k in a)


@pytest.fixture(scope="module")
def chain():
    graph = imu_window.build(N=6)
    results = {}
    for linear in ("qr", "cholesky"):
        for ordering in ("two-ended", "serial"):
            program = compile_graph(graph, SolverConfig(linear=linear, ordering=ordering))
            results[linear, ordering] = sim.run(program, problem_data(graph, program))
    return graph, results


def test_qr_cholesky_serial_two_ended_agree(chain):
    _, results = chain
    ref = results["qr", "two-ended"]
    assert ref.converged
    for key, r in results.items():
        assert r.converged, key
        assert _tangent_distance(ref.values, r.values) < 1e-8, key
        assert abs(r.final_error - ref.final_error) <= 1e-9 * max(ref.final_error, 1e-9)


def test_cost_log_and_result_agree_with_fgc_error(chain):
    graph, results = chain
    r = results["qr", "serial"]
    values = {k: r.values[str(k)] for k in graph.variables}
    assert r.cost_log[0] == pytest.approx(graph.error(), rel=1e-12)
    assert r.final_error == pytest.approx(graph.error(values), rel=1e-9, abs=1e-12)
    assert r.cost_log[-1] == r.final_error and r.iterations >= len(r.cost_log) - 1


def test_gauss_newton_and_subprocess_run(pose3, tmp_path):
    graph, _, data = pose3
    program = compile_graph(graph, SolverConfig(method="gn"))
    inproc = sim.run(program, data, tmp_path / "a")
    sub = sim.run(program, data, tmp_path / "b", in_process=False)
    assert inproc.converged and sub.converged
    assert np.array_equal(inproc.storage["x3"], sub.storage["x3"])


def test_emitted_program_runs_where_fgc_cannot_be_imported(pose3, tmp_path):
    """The copied run-time and the generated files need NumPy only: run the emitted program
    from another folder with fgc, fgc_backends, sympy and jinja2 made unimportable."""
    graph, program, data = pose3
    files = sim.emit(program, tmp_path / "out")
    write_data(data, tmp_path / "data.txt")
    code = ("import runpy, sys\n"
            "for name in ('fgc', 'fgc_backends', 'sympy', 'jinja2'):\n"
            "    sys.modules[name] = None\n"
            "sys.argv = [sys.argv[1], 'data.txt', 'result.json']\n"
            "runpy.run_path(sys.argv[0], run_name='__main__')\n")
    run = subprocess.run([sys.executable, "-c", code, str(files[0])], cwd=tmp_path,
                         capture_output=True, text=True, check=False)
    assert run.returncode == 0, run.stderr
    assert sim.read_result(program, tmp_path / "result.json").converged


def test_lm_that_does_not_converge_says_so(pose3):
    graph, _, data = pose3
    program = compile_graph(graph, SolverConfig(max_iterations=2))
    r = sim.run(program, data)
    assert r.status == "max_iterations" and not r.converged and r.iterations == 2
    assert np.isfinite(r.final_error) and r.final_error == r.cost_log[-1] < r.initial_error


def test_float32_runs_in_float32(pose3):
    graph, program, data = pose3
    r = sim.run(program, data, precision="float32")
    assert r.precision == "float32" and r.converged
    assert all(np.array_equal(v, v.astype(np.float32)) for v in r.storage.values())


# --------------------------------------------------------------------------------------------
# bad data
# --------------------------------------------------------------------------------------------


def _corrupt(data_file: Path, out: Path, line: int, edit) -> Path:
    lines = data_file.read_text().splitlines()
    lines[line - 1:line] = edit(lines[line - 1].split())
    out.write_text("\n".join(lines) + "\n")
    return out


@pytest.mark.parametrize("in_process", [True, False])
# pose3example's factor lines hold 15 numbers: its noise is isotropic, as GTSAM reads it
@pytest.mark.parametrize("edit, needle, factor", [
    (lambda f: [" ".join([str(int(f[0]) - 1)] + f[1:-1])], "needs 15 numbers, found 14", 3),
    (lambda f: [" ".join(f[:3] + ["nan"] + f[4:])], "non-finite number", 3),
    (lambda f: [], "file ends early", 6),  # a missing line: the last factor is missing
])
def test_bad_data_is_a_clear_error(pose3, tmp_path, edit, needle, factor, in_process):
    graph, program, data = pose3
    write_data(data, tmp_path / "good.txt")
    line = 2 + len(data.variables) + 1 + 3 + 1  # the line of factor instance 3
    bad = _corrupt(tmp_path / "good.txt", tmp_path / "bad.txt", line, edit)
    spec = program.factors[factor]
    with pytest.raises(DataError, match=needle) as info:
        sim.run(program, bad, tmp_path / "out", in_process=in_process)
    assert f"variables {list(spec.keys)}" in str(info.value)
    assert program.blocks[spec.block].name in str(info.value)


def test_wrong_variable_storage_names_the_variable(pose3, tmp_path):
    _, program, data = pose3
    write_data(data, tmp_path / "good.txt")
    bad = _corrupt(tmp_path / "good.txt", tmp_path / "bad.txt", 4,
                   lambda f: [" ".join(["3"] + f[1:4])])
    with pytest.raises(DataError, match=r"variable 1 needs 12 numbers.*'x1'"):
        sim.run(program, bad)


def test_singular_gauss_newton_is_reported(tmp_path):
    """A prior with (almost) no information leaves the chain's gauge free: GN fails clearly,
    LM's damping keeps every step well posed."""
    g = fgc.Graph()
    g.add_variable("a", Pose2(0.3, -0.2, 0.1))
    g.add_variable("b", Pose2(1.0, 0.0, 0.0))
    g.add(PriorFactor("a", Pose2(0.0, 0.0, 0.0), fgc.noise.isotropic(3, 1.0)))
    g.add(BetweenFactor("a", "b", Pose2(1.0, 0.0, 0.0), fgc.noise.isotropic(3, 1.0)))
    weak = None
    for method in ("gn", "lm"):
        program = compile_graph(g, SolverConfig(method=method))
        data = problem_data(g, program)
        prior = next(j for j, f in enumerate(program.factors) if f.factors == (0,))
        factors = list(data.factors)
        factors[prior] = factors[prior].copy()
        factors[prior][4] = 1e-200  # 1/σ of the prior (after its 4 measurement numbers)
        weak = type(data)(data.variables, tuple(factors), data.structure)
        if method == "gn":
            r = sim.run(program, weak, tmp_path / method)
            assert r.status == "failed" and r.reason == "singular"
        else:  # the diagnosis at LM's solution names the undetermined variable
            with pytest.warns(RankDeficientWarning, match="variable 'b'"):
                r = sim.run(program, weak, tmp_path / method)
            assert r.status != "failed" and r.singular_variable == "b"


# --------------------------------------------------------------------------------------------
# incremental smoothing
# --------------------------------------------------------------------------------------------


def _point_chain(n: int = 10) -> fgc.Graph:
    rng = np.random.default_rng(5)
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"p{i}", Point3(rng.normal(size=3)))
        g.add(PriorFactor(f"p{i}", Point3(rng.normal(size=3)),
                          fgc.noise.isotropic(3, 0.01 if i == 0 else 1.0)))
        if i:
            g.add(BetweenFactor(f"p{i - 1}", f"p{i}", Point3(rng.normal(size=3)),
                                fgc.noise.diagonal([0.1, 0.2, 0.3])))
    return g


@pytest.mark.parametrize("window", [2, 3])
def test_incremental_is_exact_on_a_linear_chain(window):
    """Linear factors: keeping the older conditionals loses nothing, so keyframe-by-keyframe
    smoothing ends at the batch optimum."""
    g = _point_chain()
    program = compile_graph(g, SolverConfig(incremental_k=window, batch_every=4))
    data = problem_data(g, program)
    inc = sim.run(program, data, policy=Incremental(window, 4))
    batch = sim.run(program, data)
    assert inc.converged and [u["mode"] for u in inc.updates].count("batch") == 2
    assert len(inc.updates) == 10 and inc.updates[-1]["first"] == 10 - window
    for key, value in batch.values.items():
        np.testing.assert_allclose(inc.storage[key], value.storage_array(), atol=1e-9)
    assert inc.final_error == pytest.approx(batch.final_error, rel=1e-12)


def test_a_policy_reaches_the_simulator_run_as_a_subprocess_too(tmp_path):
    """The policy object crosses into the emitted simulator as plain data (``--policy`` on
    its command line): a fixed-lag and an incremental run in a subprocess give the in-process
    run's updates, keyframe for keyframe (1e-12: the same arithmetic)."""
    g = _point_chain()
    program = compile_graph(g, SolverConfig(incremental_k=3))
    data = problem_data(g, program)
    for policy in (FixedLag(2), Incremental(3)):
        here = sim.run(program, data, tmp_path / "a", policy=policy)
        there = sim.run(program, data, tmp_path / "b", policy=policy, in_process=False)
        assert [u["mode"] for u in there.updates] == [policy.mode] * 10
        assert [u["first"] for u in there.updates] == [u["first"] for u in here.updates]
        for key, value in here.storage.items():
            np.testing.assert_allclose(there.storage[key], value, atol=1e-12)


def test_incremental_needs_a_plan(pose3):
    with pytest.raises(fgc.FgcError, match="no incremental plan"):
        sim.run(pose3[1], pose3[2], policy=Incremental(3))


def _pose_chain(noise: float, n: int = 30) -> fgc.Graph:
    """A Pose3 odometry chain with GPS fixes, measurements perturbed by ``noise``."""
    rng = np.random.default_rng(0)
    truth = [Pose3.identity()]
    for _ in range(n - 1):
        truth.append(truth[-1].compose(Pose3.Expmap(np.r_[0, 0, 0.2, 1.0, 0, 0])))
    g = fgc.Graph()
    for i, t in enumerate(truth):
        g.add_variable(f"x{i}", t.retract(rng.normal(size=6) * 0.1))
        g.add(GPSFactor(f"x{i}", t.t + rng.normal(size=3) * 10 * noise,
                        fgc.noise.isotropic(3, 10 * noise)))
        if i:
            z = truth[i - 1].inverse().compose(t).retract(rng.normal(size=6) * noise)
            g.add(BetweenFactor(f"x{i - 1}", f"x{i}", z, fgc.noise.isotropic(6, noise)))
    g.add(PriorFactor("x0", truth[0], fgc.noise.isotropic(6, 0.01)))
    return g


def test_incremental_on_a_nonlinear_chain_approaches_batch_as_the_window_grows():
    """Nonlinear factors: the kept conditionals stay linearised where they were eliminated, so
    the result is near the batch optimum (measured 7e-4 for a window of 3 at 1 cm noise) and
    nearer for a wider window (5e-4 for 6)."""
    g = _pose_chain(0.01)
    batch = sim.run(compile_graph(g), problem_data(g, compile_graph(g)))
    gaps = []
    for window in (3, 6):
        program = compile_graph(g, SolverConfig(incremental_k=window))
        inc = sim.run(program, problem_data(g, program), policy=Incremental(window))
        assert inc.converged
        gaps.append(max(np.linalg.norm(batch.values[k].local(v)) for k, v in inc.values.items()))
    assert gaps[0] < 2e-3 and gaps[1] < gaps[0]


def test_one_blas_thread_sets_one_thread_and_restores_the_count():
    from fgc_backends.sim.runtime import fgc_sim_linear as lin

    controls = lin._openblas_controls()
    if not controls:
        pytest.skip("no OpenBLAS in this process (numpy built against another BLAS)")
    before = [get() for _, get in controls]
    with lin.one_blas_thread():
        assert [get() for _, get in controls] == [1] * len(controls)
        a = np.random.default_rng(0).normal(size=(60, 20))
        assert np.allclose(np.abs(np.linalg.qr(a, mode="r")), np.abs(np.linalg.qr(a)[1]))
    assert [get() for _, get in controls] == before
