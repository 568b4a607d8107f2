"""The one place where user-chosen text is turned into something emitted files may contain.

Identifiers in the emitted C++ are indices (``jacobian_3``, ``in[12]``, ``t41``); only two kinds of
user text ever appear, and only through these helpers:

- :func:`identifier` — the project name, used in file names, the top function's name, the
  Makefile and the tcl script: letters, digits and single underscores, starting with a letter;
- :func:`comment` — factor/problem names shown in comments (C++ ``//``, tcl and Makefile ``#``):
  a whitelist of harmless characters, so no ``*/``, newline, backslash (line splicing), ``$``,
  brackets, quotes or non-printables survive.
"""

from __future__ import annotations

import keyword
import re

_CXX_KEYWORDS = frozenset((
    "alignas", "alignof", "and", "asm", "auto", "bitand", "bitor", "bool", "break", "case",
    "catch", "char", "class", "compl", "const", "constexpr", "continue", "decltype", "default",
    "delete", "do", "double", "else", "enum", "explicit", "export", "extern", "false", "float",
    "for", "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new",
    "noexcept", "not", "nullptr", "operator", "or", "private", "protected", "public", "register",
    "return", "short", "signed", "sizeof", "static", "struct", "switch", "template", "this",
    "throw", "true", "try", "typedef", "typename", "union", "unsigned", "using", "virtual",
    "void", "volatile", "while", "xor", "main",
))
_MAX_IDENTIFIER = 48
_MAX_COMMENT = 72


def identifier(text: str, fallback: str = "fgc_problem") -> str:
    """``text`` as a safe C/tcl/make identifier: ``[a-z][a-z0-9_]*`` without double underscores."""
    out = re.sub(r"[^a-z0-9]+", "_", str(text).lower()).strip("_")[:_MAX_IDENTIFIER].strip("_")
    if not out:
        return fallback
    if not out[0].isalpha():
        out = f"p_{out}"
    if out in _CXX_KEYWORDS or keyword.iskeyword(out):
        out = f"{out}_prj"
    return out


def comment(text: str) -> str:
    """``text`` reduced to characters that are inert in C++, tcl and Makefile comments."""
    out = re.sub(r"[^A-Za-z0-9 _+.,:=()<>-]", "_", str(text))
    return out[:_MAX_COMMENT]


_INT_KEY = re.compile(r"^-?[0-9]{1,18}$")
_MAX_TOKEN = 48


def key_token(key: str) -> str:
    """A variable key as a token the result files and the testbench's string table may hold:
    an integer key stays its digits; any other text keeps ``[A-Za-z0-9_.:+-]`` (the rest become
    ``_``, at most 48 characters) and starts with a letter or ``_`` (else ``k_`` is put in
    front), so it never reads back as an integer. Not unique by itself: :func:`key_tokens`."""
    text = str(key)
    if _INT_KEY.match(text):
        return text
    out = re.sub(r"[^A-Za-z0-9_.:+-]", "_", text)[:_MAX_TOKEN]
    if not out or not (out[0].isalpha() or out[0] == "_"):
        out = f"k_{out}"[:_MAX_TOKEN]
    return out


def key_tokens(keys) -> tuple[str, ...]:
    """:func:`key_token` of each of ``keys`` (in order), made unique: a token already taken gets
    ``~<position>`` appended (``~`` is in no single token, so these cannot collide)."""
    out, seen = [], set()
    for position, key in enumerate(keys):
        token = key_token(key)
        if token in seen:
            token = f"{token}~{position}"
        seen.add(token)
        out.append(token)
    return tuple(out)


def token_key(token: str, key: str):
    """The Python key of a variable whose Program key is ``key`` (Program keys are ``str``):
    an integer key comes back as ``int``, as the graph declared it."""
    return int(key) if _INT_KEY.match(key) and key_token(key) == token else key
