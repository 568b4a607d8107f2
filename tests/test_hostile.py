"""Hostile input: every malformed file, value or name is a clear FgcError naming where it is,
or is sanitised on its way into emitted code.

- g2o/TORO files: short, malformed, non-finite, negative, huge, binary, self-loops, edges to
  missing or mistyped vertices → DataError naming ``file:line``;
- data files (fgc's reader and the simulator's own): missing lines, NaN, absurd counts,
  non-ASCII bytes, numbers beyond float32 → DataError naming the line;
- DSL values: non-rotations, σ whose information overflows, matrix sizes → DataError/DslError;
- names: keys, factor names, factor-type names and the problem name full of quotes, newlines,
  comment terminators, C preprocessor, shell and tcl metacharacters never reach the emitted
  Python, C++, tcl or Makefile raw; the simulator still solves the problem.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc import Point2, Pose2, Pose3, Rot2, Rot3
from fgc.app.cli import main as cli_main
from fgc.compile import compile_graph
from fgc.errors import DataError, DslError, FgcError
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.interop.datasets import read_pose_graph
from fgc.ir.datafile import problem_data, read_data, write_data
from fgc.ir.program import SolverConfig
from fgc_backends import sim

SE2 = "VERTEX_SE2 {} 0.0 0.0 0.0"
EDGE = "EDGE_SE2 {} {} 1.0 0.0 0.0 100 0 0 100 0 100"
QUAT_VERTEX = "VERTEX_SE3:QUAT 2 0 0 0 0 0 0 1"


def _file(tmp_path: Path, lines: list[str], name: str = "bad.g2o") -> Path:
    path = tmp_path / name
    path.write_text("\n".join(lines) + "\n")
    return path


# --------------------------------------------------------------------------------------------
# g2o / TORO
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("bad, needle", [
    ("VERTEX_SE2 1 0.0", "takes 4 fields after the tag .*got 2"),
    ("VERTEX_SE2 1 a b c", "VERTEX_SE2 x is 'a', not a number"),
    ("VERTEX_SE2 1.5 0 0 0", "id is '1.5', not a non-negative integer"),
    ("VERTEX_SE2 1 nan 0 0", "non-finite"),
    ("VERTEX_SE2 1 0 inf 0", "non-finite"),
    ("VERTEX_SE2 1 1e999 0 0", "non-finite"),
    ("VERTEX_SE2 -1 0 0 0", "id is '-1', not a non-negative integer"),
    ("VERTEX_SE2 " + "9" * 5000 + " 0 0 0", "does not fit a GTSAM key"),
    ("VERTEX_SE2 0 0 0 0", "declared twice"),
    ("EDGE_SE2 0 0 1 0 0 100 0 0 100 0 100", "to itself"),
    ("EDGE_SE2 0 7 1 0 0 100 0 0 100 0 100", "undeclared pose 'x7'"),
    # issue 34: BR lines went to GTSAM's reader unchecked and were misread
    ("BR 0 144.7 0.185 9.13 0.0349 0.1", r"BR landmark_id is '144\.7', not a non-negative"),
    ("BR 0 5 0.1 2 0.03 0.1 BR 1 5 0.2 2 0.03 0.1", r"BR takes 6 fields .*got 13 \(a trailing"),
    ("BR 0 5 0.1 2 0.03 0.1 7", "BR takes 6 fields"),
    ("EDGE_SE2 0 1 1 0 0 100 0 0 100 0 100 0", "EDGE_SE2 takes 11 fields"),
    ("EDGE2 0 1 1 0 0 100 0 100 100 0 0 x", "EDGE2 takes 11 fields"),
    ("BR 7 5 0.1 2 0.03 0.1", "BR refers to undeclared pose 'x7'"),
    ("BR 0 5 0.1 2 abc 0.1", "BR sigma_bearing is 'abc', not a number"),
    ("BR 0 5 0.1 2 0.03 -0.1", "BR sigma_range is -0.1; it must be positive"),
    ("VERTEX_SE3:QUAT 3 0 0 0 1e308 0 0 1", "quaternion .* non-finite norm"),
    ("EDGE_SE2 0 1 1 0 0 100 5 0 100 0 100", "fits neither layout GTSAM's load2D reads"),
    ("EDGE_SE2 0 1 1 0 0 -100 0 0 100 0 100", "variance c_xx is -100.0; it must be positive"),
    ("EDGE_SE2 0 1 1 0 0 100 0 0 100 0 nan", "non-finite"),
    ("EDGE2 0 1 1 0 0 100 0 100 100", "EDGE2 takes 11 fields"),
    ("VERTEX_SE3:QUAT 3 0 0 0 0 0 0 0", "quaternion .* has zero"),
    ("EDGE_SE2 0 2 1 0 0 100 0 0 100 0 100", "x2.*Pose3.*Pose2"),
])
def test_malformed_pose_graph_lines_name_file_and_line(tmp_path, bad, needle):
    path = _file(tmp_path, [SE2.format(0), SE2.format(1), QUAT_VERTEX, EDGE.format(0, 1), bad])
    with pytest.raises(DataError, match=rf"bad\.g2o:5: .*{needle}"):
        read_pose_graph(path)


def test_binary_and_empty_pose_graph_files(tmp_path):
    binary = tmp_path / "binary.g2o"
    binary.write_bytes(SE2.format(0).encode() + b"\n\xff\xfe\x00garbage\n")
    with pytest.raises(DataError, match=r"binary\.g2o:2: not a text file"):
        read_pose_graph(binary)
    with pytest.raises(DataError, match="no vertices found"):
        read_pose_graph(_file(tmp_path, ["# nothing here"], "empty.g2o"))
    with pytest.raises(DataError, match="no such file"):
        read_pose_graph(tmp_path / "missing.g2o")


def test_huge_vertex_ids_are_refused_by_line(tmp_path):
    # the graph is built by GTSAM's reader, whose keys are 64-bit: a bigger id is named, not
    # wrapped around
    big = 10**30
    path = _file(tmp_path, [SE2.format(big), SE2.format(big + 1), EDGE.format(big, big + 1)])
    with pytest.raises(DataError, match=r"bad\.g2o:1: VERTEX_SE2 id .* does not fit a GTSAM key"):
        read_pose_graph(path)


def test_cli_reports_a_malformed_pose_graph_in_one_line(tmp_path, capsys):
    path = _file(tmp_path, [SE2.format(0), "VERTEX_SE2 1 nan 0 0"])
    assert cli_main(["simulate", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "bad.g2o:2" in err


# --------------------------------------------------------------------------------------------
# spec files
# --------------------------------------------------------------------------------------------

GOOD_BUILD = """
import fgc
from fgc.frontend.factors import PriorFactor
def build(n=2):
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"x{i}", fgc.Pose2(i, 0.0, 0.0))
        g.add(PriorFactor(f"x{i}", fgc.Pose2(i, 0.0, 0.0), fgc.noise.isotropic(3, 0.1)))
    return g
"""


@pytest.mark.parametrize("source, params, needle", [
    ("def build(:\n", [], "the spec failed to load: SyntaxError"),
    ("import no_such_module_zqx\n", [], "failed to load: ModuleNotFoundError"),
    ("raise RuntimeError('boom')\n", [], "failed to load: RuntimeError: boom"),
    ("x = 1\n", [], "must define build(**params)"),
    ("build = 3\n", [], "must define build(**params)"),
    ("def build():\n    return None\n", [], "returned NoneType, not an fgc.Graph"),
    ("def build():\n    return 1 / 0\n", [], "build() failed at line 2: ZeroDivisionError"),
    ("def build(**kw):\n    raise ValueError(kw)\n", ["-p", "n=-3"], "ValueError: {'n': -3}"),
    (GOOD_BUILD, ["-p", "n=-1"], "the graph has no factors"),
    (GOOD_BUILD, ["-p", "n=2.5"], "'float' object cannot be interpreted as an integer"),
    (GOOD_BUILD, ["-p", "m=2"], "it takes: n=2"),
])
def test_broken_spec_files_are_one_line_errors(tmp_path, capsys, source, params, needle):
    spec = tmp_path / "spec.py"
    spec.write_text(source)
    assert cli_main(["simulate", str(spec), *params]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and str(spec) in err, err
    assert needle in err, err


def test_hostile_spec_file_name_is_sanitised_in_the_hls_project(tmp_path, capsys):
    name = 'ZQX"; rm -rf $HOME; `x`\n'.replace("\n", "_")  # no newline: a file name
    spec = tmp_path / f"{name}.py"
    spec.write_text(GOOD_BUILD)
    out = tmp_path / "hls"
    assert cli_main(["compile", str(spec), "--backend", "hls", "--out", str(out)]) == 0
    for path in out.iterdir():
        assert "ZQX" not in path.name or path.name.isprintable()
        if path.is_file():
            text = path.read_text(errors="replace")
            assert "rm -rf" not in text and '"; ' not in text.replace('"; "', ""), path


# --------------------------------------------------------------------------------------------
# data files
# --------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def small_problem():
    g = fgc.Graph()
    for i in range(3):
        g.add_variable(f"x{i}", Pose2(i, 0.0, 0.0))
    g.add(PriorFactor("x0", Pose2(0, 0, 0), fgc.noise.isotropic(3, 0.1)))
    for i in range(2):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1, 0, 0), fgc.noise.isotropic(3, 0.1)))
    program = compile_graph(g, SolverConfig())
    return g, program, problem_data(g, program)


def _corrupted(tmp_path: Path, data, line: int, text: str | None) -> Path:
    good = tmp_path / "good.txt"
    write_data(data, good)
    lines = good.read_text().splitlines()
    lines[line - 1:line] = [] if text is None else [text]
    bad = tmp_path / "bad.txt"
    bad.write_text("\n".join(lines) + "\n")
    return bad


@pytest.mark.parametrize("line, text, needle", [
    (3, None, r":\d+: (expected|file ends early|malformed)"),  # a missing variable line
    (4, "4 1.0 nan 1.0 0.0", r":4: non-finite number"),
    (4, "4 1.0 0.0 1.0", r":4: expected 4 numbers, found 3"),
    (4, "4 1.0 0x10 1.0 0.0", r":4: malformed numbers"),
    (2, "VARIABLES 99999999999999999999", r":6: malformed numbers"),  # reads on and on
    (2, "VARIABLES -3", r":2: expected 'VARIABLES <count>'"),
])
@pytest.mark.parametrize("reader", ["fgc", "simulator"])
def test_malformed_data_files_name_the_line(small_problem, tmp_path, line, text, needle, reader):
    _, program, data = small_problem
    bad = _corrupted(tmp_path, data, line, text)
    with pytest.raises(DataError, match=needle):
        if reader == "fgc":
            read_data(bad)
        else:
            sim.run(program, bad, tmp_path / "out")


@pytest.mark.parametrize("reader", ["fgc", "simulator"])
def test_non_ascii_data_file_names_the_line(small_problem, tmp_path, reader):
    _, program, data = small_problem
    bad = _corrupted(tmp_path, data, 4, "4 1.0 0.0 1.0 0.0 \u00e9")
    with pytest.raises(DataError, match=r":4: not an fgc data file"):
        read_data(bad) if reader == "fgc" else sim.run(program, bad, tmp_path / "out")


def test_number_beyond_float32_range_is_refused_for_float32(small_problem, tmp_path):
    _, program, data = small_problem
    bad = _corrupted(tmp_path, data, 4, "4 1e39 0.0 1.0 0.0")
    with pytest.raises(DataError, match=r"line 4: variable 1 .*float32 range.*'x1'"):
        sim.run(program, bad, tmp_path / "out", precision="float32")
    assert sim.run(program, bad, tmp_path / "out64").status != "failed"  # fine in float64


# --------------------------------------------------------------------------------------------
# DSL values and sizes
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("make, error, needle", [
    (lambda: fgc.Graph().add_variable("r", Rot3(np.full((3, 3), 1.0))), DataError,
     "'r' initial value is not a rotation"),
    (lambda: fgc.Graph().add_variable("p", Pose3(Rot3(2 * np.eye(3)), [0, 0, 0])), DataError,
     "not a rotation"),
    (lambda: fgc.Graph().add_variable("q", Pose2([0, 0], r=Rot2(3.0, 4.0))), DataError,
     "not a rotation"),
    (lambda: PriorFactor("x", Rot3(np.diag([1.0, 1.0, -1.0])), fgc.noise.isotropic(3, 1)),
     DataError, "measurement 'prior' is not a rotation"),
    (lambda: fgc.noise.isotropic(3, 1e-320), DataError, "information"),
    (lambda: fgc.noise.diagonal([1.0, 1e-320]), DataError, "information"),
    (lambda: fgc.noise.covariance(np.eye(2) * 1e-320), DataError, "information"),
    (lambda: fgc.noise.isotropic(-1, 1.0), DataError, "positive integer dimension"),
    (lambda: fgc.noise.diagonal([]), DataError, "must be positive"),
    (lambda: fgc.Matrix(-1, 3), DslError, "rows must be a positive integer"),
    (lambda: fgc.Matrix(3, 2.5), DslError, "cols must be a positive integer"),
    (lambda: fgc.Matrix(10**6, 10**6), DslError, "more than 4096 entries"),
    (lambda: fgc.Graph().add_variable(None, Point2([0, 0])), DslError, "str or int"),
    (lambda: SolverConfig(max_iterations=-1).check(), FgcError, "max_iterations"),
    (lambda: SolverConfig(lambda_initial=float("nan")).check(), FgcError, "lambda_initial"),
    (lambda: SolverConfig(ordering="auto; rm -rf /").check(), FgcError, "ordering"),
])
def test_hostile_values_are_clear_errors(make, error, needle):
    with pytest.raises(error, match=re.escape(needle) if "*" not in needle else needle):
        make()


def test_keys_that_collide_as_text_are_refused():
    g = fgc.Graph().add_variable(1, Point2([0, 0])).add_variable("1", Point2([1, 0]))
    g.add(PriorFactor(1, Point2([0, 0]), fgc.noise.isotropic(2, 1)))
    g.add(PriorFactor("1", Point2([0, 0]), fgc.noise.isotropic(2, 1)))
    with pytest.raises(DslError, match="collide as text"):
        compile_graph(g)


# --------------------------------------------------------------------------------------------
# names in emitted code
# --------------------------------------------------------------------------------------------

# Each hostile text carries the marker ZQX, so any trace of it in an emitted file can be found;
# what follows the marker there must be harmless.
HOSTILE = ['ZQX"quote', "ZQX'tick", "ZQX\nnewline", "ZQX*/ int evil; /*", "ZQX$(rm -rf /)",
           "ZQX[exec ls]", "ZQX${HOME}", "ZQX\\", "ZQX`id`", "ZQX#include <x>", "ZQX;|&",
           "ZQX}{", "ZQX%s%n", "ZQX\x00nul", "ZQX\u00e9\u6f22", "ZQX\r\n"]
DANGEROUS = re.compile(r"ZQX[^A-Za-z0-9_ ]*?[\"'\n\r\\$`\[\]{};|&#%*/\x00]")


@fgc.factor(name='odometry"ZQX*/\n#include <stdio.h> [exec rm -rf x] $HOME `id`')
def hostile_odometry(a: Pose2, b: Pose2, *, measured: Pose2):
    return measured.local(a.between(b))


def _hostile_graph() -> fgc.Graph:
    g = fgc.Graph()
    keys = [f"k{i}{text}" for i, text in enumerate(HOSTILE)]
    for i, key in enumerate(keys):
        g.add_variable(key, Pose2(i, 0.1 * i, 0.05 * i))
    for i in range(len(keys) - 1):
        g.add(hostile_odometry(keys[i], keys[i + 1], measured=Pose2(1, 0.1, 0.05),
                               noise=fgc.noise.isotropic(3, 0.1), name=HOSTILE[i]))
    g.add(BetweenFactor(keys[0], keys[-1], Pose2(15, 1.5, 0.75), fgc.noise.isotropic(3, 0.1),
                        name="ZQX\n*/ closure"))
    g.add(PriorFactor(keys[0], Pose2(0, 0, 0), fgc.noise.isotropic(3, 0.1), name='ZQX"\n'))
    return g


def _emitted_texts(folder: Path) -> dict[str, str]:
    return {f.name: f.read_text(errors="replace") for f in sorted(folder.rglob("*"))
            if f.is_file() and f.suffix not in (".txt", ".json", ".so", ".o")}


def _assert_sanitised(texts: dict[str, str]) -> None:
    assert texts
    for name, text in texts.items():
        assert not DANGEROUS.search(text), (name, DANGEROUS.search(text).group())
        for hostile in HOSTILE:
            assert hostile not in text, (name, hostile)


@pytest.fixture(scope="module")
def hostile_program():
    graph = _hostile_graph()
    return graph, compile_graph(graph, SolverConfig(), name='ZQX"name\n*/$(x)[y]')


def test_hostile_names_never_reach_the_simulator_raw(hostile_program, tmp_path):
    graph, program = hostile_program
    result = sim.run(program, problem_data(graph, program), tmp_path)
    assert result.converged and set(result.values) == {str(k) for k in graph.variables}
    _assert_sanitised(_emitted_texts(tmp_path))


def test_hostile_names_never_reach_the_hls_project_raw(hostile_program, tmp_path):
    from fgc_backends import hls

    _, program = hostile_program
    hls.emit(program, tmp_path)
    texts = _emitted_texts(tmp_path)
    assert any(name.endswith(".tcl") for name in texts) and "Makefile" in texts
    _assert_sanitised(texts)


def test_non_finite_solver_options_are_emitted_as_values(small_problem, tmp_path):
    """``inf`` has no Python literal: the simulator gets ``float("inf")``, not a NameError."""
    from dataclasses import replace

    _, program, data = small_problem
    program = replace(program, solver=replace(program.solver, lambda_upper_bound=float("inf")))
    result = sim.run(program, data, tmp_path)
    assert result.converged
