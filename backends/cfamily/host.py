"""The machine a C++ build is for (shared by the native library's and the HLS C simulation's
build caches): ``-march=native`` code may not run elsewhere, so a cache shared between machines
keeps one build per CPU model and feature set."""

from __future__ import annotations

import platform


def host_key() -> str:
    """The CPU model, feature flags and architecture of this machine, as one string."""
    cpu = ""
    try:
        with open("/proc/cpuinfo", encoding="utf-8", errors="replace") as fh:
            cpu = "".join(sorted({line for line in fh if line.startswith(("model name",
                                                                           "flags"))}))
    except OSError:
        pass
    return f"{platform.machine()}|{platform.processor()}|{cpu}"
