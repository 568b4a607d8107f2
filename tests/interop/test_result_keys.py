"""The emitted simulator's result file names each value by the user's variable key.

An int key is written as a JSON number and read back by fgc as an int, a str key as a string;
keys reach the emitted Python only as data (JSON text, hex-coded unless plain), so a key made to
break out of a string literal is just a key.
"""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.compile import compile_graph
from fgc.errors import FgcError
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Point2, Pose2
from fgc.ir.datafile import problem_data, write_data
from fgc.ir.stream import Incremental
from fgc_backends import sim

ODD = ['q"); open("PWNED", "w")  # ', "t'''\n", "back\\slash", "new\nline", "ключ 漢",
       "{{ jinja }}", "${HOME}", "-1", "7", " "]


def _chain(keys: list) -> fgc.Graph:
    g = fgc.Graph()
    for i, k in enumerate(keys):
        g.add_variable(k, Pose2(1.1 * i, 0.1 * i, 0.05 * i))
    noise = fgc.noise.isotropic(3, 0.1)
    g.add(PriorFactor(keys[0], Pose2(0, 0, 0), noise))
    for a, b in zip(keys[:-1], keys[1:], strict=True):
        g.add(BetweenFactor(a, b, Pose2(1, 0, 0), noise))
    return g


def _run_standalone(graph: fgc.Graph, out: Path):
    """Compile, emit and run the simulator as its own program; (program, result.json path,
    the emitted files)."""
    program = compile_graph(graph)
    files = sim.emit(program, out)
    write_data(problem_data(graph, program), out / "data.txt")
    subprocess.run([sys.executable, str(files[0]), str(out / "data.txt"),
                    str(out / "result.json")], check=True, capture_output=True, cwd=out)
    return program, out / "result.json", files


@pytest.mark.parametrize("keys", [[0, 1, 2, 10], [-3, 5, 1000000007]], ids=["ints", "negative"])
def test_int_keys_are_json_numbers_and_come_back_as_ints(keys, tmp_path):
    graph = _chain(keys)
    program, path, _ = _run_standalone(graph, tmp_path)
    raw = json.loads(path.read_text())
    assert list(raw["values"]) == [str(k) for k in keys]  # the Program's variable order
    assert [v["key"] for v in raw["values"].values()] == keys
    assert all(type(v["key"]) is int and v["type"] == "Pose2" for v in raw["values"].values())
    result = sim.read_result(program, path)
    assert list(result.user_values) == keys and all(type(k) is int for k in result.user_values)
    reference = sim.run(program, problem_data(graph, program))
    for k in keys:
        np.testing.assert_array_equal(result.storage[str(k)], reference.storage[str(k)])
        assert type(result.values[str(k)]) is Pose2
    assert result.converged and result.final_error == reference.final_error


def test_str_and_int_keys_in_one_graph(tmp_path):
    g = _chain(["x0", 1, "x2"])
    g.add_variable("landmark", Point2(2.0, 1.0))
    g.add_variable(42, Point2(0.5, 0.5))
    g.add(PriorFactor("landmark", Point2(2.0, 1.1), fgc.noise.isotropic(2, 0.1)))
    g.add(PriorFactor(42, Point2(0.5, 0.4), fgc.noise.isotropic(2, 0.1)))
    program, path, _ = _run_standalone(g, tmp_path)
    raw = json.loads(path.read_text())
    assert {k: (v["key"], v["type"]) for k, v in raw["values"].items()} == {
        "x0": ("x0", "Pose2"), "1": (1, "Pose2"), "x2": ("x2", "Pose2"),
        "landmark": ("landmark", "Point2"), "42": (42, "Point2")}
    values = sim.read_result(program, path).user_values
    assert set(values) == {"x0", 1, "x2", "landmark", 42}
    np.testing.assert_allclose(values[42].to_storage(), [0.5, 0.4], atol=1e-9)


def test_odd_str_keys_are_data_in_the_emitted_code(tmp_path):
    keys = [f"{text}" for text in ODD]
    program, path, files = _run_standalone(_chain(keys), tmp_path)
    assert not (tmp_path / "PWNED").exists()
    raw = json.loads(path.read_text())
    assert [v["key"] for v in raw["values"].values()] == keys
    assert list(sim.read_result(program, path).user_values) == keys
    module = files[0].read_text()
    ast.parse(module)
    for text in ODD:  # plain keys may appear as their JSON text; none other appears at all
        if text.strip() and not text.lstrip("-").isdigit():
            assert text not in module or text.isidentifier(), text
    table = next(node for node in ast.walk(ast.parse(module))
                 if isinstance(node, ast.Dict) and any(
                     isinstance(k, ast.Constant) and k.value == "variables" for k in node.keys))
    entries = ast.literal_eval(table.values[[k.value for k in table.keys].index("variables")])
    assert all(text.isascii() and "\\" not in text and "\n" not in text for text, _ in entries)
    assert entries[0][0].startswith("hex:") and entries[-2] == ('"7"', "Pose2")


def test_incremental_updates_are_keyed(tmp_path):
    keys = [0, 1, 2, 3, 4, 5]
    graph = _chain(keys)
    program = compile_graph(graph, fgc.ir.program.SolverConfig(incremental_k=2))
    result = sim.run(program, problem_data(graph, program), tmp_path,
                     policy=Incremental(2))
    raw = json.loads((tmp_path / "result.json").read_text())
    first = raw["incremental"][0]["values"]
    assert first and all(type(v["key"]) is int for v in first.values())
    assert set(first) < set(raw["values"]) and set(result.updates[0]["values"]) == set(first)


def test_a_result_of_another_program_is_refused(tmp_path):
    _, path, _ = _run_standalone(_chain([0, 1, 2]), tmp_path / "a")
    other = compile_graph(_chain(["0", "1", "2"]))  # same text, str keys
    with pytest.raises(FgcError, match="key '0'.*another Program"):
        sim.read_result(other, path)
    bigger = compile_graph(_chain([0, 1, 2, 3]))
    with pytest.raises(FgcError, match="no value for variable '3'"):
        sim.read_result(bigger, path)
    (tmp_path / "old.json").write_text(json.dumps({"format": "fgc-sim-result 1", "values": []}))
    with pytest.raises(FgcError, match="old.json: not an fgc simulator result"):
        sim.read_result(other, tmp_path / "old.json")


def test_the_program_json_keeps_int_keys():
    from fgc.ir.program import Program

    program = compile_graph(_chain([3, 4]))
    again = Program.from_json(program.to_json())
    assert [v.user_key for v in again.variables] == [3, 4] and again == program
    str_keyed = compile_graph(_chain(["3", "4"]))
    assert "int_key" not in str_keyed.to_json()  # str-keyed Programs' JSON is as before
    assert [v.user_key for v in Program.from_json(str_keyed.to_json()).variables] == ["3", "4"]
    assert str_keyed.structure_fingerprint == program.structure_fingerprint  # same data layout
