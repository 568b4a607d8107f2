"""Session-wide test setup.

Derivations are cached on disk in ``$FGC_CACHE_DIR`` (default ``~/.cache/fgc``). The suite points it
at a fresh per-session temporary directory (one for all pytest-xdist workers), so tests never read
or write the user's cache and every run exercises the cold derivation path once (the combined IMU
factor alone takes about two minutes of one core). An explicitly set ``FGC_CACHE_DIR`` is
respected.
"""

from __future__ import annotations

import os

import pytest


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


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-golden", action="store_true", default=False,
                     help="rewrite tests/golden/ from the current emitters instead of comparing")
