"""Cache faults (issue 34): both caches, damaged every way we could think of, never crash and
never answer from a stale or foreign build.

- Native libraries (``<cache>/native/<hash>``): a truncated, emptied, byte-flipped, deleted or
  swapped-in library, a missing, garbled or foreign manifest, a folder of another hash are each
  refused *before* the library is loaded (a truncated one used to kill the process with SIGBUS),
  warned about once and rebuilt; the answer is the clean build's, to the bit. The rebuilds are
  counted. One case runs the real compiler (``make native``); the other cases stand in for it
  with a copy of that build (everything else — emit, manifest, move into place, checks, dlopen —
  is the real code), so the file stays fast; ``-m heavy`` repeats every fault with real builds
  and swaps libraries between two real specs.
- An unwritable (read-only, full) cache directory: one warning, the build runs in a temporary
  folder that is gone when the process exits; nothing is written to the cache.
- Interrupted work leaves nothing behind: a build interrupted by Ctrl-C removes its staging
  folder, an interrupted derivation-cache write its temporary file; leftovers of a killed
  process (``*.tmp<PID>``, PID dead) are removed by the next process; a live process's are not.
- ``fgc cache clear`` removes derivation entries, native builds, HLS stream projects and
  leftovers, and nothing else.

The derivation cache's own corruption fuzz (truncate, flip, swap; 10 cases, 200 heavy) is in
tests/compiler/test_cache.py; here its remaining faults (empty entry, entry deleted mid-run,
interrupted write, stale temporaries). Interrupts of whole commands: tests/app/test_interrupts.py.
"""

from __future__ import annotations

import os
import random
import shutil
import subprocess
import sys
import textwrap
import warnings
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.app.cli import main
from fgc.compile import compile_graph
from fgc.compiler import cache
from fgc.compiler.cache import MANIFEST, CacheWarning
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor
from fgc.frontend.geometry import Pose2
from fgc.ir.datafile import problem_data
from fgc.ir.program import SolverConfig
from fgc_backends.native import solver as native_solver

pytestmark = pytest.mark.skipif(shutil.which("g++") is None or shutil.which("make") is None,
                                reason="needs g++ and make")


def chain(n: int) -> fgc.Graph:
    """A Pose2 chain of ``n`` poses, a prior on each (its optimum is not the initial values)."""
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(i, Pose2(float(i) + 0.1, 0.05 * i, 0.01))
        g.add(PriorFactor(i, Pose2(float(i), 0.0, 0.0), noise.isotropic(3, 0.1)))
    for i in range(n - 1):
        g.add(BetweenFactor(i, i + 1, Pose2(1.0, 0.02, 0.0), noise.isotropic(3, 0.2)))
    return g


def _solve(program, graph) -> np.ndarray:
    """The native solve's state (flat), from a fresh load (nothing kept from an earlier one)."""
    native_solver._LOADED.clear()
    solver = native_solver.load(program)
    x, _, info = solver.solve(*solver.flatten(problem_data(graph, program)))
    assert info[1] == 0, info  # converged
    return x


def _warnings(caught) -> list[str]:
    return [str(w.message) for w in caught if issubclass(w.category, CacheWarning)]


def _leftovers(root: Path) -> list[str]:
    """fgc temporaries (``*.tmp<PID>``, ``*.built<PID>``, ``*.old<PID>``) anywhere in ``root``."""
    return sorted(str(p) for p in root.rglob("*") if cache._TEMP.search(p.name))


class Spec:
    """A graph, its Program, the clean build's folder name and answer."""

    def __init__(self, n: int, name: str) -> None:
        self.graph = chain(n)
        self.program = compile_graph(self.graph, SolverConfig(), name=name)
        self.key = native_solver.project_key(self.program,
                                             native_solver.default_config(self.program))
        self.lib = f"lib{name}.so"
        self.clean: np.ndarray | None = None


@pytest.fixture(scope="module")
def warm(tmp_path_factory):
    """Spec A built once for real in a private cache ("warm"), and its clean answer."""
    spec = Spec(4, "chain_a")
    root = tmp_path_factory.mktemp("warm-native")
    mp = pytest.MonkeyPatch()
    mp.setenv("FGC_CACHE_DIR", str(root))
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            spec.clean = _solve(spec.program, spec.graph)
        assert not _warnings(caught)
    finally:
        mp.undo()
        native_solver._LOADED.clear()
    return spec, root


@pytest.fixture
def work(warm, tmp_path, monkeypatch):
    """A copy of the warm cache as FGC_CACHE_DIR (a new path per test: the dynamic loader never
    hands back a library loaded from the same path earlier) and a count of real/stand-in
    builds: ``builds["make"]`` counts make runs, which copy the warm library into place."""
    spec, root = warm
    copy = tmp_path / "cache"
    shutil.copytree(root, copy)
    monkeypatch.setenv("FGC_CACHE_DIR", str(copy))
    monkeypatch.setattr(cache, "_SWEPT", set())
    monkeypatch.setattr(cache, "_UNUSABLE", set())
    good = root / "native" / spec.key / spec.lib
    builds = {"make": 0}

    def stand_in_make(project, target="native"):
        builds["make"] += 1
        shutil.copy2(good, project.library)
        return ""

    monkeypatch.setattr(native_solver, "make", stand_in_make)
    return spec, copy, builds


def _folder(root: Path, spec: Spec) -> Path:
    return root / "native" / spec.key


def _flip(path: Path, rng: random.Random) -> None:
    data = bytearray(path.read_bytes())
    i = rng.randrange(len(data))
    data[i] ^= 1 << rng.randrange(8)
    path.write_bytes(bytes(data))


def damage(how: str, folder: Path, lib: str, rng: random.Random, foreign: Path | None = None):
    """Damage the built project in ``folder`` the way ``how`` says (``foreign``: another
    spec's built folder, for the swaps)."""
    so = folder / lib
    if how == "truncate":
        so.write_bytes(so.read_bytes()[:rng.randrange(1, so.stat().st_size)])
    elif how == "empty":
        so.write_bytes(b"")
    elif how == "flip":
        _flip(so, rng)
    elif how == "delete library":  # e.g. removed by hand, or between two runs
        so.unlink()
    elif how == "delete manifest":  # a build that never finished, or by an older fgc
        (folder / MANIFEST).unlink()
    elif how == "garble manifest":
        (folder / MANIFEST).write_text("{not json")
    elif how == "folder of another hash":  # the folder renamed / copied under another hash
        shutil.rmtree(folder)
        shutil.copytree(foreign, folder)
    elif how == "library of another graph":  # its library swapped in, this manifest kept
        shutil.copy2(next(foreign.glob("lib*.so")), so)
    else:
        raise ValueError(how)


FAULTS = ("truncate", "empty", "flip", "delete library", "delete manifest", "garble manifest",
          "folder of another hash", "library of another graph")


def _other_build(root: Path, spec: Spec) -> Path:
    """A stand-in for another spec's build: spec's folder with its manifest's key changed and
    its library's bytes changed (the fast tests' "other graph"; heavy ones use a real one)."""
    other = root / "other-build"
    shutil.copytree(_folder(root, spec), other)
    text = (other / MANIFEST).read_text().replace(spec.key, "0" * len(spec.key))
    (other / MANIFEST).write_text(text)
    with (other / spec.lib).open("ab") as fh:
        fh.write(b"\0" * 64)
    return other


@pytest.mark.parametrize("how", FAULTS)
def test_a_damaged_native_build_is_refused_before_loading_and_rebuilt(how, work):
    spec, root, builds = work
    folder = _folder(root, spec)
    damage(how, folder, spec.lib, random.Random(how), _other_build(root, spec))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        x = _solve(spec.program, spec.graph)
    msgs = _warnings(caught)
    assert len(msgs) == 1 and str(folder) in msgs[0] and "rebuilding" in msgs[0], msgs
    assert builds["make"] == 1
    assert np.array_equal(x, spec.clean)  # the clean build's answer, to the bit
    assert cache.check_manifest(folder, spec.key, (spec.lib,)) is None  # rebuilt intact
    assert not _leftovers(root)
    # the next process finds it intact: no warning, no build
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert np.array_equal(_solve(spec.program, spec.graph), spec.clean)
    assert not _warnings(caught) and builds["make"] == 1


@pytest.mark.heavy  # a second real build (~3 s of CPU); the stand-in cases above run by default
def test_a_truncated_library_is_rebuilt_by_the_compiler(warm, tmp_path, monkeypatch):
    """The real path end to end: the truncated library that used to end the process with
    SIGBUS (exit 135, nothing printed) is refused, rebuilt by make and solved with."""
    spec, root = warm
    copy = tmp_path / "cache"
    shutil.copytree(root, copy)
    monkeypatch.setenv("FGC_CACHE_DIR", str(copy))
    folder = _folder(copy, spec)
    damage("truncate", folder, spec.lib, random.Random(1))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        x = _solve(spec.program, spec.graph)
    assert len(_warnings(caught)) == 1
    assert np.array_equal(x, spec.clean)
    assert cache.check_manifest(folder, spec.key, (spec.lib,)) is None


def test_an_unwritable_cache_builds_in_a_temporary_folder_removed_at_exit(warm, tmp_path):
    """A cache directory where no build can be created (here ``native`` is a file, which no
    permission bit lets even root write into; a read-only or full disk fails the same call):
    one warning, the right answer from a build in a temporary folder, which is gone when the
    process exits; the cache holds no build and no temporary."""
    spec, _ = warm
    root = tmp_path / "cache"
    root.mkdir()
    for entry in Path(os.environ["FGC_CACHE_DIR"]).glob("*.pkl"):  # warm derivations
        shutil.copy2(entry, root)
    (root / "native").write_text("not a folder")
    tmp = tmp_path / "tmp"
    tmp.mkdir()
    script = textwrap.dedent("""
        import sys, warnings
        sys.path.insert(0, sys.argv[1])
        from test_cache_faults import chain, _solve
        from fgc.compile import compile_graph
        from fgc.ir.program import SolverConfig
        from fgc_backends.native import solver
        graph = chain(4)
        program = compile_graph(graph, SolverConfig(), name="chain_a")
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            x = _solve(program, graph)
        print(next(iter(solver._LOADED.values())).project.directory)
        print(repr(x.tolist()))
        for w in caught:
            print("WARNING", w.message)
    """)
    env = dict(os.environ, TMPDIR=str(tmp), FGC_CACHE_DIR=str(root))
    done = subprocess.run([sys.executable, "-c", script, str(Path(__file__).parent)], env=env,
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    built_in = Path(lines[0])
    assert built_in.is_relative_to(tmp)
    assert np.array_equal(np.array(eval(lines[1])), spec.clean)  # noqa: S307 - our own repr
    warned = [line for line in lines if line.startswith("WARNING")]
    assert len(warned) == 1 and "unusable" in warned[0] and str(root) in warned[0], lines
    assert not built_in.exists() and not list(tmp.iterdir())  # removed at exit
    assert (root / "native").read_text() == "not a folder"
    assert not _leftovers(root)


def test_a_full_cache_directory_builds_uncached(work, monkeypatch):
    """ENOSPC while the build is written to the cache: one warning, the build is done again in
    a temporary folder, the answer is right and the cache holds no half-written build."""
    spec, root, builds = work
    shutil.rmtree(root / "native")
    real = native_solver.write_manifest

    def full_disk(folder, key):
        if folder.is_relative_to(root):
            raise OSError(28, "No space left on device")
        real(folder, key)

    monkeypatch.setattr(native_solver, "write_manifest", full_disk)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        x = _solve(spec.program, spec.graph)
    msgs = _warnings(caught)
    assert len(msgs) == 1 and "No space left" in msgs[0], msgs
    assert np.array_equal(x, spec.clean) and builds["make"] == 2
    assert not list((root / "native").iterdir())


def test_an_interrupted_build_leaves_nothing_and_the_next_one_builds(work, monkeypatch):
    spec, root, builds = work
    shutil.rmtree(root / "native")

    def interrupted(project, target="native"):
        (project.directory / "half.o").write_bytes(b"\0" * 10)
        raise KeyboardInterrupt

    real = native_solver.make
    monkeypatch.setattr(native_solver, "make", interrupted)
    with pytest.raises(KeyboardInterrupt):
        _solve(spec.program, spec.graph)
    assert not list((root / "native").iterdir())  # no staging folder, no half build
    monkeypatch.setattr(native_solver, "make", real)
    assert np.array_equal(_solve(spec.program, spec.graph), spec.clean)
    assert builds["make"] == 1


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid  # exited and reaped: no process has this id (until it is reused)


def test_leftovers_of_a_killed_process_are_removed_by_the_next(work):
    spec, root, builds = work
    dead, live = _dead_pid(), os.getppid()  # the parent (pytest's runner or shell) is alive
    stale = [root / "native" / f"{spec.key}.tmp{dead}",
             root / f"derive-x-{'0' * 64}.tmp{dead}",
             root / "hls-stream" / f"abc.built{dead}",
             root / "hls-stream" / f"abc.old{dead}"]
    kept = [root / "native" / f"{spec.key}.tmp{live}",  # a build under way in another process
            root / f"unrelated.tmp{dead}"]  # not fgc's (FGC_CACHE_DIR may be shared)
    for p in stale + kept:
        p.parent.mkdir(parents=True, exist_ok=True)
        if p.name.startswith("derive") or p.name.startswith("unrelated"):
            p.write_bytes(b"half")
        else:
            p.mkdir()
            (p / "half.o").write_bytes(b"\0")
    assert np.array_equal(_solve(spec.program, spec.graph), spec.clean)
    assert builds["make"] == 0
    assert [p for p in stale if p.exists()] == []
    assert all(p.exists() for p in kept)


# --------------------------------------------------------------------------------------------
# the derivation cache's remaining faults
# --------------------------------------------------------------------------------------------


def _derivation_cache(tmp_path, monkeypatch) -> tuple[Path, dict]:
    """A private derivation cache holding spec A's entries; the clean compile's files."""
    root = tmp_path / "dcache"
    monkeypatch.setenv("FGC_CACHE_DIR", str(root))
    monkeypatch.setattr(cache, "_SWEPT", set())
    _forget_memos()
    program = compile_graph(chain(3), SolverConfig(), name="chain_d")
    return root, program.to_json()


def test_an_empty_or_vanishing_derivation_entry_is_recomputed(tmp_path, monkeypatch):
    root, clean = _derivation_cache(tmp_path, monkeypatch)
    entries = sorted(root.glob("*.pkl"))
    assert entries
    entries[0].write_bytes(b"")
    real_load, gone = cache.load, []

    def vanishing(path, key, kind=object):  # deleted by another process as it is read
        if path is not None and path == entries[-1] and not gone:
            gone.append(path)
            path.unlink()
        return real_load(path, key, kind)

    monkeypatch.setattr(cache, "load", vanishing)
    for module in ("fgc.compiler.derive", "fgc.compiler.fuse", "fgc.compiler.lower",
                   "fgc.compiler.storage"):
        mod = sys.modules[module]
        if hasattr(mod, "load"):
            monkeypatch.setattr(mod, "load", vanishing)
    _forget_memos()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        again = compile_graph(chain(3), SolverConfig(), name="chain_d").to_json()
    assert again == clean
    msgs = _warnings(caught)
    assert len(msgs) == 1 and str(entries[0]) in msgs[0], msgs
    assert all(p.is_file() and p.stat().st_size > 0 for p in entries)  # both rewritten


def test_an_interrupted_derivation_write_leaves_no_temporary(tmp_path, monkeypatch):
    path = tmp_path / f"derive-x-{'1' * 64}.pkl"

    def interrupted(self, target):
        raise KeyboardInterrupt

    monkeypatch.setattr(Path, "replace", interrupted)
    with pytest.raises(KeyboardInterrupt):
        cache.store(path, "1" * 64, {"a": 1})
    assert list(tmp_path.iterdir()) == []


def _forget_memos() -> None:
    """Drop the in-process memos of derived/fused/lowered work (the disk cache is then read)."""
    from fgc.compiler import derive, fuse, lower, storage

    derive._MEMO.clear()
    derive._KEYS.clear()
    fuse._MEMO.clear()
    lower._LOWERED.clear()
    storage._STRUCTURES.clear()


# --------------------------------------------------------------------------------------------
# fgc cache clear / info
# --------------------------------------------------------------------------------------------


def test_cache_clear_removes_everything_fgc_keeps_and_nothing_else(work, capsys):
    spec, root, _ = work
    for name in ("derive-x-" + "2" * 64 + ".pkl", "fuse-x-" + "3" * 64 + ".tmp12"):
        (root / name).write_bytes(b"x")
    (root / "hls-stream" / "k" ).mkdir(parents=True)
    (root / "hls-stream" / "k" / "tb").write_bytes(b"\0" * 100)
    (root / "native" / f"{spec.key}.tmp999999").mkdir()
    (root / "notes.txt").write_text("the user's")
    assert main(["cache", "info", "--json"]) == 0
    info = __import__("json").loads(capsys.readouterr().out)
    assert info["entries"]["native"] == 1 and info["entries"]["hls-stream"] == 1
    assert info["entries"]["derive"] == 1 and info["bytes"] > (root / "native").stat().st_size
    assert main(["cache", "clear"]) == 0
    assert "removed 4 entries" in capsys.readouterr().out
    assert sorted(p.name for p in root.iterdir()) == ["notes.txt"]


# --------------------------------------------------------------------------------------------
# heavy: every fault with real builds, swaps between two real specs
# --------------------------------------------------------------------------------------------


@pytest.mark.heavy
def test_every_fault_with_real_builds_and_two_specs(warm, tmp_path, monkeypatch):
    """Seeded: 3 rounds × every fault, on spec A or spec B (each a real build, a real library
    of the other spec for the swaps). Counts: faults, rebuilds, stale answers (0), crashes
    (0, else this test would not finish)."""
    spec_a, _ = warm
    spec_b = Spec(6, "chain_b")
    root = tmp_path / "cache"
    monkeypatch.setenv("FGC_CACHE_DIR", str(root))
    monkeypatch.setattr(cache, "_UNUSABLE", set())
    for spec in (spec_a, spec_b):
        spec.clean = _solve(spec.program, spec.graph)
    rng = random.Random(34)
    counts = {"faults": 0, "rebuilds": 0, "stale": 0}
    for round_ in range(3):
        for how in FAULTS:
            spec, other = (spec_a, spec_b) if rng.random() < 0.5 else (spec_b, spec_a)
            # each case in its own directory: the loader never reuses an earlier path
            case = tmp_path / f"case{round_}-{FAULTS.index(how)}"
            shutil.copytree(root, case)
            monkeypatch.setenv("FGC_CACHE_DIR", str(case))
            damage(how, _folder(case, spec), spec.lib, rng, _folder(case, other))
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                x = _solve(spec.program, spec.graph)
            counts["faults"] += 1
            counts["rebuilds"] += len(_warnings(caught))
            counts["stale"] += int(not np.array_equal(x, spec.clean))
            assert cache.check_manifest(_folder(case, spec), spec.key, (spec.lib,)) is None
            assert not _leftovers(case)
            shutil.rmtree(case)
    print("native cache faults:", counts)
    assert counts == {"faults": 3 * len(FAULTS), "rebuilds": 3 * len(FAULTS), "stale": 0}


# --------------------------------------------------------------------------------------------
# the HLS stream's cached projects (hls-stream/<hash>)
# --------------------------------------------------------------------------------------------


# "empty" and "foreign" are heavy (each re-emits and rebuilds the stream project, ~12 s): the
# native build's test above covers every fault kind, truncate / delete manifest stay here
HEAVY = pytest.mark.heavy


@pytest.mark.parametrize("how", ["truncate", pytest.param("empty", marks=HEAVY),
                                 "delete manifest", pytest.param("foreign", marks=HEAVY)])
def test_a_damaged_hls_stream_project_is_emitted_again(how, warm, tmp_path, monkeypatch):
    from fgc_backends.hls.config import HlsConfig
    from fgc_backends.hls.streaming import _cached_project

    spec, _ = warm
    monkeypatch.setenv("FGC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(cache, "_SWEPT", set())
    config = HlsConfig(scalar="double")
    first = _cached_project(spec.program, config)
    clean = {p.name: p.read_bytes() for p in first.files}
    assert MANIFEST not in clean and cache.check_manifest(first.directory,
                                                          first.directory.name) is None
    victim = next(p for p in first.files if p.suffix == ".cpp")
    if how == "truncate":
        victim.write_bytes(victim.read_bytes()[:100])
    elif how == "empty":
        victim.write_bytes(b"")
    elif how == "delete manifest":
        (first.directory / MANIFEST).unlink()
    else:  # the folder of another hash copied under this one
        text = (first.directory / MANIFEST).read_text()
        (first.directory / MANIFEST).write_text(text.replace(first.directory.name, "f" * 24))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        again = _cached_project(spec.program, config)
    msgs = _warnings(caught)
    assert len(msgs) == 1 and str(first.directory) in msgs[0], msgs
    assert {p.name: p.read_bytes() for p in again.files} == clean
    assert not _leftovers(tmp_path / "cache")


def test_an_unwritable_cache_emits_the_hls_stream_project_in_a_temporary_folder(
        warm, tmp_path, monkeypatch):
    from fgc_backends.hls.config import HlsConfig
    from fgc_backends.hls.streaming import _cached_project

    spec, _ = warm
    root = tmp_path / "cache"
    root.mkdir()
    (root / "hls-stream").write_text("not a folder")
    monkeypatch.setenv("FGC_CACHE_DIR", str(root))
    monkeypatch.setattr(cache, "_UNUSABLE", set())
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        project = _cached_project(spec.program, HlsConfig(scalar="double"))
    assert len(_warnings(caught)) == 1
    assert not project.directory.is_relative_to(root) and project.files
    assert sorted(p.name for p in root.iterdir()) == ["hls-stream"]
