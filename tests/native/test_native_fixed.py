"""The native solver in ``ap_fixed<W,I>`` (fgc_backends.native; the HLS accelerator refuses fixed
point, tests/hls/test_hls.py).

- ``T`` is declared ``ap_fixed<W, I, AP_RND_CONV, AP_SAT>``: it rounds and saturates, never wraps;
- a constant the solver would hold outside the format's range is refused at emit time, naming
  the constant and the type (LM's default damping bound 1e10 used to wrap round to -7168), and
  nothing is written;
- data outside the range is refused before a solve, naming the variable or factor;
- floors and tolerances below one LSB are raised to one LSB (they would round to 0);
- a Pose2 loop solves in ``ap_fixed<40,16>`` to within 1e-4 of float64, with Cholesky and QR.

The ``ap_types`` headers come from the optional hls4ml package (``fgc[hls-fixed]``; CI installs
it); without them the tests that build are skipped, saying so.
"""

from __future__ import annotations

import numpy as np
import pytest

import fgc
from fgc import Pose2
from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends import native, sim
from fgc_backends.cfamily.errors import CodegenError
from fgc_backends.cfamily.scalars import (
    ap_types_include,
    check_fixed_constants,
    fixed_range,
    kernel_constants,
    lsb_floor,
)
from fgc_backends.native import NativeConfig, NativeConfigError

FIXED = "ap_fixed<40,16>"  # LSB 2^-24 ≈ 6e-8, range ±32768
FIXED_TOL = 1e-4  # every stored entry vs float64 (measured 6.2e-6 Cholesky, 6.7e-6 QR)


def _have_ap_types() -> bool:
    try:
        ap_types_include()
    except CodegenError:
        return False
    return True


needs_ap_types = pytest.mark.skipif(
    not _have_ap_types(), reason="ap_fixed needs Xilinx's ap_types headers from the optional "
    "hls4ml package, not installed (pip install 'fgc[hls-fixed]' or pip install --no-deps hls4ml)")


def pose2_loop() -> fgc.Graph:
    """The fixed-point example (examples/pose2_loop.py): 8 poses on a loop, a prior on 0."""
    return example("pose2_loop").build()


# ---- the checks themselves (no headers needed) -------------------------------------------------


def test_range_and_lsb_of_the_format():
    assert fixed_range("ap_fixed<40,16>") == (-32768.0, 32768.0 - 2.0 ** -24, 2.0 ** -24)
    assert fixed_range("ap_fixed<8,1>") == (-1.0, 1.0 - 2.0 ** -7, 2.0 ** -7)
    assert lsb_floor(1e-30, FIXED) == 2.0 ** -24
    assert lsb_floor(-1e-30, FIXED) == -(2.0 ** -24)
    assert lsb_floor(0.0, FIXED) == 0.0  # an exact zero stays zero
    assert lsb_floor(1e-3, FIXED) == 1e-3
    assert lsb_floor(1e-30, "double") == 1e-30  # floating point keeps tiny floors


def test_kernel_constants_are_named_or_located():
    text = "const T LAMBDA = T(1e10);\nx = y * T(2.5) + (-T(40000.0));\nconst int N = 3;\n"
    found = kernel_constants([("k.cpp", text)])
    assert found == [("LAMBDA", 1e10), ("T(2.5) at k.cpp:2", 2.5),
                     ("T(40000.0) at k.cpp:2", 40000.0)]
    with pytest.raises(NativeConfigError, match=r"constant LAMBDA = 10000000000\.0 does not fit "
                                                r"ap_fixed<40, 16> \(range -32768"):
        check_fixed_constants(FIXED, found, NativeConfigError)
    with pytest.raises(NativeConfigError, match=r"constant T\(40000\.0\) at k\.cpp:2"):
        check_fixed_constants(FIXED, found[1:], NativeConfigError)
    check_fixed_constants(FIXED, found[1:2], NativeConfigError)  # 2.5 fits
    check_fixed_constants("double", found, NativeConfigError)  # floating point holds them all


def test_without_ap_types_fixed_point_is_a_clear_error(tmp_path, monkeypatch):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "hls4ml" else real(name, *a))
    program = compile_graph(pose2_loop(), SolverConfig(linear="cholesky", lambda_upper_bound=1e4),
                            name="fx_none")
    with pytest.raises(NativeConfigError, match=r"hls4ml"):
        native.emit(program, tmp_path, NativeConfig(scalar=FIXED))


# ---- emitted and built -------------------------------------------------------------------------


@needs_ap_types
def test_a_constant_that_would_saturate_is_refused_naming_it(tmp_path):
    program = compile_graph(pose2_loop(), SolverConfig(linear="cholesky"), name="fx_bad")
    # LM's default bound 1e10 is far outside ±32768 (it used to wrap round to -7168)
    with pytest.raises(NativeConfigError, match=r"constant LAMBDA_UPPER_BOUND = 10000000000\.0 "
                                                r"does not fit ap_fixed<40, 16> \(range -32768"
                                                r".*SolverConfig\.lambda_upper_bound"):
        native.emit(program, tmp_path / "p", NativeConfig(scalar=FIXED))
    assert not (tmp_path / "p").exists()  # refused before anything is written
    # with enough integer bits the same bound fits: 2^(35-1) > 1e10
    native.emit(program, tmp_path / "q", NativeConfig(scalar="ap_fixed<64,35>"))


@needs_ap_types
def test_the_declaration_and_the_lsb_floors(tmp_path):
    program = compile_graph(pose2_loop(), SolverConfig(linear="cholesky", lambda_upper_bound=1e4),
                            name="fx_decl")
    native.emit(program, tmp_path, NativeConfig(scalar=FIXED))
    header = (tmp_path / "fx_decl.h").read_text()
    assert "typedef ap_fixed<40, 16, AP_RND_CONV, AP_SAT> T;" in header  # saturate, never wrap
    assert "leave the fixed type: computed in double" in header  # called out
    kernel = (tmp_path / "fx_decl.cpp").read_text()
    # MU_MIN (1e-30) and the cost tolerance (1e-14) are below one LSB 2^-24: raised to it
    assert "const T MU_MIN = T(5.960464477539063e-08);" in kernel
    assert "const T MU_MIN = T(1e-30);" not in kernel
    assert "ap_types" in (tmp_path / "Makefile").read_text()
    # in double the floors stay as the algorithm states them
    native.emit(program, tmp_path / "d", NativeConfig(scalar="double"))
    assert "const T MU_MIN = T(1e-30);" in (tmp_path / "d" / "fx_decl.cpp").read_text()


@needs_ap_types
@pytest.mark.parametrize("linear", ["cholesky", pytest.param("qr", marks=pytest.mark.heavy)])
def test_a_pose2_loop_solves_to_float64(linear):  # each ap_fixed build takes ~35 s of g++
    graph = pose2_loop()
    program = compile_graph(graph, SolverConfig(linear=linear, lambda_upper_bound=1e4),
                            name=f"fx_{linear}")
    data = problem_data(graph, program)
    reference = sim.run(program, data, precision="float64")
    result = native.run(program, data, NativeConfig(scalar=FIXED))
    assert result.converged and reference.converged
    worst = max(float(np.max(np.abs(result.storage[v.key] - reference.storage[v.key])))
                for v in program.variables)
    assert worst <= FIXED_TOL
    assert worst > 0.0  # it did run in fixed point: float64 agrees to ~1e-15, not exactly
    assert abs(result.final_error - reference.final_error) <= FIXED_TOL * reference.final_error


def _line(far: float, sigma: float) -> fgc.Graph:
    graph = fgc.Graph()
    for i, x in enumerate((0.0, 1.0, far)):
        graph.add_variable(i, Pose2(x, 0.0, 0.0))
    graph.add(PriorFactor(0, Pose2(0.0, 0.0, 0.0), noise.isotropic(3, 0.1)))
    for a in (0, 1):
        graph.add(BetweenFactor(a, a + 1, Pose2(1.0, 0.0, 0.0), noise.isotropic(3, sigma)))
    return graph


FAR_INITIAL = r"variable '2': initial value entry 0 = 40000\.0 does not fit ap_fixed<40, 16>"
STIFF_DATA = (r"factor instance 1 \(BetweenFactorPose2 on \['0', '1'\]\): data entry \d+ = "
              r"99999\.99.* does not fit")


def test_data_outside_the_format_is_named():
    """The check NativeSolver.flatten runs before every solve (no build needed here; the
    end-to-end refusal through a built library is the heavy test below)."""
    from fgc_backends.cfamily.scalars import check_fixed_data

    program = compile_graph(_line(4e4, 0.2), SolverConfig(linear="cholesky"), name="fx_far")
    with pytest.raises(NativeConfigError, match=FAR_INITIAL):
        check_fixed_data(FIXED, program, problem_data(_line(4e4, 0.2), program), NativeConfigError)
    with pytest.raises(NativeConfigError, match=STIFF_DATA):
        check_fixed_data(FIXED, program, problem_data(_line(2.0, 1e-5), program),
                         NativeConfigError)
    check_fixed_data(FIXED, program, problem_data(_line(2.0, 0.2), program), NativeConfigError)
    check_fixed_data("double", program, problem_data(_line(4e4, 1e-5), program),
                     NativeConfigError)  # floating point holds them


@needs_ap_types
@pytest.mark.heavy  # a ~35 s ap_fixed build
def test_data_outside_the_format_is_refused_before_a_solve():
    config = NativeConfig(scalar=FIXED)
    graph = _line(4e4, 0.2)  # the last pose starts 40 km away: beyond ±32768
    program = compile_graph(graph, SolverConfig(linear="cholesky", lambda_upper_bound=1e4),
                            name="fx_far")
    with pytest.raises(NativeConfigError, match=r"variable '2': initial value entry 0 = 40000\.0 "
                                                r"does not fit ap_fixed<40, 16>"):
        native.run(program, problem_data(graph, program), config)
    graph = _line(2.0, 1e-5)  # a square-root information 1/sigma = 1e5: beyond ±32768 too
    with pytest.raises(NativeConfigError, match=r"factor instance 1 \(BetweenFactorPose2 on "
                                                r"\['0', '1'\]\): data entry \d+ = 99999\.99"
                                                r".* does not fit"):
        native.run(program, problem_data(graph, program), config)
    result = native.run(program, problem_data(_line(2.0, 0.2), program), config)
    assert result.converged  # the same build takes data that fits
