"""The per-file synthesisability rules (``alloc``, ``stl``, ``recursion``, ``unbounded``,
``tripcount``) on one C++ source text."""

from __future__ import annotations

import functools
import re
from collections.abc import Iterable
from pathlib import Path

from fgc_backends.cfamily.lint import LintIssue, host_issues, views
from fgc_backends.hls.lint.cxx import (
    _BOUND,
    _CALL,
    _CONSTANT,
    _FOR,
    _KEYWORDS,
    _line,
    _matching,
    definitions,
)

_UNBOUNDED = re.compile(r"\b(while|do|goto)\b")


def lint_source(text: str, file: str = "<source>", synthesis: bool = True) -> list[LintIssue]:
    """All rule violations in one C++ source text."""
    return list(_lint_source(text, file, synthesis))


@functools.lru_cache(maxsize=64)
def _lint_source(text: str, file: str, synthesis: bool) -> tuple[LintIssue, ...]:
    """:func:`lint_source`, memoised on its arguments (a pure function of the text; every
    emitted project carries the same unit headers, linted again on every emit otherwise)."""
    # pragmas stay visible to the trip-count rule, but their words are not code
    code, plain = views(text)
    issues = host_issues(code, plain, file)
    if synthesis:
        issues += [LintIssue(file, _line(plain, m.start()), "unbounded",
                             f"'{m.group(1)}' has no bounded trip count")
                   for m in _UNBOUNDED.finditer(plain)]
        issues += _loops(code, file)
        issues += _recursion(plain, file)
    return tuple(sorted(issues, key=lambda i: (i.line, i.rule)))


def _loops(code: str, file: str) -> list[LintIssue]:
    issues = []
    for m in _FOR.finditer(code):
        close = _matching(code, m.end() - 1, "(", ")")
        parts = code[m.end():close].split(";")
        line = _line(code, m.start())
        if len(parts) != 3 or not parts[1].strip():
            issues.append(LintIssue(file, line, "unbounded", "for loop without a condition"))
            continue
        # fgc::N_X and a unit's CFG::MAX_ROWS are constants
        bound = _BOUND.match(re.sub(r"\b(?:[a-z_]\w*|CFG)::", "", parts[1]))
        if bound and _CONSTANT.match(bound.group(2)) and re.search(r"[A-Z0-9]", bound.group(2)):
            continue
        body = code[close + 1:close + 400].lstrip()
        if body.startswith("{") and re.match(r"\{\s*#\s*pragma\s+HLS\s+LOOP_TRIPCOUNT\b", body):
            continue
        issues.append(LintIssue(file, line, "tripcount", f"loop bound '{parts[1].strip()}' is "
                                "not constant and the body has no LOOP_TRIPCOUNT pragma"))
    return issues


def _recursion(code: str, file: str) -> list[LintIssue]:
    bodies: dict[str, tuple[int, str]] = {}
    for m in definitions(code):
        name = m.group(1)
        if name in _KEYWORDS:
            continue
        # a constexpr helper (fgc_cycles.h's ceil_log2) is evaluated by the compiler on the
        # constants it is given: no recursion is left for synthesis
        if re.search(r"\bconstexpr\b[^;{}]*$", code[max(0, m.start() - 120):m.start() + 1]):
            continue
        end = _matching(code, m.end() - 1, "{", "}")
        bodies.setdefault(name, (_line(code, m.start()), code[m.end():end]))
    # a call qualified through a template argument list (``unit<CFG, U + 1>::run(``) is a
    # compile-time recursion over a constant, closed by a specialisation: each instance is a
    # different function, which HLS instantiates (the unit headers' process networks)
    calls = {name: {c.group(1) for c in _CALL.finditer(body)
                    if not re.search(r">\s*::\s*$", body[:c.start()])} & bodies.keys()
             for name, (_, body) in bodies.items()}
    issues = []
    for name in sorted(bodies):
        if _reaches(calls, name):
            issues.append(LintIssue(file, bodies[name][0], "recursion",
                                    f"function '{name}' can call itself"))
    return issues


def _reaches(calls: dict[str, set[str]], start: str) -> bool:
    seen, stack = set(), list(calls[start])
    while stack:
        f = stack.pop()
        if f == start:
            return True
        if f not in seen:
            seen.add(f)
            stack.extend(calls.get(f, ()))
    return False


def lint_files(paths: Iterable[Path], synthesis: bool = True) -> list[LintIssue]:
    """Issues of every file in ``paths``."""
    return [i for p in paths for i in lint_source(Path(p).read_text(), Path(p).name, synthesis)]
