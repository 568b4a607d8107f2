"""A synthesisability lint for emitted C++ (a conservative subset of what Vitis HLS accepts).

Rules, checked on code with comments and string literals blanked out:

- ``alloc``: no dynamic allocation (``new``, ``delete``, ``malloc``, ``calloc``, ``realloc``,
  ``free``);
- ``stl``: no STL containers or strings (``std::vector``, ``<map>``, …);
- ``recursion``: no function that can reach itself through calls within the file;
- ``unbounded``: no ``while``/``do``/``goto`` and no ``for`` without a condition;
- ``tripcount``: every ``for`` loop compares its variable with a compile-time bound (integer
  literals and ALL_CAPS constants) or opens its body with ``#pragma HLS LOOP_TRIPCOUNT``.

The testbench and the native backend's files run only on the host, so they are checked for
``alloc`` and ``stl`` only (``synthesis=False``).
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from fgc.errors import FgcError


class HlsLintError(FgcError):
    """Emitted C++ breaks a synthesisability rule (each issue names file, line and rule)."""


@dataclass(frozen=True)
class LintIssue:
    file: str
    line: int
    rule: str
    message: str

    def __str__(self) -> str:
        return f"{self.file}:{self.line}: [{self.rule}] {self.message}"


_ALLOC = re.compile(r"\b(new|delete|malloc|calloc|realloc|free|alloca)\b")
_STL = re.compile(r"\bstd::(vector|list|deque|map|multimap|set|multiset|unordered_\w+|string|"
                  r"queue|priority_queue|stack|function|shared_ptr|unique_ptr)\b|"
                  r"#\s*include\s*<(vector|list|deque|map|set|unordered_\w+|string|queue|stack|"
                  r"memory|functional)>")
_UNBOUNDED = re.compile(r"\b(while|do|goto)\b")
_FOR = re.compile(r"\bfor\s*\(")
_BOUND = re.compile(r"^\s*\w+\s*(<|<=|>|>=)\s*([A-Z0-9_+\-*/() ]+)\s*$")
_CONSTANT = re.compile(r"^[A-Z0-9_+\-*/() ]+$")
_DEFINITION = re.compile(r"\b([A-Za-z_]\w*)\s*\(([^;{}]*)\)\s*(const\s*)?\{")
_CALL = re.compile(r"\b([A-Za-z_]\w*)\s*(<[^<>;]*>)?\s*\(")
_KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "do", "catch"}


def strip_comments_and_strings(text: str) -> str:
    """``text`` with comments and string/char literals replaced by spaces (newlines kept)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(\\.|[^"\\\n])*"|\'(\\.|[^\'\\\n])*\'', re.S)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def lint_source(text: str, file: str = "<source>", synthesis: bool = True) -> list[LintIssue]:
    """All rule violations in one C++ source text."""
    code = strip_comments_and_strings(text)
    # pragmas stay visible to the trip-count rule, but their words are not code
    plain = re.sub(r"#\s*pragma[^\n]*", lambda m: " " * len(m.group(0)), code)
    issues = [LintIssue(file, _line(plain, m.start()), "alloc", f"dynamic allocation "
                        f"'{m.group(1)}'") for m in _ALLOC.finditer(plain)]
    issues += [LintIssue(file, _line(code, m.start()), "stl", f"STL container "
                         f"'{m.group(0).strip()}'") for m in _STL.finditer(code)]
    if synthesis:
        issues += [LintIssue(file, _line(plain, m.start()), "unbounded",
                             f"'{m.group(1)}' has no bounded trip count")
                   for m in _UNBOUNDED.finditer(plain)]
        issues += _loops(code, file)
        issues += _recursion(plain, file)
    return sorted(issues, key=lambda i: (i.line, i.rule))


def _line(text: str, pos: int) -> int:
    return text.count("\n", 0, pos) + 1


def _matching(text: str, start: int, open_: str, close: str) -> int:
    """Index of the bracket closing the one at ``start``."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == open_:
            depth += 1
        elif text[i] == close:
            depth -= 1
            if depth == 0:
                return i
    return len(text) - 1


def _loops(code: str, file: str) -> list[LintIssue]:
    issues = []
    for m in _FOR.finditer(code):
        close = _matching(code, m.end() - 1, "(", ")")
        parts = code[m.end():close].split(";")
        line = _line(code, m.start())
        if len(parts) != 3 or not parts[1].strip():
            issues.append(LintIssue(file, line, "unbounded", "for loop without a condition"))
            continue
        bound = _BOUND.match(re.sub(r"\b[a-z_]\w*::", "", parts[1]))  # fgc::N_X is constant
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
    for m in _DEFINITION.finditer(code):
        name = m.group(1)
        if name in _KEYWORDS:
            continue
        end = _matching(code, m.end() - 1, "{", "}")
        bodies.setdefault(name, (_line(code, m.start()), code[m.end():end]))
    calls = {name: {c.group(1) for c in _CALL.finditer(body)} & bodies.keys()
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


def lint_project(project, synthesised: Iterable[Path]) -> None:
    """Lint an emitted project: full rules on ``synthesised`` files, allocation/STL rules on the
    rest; raise :class:`HlsLintError` listing every issue."""
    synthesised = [Path(p) for p in synthesised]
    host = [p for p in project.files if p.suffix in (".cpp", ".h") and p not in synthesised]
    issues = lint_files(synthesised) + lint_files(host, synthesis=False)
    if issues:
        listing = "\n".join(str(i) for i in issues[:20])
        raise HlsLintError(f"emitted project '{project.name}' is not synthesisable:\n{listing}")
