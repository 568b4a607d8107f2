"""fgc report: text, JSON and HTML views of one compiled design; user strings escaped in HTML;
consistent --help and one-line usage errors across every command."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import pytest

from fgc.app.cli import EXIT_BAD_INPUT, EXIT_OK, build_parser, main
from fgc.app.design_report import Section, format_table, render_html

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
POSE3 = [str(EXAMPLES / "pose_graph.py"), "-p", "dataset=pose3example.txt"]
COMMANDS = ("compile", "simulate", "verify", "run", "report", "sweep")


def test_report_with_given_iterations_skips_the_simulator(tmp_path, capsys):
    out = tmp_path / "r.json"
    code = main(["report", *POSE3, "--linear", "cholesky", "--iterations", "3",
                 "--json", str(out)])
    text = capsys.readouterr().out
    assert code == EXIT_OK
    r = json.loads(out.read_text())
    assert r["solve"] == {"source": "--iterations", "iterations": 3}
    assert r["cost"]["iterations"] == 3 and r["storage"]["solver"] == "cholesky"
    assert len(r["storage"]["steps"]) == 3
    assert r["cost"]["cycles"] == sum(r["cost"]["cycles_by_unit"].values())
    for block in r["blocks"]:
        assert set(block["ops"]) == {"unshared", "separate", "fused", "cost_mode"}
        assert block["ops"]["fused"]["total"] <= block["ops"]["unshared"]["total"]
    assert r["schedule"]["steps"] >= r["schedule"]["sequential_levels"] >= 1
    for title in ("Factor blocks", "Schedule", "Storage of the linear system (cholesky)",
                  "Modelled cycles by phase", "Resources on xc7z045"):
        assert title in text
    assert "3 iterations (--iterations)" in text


def test_report_costs_the_simulators_iterations(tmp_path, capsys):
    html = tmp_path / "r.html"
    assert main(["report", *POSE3, "--json", str(tmp_path / "r.json"),
                 "--html", str(html)]) == EXIT_OK
    r = json.loads((tmp_path / "r.json").read_text())
    assert r["solve"]["source"] == "simulator" and r["solve"]["status"] == "converged"
    assert r["cost"]["iterations"] == r["solve"]["iterations"] >= 1
    page = html.read_text()
    assert page.startswith("<!DOCTYPE html>") and "do not edit" in page
    assert "Modelled cycles by phase" in page and "<script" not in page
    assert "http://" not in page and "https://" not in page  # self-contained
    if importlib.util.find_spec("matplotlib"):
        assert page.count('src="data:image/png;base64,') == 2  # latency and storage figures


def test_html_escapes_user_strings(tmp_path, capsys):
    spec = tmp_path / "evil<b>&spec.py"
    spec.write_text(
        "import runpy\n"
        f"_pose_graph = runpy.run_path({str(EXAMPLES / 'pose_graph.py')!r})\n"
        "def build(note=''):\n"
        "    return _pose_graph['build'](dataset='pose3example.txt')\n")
    html = tmp_path / "r.html"
    code = main(["report", str(spec), "-p", "note=<script>alert('x')</script>",
                 "--iterations", "1", "--html", str(html)])
    assert code == EXIT_OK
    page = html.read_text()
    assert "<script>" not in page and "<b>" not in page
    assert "&lt;script&gt;" in page and "evil&lt;b&gt;&amp;spec.py" in page


def test_render_html_escapes_every_cell(monkeypatch):
    import fgc.app.design_report

    report = {"spec": "a&b", "params": {"tag": "<u>"}, "program": "p", "variables": 1,
              "factors": 1, "block_instances": 1,
              "solver": {"method": "lm", "linear": "qr", "precision": "float32",
                         "ordering": "auto", "units": 1, "cpe": 1, "clock_mhz": 143.0}}
    evil = Section('"><img src=x onerror=alert(1)>', ("<th>",), (("<td>&",),), ("<i>note",))
    monkeypatch.setattr(fgc.app.design_report, "sections", lambda r: [evil])
    page = render_html(report, {"<fig>": "data:image/png;base64,AAAA"})
    assert "<img src=x" not in page and "&#34;&gt;&lt;img src=x" in page
    for escaped in ("&lt;th&gt;", "&lt;td&gt;&amp;", "&lt;i&gt;note", "a&amp;b", "&lt;u&gt;",
                    'alt="&lt;fig&gt;"'):
        assert escaped in page, escaped


def test_html_tables_fit_the_page(monkeypatch):
    """A wide table scrolls in its own box; names wrap at CamelCase words and after + and ,
    (still escaped); number columns stay right-aligned on one line."""
    import fgc.app.design_report

    report = {"spec": "s", "params": {}, "program": "p", "variables": 1, "factors": 1,
              "block_instances": 1,
              "solver": {"method": "lm", "linear": "qr", "precision": "float32",
                         "ordering": "auto", "units": 1, "cpe": 1, "clock_mhz": 143.0}}
    wide = Section("Factor blocks", ("block", "members", "ops", "time"),
                   (("CombinedImuFactor+LidarOdometryFactor", "CombinedImuFactor, <b>Lidar",
                     "777,057,347", "4.590 ms"), ("GPSFactor", "GPSFactor", "6", "—")))
    monkeypatch.setattr(fgc.app.design_report, "sections", lambda r: [wide])
    page = render_html(report)
    assert "div.table { overflow-x: auto" in page and '<div class="table"><table>' in page
    assert ('<td class="text">Combined<wbr>Imu<wbr>Factor+<wbr>Lidar<wbr>Odometry<wbr>Factor'
            '</td>') in page
    assert '<td class="text">Combined<wbr>Imu<wbr>Factor,<wbr> &lt;b&gt;Lidar</td>' in page
    assert '<td class="num">777,057,347</td><td class="num">4.590 ms</td>' in page
    assert '<th class="text">members</th><th class="num">ops</th>' in page
    assert "td.num { white-space: nowrap; }" in page


def test_format_table_aligns_columns():
    lines = format_table(("name", "n"), [("a", "1"), ("long name", "1,000")], indent="")
    assert lines == ["name           n", "a              1", "long name  1,000"]


@pytest.mark.parametrize("command", COMMANDS)
def test_help_is_consistent(command):
    sub = next(a for a in build_parser()._subparsers._group_actions)
    text = sub.choices[command].format_help()
    for needle in ("-p KEY=VALUE", "solver:", "--ordering", "--max-iterations",
                   "exit status: 0 success", "2 bad input"):
        assert needle in text, (command, needle)
    assert "(default: None)" not in text


@pytest.mark.parametrize("argv, needle", [
    (["report", *POSE3, "--iterations", "0"], "--iterations: '0' is not a positive integer"),
    (["verify", *POSE3, "--units", "x"], "--units: 'x' is not a positive integer"),
    (["simulate", *POSE3, "--precision", "float16"], "invalid choice: 'float16'"),
    (["report"], "the following arguments are required: spec"),
    (["frobnicate"], "invalid choice: 'frobnicate'"),
    (["report", "no/such/spec.py"], "no such file"),
    (["report", *POSE3, "-p", "bogus=1"], "bogus"),
])
def test_usage_errors_are_one_line_exit_2(argv, needle, capsys):
    assert main(argv) == EXIT_BAD_INPUT
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and needle in err, err
