"""float32 never claims a false success.

A float32 state has a resolution: one unit in the last place of a coordinate near 1e6 m is
0.0625 m, and a σ of 1e-9 is below the resolution of any coordinate. When rounding the state moves
a whitened residual by a sigma or more, the float32 solver cannot reach the optimum to the data's
accuracy: the simulator then reports status "failed", reason "precision_limit", with a
:class:`fgc.ir.conditioning.PrecisionLimitWarning` naming a variable, never "converged". Before,
the ‖δ‖ ≤ 10 ulp·‖x‖ rule (‖x‖ ≈ 1e6) stopped at the first iteration and said "converged".

The native solver and the C simulation (float kernels) get the same verdict, computed on the host
after the run (``fgc_backends.cfamily.results.judge_precision``, ρ by
:func:`fgc.ir.conditioning.resolution`); before, they said "converged" in all three cases.

Tolerances: float64 runs reach their optimum (cost ≤ 1e-9); a float32 run that says "converged"
is within 1 mm of the float64 optimum (plane registration) or within 1e-6 relative of its cost
plus the float32 floor (chains). The host ρ (Jacobian in float64) equals the simulator's
(Jacobian in float32) within RHO_RTOL relative.
"""

from __future__ import annotations

import json
import runpy
import shutil
import warnings

import numpy as np
import pytest

import fgc
from fgc.compile import compile_graph
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Point3, Pose2, Pose3, Rot3
from fgc.ir import conditioning
from fgc.ir.conditioning import PrecisionLimitWarning
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import sim
from fgc_backends.sim.emitter import emit


def chain(offset: float, sigma: float, n: int = 10) -> fgc.Graph:
    """A Pose2 chain with a prior on x0 at (offset, offset) and odometry of 1 m, every noise
    isotropic σ; initial values perturbed by 0.3 m and 0.1 rad."""
    rng = np.random.default_rng(3)
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"x{i}", Pose2(offset + i + rng.normal(0, 0.3), offset + rng.normal(0, 0.3),
                                      rng.normal(0, 0.1)))
    g.add(PriorFactor("x0", Pose2(offset, offset, 0.0), fgc.noise.isotropic(3, sigma)))
    for i in range(n - 1):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0),
                            fgc.noise.isotropic(3, sigma)))
    return g


def runs(graph: fgc.Graph, local_frame: bool = True):
    program = compile_graph(graph, SolverConfig(), local_frame=local_frame)
    data = problem_data(graph, program)
    f64 = sim.run(program, data)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        f32 = sim.run(program, data, precision="float32")
    return f64, f32, [w for w in caught if issubclass(w.category, PrecisionLimitWarning)]


@pytest.mark.parametrize("offset, sigma", [(1e6, 0.1), (0.0, 1e-9)],
                         ids=["1e6-m-from-the-origin-world-frame", "sigma-1e-9"])
def test_float32_beyond_its_resolution_says_it_did_not_converge(offset, sigma):
    """Solved in world coordinates (``local_frame=False``: what a problem the local frame
    cannot move gets, tests/test_frame.py), or with a σ no frame helps."""
    f64, f32, warned = runs(chain(offset, sigma), local_frame=False)
    assert f64.converged and f64.final_error <= 1e-9  # the optimum is exact
    # measured before: "converged" (reason "step") at 352.4 (1e6 m), 2.85e4 (σ = 1e-9)
    assert f32.final_error > 1.0
    assert f32.status == "failed" and f32.reason == "precision_limit", (f32.status, f32.reason)
    assert not f32.converged
    assert len(warned) == 1 and "cannot place variable 'x" in str(warned[0].message)
    assert "recentre" in f32.message
    # no false alarm: the same chain at the origin with σ = 0.1 converges, without a warning
    _, near, warned = runs(chain(0.0, 0.1))
    assert near.converged and not warned and not near.warnings and near.final_error <= 1e-6


@fgc.factor
def plane_distance(pose: Pose3, *, point: Point3, normal: Point3, offset: float):
    """Signed distance of the body-frame ``point``, mapped to the world by ``pose``, from the
    plane n·x + d = 0 (point-to-plane registration)."""
    return [normal.dot(pose.transformFrom(point)) + offset]


def plane_registration(origin: np.ndarray, n_points: int = 60, sigma: float = 0.01):
    """One Pose3 registered to planes around ``origin`` by point-to-plane residuals (exact data:
    zero residual at the true pose); initial pose 0.5 m and ~0.03 rad off."""
    rng = np.random.default_rng(7)
    truth = Pose3(Rot3.Expmap(np.array([0.1, -0.05, 0.3])), origin)
    g = fgc.Graph()
    g.add_variable("T", Pose3(Rot3.Expmap(np.array([0.12, -0.04, 0.33])),
                              origin + np.array([0.5, -0.3, 0.2])))
    for _ in range(n_points):
        normal = rng.normal(size=3)
        normal /= np.linalg.norm(normal)
        body = rng.uniform(-10, 10, size=3)
        world = truth.transformFrom(Point3(*body))
        g.add(plane_distance("T", point=Point3(*body), normal=Point3(*normal),
                             offset=-float(normal @ np.asarray(world.v, float).reshape(-1)),
                             noise=fgc.noise.isotropic(1, sigma)))
    return g, truth


def test_plane_registration_far_from_the_origin_is_not_silently_off():
    """1e5 m from the origin (float32 resolution 7.8 mm, σ = 1 cm): float32 either reaches the
    true pose within 1 mm or says it did not (before: "converged" about 1 cm off, no warning)."""
    graph, truth = plane_registration(np.array([1e5, 2e4, 30.0]))
    f64, f32, warned = runs(graph)
    assert f64.converged and float(np.linalg.norm(truth.local(f64.values["T"]))) <= 1e-6
    off = float(np.linalg.norm(truth.local(f32.values["T"])[3:]))
    assert (f32.converged and off <= 1e-3) or (
        not f32.converged and f32.reason == "precision_limit" and warned), (f32.status, off)
    # no false alarm near the origin: float32 converges to the true pose
    graph, truth = plane_registration(np.array([3.0, -2.0, 1.0]))
    _, near, warned = runs(graph)
    assert near.converged and not warned
    assert float(np.linalg.norm(truth.local(near.values["T"]))) <= 1e-4


# --------------------------------------------------------------------------------------------
# the same verdict on the host: native solver, C simulation, fgc run --backend native
# --------------------------------------------------------------------------------------------

RHO_RTOL = 1e-6  # host ρ (float64 Jacobian) vs the simulator's (float32); measured ≤ 5.6e-8

CASES = {  # name → (graph, True when ρ ≥ 1 in float32); solved in world coordinates
    "1e6-m-from-the-origin": (lambda: chain(1e6, 0.1), True),
    "sigma-1e-9": (lambda: chain(0.0, 1e-9), True),
    "plane-1e5-m": (lambda: plane_registration(np.array([1e5, 2e4, 30.0]))[0], True),
    "near-the-origin": (lambda: chain(0.0, 0.1), False),
}


@pytest.mark.parametrize("name", list(CASES))
def test_host_resolution_equals_the_simulators(name, tmp_path):
    """The host ρ (fgc.ir.conditioning.resolution on the Program's float64 linearisation) is the
    simulator's ρ at the simulator's float32 solution, and names the same variable."""
    from fgc.ir.datafile import write_data
    from fgc_backends.cfamily.results import whitened_jacobians

    build, beyond = CASES[name]
    graph = build()
    program = compile_graph(graph, SolverConfig(), local_frame=False)
    data = problem_data(graph, program)
    write_data(data, tmp_path / "data.txt")
    module = emit(program, tmp_path / "sim")[0]
    raw = runpy.run_path(str(module), run_name="fgc_rho_test")["run"](
        str(tmp_path / "data.txt"), None, "float32")
    storage = [np.asarray(v["value"], dtype=np.float64) for v in raw["values"].values()]
    rho, variable = conditioning.resolution(whitened_jacobians(program, data, storage), storage,
                                            [v.dim for v in program.variables], "float32")
    assert rho == pytest.approx(raw["resolution"]["rho"], rel=RHO_RTOL)
    assert variable == raw["resolution"]["variable"]
    assert (rho >= conditioning.RESOLUTION_LIMIT) is beyond, rho


SPEC = """
import numpy as np

import fgc
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2


def build(offset: float = 0.0, sigma: float = 0.1, n: int = 10):
    rng = np.random.default_rng(3)
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"x{i}", Pose2(offset + i + rng.normal(0, 0.3),
                                      offset + rng.normal(0, 0.3), rng.normal(0, 0.1)))
    g.add(PriorFactor("x0", Pose2(offset, offset, 0.0), fgc.noise.isotropic(3, sigma)))
    for i in range(n - 1):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0),
                            fgc.noise.isotropic(3, sigma)))
    return g
"""


def _native_cli(tmp_path, capsys, *params):
    from fgc.app.cli import main

    spec = tmp_path / "f32chain.py"
    spec.write_text(SPEC)
    out = tmp_path / "run.json"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        code = main(["run", str(spec), "--backend", "native", "--json", str(out),
                     *[a for p in params for a in ("-p", p)]])
    warned = [w for w in caught if issubclass(w.category, PrecisionLimitWarning)]
    return code, json.loads(out.read_text()), capsys.readouterr().out, warned


@pytest.mark.skipif(shutil.which("g++") is None, reason="no g++")
def test_native_run_beyond_float32_fails_with_the_reason(tmp_path, capsys):
    """fgc run --backend native (float32, the default) on the chain with σ = 1e-9: exit 1,
    status failed, reason precision_limit, the simulator's warning. 1e6 m from the origin
    (before the local frame: exit 1, precision_limit) and at the origin it converges without a
    warning."""
    code, report, out, warned = _native_cli(tmp_path, capsys, "sigma=1e-9")
    assert (code, report["status"]) == (1, "failed"), out
    assert report["reason"] == "precision_limit"
    assert "precision_limit" in out and "cannot place variable 'x" in out
    assert len(warned) == 1 and "recentre" in str(warned[0].message)
    assert report["final_error"] > 1.0
    for offset in ("offset=1e6", "offset=0"):
        code, report, out, warned = _native_cli(tmp_path, capsys, offset)
        assert (code, report["status"]) == (0, "converged") and not warned, out
        assert report["final_error"] <= 1e-6


def _native(graph):
    from fgc_backends import native

    program = compile_graph(graph, SolverConfig(precision="float32"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = native.run(program, problem_data(graph, program))
    return result, [w for w in caught if issubclass(w.category, PrecisionLimitWarning)]


@pytest.mark.heavy
@pytest.mark.skipif(shutil.which("g++") is None, reason="no g++")
def test_native_sigma_1e_9_says_it_did_not_converge():
    """σ = 1e-9 (before: native "converged", reason "step")."""
    result, warned = _native(chain(0.0, 1e-9))
    assert (result.status, result.reason) == ("failed", "precision_limit")
    assert not result.converged and result.final_error > 1.0
    assert len(warned) == 1 and result.message == str(warned[0].message)
    assert result.resolution >= 1.0 and result.warnings == (result.message,)


@pytest.mark.heavy
@pytest.mark.skipif(shutil.which("g++") is None, reason="no g++")
def test_native_plane_registration_far_from_the_origin_is_not_silently_off():
    """The plane registration 1e5 m from the origin: native float either reaches the true pose
    within 1 mm or says it did not (before: "converged" without a warning); near the origin it
    converges to the true pose within 1e-4 without a warning."""
    graph, truth = plane_registration(np.array([1e5, 2e4, 30.0]))
    result, warned = _native(graph)
    off = float(np.linalg.norm(truth.local(result.values["T"])[3:]))
    assert (result.converged and off <= 1e-3) or (
        result.reason == "precision_limit" and not result.converged and warned), (
        result.status, off)
    graph, truth = plane_registration(np.array([3.0, -2.0, 1.0]))
    near, warned = _native(graph)
    assert near.converged and not warned and near.resolution < 1.0
    assert float(np.linalg.norm(truth.local(near.values["T"]))) <= 1e-4


@pytest.mark.heavy
@pytest.mark.skipif(shutil.which("g++") is None, reason="no g++")
def test_csim_1e6_m_from_the_origin_says_it_did_not_converge(tmp_path):
    """The C simulation (make csim, float kernel) of the chain 1e6 m from the origin: checked
    against the float64 reference the testbench refuses it (HlsMismatchError naming the first
    mismatch; before: an "internal error" saying the build failed); unchecked, the parsed result
    says failed / precision_limit with the warning (before: "converged")."""
    from fgc_backends import hls
    from fgc_backends.hls.build import HlsMismatchError

    graph = chain(1e6, 0.1)
    program = compile_graph(graph, SolverConfig(precision="float32"), local_frame=False)
    project = hls.emit(program, tmp_path / "project", hls.HlsConfig(scalar="float"))
    data = problem_data(graph, program)
    # against the float64 reference, the self-checking testbench says no (exit 4), by name
    with pytest.raises(HlsMismatchError, match=r"differs from the reference \(reference.txt\): "
                                               r"variable x\d+: rotation differs"):
        hls.run_csim(project, program, data)
    # and without it, the host's verdict on the parsed result
    with pytest.warns(PrecisionLimitWarning, match="cannot place variable 'x"):
        result = hls.run_csim(project, program, data, reference=False)
    assert (result.status, result.reason) == ("failed", "precision_limit")
    assert result.final_error > 1.0


# --------------------------------------------------------------------------------------------
# the float32 Householder step
# --------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def linear(tmp_path_factory):
    """The emitted simulator's linear-algebra module."""
    graph = chain(0.0, 0.1, n=3)
    files = emit(compile_graph(graph, SolverConfig()), tmp_path_factory.mktemp("sim"))
    return runpy.run_path(str(files[0]), run_name="fgc_float32_test")["LIB"].linear


@pytest.mark.parametrize("tiny", [1e-20, 1e-25, 1e30])
def test_householder_on_a_tiny_or_huge_column_stays_finite(linear, tiny):
    """A non-zero column of 1e-20: v·v = 1e-40 is below float32's normal range (before:
    τ = 2/v·v = inf and R full of NaN); a column of 1e30: v·v overflows."""
    rng = np.random.default_rng(1)
    m = rng.normal(size=(6, 4))
    m[:, 0] *= tiny
    r32 = linear.qr_r(m.astype(np.float32))
    assert r32.dtype == np.float32 and np.all(np.isfinite(r32))
    r64 = np.linalg.qr(m, mode="r")
    # R is unique up to the sign of each row
    signs = np.sign(np.diag(r64)) * np.sign(np.diag(r32.astype(np.float64)))
    np.testing.assert_allclose(r32 * signs[:, None], r64, rtol=1e-5,
                               atol=1e-5 * np.abs(r64).max(axis=1, keepdims=True).min())
    assert abs(r32[0, 0]) == pytest.approx(np.linalg.norm(m[:, 0]), rel=1e-6)


DRIVER = r"""
#include "KERNEL"
#include <cstdio>
// stdin: m w f, then m rows of w + 1 numbers; stdout: 1 (0: refused as rank deficient), then
// the f rows of the conditional [R | d] that step 0 stores
int main() {
    int m = 0, w = 0, f = 0;
    if (std::scanf("%d %d %d", &m, &w, &f) != 3) return 2;
    static fgc::T W[fgc::MAX_ROWS][fgc::MAX_LD];
    for (int i = 0; i < m; ++i) {
        for (int c = 0; c <= w; ++c) {
            double v = 0;
            if (std::scanf("%lf", &v) != 1) return 2;
            W[i][c] = fgc::T(v);
        }
    }
    if (fgc::STEP_W[0] != w || fgc::STEP_F[0] != f) return 3;
    const bool ok = fgc::householder<fgc::MAX_LD, fgc::MAX_ROWS>(W, m, w, f, 0, nullptr);
    std::printf("%d\n", ok ? 1 : 0);
    for (int i = 0; ok && i < f; ++i) {
        for (int c = 0; c <= w; ++c) {
            std::printf(" %.9g", static_cast<double>(fgc::COND[fgc::STEP_COND_OFF[0] +
                                                                i * (w + 1) + c]));
        }
        std::printf("\n");
    }
    return 0;
}
"""


@pytest.fixture(scope="module")
def hls_householder(tmp_path_factory):
    """The float kernel's householder (step 0 of a Pose2 chain: 6 columns, 3 frontal, 6 rows),
    driven by a host program that includes the kernel source."""
    import shutil
    import subprocess

    from fgc_backends import native

    if shutil.which("g++") is None:
        pytest.skip("no g++")
    folder = tmp_path_factory.mktemp("hh")
    program = compile_graph(chain(0.0, 0.1, n=3), SolverConfig(method="gn"))
    # the native CPU program's householder; the accelerator's QR is the unit header fgc_qr.h,
    # tested by tests/hls/test_hls_units.py
    project = native.emit(program, folder / "project", native.NativeConfig(scalar="float"))
    source = folder / "driver.cpp"
    source.write_text(DRIVER.replace("KERNEL", str(project.directory / f"{project.name}.cpp")))
    subprocess.run(["g++", "-std=c++17", "-O2", "-ffp-contract=off", "-Wno-unknown-pragmas",
                    "-I", str(project.directory / "include"),  # fgc_lm.h, shared LM control
                    str(source), "-o", str(folder / "driver")], check=True)

    def run(matrix: np.ndarray):
        text = "6 6 3\n" + "\n".join(" ".join(repr(float(v)) for v in row) for row in matrix)
        out = subprocess.run([str(folder / "driver")], input=text + "\n", capture_output=True,
                             text=True, check=True).stdout.splitlines()
        return out[0] == "1", np.array([[float(v) for v in line.split()] for line in out[1:]])

    return run


@pytest.mark.parametrize("size", [1e-20, 1e-22, 1e25])
def test_hls_householder_on_tiny_or_huge_columns(hls_householder, size):
    """A uniformly tiny (or huge) float system is well conditioned, yet the unscaled v·v
    underflowed (overflowed) and the kernel refused it as rank deficient. Scaled, R matches
    float64 QR of the same numbers to float precision (measured 1.3e-7 relative to each row)."""
    rng = np.random.default_rng(1)
    m = (rng.normal(size=(6, 7)) * size).astype(np.float32).astype(np.float64)
    ok, r = hls_householder(m)
    assert ok
    r64 = np.linalg.qr(m, mode="r")[:3]
    signs = np.sign(np.diag(r64[:, :3])) * np.sign(np.diag(r[:, :3]))
    scale = np.abs(r64).max(axis=1, keepdims=True)
    assert np.max(np.abs(r * signs[:, None] - r64) / scale) <= 1e-6
