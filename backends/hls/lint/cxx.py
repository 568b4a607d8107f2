"""The small C-like reading of emitted C++ that the lint's rules and the second reader
(:mod:`fgc_backends.hls.reader`) share: brackets, statements, function definitions and
their parameters, integer constants and their values."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from fgc_backends.cfamily.lint import line_of

_FOR = re.compile(r"\bfor\s*\(")


_BOUND = re.compile(r"^\s*\w+\s*(<|<=|>|>=)\s*([A-Z0-9_+\-*/() ]+)\s*$")


_CONSTANT = re.compile(r"^[A-Z0-9_+\-*/() ]+$")


_DEFINITION = re.compile(r"\b([A-Za-z_]\w*)\s*\(([^;{}]*)\)\s*(const\s*)?\{")
# a preprocessor line other than a pragma (#if defined(A) || defined(B), #endif, ...): not code,
# and its parentheses must not open a definition that swallows the function after it
_DIRECTIVE = re.compile(r"^[ \t]*#[ \t]*(?!pragma\b)[^\n]*", re.M)


def definitions(code: str):
    """The matches of ``_DEFINITION`` (a name, its parameters, the body's '{') in ``code`` read
    without its preprocessor directives (pragmas kept); positions are ``code``'s."""
    return _DEFINITION.finditer(_DIRECTIVE.sub(lambda m: " " * len(m.group(0)), code))


_CALL = re.compile(r"\b([A-Za-z_]\w*)\s*(<[^<>;]*>)?\s*\(")


_KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "do", "catch"}


_KEYWORDS_ALL = _KEYWORDS | {"else", "case", "default", "break", "continue", "new", "delete"}


_CONSTEXPR = re.compile(r"\b(?:static\s+)?(?:inline\s+)?(?:constexpr|const)\s+(?:unsigned\s+)?"
                        r"(?:int|long|short|std::size_t|size_t|unsigned)\s+([A-Za-z_]\w*)\s*="
                        r"\s*([^;{}]+);")


_DEFINE = re.compile(r"^[ \t]*#\s*define\s+([A-Za-z_]\w*)[ \t]+([^\n]+)$", re.M)


_FN_POINTER = re.compile(r"\(\s*\*\s*(\w*)\s*\)\s*\(")


_line = line_of


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


@dataclass(frozen=True)
class _Param:
    name: str
    type: str
    dims: tuple[str, ...]

    @property
    def stream(self) -> bool:
        return "stream" in self.type and "<" in self.type

    @property
    def const(self) -> bool:
        return re.search(r"\bconst\b", self.type) is not None

    @property
    def pointer(self) -> bool:
        return "*" in self.type

    @property
    def channel(self) -> bool:
        """Passes storage, not a value: an array, pointer, reference or stream."""
        return bool(self.dims) or self.pointer or "&" in self.type or self.stream


@dataclass(frozen=True)
class _Function:
    name: str
    ret: str
    params: tuple[_Param, ...]
    file: str
    code: str  # the file's code (comments/strings blanked)
    start: int  # of the definition
    body: tuple[int, int]  # indices of '{' and its '}'
    qualname: str = ""  # Struct::name for a member of a struct or class
    template_ints: tuple[str, ...] = ()  # int template parameters (of it and its struct)

    @property
    def inline(self) -> bool:
        return re.match(r"\s*#\s*pragma\s+HLS\s+INLINE\s*(?:\n|$)", self.text, re.I) is not None

    @property
    def text(self) -> str:
        return self.code[self.body[0] + 1:self.body[1]]


def _split_top(text: str, sep: str = ",") -> list[str]:
    """``text`` split at ``sep`` outside (), [], {}, <>."""
    parts, depth, cur = [], 0, []
    for ch in text:
        if ch in "([{<":
            depth += 1
        elif ch in ")]}>":
            depth -= 1
        if ch == sep and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    parts.append("".join(cur))
    return [p.strip() for p in parts if p.strip()]


def _params(text: str) -> tuple[_Param, ...]:
    out = []
    for part in _split_top(text):
        part = part.split("=")[0].strip()
        if part in ("void", "...") or _FN_POINTER.search(part):
            continue
        m = re.match(r"^(.*?)([A-Za-z_]\w*)\s*((?:\[[^\]]*\]\s*)*)$", part, re.S)
        if not m or not m.group(1).strip():
            continue
        dims = tuple(d.strip() for d in re.findall(r"\[([^\]]*)\]", m.group(3)))
        out.append(_Param(m.group(2), " ".join(m.group(1).split()), dims))
    return tuple(out)


def _functions(file: str, code: str) -> list[_Function]:
    """Top-level function definitions of one file (``code``: comments/strings blanked)."""
    out, pos = [], 0
    structs = []  # (name, '{', '}', int template parameters)
    for m in re.finditer(r"(template\s*<([^{};]*?)>\s*)?\b(?:struct|class)\s+([A-Za-z_]\w*)"
                         r"[^;{}()]*\{", code):
        brace = m.end() - 1
        ints = tuple(re.findall(r"\bint\s+([A-Za-z_]\w*)", m.group(2) or ""))
        structs.append((m.group(3), brace, _matching(code, brace, "{", "}"), ints))
    for m in definitions(code):
        if m.start() < pos or m.group(1) in _KEYWORDS_ALL:
            continue
        start = max(code.rfind(c, 0, m.start()) for c in ";{}")
        prefix = code[start + 1:m.start()]
        prefix = "\n".join(line for line in prefix.splitlines()
                           if not line.strip().startswith("#"))
        header = re.match(r"^\s*template\s*<([^{};]*?)>", prefix.strip())
        ints = tuple(re.findall(r"\bint\s+([A-Za-z_]\w*)", header.group(1))) if header else ()
        prefix = re.sub(r"^\s*template\s*<[^{};]*?>\s*(?=[A-Za-z_])", "", prefix.strip())
        ret = re.sub(r"\b(inline|static|constexpr|extern)\b", "", prefix).strip()
        if not ret or "=" in ret or "(" in ret or ret.endswith(("::", ".")):
            continue  # a constructor-like call or an expression, not a definition
        brace = m.end() - 1
        end = _matching(code, brace, "{", "}")
        owner = [st for st in structs if st[1] < m.start() < st[2]]
        qualname = f"{owner[-1][0]}::{m.group(1)}" if owner else m.group(1)
        ints += owner[-1][3] if owner else ()
        out.append(_Function(m.group(1), " ".join(ret.split()), _params(m.group(2)), file, code,
                             m.start(), (brace, end), qualname, ints))
        pos = end
    return out


def _constants(codes: Iterable[str]) -> dict[str, int]:
    """Integer constants (``constexpr``/``const`` ints, ``#define``) resolved to values."""
    raw: dict[str, str] = {}
    for code in codes:
        for m in _CONSTEXPR.finditer(code):
            # `const int A = 4, B = 9;`: every declarator (split outside brackets)
            first, *rest = _split_top(m.group(2))
            raw.setdefault(m.group(1), first)
            for part in rest:
                more = re.fullmatch(r"\s*([A-Za-z_]\w*)\s*=\s*(.+?)\s*", part, re.S)
                if more:
                    raw.setdefault(more.group(1), more.group(2))
        for m in _DEFINE.finditer(code):
            raw.setdefault(m.group(1), m.group(2))
    values: dict[str, int] = {}
    for _ in range(8):  # constants defined from constants
        for name, expr in raw.items():
            if name not in values:
                value = _evaluate(expr, values)
                if value is not None:
                    values[name] = value
    return values


def _evaluate(expr: str, values: dict[str, int]) -> int | None:
    """The integer value of ``expr`` (literals, known names, + - * / % ( )), or None."""
    text = re.sub(r"\b[A-Za-z_]\w*::", "", expr).strip()
    text = re.sub(r"\b(\d+)[uUlL]*\b", r"\1", text)

    def name(m):
        return str(values[m.group(0)]) if m.group(0) in values else "?"

    text = re.sub(r"\b[A-Za-z_]\w*\b", name, text)
    if not re.fullmatch(r"[0-9+\-*/%() ]+", text):
        return None
    try:
        return int(eval(text.replace("/", "//"), {"__builtins__": {}}, {}))  # noqa: S307
    except (SyntaxError, ZeroDivisionError, TypeError, ValueError):
        return None


def _is_constant(expr: str) -> bool:
    text = re.sub(r"\b\w+::", "", expr).strip()  # fgc::N_X, CFG::N_UNITS are constants
    return bool(text) and _CONSTANT.match(text) is not None


def _for_header(code: str, start: int) -> tuple[list[str], int, int] | None:
    """(init, condition, step), index after ')', of the ``for`` at ``start``."""
    open_ = code.index("(", start)
    close = _matching(code, open_, "(", ")")
    parts = code[open_ + 1:close].split(";")
    if len(parts) != 3:
        return None
    return [p.strip() for p in parts], open_, close + 1


def _constant_bounds(header: list[str]) -> bool:
    """Whether a ``for`` header starts and ends at compile-time constants."""
    init = re.match(r"^(?:const\s+)?(?:unsigned\s+)?(?:int|long|short|size_t|std::size_t|"
                    r"unsigned)?\s*\w+\s*=\s*(.+)$", header[0])
    bound = _BOUND.match(re.sub(r"\b\w+::", "", header[1]))
    return bool(init and _is_constant(init.group(1)) and bound and _is_constant(bound.group(2)))


def statement_end(code: str, pos: int, blocks: bool = False) -> int:
    """Index of the ';' ending the C++ statement that starts at ``pos``: the first ';' outside
    (), [] and {} (an initializer list or a lambda's body nests), or the '}' closing the block
    the statement is in; ``len(code)`` if there is neither. ``blocks``: a '{' or '}' outside
    () and [] ends the statement too (the second reader's scan, which reads a block's
    statements one by one and its blocks apart). The one C++ statement scanner of the lint and
    the second reader (backends/hls/reader/)."""
    depth = 0
    for i in range(pos, len(code)):
        ch = code[i]
        if ch in "{}" and blocks and depth <= 0:
            return i
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            if ch == "}" and depth == 0:
                return i
            depth -= 1
        elif ch == ";" and depth <= 0:
            return i
    return len(code)


def _enclosing_block(code: str, pos: int) -> tuple[int, int]:
    """The '{' … '}' block that contains ``pos``."""
    depth = 0
    for i in range(pos - 1, -1, -1):
        if code[i] == "}":
            depth += 1
        elif code[i] == "{":
            if depth == 0:
                return i, _matching(code, i, "{", "}")
            depth -= 1
    return 0, len(code)
