"""Running the host's build tools (make, g++, a built testbench) so that nothing outlives fgc.

``make`` starts compilers of its own; ``subprocess.run`` kills only its direct child when the
caller is interrupted, so the compilers would go on writing into a folder fgc is removing. Here
the tool runs in a session (process group) of its own and the whole group is killed on any
exception, Ctrl-C's KeyboardInterrupt included. fgc's own handler then prints one line.
"""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
from pathlib import Path


def run_tool(args: list[str], cwd: str | Path, timeout: float) -> subprocess.CompletedProcess:
    """``subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=timeout)``, the
    tool and every process it started killed if the call does not return normally (timeout,
    interrupt); raises what ``subprocess.run`` raises."""
    proc = subprocess.Popen(args, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except BaseException:
        _kill_group(proc)
        raise
    return subprocess.CompletedProcess(args, proc.returncode, out, err)


def _kill_group(proc: subprocess.Popen) -> None:
    with contextlib.suppress(OSError):
        os.killpg(proc.pid, signal.SIGKILL)
    with contextlib.suppress(OSError):
        proc.kill()
    with contextlib.suppress(BaseException):  # a second Ctrl-C must not leave a zombie behind
        proc.communicate()
