"""The lint on an emitted project (backends/hls/lint/project.py): strict, every issue raises;
the CPU program's known semantic issues returned; the algorithm headers linted with the
kernel."""

from __future__ import annotations

import pytest


def test_emit_lints_the_dataflow_design_strictly(tmp_path):
    """The emitted accelerator, kernel and unit headers together, has no semantic issue (emit
    would raise); the CPU program the native backend builds has the known ones (issue 18), which
    is why it is not an HLS design."""

    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc_backends import native
    from fgc_backends.hls import HlsConfig, emit
    from fgc_backends.hls.lint import semantic_issues

    pose_graph = example("pose_graph")

    program = compile_graph(pose_graph.build("pose3example.txt"), name="lint_p3")
    project = emit(program, tmp_path / "accel", HlsConfig(scalar="double"))
    assert project.lint_issues == ()
    cpu = native.emit(program, tmp_path / "cpu", native.NativeConfig(scalar="double"))
    texts = [(p.name, p.read_text()) for p in cpu.files if p.name in ("lint_p3.cpp", "lint_p3.h")]
    rules = {i.rule for i in semantic_issues(texts, part="xc7z045ffg900-2", scalar="double")}
    assert {"function_pointer", "pointer", "synthesis_macro"} <= rules


def test_the_lint_reads_the_algorithm_headers_with_the_kernel(tmp_path):
    """LM control, the elimination driver and the stream live in headers (include/): emit lints
    them with the kernel, so a loop without a trip count planted in the shared LM header, or a
    variable-bound loop inside a PIPELINE planted in the elimination driver, is caught and named
    by its header."""
    from fgc.app.specs import example
    from fgc.compile import compile_graph
    from fgc_backends.hls import HlsConfig, emit
    from fgc_backends.hls.emitter import SYNTHESISED, _copy_headers
    from fgc_backends.hls.lint import HlsLintError, lint_project

    program = compile_graph(example("pose_graph").build("pose3example.txt"), name="hdr")
    project = emit(program, tmp_path, HlsConfig(scalar="double"))
    include = tmp_path / "include"
    assert {"fgc_lm.h", "fgc_lm_units.h", "fgc_eliminate.h", "fgc_stream.h",
            "fgc_backsub.h"} <= {p.name for p in include.glob("*.h")}
    kernel = [tmp_path / "hdr.h", tmp_path / "hdr.cpp"]
    assert len(kernel) == len(SYNTHESISED)
    plants = (("fgc_lm.h", "for (int t = 0; t < CFG::MAX_TRIES; ++t) {",
               "for (int t = 0; t < mu_tries(); ++t) {", "tripcount"),
              ("fgc_eliminate.h", "for (int h = 0; h < PORTS; ++h) {\n            if (i + h < nc)",
               "for (int h = 0; h < nc; ++h) {\n            if (i + h < nc)", "pipeline"))
    for header, good, bad, rule in plants:
        units = _copy_headers(tmp_path)  # the clean copies again
        assert lint_project(project, kernel + units) == []
        text = (include / header).read_text()
        assert good in text, header
        (include / header).write_text(text.replace(good, bad, 1))
        with pytest.raises(HlsLintError, match=rf"{header}:\d+: \[{rule}\]"):
            lint_project(project, kernel + units)
