"""Per-iteration progress of a long solve, on stderr and in the JSON log.

A backend calls the display with one record per accepted iteration (``iteration``, ``error``,
``lambda`` and, where the backend knows it, ``relative_decrease``). Every record is kept (the
JSON log's ``progress``: the same fields plus ``elapsed_seconds``); nothing is printed until the
solve has run for ``delay`` seconds (1 s on a terminal, 2 s otherwise), so a short solve stays
silent. After that one line per iteration goes to stderr: on a terminal it overwrites itself
(``\\r``, cleared at the end), otherwise whole lines at most one every ``interval`` seconds
(plus the last). The line holds the iteration, the error, LM's damping, the elapsed time and an
estimate of what is left: at most the remaining iterations (``max_iterations``) at the mean time
per iteration so far, an upper bound (a solve usually converges before its iteration limit).

    display = Progress("fgc run w10000.graph", max_iterations=100)
    result = native.run(program, data, progress=display)
    display.finish()
    report["progress"] = display.records
"""

from __future__ import annotations

import sys
import time
from typing import TextIO

DELAY_S = 1.0  # on a terminal
PLAIN_DELAY_S = 2.0  # plain lines (a log, a pipe): only solves that are clearly long
INTERVAL_S = 1.0


class Progress:
    """A progress display for one solve (module docstring); callable with a record."""

    def __init__(self, label: str, max_iterations: int, show: bool = True,
                 stream: TextIO | None = None, delay: float | None = None,
                 interval: float = INTERVAL_S) -> None:
        self.label = label
        self.max_iterations = max(1, int(max_iterations))
        self.show = show
        self.stream = stream if stream is not None else sys.stderr
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)())
        self.delay = delay if delay is not None else (DELAY_S if self.tty else PLAIN_DELAY_S)
        self.interval = interval
        self.records: list[dict] = []
        self.t0 = time.perf_counter()
        self._printed_at: float | None = None
        self._pending: dict | None = None  # a plain-lines record not printed yet
        self._width = 0  # of the last overwritten line

    def start(self) -> None:
        """Restart the clock (call just before the solve, after any build)."""
        self.t0 = time.perf_counter()

    def __call__(self, record: dict) -> None:
        elapsed = time.perf_counter() - self.t0
        entry = {"iteration": int(record["iteration"]), "error": float(record["error"]),
                 "lambda": float(record.get("lambda", float("nan"))),
                 "elapsed_seconds": elapsed}
        if record.get("relative_decrease") is not None:
            entry["relative_decrease"] = float(record["relative_decrease"])
        self.records.append(entry)
        if not self.show or elapsed < self.delay:
            return
        if self.tty:
            self._overwrite(self.line(entry))
        elif self._printed_at is None or elapsed - self._printed_at >= self.interval:
            self._emit(entry, elapsed)
        else:
            self._pending = entry

    def line(self, entry: dict) -> str:
        """One progress line for ``entry``."""
        it, elapsed = entry["iteration"], entry["elapsed_seconds"]
        left = self.max_iterations - it
        per = elapsed / max(it, 1)
        estimate = (f", ≤ {_duration(left * per)} left (≤ {left} more iterations at "
                    f"{_duration(per)} each)" if left > 0 else "")
        damping = "" if entry["lambda"] != entry["lambda"] else f", λ {entry['lambda']:.1e}"
        decrease = ("" if "relative_decrease" not in entry
                    else f", decrease {entry['relative_decrease']:.1e}")
        return (f"{self.label}: iteration {it}/{self.max_iterations}, error "
                f"{entry['error']:.10g}{damping}{decrease}, {_duration(elapsed)} elapsed"
                f"{estimate}")

    def finish(self) -> None:
        """End the display: clear a terminal's line, print a plain stream's last record."""
        if not self.show:
            return
        if self.tty and self._width:
            self.stream.write("\r" + " " * self._width + "\r")
            self.stream.flush()
            self._width = 0
        elif self._pending is not None:
            self._emit(self._pending, self._pending["elapsed_seconds"])

    def _overwrite(self, text: str) -> None:
        pad = max(0, self._width - len(text))
        self.stream.write("\r" + text + " " * pad)
        self.stream.flush()
        self._width = len(text)

    def _emit(self, entry: dict, elapsed: float) -> None:
        self.stream.write(self.line(entry) + "\n")
        self.stream.flush()
        self._printed_at, self._pending = elapsed, None


def _duration(seconds: float) -> str:
    if seconds < 1:
        return f"{seconds * 1e3:.0f} ms"
    if seconds < 120:
        return f"{seconds:.1f} s"
    return f"{seconds / 60:.1f} min"
