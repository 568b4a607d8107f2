"""Running the host's build tools (make, g++, a built testbench) so that nothing outlives fgc.

``make`` starts compilers of its own; ``subprocess.run`` kills only its direct child when the
caller is interrupted, so the compilers would go on writing into a folder fgc is removing. Here
the tool runs in a session (process group) of its own and the whole group is stopped on any
exception, Ctrl-C's KeyboardInterrupt included: SIGTERM first, so the compilers remove their
temporary files, then SIGKILL. fgc's own handler then prints one line.
"""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import time
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


TERM_GRACE_S = 2.0  # how long make and the compilers get to remove their temporary files


def _kill_group(proc: subprocess.Popen) -> None:
    """SIGTERM to the tool's process group (make deletes a half-written target, the compiler
    driver its temporary files in $TMPDIR), SIGKILL to what is left after TERM_GRACE_S."""
    with contextlib.suppress(OSError):
        os.killpg(proc.pid, signal.SIGTERM)
    deadline = time.monotonic() + TERM_GRACE_S
    with contextlib.suppress(BaseException):  # a second Ctrl-C: go straight to SIGKILL
        proc.communicate(timeout=TERM_GRACE_S)
        while time.monotonic() < deadline and _group_alive(proc.pid):  # make's children
            time.sleep(0.02)
    with contextlib.suppress(OSError):
        os.killpg(proc.pid, signal.SIGKILL)  # stragglers of the group (and its leader)
    with contextlib.suppress(OSError):
        proc.kill()
    with contextlib.suppress(BaseException):  # reap it: no zombie left behind
        proc.communicate()


def _group_alive(pgid: int) -> bool:
    try:
        os.killpg(pgid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True
    return True
