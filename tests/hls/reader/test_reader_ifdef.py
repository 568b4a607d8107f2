"""The second reader reads only the code a translation unit compiles (issue 32): a unit
header's ``#if`` / ``#ifdef`` / ``#ifndef`` / ``#else`` sections are followed with the macros the
kernel defines before including it (fgc_stream.h's kept net and batch steps, fgc_eliminate.h's
Cholesky / QR drivers), the inactive ones blanked with their lines kept."""

from __future__ import annotations

import pytest

from fgc_backends.hls.reader import read_design
from fgc_backends.hls.reader.text import compiled_view

ADD_LATENCY = 4
DSP = {"add": 2, "mul": 3, "div": 0, "sqrt": 0, "special": 0}

HEADER = """#ifndef U_H
#define U_H
const int N = 16;
void base(const T a[N], T b[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        b[i] = a[i] + a[i];
    }
}
#if defined(FGC_A) || defined(FGC_B)
void both(const T a[N], T b[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        b[i] = a[i] * a[i];
    }
}
#endif
#ifdef FGC_EXTRA  // the extra pass
void extra(const T a[N], T b[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        b[i] = a[i] * a[i] * a[i] * a[i];
    }
}
#else
void plain(const T a[N], T b[N]) {
    for (int i = 0; i < N; ++i) {
#pragma HLS PIPELINE II=1
        b[i] = a[i] - a[i] - a[i];
    }
}
#endif  // FGC_EXTRA
void run(const T a[N], T b[N], T c[N]) {
    base(a, b);
#if defined(FGC_A) || defined(FGC_B)
    both(a, c);
#endif
#ifndef FGC_EXTRA
    plain(b, c);
#else
    extra(b, c);
#endif
}
#endif  // U_H
"""


def _kernel(*macros: str, twice: bool = False) -> str:
    defines = "".join(f"#define {m}\n" for m in macros)
    include = '#include "u.h"\n' * (2 if twice else 1)
    return ("typedef float T;\n" + defines + include +
            "void top(const T a[N], T b[N], T c[N]) {\n    run(a, b, c);\n}\n")


def _read(kernel: str):
    return read_design([("k.cpp", kernel), ("u.h", HEADER)], "top", ADD_LATENCY)


@pytest.mark.parametrize("macros, modules, dsp", [
    # FGC_B: base (1 add), both (1 mul), plain (2 add); extra's 3 mul not compiled
    (("FGC_B",), {"base", "both", "plain"}, 3 * 2 + 1 * 3),
    (("FGC_A", "FGC_EXTRA"), {"base", "both", "extra"}, 1 * 2 + 4 * 3),
    ((), {"base", "plain"}, 3 * 2),
])
def test_only_the_branches_the_kernel_compiles_are_read(macros, modules, dsp):
    for twice in (False, True):  # the include guard's second pass adds nothing, drops nothing
        design = _read(_kernel(*macros, twice=twice))
        assert {name for name, n in design.modules if n} - {"top", "run"} == modules
        assert design.dsp(DSP) == dsp
        assert dict(design.operators)["add"] == sum(
            {"base": 1, "plain": 2}.get(m, 0) for m in modules)


def test_an_inactive_section_keeps_its_lines():
    """Blanked, not cut: a loop after an inactive section is reported at its own line."""
    design = _read(_kernel("FGC_B"))
    lines = HEADER.split("\n")
    plain = next(r for r in design.loops if r.function == "plain")
    assert plain.file == "u.h" and lines[plain.line - 1] == "#pragma HLS PIPELINE II=1"
    assert lines[plain.line - 3].startswith("void plain(")
    (name, text), = [f for f in compiled_view([("k.cpp", _kernel("FGC_B")), ("u.h", HEADER)])
                     if f[0] == "u.h"]
    assert text.count("\n") == HEADER.count("\n") and len(text) == len(HEADER)
    assert "void extra" not in text and "a[i] * a[i] * a[i]" not in text and "void plain" in text


def test_a_condition_it_cannot_evaluate_keeps_every_branch():
    header = "#if FGC_LEVEL > 2\nT one;\n#else\nT two;\n#endif\n"
    kernel = '#define FGC_LEVEL 3\n#include "v.h"\n'
    (_, text), = [f for f in compiled_view([("k.cpp", kernel), ("v.h", header)])
                  if f[0] == "v.h"]
    assert text == header
    # a header no kernel includes is read whole, as before
    assert compiled_view([("v.h", HEADER)]) == [("v.h", HEADER)]
