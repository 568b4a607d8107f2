"""The on-chip stream design's kept task as the second reader reads it (issues 32, 33):
fgc_stream.h's ``reexpress`` (its five Log / retraction passes) and ``kept_walk`` run one after
another, both INLINE into ``kept_task``, whose ``ALLOCATION function ... limit=1`` shares one
instance of the kernel's datapath module among all their call sites: ``keyframe_local`` and
``keyframe_retract`` are INLINE modes of one ``keyframe_pass``, whose own ALLOCATION binds one
instance of each special function its helpers (INLINE copies) call; without those pragmas
every call site is its own RTL copy."""

from __future__ import annotations

import re

import pytest

import fgc_backends
from fgc.app import streaming
from fgc.app.specs import example
from fgc.ir.program import SolverConfig
from fgc_backends.hls.reader import emitted_files
from fgc_backends.hls.reader.design import _design, _Reader

SHARE = re.compile(r"#pragma HLS ALLOCATION function instances=keyframe_pass limit=1\n")
TRIG = re.compile(r"#pragma HLS ALLOCATION function instances=fgc_(sin|cos|atan2) limit=1\n")


@pytest.fixture(scope="module")
def emitted(tmp_path_factory):
    """LIO N = 6, incremental K = 2, a batch step at 3: the emitted files and the window's
    translation unit."""
    graph = example("lio").build(N=6)
    program = streaming.compile_stream(graph, SolverConfig(precision="float32", linear="qr"),
                                       incremental=2, batch_every=(3,))
    out = tmp_path_factory.mktemp("stream")
    hls = fgc_backends.load("hls")
    hls.emit(streaming.stream_program(graph, program, None), out, hls.Config(scalar="float"))
    files, top = emitted_files(out)
    return files, f"{top.removesuffix('_stream')}.cpp"


def _copies(files, unit) -> dict[str, int]:
    reading = _design(_Reader(files, 4), "kept_task", unit)
    modules = dict(reading.modules)
    return {k: modules.get(k, 0) for k in ("keyframe_pass", "keyframe_local", "keyframe_retract")}


def test_the_kept_task_holds_one_datapath_module(emitted):
    files, unit = emitted
    assert _copies(files, unit) == {"keyframe_pass": 1, "keyframe_local": 0,
                                    "keyframe_retract": 0}


def test_without_the_sharing_every_call_site_is_a_copy(emitted):
    files, unit = emitted
    stripped = [(name, SHARE.sub("", text)) for name, text in files]
    assert stripped != files  # the pragmas are there to strip
    assert _copies(stripped, unit)["keyframe_pass"] == 4 + 3  # reexpress's 5, kept_walk's 2


def test_the_datapath_module_binds_one_of_each_special_function(emitted):
    """LIO's keyframe: the pose's Log (so3_log's arctangent, lie_D's sine and cosine) and its
    retraction (lie_A, lie_B's two, lie_C's sines): three special operators in the module, not
    one a call site (seven); at most two adders and two multipliers (KEPT_LIMITS)."""
    files, unit = emitted
    ops = dict(_design(_Reader(files, 4), "keyframe_pass", unit).operators)
    assert ops["special"] == 3 and ops["add"] <= 2 and ops["mul"] <= 2
    stripped = [(name, TRIG.sub("", text)) for name, text in files]
    assert dict(_design(_Reader(stripped, 4), "keyframe_pass", unit).operators)["special"] == 7
