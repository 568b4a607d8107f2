"""The process network of an emitted kernel, read back from its C++ text.

:func:`read_network` finds every function whose body opens with ``#pragma HLS DATAFLOW`` (a
DATAFLOW region) and lists the processes it calls and the ``hls::stream`` channels it declares;
:func:`allocations` lists each function's ``#pragma HLS ALLOCATION`` limits. The tests and the
measurements compare these with the accelerator plan (:mod:`fgc_backends.hls.plan`): what the
plan describes must be what the file holds.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .lint import strip_comments_and_strings

_FUNCTION = re.compile(r"\b([A-Za-z_]\w*)\s*\(([^;{}]*)\)\s*\{")
_CALL = re.compile(r"^\s*([A-Za-z_]\w*)\s*\(", re.M)
_STREAM = re.compile(r"hls::stream<[^>]*>\s+([A-Za-z_]\w*)\s*[(;]")
_ALLOCATION = re.compile(r"#pragma HLS ALLOCATION (operation|function) instances=(\w+) limit=(\d+)")


@dataclass(frozen=True)
class Region:
    function: str
    processes: tuple[str, ...]  # callee of each process call, in order
    streams: tuple[str, ...]


def _bodies(text: str):
    """(name, body) of every function definition in ``text`` (comments blanked)."""
    clean = strip_comments_and_strings(text)
    for m in _FUNCTION.finditer(clean):
        if m.group(1) in ("if", "for", "while", "switch"):
            continue
        depth, i = 1, m.end()
        while depth and i < len(clean):
            depth += {"{": 1, "}": -1}.get(clean[i], 0)
            i += 1
        yield m.group(1), clean[m.end():i - 1]


def read_network(text: str) -> tuple[Region, ...]:
    """The DATAFLOW regions of a kernel's text."""
    out = []
    for name, body in _bodies(text):
        if not body.lstrip().startswith("#pragma HLS DATAFLOW"):
            continue
        calls = tuple(c for c in _CALL.findall(body) if c not in ("for", "if", "while"))
        out.append(Region(name, calls, tuple(_STREAM.findall(body))))
    return tuple(out)


def allocations(text: str) -> dict[str, tuple[tuple[str, str, int], ...]]:
    """Per function: its ALLOCATION pragmas as (kind, instances, limit)."""
    out = {}
    for name, body in _bodies(text):
        found = tuple((k, n, int(v)) for k, n, v in _ALLOCATION.findall(body))
        if found:
            out[name] = found
    return out


def counts(text: str) -> tuple[int, int]:
    """Processes and streams of the linear solver's network: the innermost regions that declare
    streams (one QR column or one CPE round), plus the unit-set region's processes."""
    regions = read_network(text)
    streamed = [r for r in regions if r.streams]
    sets = [r for r in regions if not r.streams]
    per_set = sum(len(r.processes) for r in streamed)
    n_sets = max([len(r.processes) for r in sets] + [1])
    return per_set * n_sets, sum(len(r.streams) for r in streamed) * n_sets
