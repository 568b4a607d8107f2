"""The C-family layer's source rules for host code (what the native backend's files and the HLS
testbench must meet; the HLS backend's synthesis lint, :mod:`fgc_backends.hls.lint`, adds its
own on top): no dynamic allocation (``alloc``) and no STL containers or strings (``stl``),
checked on code with comments, string literals and csim-only cycle counters blanked out."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path


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


def strip_comments_and_strings(text: str) -> str:
    """``text`` with comments and string/char literals replaced by spaces (newlines kept)."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(\\.|[^"\\\n])*"|\'(\\.|[^\'\\\n])*\'', re.S)
    return pattern.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


_COUNTING = re.compile(r"#\s*ifdef\s+FGC_COUNT_CYCLES\b(.*?)#\s*else\b", re.S)


def synthesis_view(text: str) -> str:
    """``text`` as synthesis sees it: the csim-only cycle counters (the ``#ifdef
    FGC_COUNT_CYCLES`` branch of fgc_cycles.h, which only a counting testbench defines) blanked
    out, lines kept."""
    return _COUNTING.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def line_of(text: str, pos: int) -> int:
    return text.count("\n", 0, pos) + 1


def views(text: str) -> tuple[str, str]:
    """(code, plain): ``text`` as :func:`synthesis_view` with comments and strings blanked, and
    that with its pragmas blanked too (their words are not code)."""
    code = strip_comments_and_strings(synthesis_view(text))
    return code, re.sub(r"#\s*pragma[^\n]*", lambda m: " " * len(m.group(0)), code)


def host_issues(code: str, plain: str, file: str) -> list[LintIssue]:
    """The ``alloc`` and ``stl`` issues of one source's :func:`views`."""
    issues = [LintIssue(file, line_of(plain, m.start()), "alloc", f"dynamic allocation "
                        f"'{m.group(1)}'") for m in _ALLOC.finditer(plain)]
    issues += [LintIssue(file, line_of(code, m.start()), "stl", f"STL container "
                         f"'{m.group(0).strip()}'") for m in _STL.finditer(code)]
    return issues


def lint_host_files(paths: Iterable[Path]) -> list[LintIssue]:
    """The host rules' issues of every file in ``paths``, by line."""
    out = []
    for p in paths:
        code, plain = views(Path(p).read_text())
        out += sorted(host_issues(code, plain, Path(p).name), key=lambda i: (i.line, i.rule))
    return out
