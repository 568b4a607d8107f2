"""Derivation time, cold and warm: what the disk cache saves when a factor is compiled again.

For each factor type, each repetition uses a fresh, empty ``FGC_CACHE_DIR`` and two Python
subprocesses (so fgc's in-memory memo never helps):

- *cold*: the first process derives the factor (trace, CSE, forward-mode Jacobians, structure
  probing) and writes the cache file;
- *warm*: the second process finds the file and only unpickles it.

Times are the ``derive()`` call inside the process (imports excluded; they are reported
separately). GTSAM has no counterpart to this step — its Jacobians are written by hand and compiled
into the wheel — so there is no rival column; the kernel's size is shown for scale.

Run:  python bench/bench_derive.py [--repeat N] [--factor NAME ...]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]

FACTORS = {  # name → Python expression (in the child) for the factor type
    "CombinedImuFactor(logmap)": "combined_imu_factor_type('logmap')",
    "CombinedImuFactor(componentwise)": "combined_imu_factor_type('componentwise')",
    "BetweenFactorPose3": "between_factor_type(Pose3)",
}
DEFAULT_FACTORS = ("CombinedImuFactor(logmap)", "BetweenFactorPose3")

CHILD = """
import json, sys, time
t0 = time.perf_counter()
from fgc.compiler.derive import derive
from fgc.frontend.factors import combined_imu_factor_type
from fgc.factors.basic import between_factor_type
from fgc.frontend.geometry import Pose3
t1 = time.perf_counter()
ftype = {expr}
t2 = time.perf_counter()
sf = derive(ftype)
t3 = time.perf_counter()
ops = sf.kernel.op_counts()
json.dump({{"import": t1 - t0, "derive": t3 - t2, "assignments": len(sf.kernel.assignments),
           "ops": sum(ops.values())}}, sys.stdout)
"""


@dataclass(frozen=True)
class Run:
    """One child process: its in-process times and the kernel it produced."""

    import_s: float
    derive_s: float
    assignments: int
    ops: int


def run_child(expr: str, cache_dir: Path) -> Run:
    env = dict(os.environ, FGC_CACHE_DIR=str(cache_dir))
    proc = subprocess.run([sys.executable, "-c", CHILD.format(expr=expr)], env=env, cwd=REPO,
                          capture_output=True, text=True, check=True)
    out = json.loads(proc.stdout)
    return Run(out["import"], out["derive"], out["assignments"], out["ops"])


@dataclass(frozen=True)
class Result:
    name: str
    cold: list[Run]
    warm: list[Run]
    cache_bytes: int


def measure(name: str, repeat: int) -> Result:
    cold, warm, size = [], [], 0
    for _ in range(repeat):
        with tempfile.TemporaryDirectory(prefix="fgc-bench-derive-") as tmp:
            cache = Path(tmp)
            cold.append(run_child(FACTORS[name], cache))
            files = list(cache.glob("*.pkl"))
            if len(files) != 1:
                raise RuntimeError(f"{name}: expected one cache file after the cold run, "
                                   f"found {len(files)}")
            size = files[0].stat().st_size
            warm.append(run_child(FACTORS[name], cache))
    return Result(name, cold, warm, size)


def _median(runs: list[Run], field: str) -> float:
    return statistics.median(getattr(r, field) for r in runs)


def print_table(results: list[Result], repeat: int) -> None:
    header = (f"{'factor':<34}{'cold [s]':>10}{'warm [s]':>10}{'speed-up':>10}"
              f"{'import [s]':>12}{'cache [kB]':>12}{'assign.':>9}{'ops':>7}")
    print(f"derive() time, median of {repeat} fresh cache dirs (each: cold process, warm process)")
    print(header)
    print("-" * len(header))
    for r in results:
        cold, warm = _median(r.cold, "derive_s"), _median(r.warm, "derive_s")
        print(f"{r.name:<34}{cold:>10.3f}{warm:>10.4f}{cold / warm:>9.0f}x"
              f"{_median(r.cold, 'import_s'):>12.2f}{r.cache_bytes / 1024:>12.1f}"
              f"{r.cold[0].assignments:>9}{r.cold[0].ops:>7}")


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="fresh cache dirs per factor")
    parser.add_argument("--factor", action="append", choices=sorted(FACTORS),
                        help="factor to measure (repeatable; default: IMU logmap, Pose3 between)")
    args = parser.parse_args(argv)
    names = args.factor or list(DEFAULT_FACTORS)
    print_table([measure(name, args.repeat) for name in names], args.repeat)


if __name__ == "__main__":
    main()
