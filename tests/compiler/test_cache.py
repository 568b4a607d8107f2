"""The derivation cache: content-addressed keys, and entries that defend themselves.

- Keys: a derivation is keyed by its traced residual, so a value the residual reads through a
  dict, a list, a class attribute, a ``@staticmethod`` or a helper in another module is part of
  the key (each route below changed a value that the old source-text fingerprint missed); fgc's
  code version and sympy's version are part of it and of the file name.
- Entries: truncated, byte-flipped or swapped files give one ``CacheWarning`` naming the file,
  the correct result and a rewritten entry; never a traceback. The corruption fuzz runs 10 cases
  by default and 200 with ``-m heavy``.
"""

from __future__ import annotations

import importlib.util
import json
import random
import shutil
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import fgc
from fgc.app.cli import main
from fgc.compile import compile_graph
from fgc.compiler import cache, fuse, lower, storage
from fgc.compiler import derive as derive_mod
from fgc.compiler.cache import CacheWarning
from fgc.frontend.geometry import Pose2

ROUTES = {
    "dict": ("K = {'s': 1.0}\n", "K['s']", "K['s'] = v"),
    "list": ("L = [1.0]\n", "L[0]", "L[0] = v"),
    "class attribute": ("class C:\n    s = 1.0\n", "C.s", "C.s = v"),
    "staticmethod": ("S = 1.0\nclass C:\n    @staticmethod\n    def s():\n        return S\n",
                     "C.s()", "global S\n    S = v"),
    "helper module": ("import cache_helper_mod as H\n", "H.scaled(1.0)", "H.S = v"),
}

SPEC = '''
import fgc
from fgc import Point2, Pose2
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor

K = {"s": 1.0}


@fgc.factor
def scaled_position(x: Pose2, *, z: Point2):
    return [x.x() * K["s"] - z[0], x.y() * K["s"] - z[1]]


def build(s: float = 1.0, n: int = 4):
    K["s"] = s
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(f"x{i}", Pose2(0.1 * i, 0.05, 0.02))
    g.add(PriorFactor("x0", Pose2(0.0, 0.0, 0.0), noise.isotropic(3, 0.1)))
    for i in range(n - 1):
        g.add(BetweenFactor(f"x{i}", f"x{i + 1}", Pose2(1.0, 0.0, 0.1), noise.isotropic(3, 0.1)))
    for i in range(n):
        g.add(scaled_position(f"x{i}", z=Point2(1.2 * i, 0.3), noise=noise.isotropic(2, 0.2)))
    return g
'''


def _forget_memos() -> None:
    """What a new process would not have: only the disk cache remains."""
    derive_mod._MEMO.clear()
    derive_mod._KEYS.clear()
    fuse._MEMO.clear()
    lower._LOWERED.clear()
    storage._STRUCTURES.clear()


@pytest.fixture
def cache_dir(tmp_path, monkeypatch) -> Path:
    path = tmp_path / "cache"
    monkeypatch.setenv("FGC_CACHE_DIR", str(path))
    _forget_memos()
    yield path
    _forget_memos()


def _import(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod
    spec.loader.exec_module(mod)
    return mod


@pytest.mark.parametrize("route", list(ROUTES))
def test_value_read_by_any_route_is_in_the_key(route, tmp_path, cache_dir, monkeypatch):
    prelude, read, assign = ROUTES[route]
    (tmp_path / "cache_helper_mod.py").write_text("S = 1.0\n\ndef scaled(v):\n    return v * S\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    sys.modules.pop("cache_helper_mod", None)
    src = (f"import fgc\nfrom fgc import Point2, Pose2\n{prelude}\n\n"
           f"@fgc.factor\ndef reads(x: Pose2, *, z: Point2):\n"
           f"    return [x.x() * {read} - z[0], x.y() - z[1]]\n\n\n"
           f"def set_value(v):\n    {assign}\n")
    (tmp_path / "route_spec.py").write_text(src)
    mod = _import(tmp_path / "route_spec.py", f"route_spec_{route.replace(' ', '_')}")
    at, z = [Pose2(2.0, 5.0, 0.3)], {"z": np.zeros(2)}
    fgc.Graph()  # a spec's build() sets the value, then builds its graph
    first = derive_mod.derive(mod.reads).evaluate_residual(at, z)
    np.testing.assert_allclose(first, [2.0, 5.0])
    for fresh_process in (False, True):  # in-process memo, then the disk cache alone
        mod.set_value(3.0 if fresh_process else 7.0)
        fgc.Graph()
        if fresh_process:
            _forget_memos()
        got = derive_mod.derive(mod.reads).evaluate_residual(at, z)
        np.testing.assert_allclose(got, [6.0 if fresh_process else 14.0, 5.0])
    sys.modules.pop("cache_helper_mod", None)


def test_key_has_code_and_sympy_version(tmp_path, cache_dir, monkeypatch):
    (tmp_path / "s.py").write_text(SPEC)
    mod = _import(tmp_path / "s.py", "cache_version_spec")
    derive_mod.derive(mod.scaled_position)
    assert len(list(cache_dir.glob("derive-*.pkl"))) == 1
    # an fgc upgrade: a new derivation code version must not reuse the old entry
    _forget_memos()
    monkeypatch.setattr(derive_mod, "_code_version", lambda: "0123456789abcdef")
    derive_mod.derive(mod.scaled_position)
    names = sorted(p.name for p in cache_dir.glob("derive-*.pkl"))
    assert len(names) == 2, names
    monkeypatch.undo()
    # a sympy upgrade changes the code version
    import sympy

    before = derive_mod._code_version.__wrapped__()
    monkeypatch.setattr(sympy, "__version__", sympy.__version__ + ".post999")
    assert derive_mod._code_version.__wrapped__() != before
    # the file name holds the whole key, and the entry stores it
    _forget_memos()
    key, _ = derive_mod.content_key(mod.scaled_position)
    path = cache_dir / f"derive-scaled_position-{key}.pkl"
    assert path.exists() and key.encode() in path.read_bytes().split(b"\n", 1)[0]


def _run(spec: Path, s: float, out: Path) -> dict:
    assert main(["run", str(spec), "--backend", "sim", "-p", f"s={s}", "--json", str(out)]) == 0
    return json.loads(out.read_text())


def test_changed_parameter_with_one_cache_matches_a_fresh_cache(tmp_path, cache_dir, monkeypatch,
                                                                capsys):
    spec = tmp_path / "spec.py"
    spec.write_text(SPEC)
    _run(spec, 1.0, tmp_path / "a.json")
    _forget_memos()  # the second run is a new `fgc run` process with the same cache
    reused = _run(spec, 2.0, tmp_path / "b.json")["final_error"]
    monkeypatch.setenv("FGC_CACHE_DIR", str(tmp_path / "fresh"))
    _forget_memos()
    fresh = _run(spec, 2.0, tmp_path / "c.json")["final_error"]
    assert reused == fresh  # same program, same arithmetic: bit-identical


def test_warm_compile_leaves_expressions_pickled_until_used(tmp_path, cache_dir):
    """A warm compile reads a derivation's and a fused kernel's small parts only; the sympy
    expressions (most of the unpickling time) are rebuilt on first use, equal to the fresh ones,
    and the Program is the same as the cold compile's."""
    spec = tmp_path / "spec.py"
    spec.write_text(SPEC)
    graph = _import(spec, "lazy_spec").build()
    cold = compile_graph(graph)
    ftype = next(f.type for f in graph.factors if f.type.name == "scaled_position")
    fresh = derive_mod.derive(ftype)
    fused = fuse.fuse(graph)
    _forget_memos()
    warm = compile_graph(graph)
    assert warm.to_json() == cold.to_json()
    sf = derive_mod.derive(ftype)
    assert "_deferred" in sf.__dict__ and "kernel" not in sf.__dict__
    assert sf.residual_dim == 2 and sf.structure == fresh.structure
    assert sf.kernel == fresh.kernel and sf.expression == fresh.expression
    assert "_deferred" not in sf.__dict__
    block = next(t for t in fuse._MEMO.values() if t.name == "scaled_position")
    assert block.kernels._blob is not None  # lowered from the cache: never unpickled
    assert block.kernel == next(b.type for b in fused if b.type.name == block.name).kernel


def test_unusable_cache_dir_warns_once_and_runs_uncached(tmp_path, monkeypatch, capsys):
    spec = tmp_path / "spec.py"
    spec.write_text(SPEC)
    monkeypatch.setenv("FGC_CACHE_DIR", "/dev/null")
    cache._UNUSABLE.clear()
    _forget_memos()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _run(spec, 1.0, tmp_path / "a.json")
    msgs = [str(w.message) for w in caught if issubclass(w.category, CacheWarning)]
    assert len(msgs) == 1 and "/dev/null" in msgs[0], msgs
    _forget_memos()


def test_cache_cli_info_and_clear(tmp_path, cache_dir, capsys):
    (tmp_path / "s.py").write_text(SPEC)
    mod = _import(tmp_path / "s.py", "cache_cli_spec")
    derive_mod.derive(mod.scaled_position)
    assert main(["cache", "info", "--json"]) == 0
    info = json.loads(capsys.readouterr().out)
    assert info["dir"] == str(cache_dir) and info["entries"]["derive"] == 1 and info["bytes"] > 0
    (cache_dir / "unrelated.txt").write_text("keep me")
    assert main(["cache", "clear"]) == 0
    assert [p.name for p in cache_dir.iterdir()] == ["unrelated.txt"]


# --------------------------------------------------------------------------------------------
# corrupt entries
# --------------------------------------------------------------------------------------------


def _compile(spec: Path, out: Path) -> tuple[dict[str, bytes], list[str]]:
    """Emitted files of ``fgc compile`` (sim backend) and the CacheWarnings it gave."""
    _forget_memos()
    shutil.rmtree(out, ignore_errors=True)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert main(["compile", str(spec), "--backend", "sim", "--out", str(out),
                     "-p", "s=1.5"]) == 0
    files = {str(p.relative_to(out)): p.read_bytes() for p in sorted(out.rglob("*"))
             if p.is_file()}
    return files, [str(w.message) for w in caught if issubclass(w.category, CacheWarning)]


@pytest.fixture(scope="module")
def warm(tmp_path_factory):
    """A warm cache of the spec and the files a clean compile emits."""
    root = tmp_path_factory.mktemp("warm")
    spec = root / "spec.py"
    spec.write_text(SPEC)
    mp = pytest.MonkeyPatch()
    mp.setenv("FGC_CACHE_DIR", str(root / "cache"))
    try:
        clean, msgs = _compile(spec, root / "out")
        assert not msgs
    finally:
        mp.undo()
        _forget_memos()
    return spec, root / "cache", clean


def _corrupt(rng: random.Random, entries: list[Path]) -> list[Path]:
    """Damage the cache in one of three ways; returns the files that are now bad."""
    how = rng.choice(("truncate", "flip", "swap"))
    if how == "swap":
        a, b = rng.sample(entries, 2)
        da, db = a.read_bytes(), b.read_bytes()
        a.write_bytes(db)
        b.write_bytes(da)
        return [a, b]
    path = rng.choice(entries)
    data = bytearray(path.read_bytes())
    if how == "truncate":
        data = data[:rng.randrange(len(data))]
    else:
        i = rng.randrange(len(data))
        data[i] ^= 1 << rng.randrange(8)
    path.write_bytes(bytes(data))
    return [path]


def _valid(path: Path) -> bool:
    """``path`` holds a good entry of the key its name gives."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return cache.load(path, path.stem.rsplit("-", 1)[1]) is not None


def _fuzz(n: int, warm, tmp_path, monkeypatch) -> None:
    spec, warm_cache, clean = warm
    rng = random.Random(16)
    for case in range(n):
        work = tmp_path / "cache"
        shutil.rmtree(work, ignore_errors=True)
        shutil.copytree(warm_cache, work)
        monkeypatch.setenv("FGC_CACHE_DIR", str(work))
        entries = sorted(work.glob("*.pkl"))
        bad = _corrupt(rng, entries)
        files, msgs = _compile(spec, tmp_path / "out")
        assert files == clean, f"case {case}: output differs from a clean compile"
        for path in bad:  # one warning per bad file, naming it; the entry is rewritten good
            named = [m for m in msgs if str(path) in m]
            assert len(named) == 1, (case, msgs)
            assert _valid(path)
        assert len(msgs) == len(bad), (case, msgs)


def test_corrupt_entries_fuzz(warm, tmp_path, monkeypatch):
    _fuzz(10, warm, tmp_path, monkeypatch)


@pytest.mark.heavy
def test_corrupt_entries_fuzz_200(warm, tmp_path, monkeypatch):
    _fuzz(200, warm, tmp_path, monkeypatch)


@pytest.mark.parametrize("how", ["truncate", "flip", "swap"])
def test_each_corruption_kind(how, warm, tmp_path, monkeypatch):
    spec, warm_cache, clean = warm
    work = tmp_path / "cache"
    shutil.copytree(warm_cache, work)
    monkeypatch.setenv("FGC_CACHE_DIR", str(work))
    derives = sorted(work.glob("derive-*.pkl"))
    if how == "swap":
        a, b = derives[:2]
        da, db = a.read_bytes(), b.read_bytes()
        a.write_bytes(db)
        b.write_bytes(da)
        bad = [a, b]
    else:
        data = bytearray(derives[0].read_bytes())
        if how == "truncate":
            data = data[:len(data) // 2]
        else:
            data[len(data) // 2] ^= 0x10
        derives[0].write_bytes(bytes(data))
        bad = [derives[0]]
    files, msgs = _compile(spec, tmp_path / "out")
    assert files == clean
    assert len(msgs) == len(bad) and all(any(str(p) in m for m in msgs) for p in bad), msgs
    assert all(_valid(p) for p in bad)
