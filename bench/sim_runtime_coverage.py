"""Line coverage of the simulator's run-time (backends/sim/runtime) by the simulator's tests.

Every emitted simulator runs a byte-identical copy of the run-time modules from its own folder
(mostly temporary ones), so coverage sees many files called ``fgc_sim_linear.py`` and so on.
This script runs the tests under coverage with every ``fgc_sim_*.py`` included, then credits the
lines executed in any copy to the package source of the same name (a copy has the source's line
numbers: it is the same bytes) and reports the coverage of the sources.

    pip install coverage          # not among the test extras
    python bench/sim_runtime_coverage.py [--tests tests/sim/test_sim.py ...] [--show-missing]

Tests that run a simulator in a subprocess (``in_process=False``, the emitted program's command
line) are not traced, so the number is a lower bound.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
RUNTIME = ROOT / "backends" / "sim" / "runtime"
SIM_TESTS = ("tests/sim/test_sim.py", "tests/sim/test_sim_gtsam.py", "tests/sim/test_float32.py",
             "tests/app/test_stream.py", "tests/sim/test_marginals.py")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tests", nargs="+", default=list(SIM_TESTS))
    parser.add_argument("--show-missing", action="store_true")
    args = parser.parse_args(argv)
    try:
        import coverage
    except ImportError:
        print("coverage is not installed (pip install coverage)", file=sys.stderr)
        return 2
    sources = {p.name: p for p in sorted(RUNTIME.glob("fgc_sim_*.py"))}
    with tempfile.TemporaryDirectory(prefix="fgc-sim-cov-") as tmp:
        raw = Path(tmp) / "raw"
        run = subprocess.run([sys.executable, "-m", "coverage", "run", f"--data-file={raw}",
                              "--include=*fgc_sim_*.py", "-m", "pytest", "-q", "-n", "0",
                              "-p", "no:cacheprovider", *args.tests], cwd=ROOT, check=False)
        if run.returncode != 0:
            print(f"the tests failed (exit {run.returncode}); coverage not reported",
                  file=sys.stderr)
            return 1
        data = coverage.CoverageData(basename=str(raw))
        data.read()
        lines: dict[str, set[int]] = {str(p): set() for p in sources.values()}
        copies = 0
        for measured in data.measured_files():
            source = sources.get(Path(measured).name)
            if source is not None:
                lines[str(source)] |= set(data.lines(measured) or ())
                copies += Path(measured) != source
        merged = Path(tmp) / "merged"
        out = coverage.CoverageData(basename=str(merged))
        out.add_lines({name: sorted(found) for name, found in lines.items()})
        out.write()
        cov = coverage.Coverage(data_file=str(merged))
        cov.load()
        print(f"\nrun-time line coverage by {' '.join(args.tests)} "
              f"({copies} emitted copies credited to their sources):")
        total = cov.report(morfs=[str(p) for p in sources.values()],
                           show_missing=args.show_missing)
    print(f"total: {total:.1f}%")
    return 0


if __name__ == "__main__":
    sys.exit(main())
