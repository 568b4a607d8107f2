"""The second reader's design reading (backends/hls/reader/design.py): a template cascade read
per stage, and on emitted designs every Update unit copy and every pipelined loop the plan
prints."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from fgc_backends.hls.reader import check, emitted_files, read_design
from fgc_backends.hls.reader.text import compiled_view

ADD_LATENCY = 4  # a float adder's stages in these snippets
DSP = {"add": 2, "mul": 3, "div": 0, "sqrt": 0, "special": 0}


def test_a_recursive_template_cascade_is_read_per_stage():
    """A unit instantiated through a struct template's recursion (fgc_cpe.h's
    cpe_cascade<CFG, K>::run calling cpe<CFG, K>) is read once per stage, each stage's
    pipelined loop with its operators: the cascade's DSP grows with the stages."""
    text = """
typedef float T;
const int N = 32;
template <int K>
void stage(const T a[N], T b[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        b[i] = a[i] * a[i] + T(K);
    }
}
template <int K, int M, bool END = (K == M)>
struct cascade {
    static void run(T link[M + 1][N]) {
#pragma HLS INLINE
        stage<K>(link[K], link[K + 1]);
        cascade<K + 1, M>::run(link);
    }
};
template <int K, int M>
struct cascade<K, M, true> {
    static void run(T link[M + 1][N]) {
#pragma HLS INLINE
    }
};
void top3(T link[4][N]) {
    cascade<0, 3>::run(link);
}
void top6(T link[7][N]) {
    cascade<0, 6>::run(link);
}
"""
    dsp = {"add": 2, "mul": 3}
    three = read_design([("s.cpp", text)], "top3", ADD_LATENCY)
    six = read_design([("s.cpp", text)], "top6", ADD_LATENCY)
    assert dict(three.modules)["stage"] == 3 and dict(six.modules)["stage"] == 6
    assert {dict(r.template)["K"] for r in three.loops if r.function == "stage"} == {0, 1, 2}
    assert three.dsp(dsp) == 3 * 5 and six.dsp(dsp) == 6 * 5


@pytest.fixture(scope="module")
def chain_design(tmp_path_factory):
    import fgc
    from fgc import Pose2
    from fgc.compile import compile_graph
    from fgc.frontend import noise
    from fgc.frontend.factors import BetweenFactor, PriorFactor
    from fgc.ir.program import SolverConfig
    from fgc_backends.hls import HlsConfig, emit

    graph = fgc.Graph()
    for i in range(8):
        graph.add_variable(f"x{i}", Pose2(1.0 * i, 0.1 * i, 0.05 * i))
    graph.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), noise.isotropic(3, 0.1)))
    for i in range(7):
        graph.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.0),
                                noise.isotropic(3, 0.1)))
    program = compile_graph(graph, name="reader_chain", solver=SolverConfig(units=3))
    out = tmp_path_factory.mktemp("reader") / "accel"
    emit(program, out, HlsConfig())
    return out


def test_an_emitted_design_read_back(chain_design):
    """Every pipelined loop the kernel prints is read (one per instantiation of a template),
    each Update unit is its own module (3 units x 2 unit sets; qr_step's two parity call sites
    of the reflection share one instance through its ALLOCATION function limit=1, as LM
    control's two calls of the solve, whose back-substitution region holds the cost pass, share
    one solve), and every loop's II is read from its pragma."""
    files, top = emitted_files(chain_design)
    design = read_design(files, top, ADD_LATENCY)
    # the pragmas the kernel compiles: a unit header's #ifdef sections the kernel does not
    # define (fgc_eliminate.h's Cholesky driver in a QR design) are not read
    text = "\n".join(t for _, t in compiled_view(files))
    pragmas = len(re.findall(r"#pragma HLS PIPELINE II=", text))
    assert len({(r.file, r.line) for r in design.loops}) == pragmas
    assert pragmas < len(re.findall(r"#pragma HLS PIPELINE II=", "\n".join(t for _, t in files)))
    modules = dict(design.modules)
    assert modules["qr_update"] == 3 * 2
    assert modules["qr_reflection"] == 2
    # LM control's two calls of the solve (the solve at μ with the cost at X_TRIAL beside its
    # back-substitution; the cost at X, no elimination) share one: fgc_lm.h's ALLOCATION over
    # the INLINE hooks (two would build the solver and every cost datapath twice)
    assert modules["solve"] == 1 and modules["back_substitute"] == 1
    assert modules["trial_cost"] == 1
    assert "LmConfig::cost_x" not in modules and "try_steps" not in modules
    assert all(r.ii >= 1 and r.ii_bound >= 1 for r in design.loops)
    assert design.dsp(DSP) > 0


@pytest.mark.heavy  # ~40 s of CPU: two kernels emitted and read
def test_the_on_chip_stream_design_reads_both_kernels(tmp_path):
    """The on-chip incremental design (fgc compile --incremental K): one top, the stream
    section, the window kernel and the batch kernel, each kernel's functions in its own .cpp's
    anonymous namespace under the same names (evaluate_0, LmConfig::…). Each call resolves in
    its own translation unit, so both kernels' datapaths are read, each with its own
    constants."""
    from fgc.app.cli import main

    out = tmp_path / "k"
    lio = Path(__file__).resolve().parents[3] / "examples" / "lio.py"
    assert main(["compile", str(lio), "-p", "N=5", "--incremental", "2",
                 "--batch-every", "3", "--backend", "hls", "--out", str(out)]) == 0
    files, top = emitted_files(out)
    kernels = sorted(name for name, _ in files if name.endswith(".cpp"))
    assert len(kernels) == 2
    design = read_design(files, top, ADD_LATENCY)
    window, batch = (design.dsp(DSP, [k]) for k in kernels)
    # each kernel holds its own factor datapaths: comparable figures (the window kernel's
    # were read as the batch kernel's, leaving it ~100 DSP of stream glue)
    assert window > 0.4 * batch and batch > 0.4 * window
    # the kept net's walk is INLINE into kept_task (one instance of its Log / retraction): the
    # task is the module the reader finds
    assert "kept_task" in dict(design.modules) and "kept_walk" not in dict(design.modules)
    assert not [i for i in check(design.reached_loops) if i.file in kernels]


def test_a_header_function_is_counted_in_each_kernel_that_instantiates_it():
    """DesignReading.by_unit / unit_dsp: a header's unit (one multiply-add at II 1) called from
    two kernels' .cpp files is one instance in each translation unit (bench_second_reader's
    per-kernel comparison of the on-chip stream design), and a kernel's own loop is its own."""
    header = """
typedef float T;
inline void mac(const T a[16], const T b[16], T out[16]) {
    for (int i = 0; i < 16; ++i) {
#pragma HLS PIPELINE II=1
        out[i] = a[i] * b[i] + out[i];
    }
}
"""
    one = """
#include "unit.h"
void window(const T a[16], const T b[16], T out[16]) { mac(a, b, out); }
"""
    two = """
#include "unit.h"
void batch(const T a[16], const T b[16], T out[16]) {
    mac(a, b, out);
    for (int i = 0; i < 16; ++i) {
#pragma HLS PIPELINE II=1
        out[i] = out[i] * a[i];
    }
}
void top(const T a[16], const T b[16], T out[16]) { window(a, b, out); batch(a, b, out); }
"""
    files = [("batch.cpp", two), ("window.cpp", one), ("unit.h", header)]
    design = read_design(files, "top", ADD_LATENCY)
    assert design.unit_dsp(DSP, "window.cpp") == 5  # mac: an adder and a multiplier
    assert design.unit_dsp(DSP, "batch.cpp") == 5 + 3  # mac, and its own multiply
    assert design.unit_dsp(DSP, "batch.cpp", exclude=["unit.h"]) == 3
    assert design.dsp(DSP) == 13
