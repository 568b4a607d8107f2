"""Build an emitted native project with the host compiler: ``make native``.

The project's Makefile is the single description of the build; this helper only calls it with
fixed target names inside the project folder, so no caller-chosen path reaches make or the shell.
"""

from __future__ import annotations

import subprocess

from fgc.errors import FgcError
from fgc_backends.cfamily.process import run_tool
from fgc_backends.native.emitter import NativeProject

BUILD_LOG = "build.log"
BUILD_TIMEOUT_S = 900


class NativeBuildError(FgcError):
    """``make`` failed on an emitted project: an internal error (fgc emitted C++ that does not
    build); the message is one line naming ``build.log``, which holds the compiler's output."""


def make(project: NativeProject, target: str = "native") -> str:
    """Run ``make -s <target>`` (``native`` or ``clean``) in the project folder; returns its
    standard output. make and its compilers are killed if this is interrupted."""
    if target not in ("native", "clean"):
        raise ValueError(f"unknown make target {target!r}")
    try:
        done = run_tool(["make", "-s", target], project.directory, BUILD_TIMEOUT_S)
    except subprocess.TimeoutExpired:
        raise NativeBuildError(f"make {target} in {project.directory} took over "
                               f"{BUILD_TIMEOUT_S} s") from None
    if done.returncode != 0:
        log = project.directory / BUILD_LOG
        log.write_text(done.stdout + done.stderr)
        raise NativeBuildError(f"internal error: make {target} failed (exit {done.returncode}) "
                               f"on the project fgc generated (a bug in fgc if the build "
                               f"failed); full output in {log}")
    return done.stdout
