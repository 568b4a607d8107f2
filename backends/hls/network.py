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
_CALL = re.compile(r"^\s*([A-Za-z_][\w:]*)\s*(?:<[^;()]*>)?\s*(::run)?\s*\(", re.M)
_STREAM = re.compile(r"hls::stream<.*?>\s+([A-Za-z_]\w*)\s*((?:\[[^\]]*\]\s*)*)[(;]")
_CONSTANT = re.compile(r"^const int (N_UNITS|N_CPE) = (\d+);", re.M)
_ALLOCATION = re.compile(r"#pragma HLS ALLOCATION (operation|function) instances=(\w+) limit=(\d+)")


@dataclass(frozen=True)
class Region:
    function: str
    processes: tuple[str, ...]  # callee of each process call, in order (``name::run``: a
    # template recursion that instantiates one process per unit)
    streams: tuple[tuple[str, str], ...]  # (name, array size as written, "" for one stream;
    # an array of several dimensions: its sizes joined by "][", e.g. "CFG::N_UNITS][2")


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
    """The DATAFLOW regions of a kernel's or unit header's text."""
    out = []
    for name, body in _bodies(text):
        if not body.lstrip().startswith("#pragma HLS DATAFLOW"):
            continue
        calls = tuple(c + (run or "") for c, run in _CALL.findall(body)
                      if c not in ("for", "if", "while") and not c.isupper())
        streams = tuple((n, dims.strip().removeprefix("[").removesuffix("]").replace("] [", "]["))
                        for n, dims in _STREAM.findall(body))
        out.append(Region(name, calls, streams))
    return tuple(out)


def allocations(text: str) -> dict[str, tuple[tuple[str, str, int], ...]]:
    """Per function: its ALLOCATION pragmas as (kind, instances, limit)."""
    out = {}
    for name, body in _bodies(text):
        found = tuple((k, n, int(v)) for k, n, v in _ALLOCATION.findall(body))
        if found:
            out[name] = found
    return out


def _lanes_view(header: str, wide: bool) -> str:
    """``header`` with the branches of ``#ifdef FGC_BS_LANES`` (the two-lane-wide driver,
    ``HlsConfig.backsub_lanes`` > 1) or of their ``#else`` (the one-lane driver) blanked (and
    ``#ifndef FGC_BS_LANES`` blocks alike, their branches the other way round), as a
    kernel that does (``wide``) or does not define FGC_BS_LANES compiles it (the blocks do not
    nest)."""
    out, keep, inside = [], True, False
    for line in header.split("\n"):
        word = line.strip()
        if word.startswith(("#ifdef FGC_BS_LANES", "#ifndef FGC_BS_LANES")):
            negated = word.startswith("#ifndef")
            inside, keep = True, wide != negated
        elif inside and word.startswith("#else"):
            keep = not keep
        elif inside and word.startswith("#endif"):
            inside, keep = False, True
        else:
            out.append(line if keep else "")
            continue
        out.append("")
    return "\n".join(out)


def _columns_view(header: str, columns: bool) -> str:
    """``header`` with the branches of ``#ifndef FGC_BS_COLUMNS`` (the slot driver) or of their
    ``#else`` (the column driver, ``HlsConfig.backsub_lanes`` = 4) blanked, as a kernel that
    does not or does (``columns``) define FGC_BS_COLUMNS compiles it (other conditionals nest
    inside and are kept for :func:`_lanes_view`)."""
    out, keep, depth = [], True, 0  # depth: conditionals open inside an FGC_BS_COLUMNS block
    inside = False
    for line in header.split("\n"):
        word = line.strip()
        if not inside and word.startswith("#ifndef FGC_BS_COLUMNS"):
            inside, keep, depth = True, not columns, 0
            out.append("")
            continue
        if inside and word.startswith("#if"):
            depth += 1
        elif inside and depth == 0 and word.startswith("#else"):
            keep = columns
            out.append("")
            continue
        elif inside and word.startswith("#endif"):
            if depth == 0:
                inside, keep = False, True
                out.append("")
                continue
            depth -= 1
        out.append(line if keep else "")
    return "\n".join(out)


def backsub_region(header: str, wide: bool = False, columns: bool = False) -> Region:
    """Back-substitution's regions (``fgc_backsub.h``'s driver: ``backsub_lane0`` and
    ``backsub_lane1``, a lane's solve beside the other lane's load; ``back_substitute``, the slot
    process beside the state update it feeds) as one: their processes and streams in order.
    ``wide``: the driver a kernel defining FGC_BS_LANES compiles (``HlsConfig.backsub_lanes``
    > 1), else the one-lane driver."""
    regions = read_network(_lanes_view(_columns_view(header, columns), wide))
    if columns:  # back-substitution by columns: one region, the loader, the ends, the retire
        return next(r for r in regions if r.function == "back_substitute")
    lanes = [r for r in regions if r.function.startswith("backsub_lane")]
    if len(lanes) != 2:
        raise ValueError(f"expected two backsub_lane regions, found {len(lanes)}")
    lanes += [r for r in regions if r.function == "back_substitute"]
    return Region("backsub_lane", tuple(p for r in lanes for p in r.processes),
                  tuple(st for r in lanes for st in r.streams))


def counts(kernel: str, units: str, backsub: str) -> tuple[int, int]:
    """Processes and streams of the kernel's process network: the linear solver's - the
    kernel's unit-set region (QR: how many unit sets run side by side; Cholesky: one cascade)
    times the unit header's innermost region (one reflection, one CPE round) with the kernel's
    N_UNITS / N_CPE (Cholesky: and the overlap region the kernel uses, with the HGC beside the
    elimination the Gram stream of its linearize_solve) - and back-substitution's regions in its
    header ``backsub`` (:func:`backsub_region`: their process calls and any streams they
    declare)."""
    const = {k: int(v) for k, v in _CONSTANT.findall(kernel)}
    cfg = {f"CFG::{k}": v for k, v in const.items()}
    sets = next((len(r.processes) for r in read_network(kernel) if r.function == "qr_level"), 1)
    # Cholesky with the HGC beside the elimination: fgc_eliminate.h's cholesky_overlap_beside
    # (not cholesky_overlap) and the kernel's linearize_solve stream (the Grams)
    beside = "#define FGC_ELIMINATE_BESIDE" in kernel
    unused = "cholesky_overlap" if beside else "cholesky_overlap_beside"
    procs = streams = 0
    for region in read_network(units):
        if not region.streams or region.function == unused:
            continue
        for call in region.processes:
            if call.endswith("::run"):  # per unit: N_UNITS updates; N_CPE taps and CPEs
                procs += const["N_UNITS"] if "update" in call else 2 * const["N_CPE"]
            else:
                procs += 1
        streams += _stream_count(region, cfg)
    if beside:
        streams += sum(_stream_count(r, cfg) for r in read_network(kernel)
                       if r.function == "linearize_solve")
    backsub = backsub_region(backsub, "#define FGC_BS_LANES" in kernel,
                             "#define FGC_BS_COLUMNS" in kernel)
    # the kernel's trial_cost, a process of back_substitute's region, is itself a DATAFLOW
    # region where the column design's LM splits the cost in two (trial_cost_a, trial_cost_b)
    # (the slot design's too, with the feed of trial_cost_b's data words: a stream)
    trial = [r for r in read_network(kernel) if r.function == "trial_cost"]
    inner = sum(len(r.processes) - 1 for r in trial)
    return (procs * sets + len(backsub.processes) + inner,
            streams * sets + _stream_count(backsub, cfg) + sum(_stream_count(r, cfg)
                                                               for r in trial))


def _stream_count(region: Region, cfg: dict) -> int:
    """Streams ``region`` declares (an array of streams counts its constant size, the product
    of its dimensions)."""
    n = 0
    for _, size in region.streams:
        count = 1
        for dim in (size or "1").split("]["):
            expr = dim
            for k, v in cfg.items():
                expr = expr.replace(k, str(v))
            if not re.fullmatch(r"[0-9+\-* ]+", expr):
                raise ValueError(f"stream array size {size!r} is not a constant expression")
            count *= eval(expr)  # noqa: S307 - digits and + - * only (checked above)
        n += count
    return n
