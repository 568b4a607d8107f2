"""The ``fgc`` console script's entry point: :func:`fgc.app.cli.main`, with Ctrl-C handled from
the first instruction.

Importing fgc (numpy, sympy, fgc's own modules) takes a second or more, and an interrupt in that
time would otherwise reach the interpreter as a traceback. This module imports nothing of fgc
until it is inside its handler, so Ctrl-C at any point prints one line, ``fgc: interrupted``,
and exits 130. It is a top-level module because importing anything inside the ``fgc`` package
runs the package's (heavy) ``__init__`` first.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import sys
from typing import NoReturn

EXIT_INTERRUPTED = 130


def _interrupted() -> int:
    print("fgc: interrupted", file=sys.stderr, flush=True)
    return EXIT_INTERRUPTED


def _by_interrupt(exc: BaseException) -> bool:
    seen, todo = set(), [exc]
    while todo:
        exc = todo.pop()
        if exc is None or id(exc) in seen:
            continue
        if isinstance(exc, KeyboardInterrupt):
            return True
        seen.add(id(exc))
        todo += [exc.__cause__, exc.__context__]
    return False


def _exit_interrupted() -> NoReturn:
    """Exit with status 130 after the clean-up of a normal exit (the ``atexit`` functions:
    temporary folders), then at once: CPython ends a process whose interrupt was raised inside
    ``exec``/``eval`` of a string (dataclasses and sympy define functions that way) by SIGINT
    at exit, even when the interrupt was handled, so a plain return would not always be 130."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # a second Ctrl-C must not stop the clean-up
    try:
        atexit._run_exitfuncs()
    finally:
        for stream in (sys.stdout, sys.stderr):
            with contextlib.suppress(Exception):
                stream.flush()
        os._exit(EXIT_INTERRUPTED)


def main(argv: list[str] | None = None) -> int:
    """Run ``fgc`` (:func:`fgc.app.cli.main`); an interrupt before it runs is handled here."""
    try:
        from fgc.app.cli import main as cli_main
    except KeyboardInterrupt:
        _interrupted()
        _exit_interrupted()
    except ImportError as exc:  # an extension module interrupted while it initialised
        if _by_interrupt(exc):
            _interrupted()
            _exit_interrupted()
        raise
    try:
        code = cli_main(argv)
    except KeyboardInterrupt:  # between the import and cli_main's own handler
        code = _interrupted()
    if code == EXIT_INTERRUPTED:
        _exit_interrupted()
    # the command is done: a Ctrl-C now (while the interpreter exits and removes temporary
    # folders) must neither print a traceback nor stop that clean-up
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    return code


if __name__ == "__main__":
    sys.exit(main())
