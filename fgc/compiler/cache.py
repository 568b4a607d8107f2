"""The on-disk cache of symbolic work (derivations, fused kernels, structure analyses, lowered
kernels).

Entries live under ``$FGC_CACHE_DIR`` (default ``~/.cache/fgc``), one file per entry, named
``KIND-NAME-DIGEST.pkl`` with the full hex digest of the entry's key. Keys are content addresses:
a derivation's key is a digest of the traced symbolic residual (see ``fgc.compiler.derive``), and
the keys
of every kind built on a derivation chain from it, so an entry can only be found by the work it
answers.

A file holds a header line (format tag, full key, SHA-256 of the payload) and the pickled payload.
Reads are validated: a wrong tag, key or checksum, an unpicklable payload or one of the wrong type
means the entry is discarded, recomputed and rewritten, with one :class:`CacheWarning` naming the
file. Writes are atomic (temporary file + rename) so parallel compiles never read half a file. A
cache directory that cannot be created or written gives one warning and fgc continues uncached.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import pickle
import re
from collections.abc import Callable
from functools import cache
from pathlib import Path
from typing import TypeVar

from fgc.ir.conditioning import FgcWarning, warn

T = TypeVar("T")

_MAGIC = b"fgc-cache-1"
KINDS = ("derive", "fuse", "lower", "structure")


class CacheWarning(FgcWarning):
    """A cache entry was unusable (corrupt, foreign) or the cache directory cannot be used."""


@cache
def source_digest(*names: str) -> bytes:
    """SHA-256 of the fgc source files ``names`` (paths inside the fgc package), read once per
    process: a cache key that includes it changes with the code that built the entry."""
    root = Path(__file__).resolve().parent.parent  # the fgc package
    h = hashlib.sha256()
    for name in names:
        h.update((root / name).read_bytes())
    return h.digest()


def cache_root() -> Path:
    """The configured cache directory (not created)."""
    return Path(os.environ.get("FGC_CACHE_DIR") or Path.home() / ".cache" / "fgc")


_UNUSABLE: set[str] = set()  # directories already warned about in this process


def _unusable(path: Path, why: str) -> None:
    if str(path) not in _UNUSABLE:
        _UNUSABLE.add(str(path))
        warn(f"fgc cache directory {path} is unusable ({why}); continuing without a "
             "derivation cache (set FGC_CACHE_DIR to a writable directory)", CacheWarning)


def cache_dir() -> Path | None:
    """The cache directory, created if needed; None (after one warning) if it cannot be used."""
    path = cache_root()
    if str(path) in _UNUSABLE:
        return None
    if path.exists() and not path.is_dir():
        _unusable(path, "not a directory")
        return None
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        _unusable(path, exc.strerror or type(exc).__name__)
        return None
    if not path.is_dir():
        _unusable(path, "not a directory")
        return None
    return path


def entry(kind: str, name: str, key: str) -> Path | None:
    """Path of the entry of ``key`` (a hex digest, kept whole), or None if there is no usable
    cache directory; ``name`` (a user's factor name) is reduced to safe characters."""
    root = cache_dir()
    if root is None:
        return None
    safe = re.sub(r"[^A-Za-z0-9_.+]", "_", name)[:60] or "_"
    return root / f"{kind}-{safe}-{key}.pkl"


def _discard(path: Path, why: str) -> None:
    warn(f"fgc cache entry {path} discarded ({why}); recomputing it", CacheWarning)
    with contextlib.suppress(OSError):
        path.unlink(missing_ok=True)


def load(path: Path | None, key: str, kind: type | tuple[type, ...] = object):
    """The validated object stored at ``path`` for ``key``, or None if it is missing or bad (a bad
    entry is deleted, with one warning)."""
    if path is None:
        return None
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        return None
    except OSError as exc:
        _discard(path, f"unreadable: {exc.strerror}")
        return None
    header, sep, payload = data.partition(b"\n")
    fields = header.split(b" ")
    if not sep or len(fields) != 3 or fields[0] != _MAGIC:
        _discard(path, "not an fgc cache entry of this format")
        return None
    if fields[1] != key.encode():
        _discard(path, "it holds the entry of another key")
        return None
    if fields[2] != hashlib.sha256(payload).hexdigest().encode():
        _discard(path, "checksum mismatch: the file is truncated or corrupt")
        return None
    try:
        obj = pickle.loads(payload)
    except Exception as exc:  # noqa: BLE001 - any unpickling failure means: rebuild
        _discard(path, f"cannot be unpickled: {type(exc).__name__}")
        return None
    if not isinstance(obj, kind):
        _discard(path, f"holds a {type(obj).__name__}, not the expected type")
        return None
    return obj


def store(path: Path | None, key: str, obj) -> None:
    """Write ``obj`` as the entry of ``key`` at ``path``, atomically; failures only warn."""
    if path is None:
        return
    payload = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    header = b" ".join((_MAGIC, key.encode(), hashlib.sha256(payload).hexdigest().encode()))
    tmp = path.with_suffix(f".tmp{os.getpid()}")
    try:
        with tmp.open("wb") as fh:
            fh.write(header + b"\n" + payload)
        tmp.replace(path)
    except OSError as exc:
        _unusable(path.parent, f"cannot write: {exc.strerror or type(exc).__name__}")
        with contextlib.suppress(OSError):
            tmp.unlink(missing_ok=True)


class Deferred:
    """A value pickled on its own inside a cache entry and unpickled on first :meth:`get`.

    Unpickling sympy expressions rebuilds them through their constructors (≈0.3 s of CPU for
    the LIO set's derivations and fused kernels), while a warm compile only needs the small
    parts of those entries (fingerprints, structure, op counts): the expressions stay bytes
    until a cache miss downstream needs them. The bytes are inside the entry, so its checksum
    covers them."""

    __slots__ = ("_blob", "_value")

    def __init__(self, value=None, blob: bytes | None = None) -> None:
        self._value, self._blob = value, blob

    def get(self):
        if self._blob is not None:
            self._value, self._blob = pickle.loads(self._blob), None
        return self._value

    def __reduce__(self):
        blob = self._blob if self._blob is not None else pickle.dumps(
            self._value, protocol=pickle.HIGHEST_PROTOCOL)
        return (_deferred, (blob,))


def _deferred(blob: bytes) -> Deferred:
    return Deferred(blob=blob)


def cached(kind_name: tuple[str, str], key: str, build: Callable[[], T],
           kind: type | tuple[type, ...] = object) -> T:
    """``build()``'s result, read from / written to the entry ``(kind, name)`` of ``key``."""
    path = entry(*kind_name, key)
    hit = load(path, key, kind)
    if hit is not None:
        return hit
    obj = build()
    store(path, key, obj)
    return obj


# --------------------------------------------------------------------------------------------
# fgc cache info / clear
# --------------------------------------------------------------------------------------------


def _entries(root: Path) -> list[Path]:
    if not root.is_dir():
        return []
    return sorted(p for p in root.iterdir()
                  if p.is_file() and p.name.split("-", 1)[0] in KINDS
                  and (p.suffix == ".pkl" or ".tmp" in p.suffix))


def info() -> dict:
    """The cache directory, its number of entries per kind and their total size in bytes."""
    root = cache_root()
    counts = dict.fromkeys(KINDS, 0)
    size = 0
    for p in _entries(root):
        if p.suffix == ".pkl":
            counts[p.name.split("-", 1)[0]] += 1
        size += p.stat().st_size
    return {"dir": str(root), "entries": counts, "bytes": size}


def clear() -> int:
    """Delete every fgc cache entry (only fgc's own files); returns how many were removed."""
    n = 0
    for p in _entries(cache_root()):
        p.unlink(missing_ok=True)
        n += 1
    return n
