"""HLS backend, without building the examples: printer, lint, limits, name safety, determinism.

The C simulation and native runs of the examples are in ``test_hls_csim.py``.
"""

from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import fgc
from fgc import Pose2
from fgc.app.specs import example  # noqa: E402
from fgc.compile import compile_graph
from fgc.frontend import noise
from fgc.frontend.factors import PriorFactor
from fgc.frontend.geometry import special
from fgc.ir.datafile import problem_data
from fgc.ir.program import KernelText, Program
from fgc_backends.cfamily.names import comment, identifier
from fgc_backends.cfamily.printer import HlsCodePrinter
from fgc_backends.hls import (
    HlsConfig,
    HlsConfigError,
    HlsLintError,
    UnsupportedExpressionError,
    emit,
    lint_source,
    run_csim,
)
from fgc_backends.hls.lint import lint_files

pose_graph = example("pose_graph")

ROOT = Path(__file__).resolve().parents[2]


EVIL = 'ev"il*/ \n#include <stdio.h>\r[exec rm -rf x] $HOME ${X} \\ `id` \x07 é /* '


@pytest.fixture(scope="module")
def pose3_program() -> Program:
    return compile_graph(pose_graph.build("pose3example.txt"), name="pose3example")


# ---- printer ---------------------------------------------------------------------------------


def test_printer_keeps_arithmetic_in_the_scalar_type():
    x, y = sp.symbols("x y", real=True)
    p = HlsCodePrinter({x: "in[0]", y: "t1"})
    assert p.doprint(x / 2) == "(T(0.5))*in[0]"
    assert p.doprint(x**2) == "(in[0]*in[0])"
    assert p.doprint(1 / y**2) == "(T(1)/(t1*t1))"
    assert p.doprint(sp.sqrt(x)) == "fgc_sqrt(in[0])"
    assert p.doprint(x ** sp.Rational(-3, 2)) == "(T(1)/(fgc_sqrt(in[0])*in[0]))"  # bearing-range
    assert p.doprint(y ** sp.Rational(5, 2)) == "(fgc_sqrt(t1)*t1*t1)"
    assert p.doprint(sp.Rational(1, 3) * y) == "(T(0.3333333333333333))*t1"
    assert p.doprint(special.lie_A(x * x)) == "lie_A((in[0]*in[0]))"
    assert p.doprint(sp.atan2(y, x)) == "fgc_atan2(t1, in[0])"


@pytest.mark.parametrize("expr", [sp.Max(sp.Symbol("x"), 1), sp.Symbol("x") ** sp.Rational(1, 3),
                                  sp.Symbol("x") ** 20, sp.Symbol("x") ** sp.Rational(19, 2),
                                  sp.Symbol("x") ** sp.Float(1.5), sp.gamma(sp.Symbol("x"))])
def test_printer_refuses_what_it_cannot_print(expr):
    with pytest.raises(UnsupportedExpressionError):
        HlsCodePrinter({sp.Symbol("x"): "in[0]"}).doprint(expr)


def test_unknown_symbol_is_refused():
    with pytest.raises(UnsupportedExpressionError, match="symbol"):
        HlsCodePrinter({}).doprint(sp.Symbol("user_name"))


# ---- lint ------------------------------------------------------------------------------------

BAD = {
    "alloc": "void f() { int* p = new int[3]; delete[] p; }",
    "stl": "#include <vector>\nvoid f() { std::vector<int> v; }",
    "recursion": "int f(int n) { return n ? g(n - 1) : 0; }\nint g(int n) { return f(n); }",
    "unbounded": "void f(int n) { while (n > 0) --n; }",
    "tripcount": "void f(int n, float* a) { for (int i = 0; i < n; ++i) a[i] = 0; }",
}


@pytest.mark.parametrize("rule", sorted(BAD))
def test_lint_catches(rule):
    assert rule in {i.rule for i in lint_source(BAD[rule])}


def test_lint_accepts_bounded_loops_and_ignores_comments():
    ok = """// new malloc std::vector while
const int N = 4;
void f(int n, float* a) {
    for (int i = 0; i < N; ++i) a[i] = 0;
    for (int i = 0; i < n; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=4
        a[i] = 1;
    }
    const char* s = "while (1) new";
    (void)s;
}"""
    assert lint_source(ok) == []


# ---- limits and unsupported kernels ----------------------------------------------------------


def test_window_above_the_backend_maximum_fails_at_emit(tmp_path, pose3_program):
    with pytest.raises(HlsConfigError, match="max_variables"):
        emit(pose3_program, tmp_path, HlsConfig(max_variables=3))
    assert not list(tmp_path.iterdir())


def test_mixed_design_gets_a_double_linear_solver(tmp_path, pose3_program):
    solver = dataclasses.replace(pose3_program.solver, precision="float32",
                                 linear_precision="float64")
    project = emit(dataclasses.replace(pose3_program, solver=solver), tmp_path, name="p3")
    header = (tmp_path / "p3.h").read_text()
    assert "typedef float T;" in header and "typedef double L;" in header
    assert "namespace les {" in (tmp_path / "p3.cpp").read_text()
    plain = emit(pose3_program, tmp_path / "plain", name="p3")
    assert "typedef T L;" in (tmp_path / "plain" / "p3.h").read_text()
    assert "namespace les" not in (tmp_path / "plain" / "p3.cpp").read_text()
    assert project.files and plain.files


@pytest.mark.parametrize("config, needle", [
    (HlsConfig(linear_scalar="half"), "expected 'float' or 'double'"),
    (HlsConfig(scalar="double", linear_scalar="float"), "can only be widened"),
    (HlsConfig(scalar="ap_fixed<32,12>", linear_scalar="double"), "floating-point scalar"),
])
def test_bad_linear_scalar_is_refused(config, needle):
    with pytest.raises(HlsConfigError, match=needle):
        config.check()


def test_step_wider_than_the_backend_fails_at_emit(tmp_path, pose3_program):
    with pytest.raises(HlsConfigError, match="max_step_columns"):
        emit(pose3_program, tmp_path, HlsConfig(max_step_columns=6))


def test_unsupported_expression_fails_at_emit_naming_the_block(tmp_path, pose3_program):
    block = pose3_program.blocks[0]
    kernel = block.kernel.kernel()
    first = kernel.inputs[0]
    outputs = (sp.gamma(first) + kernel.outputs[0],) + tuple(kernel.outputs[1:])
    bad = dataclasses.replace(block, kernel=KernelText.of(
        type(kernel)(kernel.inputs, kernel.assignments, outputs)))
    program = dataclasses.replace(pose3_program, blocks=(bad, *pose3_program.blocks[1:]))
    with pytest.raises(UnsupportedExpressionError, match="block type 0.*gamma"):
        emit(program, tmp_path, HlsConfig())


@pytest.mark.parametrize("option", [{"scalar": "long double"}, {"scalar": "ap_fixed<16>"},
                                    {"part": "xc7z045; exec rm"}, {"clock_ns": 0.0},
                                    {"cxxflags": ("-O2", "$(shell id)")}])
def test_invalid_options_are_refused(tmp_path, pose3_program, option):
    with pytest.raises(HlsConfigError):
        emit(pose3_program, tmp_path, HlsConfig(**option))


def test_fixed_point_without_ap_types_is_a_clear_error(tmp_path, pose3_program, monkeypatch):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "hls4ml" else real(name, *a))
    from fgc_backends import native  # the CPU program has a fixed-point build; HLS refuses one
    with pytest.raises(native.NativeConfigError, match="hls4ml"):
        native.emit(pose3_program, tmp_path, native.NativeConfig(scalar="ap_fixed<32,12>"))


# ---- names -----------------------------------------------------------------------------------


def test_sanitisers():
    assert identifier(EVIL) == "ev_il_include_stdio_h_exec_rm_rf_x_home_x_id"
    assert identifier("3d") == "p_3d" and identifier("int") == "int_prj"
    assert identifier("") == "fgc_problem"
    text = comment(EVIL)
    for bad in ("*/", "/*", "\n", "\r", "\\", "$", "[", "`", '"', "#", "\x07"):
        assert bad not in text


def _hostile_graph() -> fgc.Graph:
    type_name = "odo" + EVIL.replace("/", "|")  # '/' would reach fgc's cache file names

    @fgc.factor(name=type_name)
    def odo(a: Pose2, b: Pose2, *, measured: Pose2):
        return measured.local(a.between(b))

    g = fgc.Graph()
    keys = [f"k{EVIL}{i}" for i in range(4)]
    for i, k in enumerate(keys):
        g.add_variable(k, Pose2(i * 1.0, 0.1 * i, 0.05 * i))
    g.add(PriorFactor(keys[0], Pose2(0.0, 0.0, 0.0), noise.isotropic(3, 0.1)))
    for i in range(3):
        g.add(odo(keys[i], keys[i + 1], measured=Pose2(1.0, 0.0, 0.0),
                  noise=noise.isotropic(3, 0.2), name="f" + EVIL))
    return g


def test_hostile_names_never_reach_the_emitted_files_raw(tmp_path):
    graph = _hostile_graph()
    program = compile_graph(graph, name="prj" + EVIL)
    project = emit(program, tmp_path / "out", HlsConfig(scalar="double"))
    for path in project.files:
        text = path.read_text()
        for line in text.splitlines():
            if "exec rm" in line or "include <stdio" in line:  # the hostile text, sanitised
                assert line.lstrip().startswith(("//", "#")), (path.name, line)
        for bad in ("[exec", "${X}", "`id`", '"il', "*/", "/*", "\x07", "\\ ", "é"):
            assert bad not in text, (path.name, bad)
    result = run_csim(project, program, problem_data(graph, program))
    assert result.converged and result.final_error < 1e-12


# ---- determinism -----------------------------------------------------------------------------


def test_emitting_twice_is_byte_identical(tmp_path, pose3_program):
    a = emit(pose3_program, tmp_path / "a", HlsConfig())
    b = emit(pose3_program, tmp_path / "b", HlsConfig())
    assert [p.name for p in a.files] == [p.name for p in b.files]
    for pa, pb in zip(a.files, b.files, strict=True):
        assert pa.read_bytes() == pb.read_bytes(), pa.name
    assert lint_files(p for p in a.files if p.suffix in (".h", ".cpp") and "tb_" not in p.name) \
        == []


def test_emitting_is_identical_across_hash_seeds(tmp_path):
    code = ("import sys; from fgc.app.specs import example; pose_graph = example('pose_graph'); "
            "from fgc.compile import compile_graph; from fgc_backends.hls import emit; "
            "p = compile_graph(pose_graph.build('pose3example.txt'), name='p3'); "
            "emit(p, sys.argv[1])")
    texts = []
    for seed in ("1", "2"):
        out = tmp_path / seed
        env = dict(os.environ, PYTHONHASHSEED=seed)
        subprocess.run([sys.executable, "-c", code, str(out)], env=env, check=True)
        texts.append({str(p.relative_to(out)): p.read_bytes() for p in sorted(out.rglob("*"))
                      if p.is_file()})
    # the five emitted files, the csim stand-in for hls_stream.h and the unit headers (this
    # backend's and the C-family ones it shares with the native solver)
    headers = len([*(ROOT / "backends" / "hls" / "include").glob("*.h"),
                   *(ROOT / "backends" / "cfamily" / "include").glob("*.h")])
    assert texts[0] == texts[1] and len(texts[0]) == 5 + 1 + headers


def test_lint_error_lists_the_issue(tmp_path, pose3_program, monkeypatch):
    import fgc_backends.hls.emitter as emitter

    monkeypatch.setattr(emitter, "SYNTHESISED", ("kernel.h.jinja", "kernel.cpp.jinja",
                                                 "tb.cpp.jinja"))
    with pytest.raises(HlsLintError, match="tb_p3.cpp"):  # the testbench reads files: host only
        emit(pose3_program, tmp_path, HlsConfig(), name="p3")


def test_top_function_has_interfaces(tmp_path, pose3_program):
    project = emit(pose3_program, tmp_path, HlsConfig(), name="p3")
    kernel = (tmp_path / "p3.cpp").read_text()
    for pragma in ("INTERFACE m_axi port=x_in", "INTERFACE s_axilite port=return",
                   "PIPELINE II=", "ALLOCATION operation instances=", "ARRAY_PARTITION",
                   "DATAFLOW"):
        assert f"#pragma HLS {pragma}" in kernel
    assert all(p.read_text().startswith("// generated from template")
               or p.read_text().startswith("# generated from template") for p in project.files)
    assert np.all([len(line) < 4000 for line in kernel.splitlines()])


def test_fixed_point_accelerator_is_refused_with_the_reason(tmp_path, pose3_program):
    with pytest.raises(HlsConfigError, match=r"float or double only: ap_fixed<40, ?16> has no"):
        emit(pose3_program, tmp_path, HlsConfig(scalar="ap_fixed<40,16>"))
