"""The run-time data file: measurements, noise and initial values for a compiled Program.

A compiled Program fixes the *structure*; the emitted accelerator (simulator or HLS testbench)
reads the *data* from a plain text file that Python and C++ parse with the same few lines::

    FGCDATA 1
    VARIABLES <n>
    <storage_dim> <v> ...            one line per variable, Program.variables order
    FACTORS <m>
    <count> <v> ...                  one line per factor instance, Program.factors order

A factor line holds, for each member of its block (block member order): the measurements (each
measurement's storage, in ``MemberSpec.measurements`` order), the noise parameters
(``NoiseModel.params()``), then two numbers: robust code (0 none, 1 Huber, 2 Cauchy) and k.
Numbers are written with Python's ``repr`` so they read back bit-exactly.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fgc.dsl import Graph
from fgc.errors import DataError
from fgc.program import Program

MAGIC = "FGCDATA 1"
ROBUST_CODES = {None: 0, "huber": 1, "cauchy": 2}


@dataclass(frozen=True)
class ProblemData:
    """Data of one problem instance, laid out for a Program."""

    variables: tuple[np.ndarray, ...]  # initial storage per variable
    factors: tuple[np.ndarray, ...]  # the flat numbers of each factor instance (see module doc)


def problem_data(graph: Graph, program: Program) -> ProblemData:
    """Collect ``graph``'s data in the layout of ``program`` (compiled from the same structure)."""
    by_key = {str(k): v for k, v in graph.variables.items()}
    if [v.key for v in program.variables] != list(by_key):
        raise DataError("the graph's variables do not match the compiled Program's")
    variables = tuple(by_key[v.key].initial.storage_array() for v in program.variables)
    factors = []
    for spec in program.factors:
        block = program.blocks[spec.block]
        parts = []
        for member, index in zip(block.members, spec.factors, strict=True):
            f = graph.factors[index]
            if f.type.name != member.factor_type:
                raise DataError(f"factor {index} ('{f.name}') is a {f.type.name}, the Program "
                                f"expects a {member.factor_type}")
            parts += [np.asarray(f.measured[name], float).reshape(-1)
                      for name, _ in member.measurements]
            parts.append(f.noise.params())
            robust = f.noise.robust
            parts.append(np.array([ROBUST_CODES[robust.kind if robust else None],
                                   robust.k if robust else 0.0]))
        factors.append(np.concatenate(parts))
    return ProblemData(variables, tuple(factors))


def write_data(data: ProblemData, path: str | Path) -> None:
    lines = [MAGIC, f"VARIABLES {len(data.variables)}"]
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
    if not lines or lines[0].strip() != MAGIC:
        raise DataError(f"{path}:1: not an fgc data file (expected '{MAGIC}')")
    pos = 1
    sections = []
    for name in ("VARIABLES", "FACTORS"):
        count, pos = _header(path, lines, pos, name)
        rows = []
        for _ in range(count):
            rows.append(_row(path, lines, pos))
            pos += 1
        sections.append(tuple(rows))
    return ProblemData(*sections)


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
