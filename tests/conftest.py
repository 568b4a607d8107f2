"""Session-wide test setup.

Derivations are cached on disk in ``$FGC_CACHE_DIR`` (default ``~/.cache/fgc``). The suite points it
at a fresh per-session temporary directory (one for all pytest-xdist workers), so tests never read
or write the user's cache and every run exercises the cold derivation path once (the combined IMU
factor now takes seconds, not minutes: in a cold run of the default suite on a loaded 2-core
host, 2026-12-07, the LIO and IMU sets' derivations were all written in the run's first two
minutes, the rest are small factors of single tests). An explicitly set ``FGC_CACHE_DIR`` is
respected.
"""

from __future__ import annotations

import os

import pytest

# The C++ builds: the emitted Makefiles put $(FGC_CSIM_FLAGS) (HLS testbench) and
# $(FGC_NATIVE_FLAGS) (native library) after the project's own flags, so -O0 here builds in a
# fraction of the g++ time (LIO N = 6 testbench, double: 2.2 s of CPU against 7.7 s at -O2;
# LIO N = 30 native library: 1.6 s against 9.1 s at -O3, a solve 19 ms against 2 ms) and runs
# the same IEEE operations in the same order (-ffp-contract=off, no FMA): the same numbers, byte
# for byte (tests/hls/test_hls_csim.py compares LIO's result.txt at -O0 and -O2,
# tests/native/test_native.py's lanes test the library at -O0 and -O3). The builds whose point
# is the flags keep the project's own: tests/hls/test_emit_builds.py (-Werror under the
# optimiser) and test_native's fused multiply-add check (the vectoriser's code). The counting
# builds (bench/bench_cycles.py, bench_stream_cycles.py) stay at their -O1: their runs are long
# (LIO N = 30: 14 s at -O1, over a minute at -O0). An explicitly set variable (even empty) is
# respected.
CSIM_FLAGS = NATIVE_FLAGS = "-O0"
os.environ.setdefault("FGC_CSIM_FLAGS", CSIM_FLAGS)
os.environ.setdefault("FGC_NATIVE_FLAGS", NATIVE_FLAGS)


@pytest.fixture(scope="session", autouse=True)
def fgc_cache_dir(tmp_path_factory: pytest.TempPathFactory):
    """The derivation cache directory used by this test session."""
    preset = os.environ.get("FGC_CACHE_DIR")
    if preset:
        yield preset
        return
    if os.environ.get("PYTEST_XDIST_WORKER"):
        # pytest-xdist: every worker's base temp sits in one session folder; share one cache
        # there (entries are written atomically), so a derivation is done once per run
        path = tmp_path_factory.getbasetemp().parent / "fgc-cache"
        path.mkdir(exist_ok=True)
    else:
        path = tmp_path_factory.mktemp("fgc-cache")
    os.environ["FGC_CACHE_DIR"] = str(path)
    try:
        yield str(path)
    finally:
        os.environ.pop("FGC_CACHE_DIR", None)


# The test files that take longest in the default run, slowest first (the seconds are their
# slowest tests' sum in one --durations run on a loaded 2-core host, 2026-12-07: an order, not
# a promise). pytest-xdist's --dist loadfile hands a worker one file at a time; with
# its default --loadscope-reorder it queues the files with the most tests first, so files of a
# few slow tests (C simulations, GTSAM runs) were handed out last and one worker ran them alone
# while the other idled. pyproject's addopts turn that reorder off and this list puts the
# slowest files at the head of the queue (longest first), the others after them in collection
# order; a file missing from the list only loses its place in the queue, nothing else.
SLOW_FILES: tuple[str, ...] = (
    "tests/hls/test_hls_window.py",  # 565
    "tests/hls/test_hls_csim.py",  # 540
    "tests/native/test_native.py",  # 375
    "tests/hls/test_hls_stream.py",  # 243
    "tests/hls/test_units_cholesky.py",  # 221
    "tests/hls/test_cholesky_cascades.py",  # 177
    "tests/hls/test_hls_structure.py",  # 135
    "tests/hls/test_hls_stream_sweep.py",  # 123
    "tests/native/test_native_fixed.py",  # 120
    "tests/native/test_native_stream.py",  # 114
    "tests/hls/test_emit_builds.py",  # 105
    "tests/hls/test_hls_check.py",  # 102
    "tests/hls/test_hls_units.py",  # 90
    "tests/hls/test_cascade_lanes.py",  # 85
    "tests/app/test_sweep.py",  # 83
    "tests/compiler/test_cache_faults.py",  # 78
    "tests/test_determinism.py",  # 77
    "tests/hls/test_hls_stream_csim.py",  # 76
)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Order the collected tests so the files of SLOW_FILES come first, slowest first; tests
    keep their order inside a file (module fixtures are built once per file as before)."""
    rank = {name: i for i, name in enumerate(SLOW_FILES)}
    root = config.rootpath

    def key(item: pytest.Item) -> int:
        try:
            name = item.path.relative_to(root).as_posix()
        except ValueError:
            return len(rank)
        return rank.get(name, len(rank))

    items.sort(key=key)  # stable: collection order within a file and among unlisted files


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-golden", action="store_true", default=False,
                     help="rewrite tests/golden/ from the current emitters instead of comparing")
