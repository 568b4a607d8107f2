"""Spec files: a ``.py`` file whose ``build(**params)`` returns an fgc Graph, or a pose-graph file
(g2o / TORO) from disk or from the gtsam wheel's example data. The CLI, the tests and the
benchmarks load the examples through :func:`spec_module` / :func:`load_spec` (no ``sys.path``
edits)."""

from __future__ import annotations

import importlib.util
import inspect
import sys
from pathlib import Path
from types import ModuleType

from fgc.errors import FgcError
from fgc.frontend.dsl import Graph

# the repository's example specs (examples/ beside the fgc package in a checkout)
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def spec_module(path: str | Path, shown: str | None = None) -> ModuleType:
    """Import the spec file ``path`` as the module ``fgc_spec_<stem>`` (loaded afresh, and
    registered in ``sys.modules`` so dataclasses and pickling inside it work); a spec that fails
    to import raises an FgcError naming it."""
    p = Path(path)
    shown = shown or str(path)
    if not p.is_file():
        raise FgcError(f"{shown}: no such file")
    name = f"fgc_spec_{p.stem}"
    spec = importlib.util.spec_from_file_location(name, p)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except FgcError:
        del sys.modules[name]
        raise
    except Exception as exc:
        del sys.modules[name]
        raise FgcError(f"{shown}: the spec failed to load: {type(exc).__name__}: {exc}") from exc
    return module


def example(name: str) -> ModuleType:
    """The repository's example spec ``examples/<name>.py`` as a module (tests, benchmarks)."""
    return spec_module(EXAMPLES / f"{name}.py")


def load_spec(path: str, params: dict) -> Graph:
    """Build the graph of a spec: a ``.py`` file with ``build(**params)``, or a g2o/TORO file
    (which gets a prior on its first pose to fix the gauge) given as a path or as the name of a
    file in the gtsam wheel's example data (``fgc simulate w100.graph``)."""
    p = Path(path)
    if not p.is_file() and p.suffix != ".py" and p.name == path:
        from fgc.interop.gtsam_data import gtsam_data_dir

        candidate = gtsam_data_dir() / path
        p = candidate if candidate.is_file() else p
    if not p.is_file():
        raise FgcError(f"{path}: no such file")
    if p.suffix != ".py":
        return _load_pose_graph_file(p, params)
    module = spec_module(p, shown=path)
    build = getattr(module, "build", None)
    if not callable(build):
        raise FgcError(f"{path}: a spec must define build(**params) returning an fgc.Graph")
    unknown = _unknown_parameters(build, params)
    if unknown:
        raise FgcError(f"{path}: build() has no parameter {', '.join(map(repr, unknown))} "
                       f"(it takes: {_parameter_list(build)})")
    try:
        graph = build(**params)
    except FgcError:
        raise
    except TypeError as exc:
        if exc.__traceback__.tb_next is None:  # raised binding the call, not inside build()
            raise FgcError(f"{path}: build() rejected the parameters {sorted(params)}: "
                           f"{exc}") from exc
        raise FgcError(f"{path}: build() failed{_where(p, exc)}: TypeError: {exc}") from exc
    except Exception as exc:  # the user's code: one line naming the spec, not a traceback
        raise FgcError(f"{path}: build() failed{_where(p, exc)}: {type(exc).__name__}: "
                       f"{exc}") from exc
    if not isinstance(graph, Graph):
        raise FgcError(f"{path}: build() returned {type(graph).__name__}, not an fgc.Graph")
    return graph


def _where(spec: Path, exc: BaseException) -> str:
    """`` at line N``: the innermost line of the spec file on ``exc``'s traceback."""
    import traceback

    lines = [f.lineno for f in traceback.extract_tb(exc.__traceback__)
             if Path(f.filename).resolve() == spec.resolve()]
    return f" at line {lines[-1]}" if lines else ""


def _unknown_parameters(build, params: dict) -> list[str]:
    """Names in ``params`` that ``build`` cannot take (none if it accepts **kwargs)."""
    try:
        sig = inspect.signature(build)
    except (TypeError, ValueError):
        return []
    kinds = {p.kind for p in sig.parameters.values()}
    if inspect.Parameter.VAR_KEYWORD in kinds:
        return []
    names = {n for n, p in sig.parameters.items()
             if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)}
    return sorted(k for k in params if k not in names)


def _parameter_list(build) -> str:
    """``build``'s parameters with their defaults, as -p would set them."""
    parts = [f"{n}={p.default!r}" if p.default is not p.empty else n
             for n, p in inspect.signature(build).parameters.items()
             if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)]
    return ", ".join(parts) or "no parameters"


def _load_pose_graph_file(p: Path, params: dict) -> Graph:
    from fgc.frontend import noise
    from fgc.frontend.factors import PriorFactor
    from fgc.interop.datasets import read_pose_graph

    unknown = sorted(set(params) - {"prior_sigma", "init"})
    if unknown:
        raise FgcError(f"{p}: unknown parameters {unknown} for a g2o/TORO file "
                       "(only prior_sigma, init=odometry|chordal)")
    # the file's own ids are the keys (GTSAM's readers' keys: an int stays an int, a landmark
    # is GTSAM's Symbol string "l<id>"), so results go back to GTSAM under the same keys
    graph = read_pose_graph(p, key_prefix=None, init=str(params.get("init", "odometry")))
    first = next(iter(graph.variables.values()))
    sigma = float(params.get("prior_sigma", 1e-3))
    graph.add(PriorFactor(first.key, first.initial, noise.isotropic(first.type.dim, sigma)))
    return graph
