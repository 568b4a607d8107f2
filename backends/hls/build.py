"""Build and run an emitted project with the host compiler: ``make csim``.

The project's Makefile is the single description of the build; these helpers only call it with
fixed target names and fixed file names inside the project folder (``data.txt``, ``result.txt``),
so no caller-chosen path ever reaches make or the shell.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from fgc.errors import FgcError
from fgc.ir.datafile import ProblemData, write_data
from fgc.ir.program import Program
from fgc_backends.cfamily.process import run_tool
from fgc_backends.cfamily.results import (
    REFERENCE_FILE,
    HlsResult,
    error_floor,
    keyed,
    read_result,
    reference_run,
    write_reference,
)
from fgc_backends.cfamily.scalars import check_fixed_data
from fgc_backends.hls.config import HlsConfig, HlsConfigError
from fgc_backends.hls.emitter import HlsProject

DATA_FILE, RESULT_FILE, BUILD_LOG = "data.txt", "result.txt", "build.log"
BUILD_TIMEOUT_S = 900


class HlsBuildError(FgcError):
    """``make`` failed on an emitted project: an internal error (fgc emitted C++ that does not
    build); the message is one line naming ``build.log``, which holds the compiler's output."""


class HlsMismatchError(HlsBuildError):
    """The testbench built and ran, and its result differs from the reference beside the data
    (it exits 4): the message names the first mismatch the testbench printed."""


def write_project_reference(project: HlsProject, program: Program, data: ProblemData,
                            reference) -> Path:
    """``reference.txt`` in ``project``: ``reference`` (a simulator result of ``program`` on
    ``data``) with the error floor of the project's scalar (:func:`error_floor`)."""
    return write_reference(project.directory / REFERENCE_FILE, program, reference,
                           error_floor(program, data, reference, project.config.scalar_cxx))


def make(project: HlsProject, target: str) -> str:
    """Run ``make -s <target>`` in the project folder; returns its standard output."""
    if target not in ("csim", "clean"):
        raise ValueError(f"unknown make target {target!r}")
    return run_command(project, ["make", "-s", target], f"make {target}")


def run_command(project: HlsProject, args: list[str], what: str) -> str:
    """Run ``args`` in the project folder (a build or the built testbench, at most
    BUILD_TIMEOUT_S); returns its standard output. A failure writes the output to BUILD_LOG
    and raises :class:`HlsMismatchError` if the testbench printed a MISMATCH line (it built and
    ran: its check against the reference said no), else :class:`HlsBuildError`."""
    try:
        done = run_tool(args, project.directory, BUILD_TIMEOUT_S)  # killed if interrupted
    except subprocess.TimeoutExpired:
        raise HlsBuildError(f"{what} in {project.directory} took over "
                            f"{BUILD_TIMEOUT_S} s") from None
    if done.returncode != 0:
        log = project.directory / BUILD_LOG
        log.write_text(done.stdout + done.stderr)
        mismatch = next((line for line in done.stderr.splitlines()
                         if line.startswith("MISMATCH: ")), None)
        if mismatch is not None:  # it built and ran: the testbench's check said no (exit 4)
            raise HlsMismatchError(f"{what} failed: the C simulation's result differs "
                                   f"from the reference ({REFERENCE_FILE}): "
                                   f"{mismatch[len('MISMATCH: '):]}; full output in {log}")
        raise HlsBuildError(f"internal error: {what} failed (exit {done.returncode}) on "
                            f"the project fgc generated (a bug in fgc if the build failed); "
                            f"full output in {log}")
    return done.stdout


def run_csim(project: HlsProject, program: Program, data: ProblemData,
             reference=True) -> HlsResult:
    """Write ``data`` as the project's ``data.txt`` and the simulator's result beside it as
    ``reference.txt``, build and run the testbench (``make csim``, which fails with
    :class:`HlsBuildError` if the result differs from the reference) and return the parsed
    ``result.txt``, with the host-side float32 verdict
    (:func:`fgc_backends.cfamily.results.judge_precision`).

    ``reference``: True computes it (:func:`~fgc_backends.cfamily.results.reference_run`), a
    simulator result of the same Program and data is used as it is, False writes none (the
    testbench then says the result is unchecked)."""
    check_fixed_data(project.config.scalar_cxx, program, data, HlsConfigError)  # no saturating
    write_data(data, project.directory / DATA_FILE)
    ref_path = project.directory / REFERENCE_FILE
    ref_path.unlink(missing_ok=True)
    if reference is True:
        reference = reference_run(program, data)
    if reference is not False and reference is not None:
        write_project_reference(project, program, data, reference)
    result = project.directory / RESULT_FILE
    result.unlink(missing_ok=True)
    make(project, "csim")
    return read_result(result, program, data, project.config.scalar)


def run(program: Program, data: ProblemData, config: HlsConfig | None = None,
        out_dir: str | Path | None = None) -> HlsResult:
    """The backend contract's ``run``: emit ``program``'s accelerator into ``out_dir`` (a
    temporary directory if None), run its C simulation against the simulator's reference
    (:func:`run_csim`) and return the result with ``values`` as fgc values by Program key (the
    raw arrays in ``storage``), as the simulator and the native backend do."""
    import tempfile

    from fgc_backends.hls.emitter import emit

    with tempfile.TemporaryDirectory(prefix="fgc-hls-") as tmp:
        project = emit(program, out_dir or tmp, config)
        result = run_csim(project, program, data)
    return keyed(result, program)
