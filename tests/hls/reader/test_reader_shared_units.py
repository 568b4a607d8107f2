"""One module for every block type (issue 33 item 5): the gradient's ``accumulate`` and the
rounding noise's ``rounding_noise`` take the block type's sizes at run time, each block type's
caller (``reduce_<b>``, ``noise_<b>``) is INLINE into ``linearize_all`` / ``rounding_noise_all``,
whose ``ALLOCATION function ... limit=1`` makes their calls one after another one RTL module:
the second reader reads one of each; without those pragmas every block type's call site is its
own copy (as the per-block template instances were)."""

from __future__ import annotations

import re

import pytest

from fgc.app.specs import example
from fgc.compile import compile_graph
from fgc.ir.program import SolverConfig
from fgc_backends.hls import HlsConfig, emit
from fgc_backends.hls.reader import emitted_files, read_design

SHARE = re.compile(r"#pragma HLS ALLOCATION function instances=(?:accumulate|rounding_noise) "
                   r"limit=1\n")


@pytest.fixture(scope="module")
def emitted(tmp_path_factory):
    """LIO N = 6, QR, LM, float design: its files, top and block types."""
    program = compile_graph(example("lio").build(N=6), SolverConfig(
        method="lm", linear="qr", precision="float32"))
    out = tmp_path_factory.mktemp("lio")
    emit(program, out, HlsConfig(scalar="float"))
    files, top = emitted_files(out)
    return files, top, len(program.blocks)


def _copies(files, top) -> dict[str, int]:
    modules = dict(read_design(files, top, 4).modules)
    return {k: modules.get(k, 0) for k in ("accumulate", "rounding_noise")}


def test_every_block_type_shares_one_gradient_and_one_rounding_noise_module(emitted):
    files, top, _ = emitted
    assert _copies(files, top) == {"accumulate": 1, "rounding_noise": 1}


def test_without_the_sharing_every_block_types_call_is_a_copy(emitted):
    files, top, blocks = emitted
    stripped = [(name, SHARE.sub("", text)) for name, text in files]
    assert stripped != files  # the pragmas are there to strip
    assert blocks > 2
    assert _copies(stripped, top) == {"accumulate": blocks, "rounding_noise": blocks}
