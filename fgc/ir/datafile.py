"""The run-time data file: measurements, noise and initial values for a compiled Program.

A compiled Program fixes the *structure*; the emitted accelerator (simulator or HLS testbench)
reads the *data* from a plain text file that Python and C++ parse with the same few lines::

    FGCDATA 2 <structure fingerprint>
    VARIABLES <n>
    <storage_dim> <v> ...            one line per variable, Program.variables order
    FACTORS <m>
    <count> <v> ...                  one line per factor instance, Program.factors order

A factor line holds, for each member of its block (block member order): the measurements (each
measurement's storage, in ``MemberSpec.measurements`` order), the noise parameters
(``NoiseModel.params()``), then two numbers: robust code (0 none, 1 Huber, 2 Cauchy) and k.
Numbers are written with Python's ``repr`` so they read back bit-exactly.

The first line carries the Program's :attr:`~fgc.ir.program.Program.structure_fingerprint` (16 hex
digits): counts alone do not say which keys each factor connects, so every reader (this module,
the emitted simulator, the HLS testbench, the native library) refuses a file whose fingerprint
is not the compiled one, naming both.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fgc.errors import DataError
from fgc.frontend.dsl import Graph
from fgc.ir.codes import ROBUST_CODES
from fgc.ir.program import Program

MAGIC = "FGCDATA 2"
FINGERPRINT = re.compile(r"[0-9a-f]{16}")


@dataclass(frozen=True)
class ProblemData:
    """Data of one problem instance, laid out for a Program."""

    variables: tuple[np.ndarray, ...]  # initial storage per variable
    factors: tuple[np.ndarray, ...]  # the flat numbers of each factor instance (see module doc)
    structure: str | None = None  # the structure fingerprint of the Program they are laid out for


def check_structure(data: ProblemData, program: Program, what: str = "the data") -> None:
    """Raise DataError unless ``data`` was laid out for ``program``'s structure."""
    if data.structure != program.structure_fingerprint:
        have = data.structure or "none"
        raise DataError(f"{what} is for another structure: structure fingerprint {have}, the "
                        f"compiled Program '{program.name}' has "
                        f"{program.structure_fingerprint} (same counts do not mean the same "
                        "factor connectivity; write the data with problem_data(graph, program) "
                        "for this Program)")


def factor_words(measured: dict, noise, member) -> list[np.ndarray]:
    """One factor's numbers in a block instance's data, as arrays: its measurements in the
    member's order, its noise parameters, its robust loss (code, k). A robust loss on a member
    the Program built without one (``MemberSpec.robust`` False) is refused: its accelerator
    has no datapath for it."""
    robust = noise.robust
    if robust is not None and not member.robust:
        raise DataError(f"a {member.factor_type} factor has a {robust.kind} robust loss, but the "
                        f"compiled Program's {member.factor_type} members have none (it was "
                        "compiled from a graph without robust losses there: compile this graph)")
    return [*(np.asarray(measured[name], float).reshape(-1) for name, _ in member.measurements),
            noise.params(), np.array([ROBUST_CODES[robust.kind if robust else None],
                                      robust.k if robust else 0.0])]


def problem_data(graph: Graph, program: Program) -> ProblemData:
    """Collect ``graph``'s data in the layout of ``program`` (compiled from the same structure);
    a Program with a local frame (``Program.frame``, :mod:`fgc.ir.frame`) gets its positions
    relative to the frame's origin, as every reader of its results expects."""
    by_key = {str(k): v for k, v in graph.variables.items()}
    if [v.key for v in program.variables] != list(by_key):
        raise DataError("the graph's variables do not match the compiled Program's")
    for spec in program.variables:
        type_name = by_key[spec.key].type.__name__
        if type_name != spec.type_name:
            raise DataError(f"variable '{spec.key}' is a {type_name} in the graph, "
                            f"the Program expects a {spec.type_name}")
    if sum(len(spec.factors) for spec in program.factors) != len(graph.factors):
        raise DataError(f"the graph has {len(graph.factors)} factors, the compiled Program "
                        f"{sum(len(spec.factors) for spec in program.factors)}")
    frame = program.frame  # a float32 Program's local frame (fgc.ir.frame): positions relative
    variables = tuple(by_key[v.key].initial.storage_array() if frame is None else
                      frame.move(v.type_name, by_key[v.key].initial.storage_array(), -1.0)
                      for v in program.variables)
    factors = []
    for spec in program.factors:
        block = program.blocks[spec.block]
        parts = []
        for member, index in zip(block.members, spec.factors, strict=True):
            f = graph.factors[index]
            if f.type.name != member.factor_type:
                raise DataError(f"factor {index} ('{f.name}') is a {f.type.name}, the Program "
                                f"expects a {member.factor_type}")
            keys = [str(k) for k in f.keys]
            if member.positions:
                expected = [spec.keys[i] for i in member.positions]
            else:  # a Program without member positions: at least the keys must be the block's
                expected = keys if set(keys) <= set(spec.keys) else list(spec.keys)
            if keys != expected:
                raise DataError(f"factor {index} ('{f.name}', a {f.type.name}) connects "
                                f"{keys}, the compiled Program connects {expected}: the graph "
                                "has another structure (compile it, or use its own Program)")
            measured = f.measured if frame is None else frame.local_measured(f)
            try:
                parts += factor_words(measured, f.noise, member)
            except DataError as err:
                raise DataError(f"factor {index} ('{f.name}'): {err}") from None
        factors.append(np.concatenate(parts))
    return ProblemData(variables, tuple(factors), program.structure_fingerprint)


def write_data(data: ProblemData, path: str | Path) -> None:
    if data.structure is None or not FINGERPRINT.fullmatch(data.structure):
        raise DataError(f"refusing to write {path}: the data carry no structure fingerprint "
                        "(make it with problem_data(graph, program))")
    lines = [f"{MAGIC} {data.structure}", f"VARIABLES {len(data.variables)}"]
    lines += [_line(v) for v in data.variables]
    lines.append(f"FACTORS {len(data.factors)}")
    lines += [_line(f) for f in data.factors]
    Path(path).write_text("\n".join(lines) + "\n")


def _line(values: np.ndarray) -> str:
    vals = np.asarray(values, dtype=np.float64).reshape(-1)
    if not np.all(np.isfinite(vals)):
        raise DataError("refusing to write a non-finite number to a data file")
    return " ".join([str(len(vals))] + [repr(float(x)) for x in vals])


def read_data(path: str | Path) -> ProblemData:
    """Parse a data file; errors name the file and line."""
    path = Path(path)
    try:
        lines = path.read_text(encoding="ascii").splitlines()
    except OSError as exc:
        raise DataError(f"{path}: cannot read data file ({exc.strerror})") from None
    except UnicodeDecodeError as exc:
        line = path.read_bytes()[:exc.start].count(b"\n") + 1
        raise DataError(f"{path}:{line}: not an fgc data file (byte {exc.start} is not "
                        "ASCII)") from None
    first = lines[0].split() if lines else []
    if first[:2] != MAGIC.split():
        raise DataError(f"{path}:1: not an fgc data file (expected '{MAGIC} <fingerprint>')")
    if len(first) != 3 or not FINGERPRINT.fullmatch(first[2]):
        raise DataError(f"{path}:1: expected '{MAGIC}' and a 16-hex-digit structure "
                        "fingerprint")
    pos = 1
    sections = []
    for name in ("VARIABLES", "FACTORS"):
        count, pos = _header(path, lines, pos, name)
        rows = []
        for _ in range(count):
            rows.append(_row(path, lines, pos))
            pos += 1
        sections.append(tuple(rows))
    return ProblemData(*sections, structure=first[2])


def _header(path: Path, lines: list[str], pos: int, name: str) -> tuple[int, int]:
    fields = lines[pos].split() if pos < len(lines) else []
    if len(fields) != 2 or fields[0] != name or not fields[1].isdigit():
        raise DataError(f"{path}:{pos + 1}: expected '{name} <count>'")
    return int(fields[1]), pos + 1


def _row(path: Path, lines: list[str], pos: int) -> np.ndarray:
    if pos >= len(lines):
        raise DataError(f"{path}:{pos + 1}: file ends early")
    fields = lines[pos].split()
    try:
        n = int(fields[0])
        vals = np.array([float(x) for x in fields[1:]])
    except (ValueError, IndexError):
        raise DataError(f"{path}:{pos + 1}: malformed numbers") from None
    if len(vals) != n:
        raise DataError(f"{path}:{pos + 1}: expected {n} numbers, found {len(vals)}")
    if not np.all(np.isfinite(vals)):
        raise DataError(f"{path}:{pos + 1}: non-finite number")
    return vals
