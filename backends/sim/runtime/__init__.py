"""The simulator's run-time: the static part of every emitted simulator, as ordinary modules.

Each ``fgc_sim_*.py`` here is copied byte for byte into the emitted project beside the generated
problem module (``<name>_sim.py``: kernels, tables, sizes, each variable type's retraction and
local coordinates) and the generated constants module (``fgc_sim_constants.py``: fgc's Lie
series), and fgc's own ``lie_closed_forms.py`` (the Lie closed forms, :data:`SHARED`). The
modules import only NumPy and the standard library and never each other: the
problem module loads them and hands them around as one namespace (``lib``), so an emitted
simulator runs without fgc and several can share one process. This package file itself is not
copied.
"""

from pathlib import Path

# the copied modules, in the order the problem module loads them
MODULES = ("fgc_sim_special", "fgc_sim_linear", "fgc_sim_runtime", "fgc_sim_optimizer",
           "fgc_sim_incremental", "fgc_sim_diagnostics")


# copied from fgc itself, under its own name: the Lie closed forms (fgc.frontend.geometry)
SHARED = ("lie_closed_forms",)


def module_paths() -> tuple[Path, ...]:
    """The source file of every copied module: the run-time's, then fgc's shared ones."""
    import fgc.frontend.geometry as geometry  # this file is not copied: it may import fgc

    here = Path(__file__).resolve().parent
    shared = Path(geometry.__file__).resolve().parent
    return (tuple(here / f"{name}.py" for name in MODULES)
            + tuple(shared / f"{name}.py" for name in SHARED))
