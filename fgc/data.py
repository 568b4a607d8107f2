"""Locating the example data files that ship inside the gtsam wheel (without importing gtsam)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

from fgc.errors import DataError


def gtsam_data_dir() -> Path:
    spec = importlib.util.find_spec("gtsam")
    if spec is None or not spec.submodule_search_locations:
        raise DataError("the gtsam package is not installed; its wheel carries the example data")
    return Path(next(iter(spec.submodule_search_locations))) / "Data"


def example_data_file(name: str) -> Path:
    """Path of ``name``: an existing path as given, else a file of the gtsam wheel's data."""
    p = Path(name)
    if p.is_file():
        return p
    candidate = gtsam_data_dir() / name
    if candidate.is_file() and candidate.resolve().parent == gtsam_data_dir().resolve():
        return candidate
    raise DataError(f"data file {name!r} not found (neither a path nor in gtsam's example data)")
