"""Ctrl-C (issue 34): at any point of ``fgc compile``, ``simulate``, ``run --backend native`` and
``stream``, the command prints one line, ``fgc: interrupted``, exits 130, prints no traceback,
leaves no temporary file in the cache directory, the output directory or $TMPDIR, and leaves no
process behind (make and the compilers it started are killed with it).

Each case starts ``fgc`` (the console script's entry, ``fgc_cli``) in a session of its own, as a
terminal starts a foreground job, and sends SIGINT to the whole process group after a seeded
random delay (at least 0.4 s: before that the Python interpreter itself is starting — its
``site`` module, the environment's ``.pth`` files — and no program's code runs yet), as Ctrl-C
does. A run that finished before the signal (exit 0) is counted apart; the tests check that most
runs were really interrupted. 4 cases by default; with ``-m heavy`` 20 more and 12 of verify,
``run --backend hls``, ``stream --backend native`` and ``sweep``.
"""

from __future__ import annotations

import contextlib
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(shutil.which("g++") is None or shutil.which("make") is None,
                                reason="needs g++ and make")

SPEC = '''
import fgc
from fgc import Pose2
from fgc.frontend import noise
from fgc.frontend.factors import BetweenFactor, PriorFactor


def build(n: int = 8) -> fgc.Graph:
    g = fgc.Graph()
    for i in range(n):
        g.add_variable(i, Pose2(float(i) + 0.1, 0.05 * i, 0.01))
        g.add(PriorFactor(i, Pose2(float(i), 0.0, 0.0), noise.isotropic(3, 0.1)))
    for i in range(n - 1):
        g.add(BetweenFactor(i, i + 1, Pose2(1.0, 0.0, 0.0), noise.isotropic(3, 0.2)))
    return g
'''

COMMANDS = {
    "compile": ["compile", "{spec}", "--backend", "native", "--out", "{out}"],
    "simulate": ["simulate", "{spec}", "--json", "{out}/sim.json"],
    "run native": ["run", "{spec}", "--backend", "native"],
    "stream": ["stream", "{spec}", "--window", "2", "--json", "{out}/stream.json"],
}
# the other commands that build, run subprocesses or workers (heavy only)
MORE_COMMANDS = {
    "verify": ["verify", "{spec}"],
    "run hls": ["run", "{spec}", "--backend", "hls"],
    "stream native": ["stream", "{spec}", "--window", "2", "--backend", "native"],
    "sweep": ["sweep", "{spec}", "--units", "1,2", "--precision", "float32,float64", "--jobs",
              "2", "--out", "{out}"],
}
TEMP = re.compile(r"\.(tmp|built|old)\d+$")


@pytest.fixture(scope="module")
def setup(tmp_path_factory):
    """The spec, and a private cache holding its derivations (one uninterrupted compile)."""
    root = tmp_path_factory.mktemp("interrupts")
    spec = root / "chain.py"
    spec.write_text(SPEC)
    cache = root / "cache"
    for entry in Path(os.environ["FGC_CACHE_DIR"]).glob("*.pkl"):  # the session's derivations
        cache.mkdir(exist_ok=True)
        shutil.copy2(entry, cache)
    done = _fgc(["compile", str(spec), "--backend", "sim", "--out", str(root / "warm")],
                root, cache)
    assert done.returncode == 0, done.stderr
    return spec, cache


def _env(tmp: Path, cache: Path) -> dict:
    # the projects' own compiler flags, not the suite's quick -O0 (tests/conftest.py): with
    # builds that take a user's time the delays land in make or g++ as a user's Ctrl-C does
    return dict(os.environ, TMPDIR=str(tmp), FGC_CACHE_DIR=str(cache), PYTHONUNBUFFERED="1",
                FGC_CSIM_FLAGS="", FGC_NATIVE_FLAGS="")


def _fgc(args: list[str], tmp: Path, cache: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "fgc_cli", *args], env=_env(tmp, cache),
                          capture_output=True, text=True, timeout=900)


def _processes_in(folder: Path) -> list[str]:
    """Processes whose working directory is inside ``folder`` (an orphaned make or g++)."""
    found = []
    for proc in Path("/proc").iterdir():
        if proc.name.isdigit():
            try:
                cwd = Path(os.readlink(proc / "cwd"))
            except OSError:
                continue
            if cwd.is_relative_to(folder):
                found.append(f"{proc.name} in {cwd}")
    return found


def _args(name: str, spec: Path, cache: Path, out: Path) -> list[str]:
    """Command ``name``'s arguments; a native command's build removed first (a cold build: the
    interrupt lands in make or g++ most often)."""
    if "native" in name:
        shutil.rmtree(cache / "native", ignore_errors=True)
    return [a.format(spec=spec, out=out) for a in {**COMMANDS, **MORE_COMMANDS}[name]]


def _duration(name: str, spec: Path, cache: Path, work: Path) -> float:
    """Seconds command ``name`` takes uninterrupted on this machine (it must succeed)."""
    out, tmp = work / "out", work / "tmp"
    out.mkdir(parents=True)
    tmp.mkdir()
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "fgc_cli", *_args(name, spec, cache, out)],
                          env=_env(tmp, cache), capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, (name, done.stderr[-2000:])
    return time.monotonic() - start


def _default_sigint() -> None:
    """Ctrl-C's default action in the command's process: a shell without job control starts a
    background job (``pytest &``) with SIGINT ignored, the command would inherit that and
    Python would then install no KeyboardInterrupt handler (every run "finished")."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def interrupt(name: str, delay: float, spec: Path, cache: Path, work: Path) -> str:
    """Run command ``name``, SIGINT its process group after ``delay`` s, check what it left;
    returns "interrupted" or "finished" (done before the signal)."""
    out, tmp = work / "out", work / "tmp"
    out.mkdir(parents=True)
    tmp.mkdir()
    args = _args(name, spec, cache, out)
    proc = subprocess.Popen([sys.executable, "-m", "fgc_cli", *args], env=_env(tmp, cache),
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True, preexec_fn=_default_sigint)
    time.sleep(delay)
    with contextlib.suppress(ProcessLookupError):  # already done
        os.killpg(proc.pid, signal.SIGINT)  # Ctrl-C: the whole foreground group
    stdout, stderr = proc.communicate(timeout=600)
    what = f"{name} after {delay:.2f} s: exit {proc.returncode}, stderr {stderr[-2000:]!r}"
    assert "Traceback" not in stderr, what
    if proc.returncode == 130:
        assert stderr.strip().splitlines()[-1] == "fgc: interrupted", what
        outcome = "interrupted"
    elif proc.returncode == 0:
        outcome = "finished"
    else:
        raise AssertionError(what)
    leftovers = [str(p) for folder in (cache, out) for p in folder.rglob("*")
                 if TEMP.search(p.name)]
    assert not leftovers, (what, leftovers)
    assert not list(tmp.iterdir()), (what, list(tmp.iterdir()))
    for _ in range(20):  # a killed compiler may take a moment to be reaped
        orphans = _processes_in(work) + _processes_in(cache)
        if not orphans:
            break
        time.sleep(0.1)
    assert not orphans, (what, orphans)
    return outcome


def _interrupts(n: int, setup, tmp_path, max_delay: float, names=tuple(COMMANDS)) -> dict:
    spec, cache = setup
    rng = random.Random(34)
    counts = {"interrupted": 0, "finished": 0}
    took = {}  # each command's uninterrupted time here: a delay lands within it
    for i in range(n):
        name = names[i % len(names)]
        if name not in took:
            took[name] = _duration(name, spec, cache, tmp_path / f"timed{len(took)}")
        delay = min(rng.uniform(0.4, max_delay), 0.6 * took[name])
        counts[interrupt(name, delay, spec, cache, tmp_path / f"case{i}")] += 1
    print(f"{n} interrupts:", counts)
    # the delays reach into the work at least once (each at most 0.6 of the command's own time
    # here, so a faster machine does not outrun them all; a command may still finish first,
    # which is checked as cleanly as an interrupt)
    assert counts["interrupted"] >= 1, counts
    return counts


def test_interrupts(setup, tmp_path):
    _interrupts(4, setup, tmp_path, 3.0)


@pytest.mark.heavy
def test_interrupts_20(setup, tmp_path):
    _interrupts(20, setup, tmp_path, 6.0)


@pytest.mark.heavy
def test_interrupts_of_the_other_commands(setup, tmp_path):
    """verify, run --backend hls (make csim), stream --backend native and sweep (worker
    processes, which ignore Ctrl-C while idle and unwind on it while working)."""
    _interrupts(12, setup, tmp_path, 12.0, tuple(MORE_COMMANDS))


def test_an_interrupted_import_of_gtsam_is_an_interrupt_not_a_missing_package(monkeypatch):
    """A C extension interrupted while it initialises reports an ImportError caused by the
    KeyboardInterrupt: that is Ctrl-C, not "needs the 'gtsam' package"."""
    import builtins

    from fgc.interop import to_gtsam

    real = builtins.__import__

    def interrupted(name, *args, **kwargs):
        if name == "gtsam":
            try:
                raise KeyboardInterrupt
            except KeyboardInterrupt as exc:
                raise ImportError("initialization failed") from exc
        return real(name, *args, **kwargs)

    monkeypatch.delitem(sys.modules, "gtsam", raising=False)
    monkeypatch.setattr(builtins, "__import__", interrupted)
    with pytest.raises(KeyboardInterrupt):
        to_gtsam._gtsam()


def test_main_reports_an_interrupt_in_one_line(monkeypatch, capsys):
    from fgc.app import cli

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli, "_cmd_cache", interrupted)
    assert cli.main(["cache", "info"]) == 130
    assert capsys.readouterr().err == "fgc: interrupted\n"
