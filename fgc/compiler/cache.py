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
cache directory that cannot be created or written (read-only, full) gives one warning and fgc
continues uncached.

The backends keep built projects in sub-folders of the same directory (:data:`FOLDERS`:
``native/<hash>`` for the native solver's libraries, ``hls-stream/<hash>`` for the streaming HLS
C simulations), each with a manifest of the key it was built for and the SHA-256 of its files
(:func:`write_manifest`, :func:`check_manifest`), checked before anything in it is used.
Temporary files and folders (``*.tmp<PID>`` and the like) of a process that died are removed the
first time a later process uses the directory (:func:`sweep_stale`); ``fgc cache clear`` removes
entries, built projects and leftovers alike.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import pickle
import re
import shutil
from collections.abc import Callable
from functools import cache
from pathlib import Path
from typing import TypeVar

from fgc.ir.conditioning import FgcWarning, warn

T = TypeVar("T")

_MAGIC = b"fgc-cache-1"
KINDS = ("derive", "fuse", "lower", "structure")
# sub-folders of the cache directory holding the backends' built projects, one folder a hash
FOLDERS = ("native", "hls-stream")
MANIFEST = "fgc-manifest.json"
# the suffix of a temporary file or folder of process PID: ``.tmpPID`` (entries, staging builds),
# ``.builtPID`` / ``.oldPID`` (hls-stream's swap of a built project into place)
_TEMP = re.compile(r"\.(tmp|built|old)(\d+)$")


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


def unusable(path: Path, why: str) -> None:
    """Say once per process that the cache directory ``path`` cannot be used (``why``); the
    derivation cache and the backends' builds then work uncached (in temporary folders)."""
    if str(path) not in _UNUSABLE:
        _UNUSABLE.add(str(path))
        warn(f"fgc cache directory {path} is unusable ({why}); continuing without a "
             "cache (set FGC_CACHE_DIR to a writable directory)", CacheWarning)


_unusable = unusable
_SWEPT: set[str] = set()  # directories whose dead processes' leftovers were removed


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # EPERM: it exists (another user's)
        return True
    return True


def _remove(path: Path) -> None:
    if path.is_dir() and not path.is_symlink():
        shutil.rmtree(path, ignore_errors=True)
    else:
        with contextlib.suppress(OSError):
            path.unlink(missing_ok=True)


def _temporary(path: Path, live: bool) -> bool:
    """Whether ``path`` is a temporary of fgc's (in its cache directory or a FOLDERS folder) and,
    unless ``live``, of a process that is no longer running."""
    match = _TEMP.search(path.name)
    if match is None:
        return False
    if path.parent.name not in FOLDERS and path.name.split("-", 1)[0] not in KINDS:
        return False  # not one of ours (FGC_CACHE_DIR may be a directory shared with others)
    return live or not _alive(int(match.group(2)))


def sweep_stale(root: Path) -> int:
    """Remove the temporary files and folders that processes which are no longer running left
    in the cache directory ``root`` (killed while writing an entry or building a project);
    returns how many. Done once per process and directory, by :func:`cache_dir`."""
    n = 0
    for folder in (root, *(root / f for f in FOLDERS)):
        try:
            names = list(folder.iterdir())
        except OSError:
            continue
        for path in names:
            if _temporary(path, live=False):
                _remove(path)
                n += 1
    return n


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
    if str(path) not in _SWEPT:
        _SWEPT.add(str(path))
        sweep_stale(path)
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
    except BaseException:  # interrupted (Ctrl-C): leave nothing half-written behind
        with contextlib.suppress(OSError):
            tmp.unlink(missing_ok=True)
        raise


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
# built projects: manifests
# --------------------------------------------------------------------------------------------


def file_digest(path: Path) -> str:
    """SHA-256 (hex) of the file at ``path``."""
    h = hashlib.sha256()
    with path.open("rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def write_manifest(folder: Path, key: str) -> None:
    """Record in ``folder`` (a built project, before it is moved into the cache) the key it was
    built for and the SHA-256 of each of its files."""
    files = {p.name: file_digest(p) for p in sorted(folder.iterdir())
             if p.is_file() and p.name != MANIFEST}
    (folder / MANIFEST).write_text(json.dumps({"format": 1, "key": key, "files": files},
                                              indent=1, sort_keys=True) + "\n")


def check_manifest(folder: Path, key: str, required: tuple[str, ...] = ()) -> str | None:
    """Why the project in ``folder`` cannot be used for ``key`` (no or a foreign manifest, a
    file missing, changed, truncated), or None if every file it recorded is as written and
    ``required`` are among them."""
    try:
        manifest = json.loads((folder / MANIFEST).read_text())
        files = manifest["files"]
        recorded = manifest["key"]
    except FileNotFoundError:
        return "no manifest (an unfinished or foreign build)"
    except (OSError, ValueError, KeyError, TypeError) as exc:
        return f"unreadable manifest ({type(exc).__name__})"
    if recorded != key or not isinstance(files, dict):
        return "it holds the build of another key"
    for name in required:
        if name not in files:
            return f"{name} is not in its manifest"
    for name, digest in files.items():
        path = folder / name
        try:
            if file_digest(path) != digest:
                return f"{name} differs from what was built (truncated or replaced)"
        except OSError as exc:
            return f"{name} cannot be read ({exc.strerror or type(exc).__name__})"
    return None


def discard_folder(folder: Path, why: str) -> None:
    """Remove a damaged built project (one warning naming it): moved aside first, so another
    process finds either the whole folder or none."""
    warn(f"fgc cache entry {folder} discarded ({why}); rebuilding it", CacheWarning)
    aside = folder.with_name(f"{folder.name}.tmp{os.getpid()}")
    _remove(aside)
    try:
        os.replace(folder, aside)
    except OSError:
        aside = folder
    _remove(aside)


# --------------------------------------------------------------------------------------------
# fgc cache info / clear
# --------------------------------------------------------------------------------------------


def _entries(root: Path) -> list[Path]:
    if not root.is_dir():
        return []
    return sorted(p for p in root.iterdir()
                  if p.is_file() and p.name.split("-", 1)[0] in KINDS
                  and (p.suffix == ".pkl" or ".tmp" in p.suffix))


def _size(path: Path) -> int:
    if not path.is_dir():
        return path.stat().st_size
    return sum(p.lstat().st_size for p in path.rglob("*") if p.is_file())


def info() -> dict:
    """The cache directory, its number of entries per kind (derivation kinds, and the backends'
    built projects per folder) and their total size in bytes."""
    root = cache_root()
    counts = dict.fromkeys((*KINDS, *FOLDERS), 0)
    size = 0
    for p in _entries(root):
        if p.suffix == ".pkl":
            counts[p.name.split("-", 1)[0]] += 1
        size += p.stat().st_size
    for name in FOLDERS:
        folder = root / name
        if folder.is_dir():
            for p in folder.iterdir():
                if p.is_dir() and not _temporary(p, live=True):
                    counts[name] += 1
                size += _size(p)
    return {"dir": str(root), "entries": counts, "bytes": size}


def clear() -> int:
    """Delete everything fgc keeps in the cache directory (derivation entries, built projects,
    temporary leftovers; no other file); returns how many entries and projects were removed."""
    root = cache_root()
    n = 0
    for p in _entries(root):
        p.unlink(missing_ok=True)
        n += 1
    for name in FOLDERS:
        folder = root / name
        if folder.is_dir() and not folder.is_symlink():
            n += sum(1 for p in folder.iterdir() if p.is_dir() and not _temporary(p, live=True))
            shutil.rmtree(folder)
        elif folder.is_symlink():
            folder.unlink()
    return n
