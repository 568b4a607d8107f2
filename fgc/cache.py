"""The on-disk cache of symbolic work (derivations, fused kernels, structure analyses).

Entries are pickles under ``$FGC_CACHE_DIR`` (default ``~/.cache/fgc``), written atomically so
parallel compiles never read half a file; an unreadable entry is rebuilt, never trusted.
"""

from __future__ import annotations

import hashlib
import os
import pickle
import re
from collections.abc import Callable
from functools import cache
from pathlib import Path
from typing import TypeVar

T = TypeVar("T")


@cache
def source_digest(*names: str) -> bytes:
    """SHA-256 of the fgc source files ``names`` (paths inside the fgc package), read once per
    process: a cache key that includes it changes with the code that built the entry."""
    root = Path(__file__).parent
    h = hashlib.sha256()
    for name in names:
        h.update((root / name).read_bytes())
    return h.digest()


def cache_dir() -> Path:
    root = os.environ.get("FGC_CACHE_DIR") or Path.home() / ".cache" / "fgc"
    path = Path(root)
    path.mkdir(parents=True, exist_ok=True)
    return path


def entry(kind: str, name: str, key: str) -> Path:
    """Path of a cache entry; ``name`` (a user's factor name) is reduced to safe characters."""
    safe = re.sub(r"[^A-Za-z0-9_.+-]", "_", name)[:60] or "_"
    return cache_dir() / f"{kind}-{safe}-{key[:24]}.pkl"


def load(path: Path):
    """The object pickled at ``path``, or None if it is missing or unreadable."""
    try:
        with path.open("rb") as fh:
            return pickle.load(fh)
    except (OSError, EOFError, pickle.UnpicklingError, AttributeError, ImportError, TypeError):
        return None


def store(path: Path, obj) -> None:
    tmp = path.with_suffix(f".tmp{os.getpid()}")
    try:
        with tmp.open("wb") as fh:
            pickle.dump(obj, fh, protocol=pickle.HIGHEST_PROTOCOL)
        tmp.replace(path)
    except OSError:
        tmp.unlink(missing_ok=True)


def cached(path: Path, build: Callable[[], T]) -> T:
    """``build()``'s result, read from / written to the pickle at ``path``."""
    hit = load(path)
    if hit is not None:
        return hit
    obj = build()
    store(path, obj)
    return obj
