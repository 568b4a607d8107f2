"""The project's import graph, read from the source with ``ast`` (nothing is imported).

Prints: every import from one backend into a sibling backend (``fgc_backends.X`` →
``fgc_backends.Y``, the shared layers ``cfamily`` and ``cost`` counted as backends' siblings
too: neither may import a backend), the largest strongly connected component of the module
import graph (a set of modules that import each other in a circle, function-level imports
included), and the share of imports written inside functions rather than at module level.

    python bench/import_graph.py [--root DIR] [--json FILE] [--inner]
    python bench/import_graph.py --startup MODULE [MODULE …]

``--root``: another checkout of the project (default: this one), e.g. an earlier commit's tree
from ``git archive``. ``--inner``: also list the function-level imports per module (each should
have a measured reason: start-up time, an import circle). ``--startup``: what importing the
MODULEs adds to ``import fgc.app.cli`` (the command line's start-up), the best of 5 fresh
interpreters each (this one does import).
"""

from __future__ import annotations

import argparse
import ast
import json
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path

import networkx as nx

ROOT = Path(__file__).resolve().parent.parent
LAYERS = ("sim", "hls", "native", "cfamily", "cost")


def modules(root: Path = ROOT) -> dict[str, Path]:
    """Every module of the project by dotted name (a package by its ``__init__``): the source
    trees and the import package each installs as."""
    out = {}
    for package, tree in (("fgc", root / "fgc"), ("fgc_backends", root / "backends")):
        for path in sorted(tree.rglob("*.py")):
            rel = path.relative_to(tree).with_suffix("")
            parts = [package, *rel.parts]
            if parts[-1] == "__init__":
                parts = parts[:-1]
            if "templates" in parts:
                continue  # templates of emitted programs, not modules of fgc
            out[".".join(parts)] = path
    return out


def _resolve(name: str, known: dict[str, Path]) -> str | None:
    """The longest known module that ``name`` is or lies in."""
    while name:
        if name in known:
            return name
        name = name.rpartition(".")[0]
    return None


def imports(known: dict[str, Path]) -> list[tuple[str, str, bool, int]]:
    """(importer, imported module, inside a function, line) for every import of a project
    module."""
    out = []
    for mod, path in known.items():
        tree = ast.parse(path.read_text(), str(path))
        package = mod if path.name == "__init__.py" else mod.rpartition(".")[0]
        functions = {id(n) for f in ast.walk(tree)
                     if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef))
                     for n in ast.walk(f)}
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    parts = package.split(".")
                    parts = parts[:len(parts) - node.level + 1]
                    base = ".".join([*parts, base] if base else parts)
                targets = [f"{base}.{a.name}" for a in node.names]
            else:
                continue
            inner = id(node) in functions
            for target in targets:
                resolved = _resolve(target, known)
                if resolved is not None and resolved != mod:
                    out.append((mod, resolved, inner, node.lineno))
    return out


def layer(mod: str) -> str | None:
    parts = mod.split(".")
    if parts[0] == "fgc_backends" and len(parts) > 1 and parts[1] in LAYERS:
        return parts[1]
    return None


def startup_seconds(modules: list[str], runs: int = 5) -> float:
    """The best wall time of ``runs`` fresh interpreters importing ``modules``."""
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-c", f"import {', '.join(modules)}"], check=True)
        best = min(best, time.perf_counter() - start)
    return best


def startup(extra: list[str]) -> None:
    base = startup_seconds(["fgc.app.cli"])
    both = startup_seconds(["fgc.app.cli", *extra])
    print(f"import fgc.app.cli: {base:.2f} s; with {', '.join(extra)}: {both:.2f} s "
          f"(+{both - base:.2f} s; best of 5 each)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", type=Path, default=ROOT, help="the checkout to read")
    parser.add_argument("--json", help="also write the figures as JSON")
    parser.add_argument("--inner", action="store_true",
                        help="list the function-level imports per module")
    parser.add_argument("--startup", nargs="+", metavar="MODULE",
                        help="time what importing MODULE adds to the CLI's start-up")
    args = parser.parse_args()
    if args.startup:
        startup(args.startup)
        return
    known = modules(args.root)
    edges = imports(known)
    sibling = sorted({(a, b, line) for a, b, _, line in edges
                      if layer(a) and layer(b) and layer(a) != layer(b)
                      and not (layer(a) in ("sim", "hls", "native")
                               and layer(b) in ("cfamily", "cost"))})
    # hls may price with cost (the analytic model's operator table): a shared layer, allowed
    graph = nx.DiGraph()
    graph.add_nodes_from(known)
    graph.add_edges_from((a, b) for a, b, _, _ in edges)
    largest = max(nx.strongly_connected_components(graph), key=len)
    inner = sum(1 for e in edges if e[2])
    print(f"modules: {len(known)}, imports of project modules: {len(edges)}")
    print(f"backend -> sibling-backend imports: {len(sibling)}")
    for a, b, line in sibling:
        print(f"  {a}:{line} -> {b}")
    print(f"largest strongly connected component: {len(largest)} modules")
    for mod in sorted(largest) if len(largest) > 1 else ():
        print(f"  {mod}")
    print(f"function-level imports: {inner} of {len(edges)} ({100 * inner / len(edges):.1f} %)")
    for mod, count in Counter(a for a, _, fn, _ in edges if fn).most_common() if args.inner else ():
        print(f"  {count:>3} {mod}: " + ", ".join(sorted({b for a, b, fn, _ in edges
                                                          if fn and a == mod})))
    if args.json:
        Path(args.json).write_text(json.dumps({
            "modules": len(known), "imports": len(edges),
            "sibling_imports": [f"{a}:{line} -> {b}" for a, b, line in sibling],
            "largest_scc": sorted(largest), "function_level": inner}, indent=1) + "\n")


if __name__ == "__main__":
    main()
