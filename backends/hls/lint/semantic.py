"""The semantic rules (``dataflow``, ``channel``, ``pointer``, ``function_pointer``,
``partition``, ``pipeline``, ``dsp``, ``synthesis_macro``: the package's docstring) on the
synthesised files of a project read together."""

from __future__ import annotations

import re
from collections.abc import Iterable

from fgc_backends.cfamily.lint import LintIssue, strip_comments_and_strings
from fgc_backends.hls.lint.cxx import (
    _BOUND,
    _FN_POINTER,
    _FOR,
    _KEYWORDS_ALL,
    _constant_bounds,
    _constants,
    _enclosing_block,
    _evaluate,
    _for_header,
    _Function,
    _functions,
    _line,
    _matching,
    _Param,
    _split_top,
    statement_end,
)

SEMANTIC_RULES = ("dataflow", "channel", "pointer", "function_pointer", "partition", "pipeline",
                  "dsp", "synthesis_macro")


# Vitis HLS operation names of ALLOCATION → (operator kind, precision or None: the scalar's)
ALLOCATION_OPS = {
    "fadd": ("add", "float32"), "fsub": ("add", "float32"), "dadd": ("add", "float64"),
    "dsub": ("add", "float64"), "fmul": ("mul", "float32"), "dmul": ("mul", "float64"),
    "fdiv": ("div", "float32"), "ddiv": ("div", "float64"), "fsqrt": ("sqrt", "float32"),
    "dsqrt": ("sqrt", "float64"), "frsqrt": ("recip_sqrt", "float32"),
    "drsqrt": ("recip_sqrt", "float64"), "fexp": ("exp", "float32"), "dexp": ("exp", "float64"),
    "flog": ("log", "float32"), "dlog": ("log", "float64"), "add": ("add", None),
    "sub": ("add", None), "mul": ("mul", None), "div": ("div", None),
}


_PRAGMA = re.compile(r"#\s*pragma\s+HLS\s+([^\n]*)", re.I)


_POINTER_DECL = re.compile(r"(?:^|(?<=[;{}])|(?<=for\()|(?<=for \())\s*(?:const\s+)?"
                           r"[A-Za-z_][\w:]*(?:<[^;<>]*>)?\s*(?:const\s*)?\*\s*(?:const\s+)?"
                           r"([A-Za-z_]\w*)\s*(?=[=;,)\[])", re.M)


class _Checker:
    def __init__(self, files: list[tuple[str, str]], part: str | None, scalar: str | None,
                 bind=()):
        self.files = [(name, strip_comments_and_strings(text)) for name, text in files]
        self.functions: dict[str, _Function] = {}
        self.macros: set[str] = set()
        for name, code in self.files:
            for f in _functions(name, code):
                self.functions.setdefault(f.name, f)
                self.functions.setdefault(f.qualname, f)
            self.macros |= set(re.findall(r"^[ \t]*#\s*define\s+([A-Za-z_]\w*)\(", code, re.M))
        self.inlining: set[str] = set()
        self.constants = _constants(code for _, code in self.files)
        self.part, self.scalar = part, scalar
        self.bind = tuple(bind or ())
        self.issues: list[LintIssue] = []
        # global_uses' memos, keyed on the identity of this checker's own _Function objects
        self._global_memo: dict[int, tuple[dict[str, set[str]], frozenset]] = {}
        self._callee_memo: dict[int, list[_Function]] = {}
        self._direct_memo: dict[int, dict[str, set[str]]] = {}
        self._uses_memo: dict[tuple, tuple[frozenset, frozenset]] = {}
        self._passed_memo: dict[int, list] = {}

    def add(self, file: str, code: str, pos: int, rule: str, message: str) -> None:
        self.issues.append(LintIssue(file, _line(code, pos), rule, message))

    def run(self) -> list[LintIssue]:
        for name, code in self.files:
            for m in re.finditer(r"\b__SYNTHESIS__\b", code):
                self.add(name, code, m.start(), "synthesis_macro", "'__SYNTHESIS__' in a "
                         "synthesised file: C simulation would not compile the synthesised code")
            self.pointers(name, code)
            for m in _PRAGMA.finditer(code):
                words = m.group(1).split()
                kind = words[0].upper() if words else ""
                if kind == "DATAFLOW":
                    self.dataflow(name, code, m.start(), m.end())
                elif kind == "PIPELINE" and "off" not in (w.lower() for w in words[1:]):
                    self.pipeline(name, code, m.start())
                elif kind == "ARRAY_PARTITION":
                    self.partition(name, code, m.start(), m.group(1))
        self.dsp()
        return sorted(self.issues, key=lambda i: (i.file, i.line, i.rule, i.message))

    # -- pointers and function pointers -------------------------------------------------------
    def pointers(self, file: str, code: str) -> None:
        for f in self.functions.values():
            if f.file != file:
                continue
            if f.ret.endswith("*") or re.search(r"\*\s*$", code[f.start - 2:f.start]):
                self.add(file, code, f.start, "pointer", f"function '{f.name}' returns a "
                         f"pointer ('{f.ret}')")
            names = {p.name for p in f.params if p.pointer}
            names |= {m.group(1) for m in _POINTER_DECL.finditer(code[f.body[0]:f.body[1]])}
            for pname in names:
                pattern = (rf"(?<![\w.>])\b{pname}\s*(?:(?<![=!<>])=(?!=)|\+=|-=|\+\+|--)|"
                           rf"(?:\+\+|--)\s*\b{pname}\b")
                for m in re.finditer(pattern, code[f.body[0]:f.body[1]]):
                    at = f.body[0] + m.start()
                    if not self._is_declaration(code, at):
                        self.add(file, code, at, "pointer", f"pointer '{pname}' in '{f.name}' is "
                                 "reassigned (HLS needs each pointer bound to one object)")
        for m in _FN_POINTER.finditer(code):
            self.add(file, code, m.start(), "function_pointer", "function pointer "
                     f"'{m.group(1) or '(*)'}' (HLS cannot synthesise indirect calls)")
        for m in re.finditer(r"\b([A-Za-z_]\w*)\s*<([^<>;{}]*)>\s*\(", code):
            for arg in _split_top(m.group(2)):
                name = arg.lstrip("&").strip()
                if name in self.functions and m.group(1) not in ("static_cast", "reinterpret_cast"):
                    self.add(file, code, m.start(), "function_pointer", f"function '{name}' "
                             f"passed as a template argument of '{m.group(1)}' (a function "
                             "pointer)")

    @staticmethod
    def _is_declaration(code: str, at: int) -> bool:
        """Whether the name at ``at`` is being declared (``T* name =``) or written through
        (``*name =``), not reassigned."""
        before = code[max(0, at - 120):at]
        return re.search(r"\*\s*(?:const\s+)?$", before) is not None

    # -- dataflow ------------------------------------------------------------------------------
    def dataflow(self, file: str, code: str, pragma: int, after: int) -> None:
        lo, hi = _enclosing_block(code, pragma)
        calls: list[tuple[int, str, list[str], dict[str, int], str]] = []
        self._region(file, code, lo + 1, hi, calls, {}, pragma)
        # per channel: (call index in region order, process label, its uses) of every access
        access: dict[str, list[tuple[int, str, frozenset[str]]]] = {}
        for order, (pos, callee, args, loop, where) in enumerate(calls):
            f = self.functions.get(callee)
            if f is None:
                continue
            for index, (arg, param) in enumerate(zip(args, f.params, strict=False)):
                if not param.channel:
                    continue
                base = re.match(r"^&?\s*([A-Za-z_]\w*)", arg)
                if not base:
                    continue
                key = base.group(1)
                subscript = arg[base.end():].strip()
                # an unrolled loop makes one process per iteration: an argument indexed by the
                # loop's variable is another channel each time, any other the same channel
                copies = 1
                index_value = _evaluate(subscript[1:-1], self.constants) if \
                    re.fullmatch(r"\[[^\[\]]*\]", subscript) else None
                if index_value is not None:  # a constant element: its own channel
                    key = f"{key}[{index_value}]"
                for v, trips in loop.items():
                    if subscript and re.search(rf"\b{v}\b", subscript):
                        key = f"{base.group(1)}{subscript}"  # one element per copy
                    else:
                        copies *= trips
                uses = frozenset(self.uses(f, param, set()))
                label = f"{callee} (line {_line(where, pos)}, argument {index + 1})"
                labels = [label] if copies == 1 else [f"{label} x{copies}#{c}"
                                                      for c in range(copies)]
                access.setdefault(key, []).extend((order, lb, uses) for lb in labels)
            # file-scope arrays a process reaches are channels too (issue 18's shared COND/NF)
            for g, uses in sorted(self.global_uses(f, set()).items()):
                label = f"{callee} (line {_line(where, pos)}, global)"
                copies = 1
                for trips in loop.values():
                    copies *= trips
                labels = [label] if copies == 1 else [f"{label} x{copies}#{c}"
                                                      for c in range(copies)]
                access.setdefault(g, []).extend((order, lb, frozenset(uses)) for lb in labels)
        # a whole array passed to one process overlaps each element another one takes
        bases = {k.split("[")[0] for k in access if "[" in k}
        for key in [k for k in access if "[" in k]:
            access[key] = access[key] + access.get(key.split("[")[0], [])
        for base in bases:
            access.pop(base, None)  # reported through its elements
        for key, entries in sorted(access.items()):
            self._channel(file, code, pragma, key, entries)

    def _channel(self, file, code, pragma, key, entries) -> None:
        """UG1399's canonical form for one channel of a DATAFLOW region: at most one writer and
        one reader; a channel both written and read in the region is written by one process and
        read by another, later one (no feedback through it, no process reading and writing it).
        A memory that one process alone reads and writes is that process's own, no channel."""
        def name(label):
            return label.split("#")[0]

        writers = [(o, lb) for o, lb, u in entries if "write" in u]
        readers = [(o, lb) for o, lb, u in entries if "read" in u]
        for what, who in (("written", writers), ("read", readers)):
            if len(who) > 1:
                names = [name(lb) for _, lb in who]
                self.add(file, code, pragma, "channel", f"'{key}' is {what} by "
                         f"{len(who)} processes of the DATAFLOW region: "
                         f"{', '.join(sorted(set(names), key=names.index))} "
                         "(one producer and one consumer per channel)")
        processes = {lb for _, lb, _ in entries}
        if not writers or not readers or len(processes) == 1:
            return
        for _, lb, u in entries:
            if {"read", "write"} <= u:
                self.add(file, code, pragma, "channel", f"'{key}' is read and written by the "
                         f"same process {name(lb)} while another process of the DATAFLOW "
                         "region also uses it (a channel has one writer and a different reader)")
                return
        first_write = min(o for o, _ in writers)
        early = [(o, lb) for o, lb in readers if o <= first_write]
        if early:
            writer = next(lb for o, lb in writers if o == first_write)
            self.add(file, code, pragma, "channel", f"'{key}' is read by {name(early[0][1])} "
                     f"before {name(writer)} writes it in the DATAFLOW region: a feedback "
                     "through the channel (the writer must come first; pass data between "
                     "invocations through two buffers that alternate)")

    def _region(self, file, code, lo, hi, calls, loop, pragma) -> None:
        pos = lo
        while pos < hi:
            m = re.compile(r"\S").search(code, pos, hi)
            if not m:
                return
            pos = m.start()
            if code.startswith("#", pos):
                end = code.find("\n", pos)
                pos = hi if end < 0 else end + 1
                continue
            word = re.match(r"[A-Za-z_]\w*", code[pos:hi])
            w = word.group(0) if word else ""
            if w == "for":
                header = _for_header(code, pos)
                if header is None:
                    self.add(file, code, pos, "dataflow", "a for loop in a DATAFLOW region")
                    return
                parts, _, after = header
                body_at = re.compile(r"\S").search(code, after, hi)
                body_lo = body_at.start() if body_at else hi
                if code.startswith("{", body_lo):
                    body_hi = _matching(code, body_lo, "{", "}")
                    inner = (body_lo + 1, body_hi)
                else:
                    body_hi = statement_end(code, body_lo)
                    inner = (body_lo, body_hi + 1)
                unrolled = re.match(r"\s*#\s*pragma\s+HLS\s+UNROLL\s*(?:\n|$)",
                                    code[inner[0]:inner[1]], re.I)
                if not (unrolled and _constant_bounds(parts)):
                    self.add(file, code, pos, "dataflow", "a loop around processes of a "
                             f"DATAFLOW region ('for ({'; '.join(parts)})') that is not a fully "
                             "unrolled constant-bound loop")
                var = re.search(r"(\w+)\s*=\s*(.+)$", parts[0])
                bound = _BOUND.match(re.sub(r"\b[a-z_]\w*::", "", parts[1]))
                first = _evaluate(var.group(2), self.constants) if var else None
                last = _evaluate(bound.group(2), self.constants) if bound else None
                trips = 1
                if first is not None and last is not None and bound.group(1) in ("<", "<="):
                    trips = max(1, last - first + (bound.group(1) == "<="))
                self._region(file, code, inner[0], inner[1], calls,
                             {**loop, (var.group(1) if var else "?"): trips}, pragma)
                pos = body_hi + 1
                continue
            if w in ("if", "else", "while", "do", "switch", "return", "goto", "break",
                     "continue"):
                self.add(file, code, pos, "dataflow", f"'{w}' in a DATAFLOW region: only "
                         "channel declarations and unconditional calls of void functions")
                if w in ("if", "while", "switch"):  # the guarded statements are checked too
                    open_ = code.index("(", pos)
                    pos = _matching(code, open_, "(", ")") + 1
                elif w in ("else", "do"):
                    pos += len(w)
                else:
                    pos = statement_end(code, pos) + 1
                continue
            if code.startswith("{", pos):
                end = _matching(code, pos, "{", "}")
                self._region(file, code, pos + 1, end, calls, loop, pragma)
                pos = end + 1
                continue
            end = min(statement_end(code, pos), hi)
            self._statement(file, code, pos, code[pos:end].strip(), calls, loop)
            pos = end + 1

    def _statement(self, file, code, pos, text, calls, loop) -> None:
        if not text:
            return
        call = re.fullmatch(r"((?:::)?(?:[A-Za-z_]\w*\s*(?:<[^;()]*?>)?\s*::\s*)*[A-Za-z_]\w*)"
                            r"\s*(?:<[^;()]*?>)?\s*\((.*)\)", text, re.S)
        if call and call.group(1) not in _KEYWORDS_ALL:
            parts = re.sub(r"<[^;()]*?>|\s", "", call.group(1)).strip(":").split("::")
            name = "::".join(parts[-2:])
            f = self.functions.get(name) or self.functions.get(parts[-1])
            if parts[-1] in self.macros and f is None:
                return  # a function-like macro (instrumentation): not judged
            if f is not None and f.inline and f.ret == "void":
                # an inlined helper (a template recursion over units): its calls are processes
                # of this region, its int template parameters index one copy each
                if f.qualname not in self.inlining:
                    self.inlining.add(f.qualname)
                    self._region(f.file, f.code, f.body[0] + 1, f.body[1], calls,
                                 {**loop, **{t: 1 for t in f.template_ints}}, None)
                    self.inlining.discard(f.qualname)
                return
            if f is None:
                self.add(file, code, pos, "dataflow", f"call of '{name}' in a DATAFLOW region: "
                         "its definition is not in the project, so it cannot be checked void")
            elif f.ret != "void":
                self.add(file, code, pos, "dataflow", f"process '{name}' returns '{f.ret}': "
                         "DATAFLOW processes must be void functions")
            calls.append((pos, f.qualname if f else name, _split_top(call.group(2)), loop,
                          code))
            return
        declaration = re.fullmatch(r"(?:static\s+)?[A-Za-z_][\w:]*(?:\s*<[^;=]*>)?\s+"
                                   r"[A-Za-z_]\w*\s*(?:\[[^\]=;]*\]\s*)*(?:\(\s*\))?", text, re.S)
        constant = re.fullmatch(r"(?:static\s+)?(?:const|constexpr)\s+(?:unsigned\s+)?"
                                r"(?:int|long|short|unsigned|bool)\s+[A-Za-z_]\w*\s*=\s*(.+)",
                                text, re.S)
        enum = re.fullmatch(r"enum\s*\w*\s*\{[^{}]*\}", text)
        constant = constant and _evaluate(constant.group(1), self.constants) is not None
        if declaration or enum or constant:
            return  # a channel, or an integer constant (no computation, no process)
        inner = [m for m in re.finditer(r"\b([A-Za-z_]\w*)\s*(?:<[^;()]*?>)?\s*\(", text)
                 if m.group(1) not in _KEYWORDS_ALL]
        if inner:
            self.add(file, code, pos, "dataflow", f"'{' '.join(text.split())[:60]}' in a "
                     "DATAFLOW region uses a process's return value or computes: only "
                     "channel declarations and unconditional calls of void functions")
            for m in inner:
                f = self.functions.get(m.group(1))
                if f is not None and f.ret != "void":
                    self.add(file, code, pos, "dataflow", f"process '{f.name}' returns "
                             f"'{f.ret}': DATAFLOW processes must be void functions")
                if f is not None:
                    open_ = text.index("(", m.start())
                    close = _matching(text, open_, "(", ")")
                    calls.append((pos, f.name, _split_top(text[open_ + 1:close]), loop, code))
        else:
            self.add(file, code, pos, "dataflow", f"'{' '.join(text.split())[:60]}' in a "
                     "DATAFLOW region: only channel declarations (no initialiser) and "
                     "unconditional calls of void functions")

    def globals_(self) -> dict[str, bool]:
        """File-scope arrays of the project: name → whether declared ``const``."""
        if not hasattr(self, "_globals"):
            found: dict[str, bool] = {}
            for _, code in self.files:
                # function bodies cut to "{}" in one pass: blanking them to spaces left long
                # runs of whitespace the declaration pattern's \s* rescanned from every line
                # start (quadratic: 9 s of a LIO design's lint)
                parts, at = [], 0
                for lo, hi in sorted(f.body for f in self.functions.values() if f.code is code):
                    if lo < at:  # a body inside one already cut
                        continue
                    parts += [code[at:lo], "{}"]
                    at = hi + 1
                blanked = re.sub(r"[ \t]*\n\s*", "\n", "".join(parts) + code[at:])
                for m in re.finditer(r"(?:^|[;}])\s*((?:static\s+|const\s+|constexpr\s+)*)"
                                     r"[A-Za-z_][\w:]*(?:<[^;<>]*>)?\s+([A-Za-z_]\w*)\s*\[",
                                     blanked, re.M):
                    found.setdefault(m.group(2), bool(re.search(r"const", m.group(1))))
            self._globals = found
        return self._globals

    def global_uses(self, f: _Function, seen: set) -> dict[str, set[str]]:
        """The non-const file-scope arrays ``f`` (and what it calls) reads and writes."""
        out, _, _ = self._global_uses(f, frozenset(seen))
        return {g: set(uses) for g, uses in out.items()}

    def _global_uses(self, f: _Function, seen: frozenset):
        """:meth:`global_uses` with the functions it reached and whether a call was cut by
        ``seen`` (a cycle). A result no cut shaped is memoised on ``f``: it holds for any
        ``seen`` disjoint from the functions it reached (the walk is then the same one), so a
        DATAFLOW region's processes do not re-walk the shared unit headers per call (7,094
        walks of a LIO stream design, 19 s of its lint)."""
        if f.name in seen:
            return {}, frozenset(), True
        memo = self._global_memo.get(id(f))
        if memo is not None and memo[1].isdisjoint(seen):
            return memo[0], memo[1], False
        seen = seen | {f.name}
        out = {g: set(uses) for g, uses in self._direct_global_uses(f).items()}
        reach, cut = {f.name}, False
        for callee in self._callees(f):
            if callee.name != f.name:
                inner, inner_reach, inner_cut = self._global_uses(callee, seen)
                reach |= inner_reach
                cut = cut or inner_cut
                for g, uses in inner.items():
                    out.setdefault(g, set()).update(uses)
        reach = frozenset(reach)
        if not cut:
            self._global_memo[id(f)] = (out, reach)
        return out, reach, cut

    def _callees(self, f: _Function) -> list[_Function]:
        """The project's functions ``f``'s text calls, each once, in order of first call."""
        if id(f) not in self._callee_memo:
            found: dict[int, _Function] = {}
            for m in re.finditer(r"\b([A-Za-z_]\w*)\s*(?:<[^;()]*?>)?\s*\(", f.text):
                callee = self.functions.get(m.group(1))
                if callee is not None:
                    found.setdefault(id(callee), callee)
            self._callee_memo[id(f)] = list(found.values())
        return self._callee_memo[id(f)]

    def _direct_global_uses(self, f: _Function) -> dict[str, set[str]]:
        """The non-const file-scope arrays ``f``'s own text reads and writes (memoised)."""
        if id(f) in self._direct_memo:
            return self._direct_memo[id(f)]
        local = {p.name for p in f.params}
        local |= set(re.findall(r"[\w>]\s+([A-Za-z_]\w*)\s*\[", f.text))
        # a name occurs as a whole word (\bg\b) exactly when it is one of the text's \w runs
        words = set(re.findall(r"\w+", f.text))
        out: dict[str, set[str]] = {}
        for g, const in self.globals_().items():
            if const or g in local or g not in words:
                continue
            assign = (rf"(?<![\w.>])\b{g}\s*(?:\[[^\]]*\]\s*)*(?:\.\s*\w+\s*)*"
                      r"(=(?!=)|[-+*/|&^]=|\+\+|--)")
            uses = set()
            for m in re.finditer(assign, f.text):
                uses |= {"write"} if m.group(1) == "=" else {"write", "read"}
            if re.search(rf"\b{g}\b", re.sub(assign, " ", f.text)):
                uses.add("read")  # read, or passed on (conservatively: both)
                if re.search(rf"[(,]\s*{g}\s*[,)]", f.text):
                    uses.add("write")
            out[g] = uses
        self._direct_memo[id(f)] = out
        return out

    def uses(self, f: _Function, param: _Param, seen: set) -> set[str]:
        """How ``f`` uses its parameter ``param``: a subset of {"read", "write"}; an argument
        passed on to another function of the project counts as that function's use."""
        return set(self._uses(f, param, frozenset(seen))[0])

    def _uses(self, f: _Function, param: _Param, seen: frozenset):
        """:meth:`uses` with the (function, parameter) pairs it reached and whether ``seen``
        cut a call (a cycle); memoised as :meth:`_global_uses` is (a result no cut shaped holds
        for any ``seen`` disjoint from what it reached)."""
        if (f.name, param.name) in seen:
            return frozenset(), frozenset(), True
        key = (id(f), param)
        memo = self._uses_memo.get(key)
        if memo is not None and memo[1].isdisjoint(seen):
            return memo[0], memo[1], False
        seen = seen | {(f.name, param.name)}
        reach, cut = {(f.name, param.name)}, False
        body, name, out = f.text, re.escape(param.name), set()
        # passed on: the callee's use, and the occurrence is blanked for the direct analysis
        for callee, inner, arg, at in self._passed(f):
            if inner.channel and re.fullmatch(rf"&?\s*{name}", arg) and at >= 0:
                inner_out, inner_reach, inner_cut = self._uses(callee, inner, seen)
                out |= inner_out
                reach |= inner_reach
                cut = cut or inner_cut
                body = body[:at] + " " * len(arg) + body[at + len(arg):]
        calls = rf"\b{name}\s*(?:\[[^\]]*\]\s*)*\.\s*(write|read)(?:_nb)?\s*\("
        # a stream, or a template parameter by reference (``XIN&& x``, ``PASS& q``) the
        # function reads and writes as one: its uses are the stream's (fgc_backsub.h's
        # backsub_end, fgc_qr.h's qr_collect)
        if param.stream or (param.type.endswith("&") and re.search(calls, body)):
            out |= {m.group(1) for m in re.finditer(calls, body)}
        elif param.const:
            if re.search(rf"\b{name}\b", body):
                out.add("read")
        else:
            assign = (rf"(?<![\w.>])\b{name}\s*(?:\[[^\]]*\]\s*)*(?:\.\s*\w+\s*)*"
                      r"(=(?!=)|[-+*/|&^]=|\+\+|--)")
            for m in re.finditer(assign, body):
                out.add("write")
                if m.group(1) != "=":
                    out.add("read")
            if re.search(rf"\b{name}\b", re.sub(assign, " ", body)):
                out.add("read")
        out, reach = frozenset(out), frozenset(reach)
        if not cut:
            self._uses_memo[key] = (out, reach)
        return out, reach, cut

    def _passed(self, f: _Function) -> list[tuple[_Function, _Param, str, int]]:
        """Every argument ``f`` passes to a function of the project, in order: (callee, its
        parameter, the argument's text, where it starts in ``f.text`` or -1), parsed once."""
        if id(f) not in self._passed_memo:
            text, found = f.text, []
            for m in re.finditer(r"\b([A-Za-z_]\w*)\s*(?:<[^;()]*?>)?\s*\(", text):
                callee = self.functions.get(m.group(1))
                if callee is None:
                    continue
                open_ = text.index("(", m.start())
                close = _matching(text, open_, "(", ")")
                offset = open_ + 1
                for arg, inner in zip(_split_top(text[open_ + 1:close]), callee.params,
                                      strict=False):
                    at = text.find(arg, offset)
                    offset = at + len(arg) if at >= 0 else offset
                    found.append((callee, inner, arg, at))
            self._passed_memo[id(f)] = found
        return self._passed_memo[id(f)]

    # -- pipeline -------------------------------------------------------------------------------
    def pipeline(self, file: str, code: str, pragma: int) -> None:
        lo, hi = _enclosing_block(code, pragma)
        for m in _FOR.finditer(code, lo + 1, hi):
            header = _for_header(code, m.start())
            if header is None:
                continue
            parts = header[0]
            if not _constant_bounds(parts):
                self.add(file, code, m.start(), "pipeline", f"loop 'for ({'; '.join(parts)})' "
                         f"inside the PIPELINE at line {_line(code, pragma)} has a variable "
                         "bound: a pipelined loop may hold only constant-bound loops (HLS "
                         "unrolls them completely)")

    # -- partition ------------------------------------------------------------------------------
    def partition(self, file: str, code: str, pragma: int, text: str) -> None:
        options = dict(re.findall(r"(\w+)\s*=\s*([\w:]+)", text))
        var, factor = options.get("variable"), options.get("factor")
        if not var or factor is None:
            return
        factor_value = _evaluate(factor, self.constants)
        dims = self._dimensions(code, pragma, var)
        if dims is None or factor_value is None:
            return
        dim = int(options.get("dim", "1"))
        checked = range(len(dims)) if dim == 0 else [dim - 1]
        for d in checked:
            if d >= len(dims):
                self.add(file, code, pragma, "partition", f"ARRAY_PARTITION of '{var}' dim="
                         f"{dim}: the array has {len(dims)} dimension(s)")
                continue
            size = _evaluate(dims[d], self.constants)
            if size is not None and factor_value > size:
                self.add(file, code, pragma, "partition", f"ARRAY_PARTITION of '{var}': factor "
                         f"{factor_value} exceeds dimension {d + 1} of size {size} "
                         f"('{dims[d]}')")

    def _dimensions(self, code: str, pragma: int, var: str) -> list[str] | None:
        """The declared dimensions of ``var`` seen from ``pragma``: the enclosing function's
        parameters and locals first, then file scope."""
        decl = re.compile(rf"[\w>*&]\s+{re.escape(var)}\s*((?:\[[^\]]*\]\s*)+)")
        for f in self.functions.values():
            if f.code is code and f.body[0] <= pragma <= f.body[1]:
                for p in f.params:
                    if p.name == var:
                        return list(p.dims) or None
                m = decl.search(code, f.body[0], f.body[1])
                if m:
                    return re.findall(r"\[([^\]]*)\]", m.group(1))
        for _, other in self.files:
            m = decl.search(other)
            if m:
                return re.findall(r"\[([^\]]*)\]", m.group(1))
        return None

    # -- DSP budget -----------------------------------------------------------------------------
    def dsp(self) -> None:
        if not self.part:
            return
        from fgc_backends.hls.target import Target, device_of

        device = device_of(self.part)
        if device is None:
            return

        default = "float64" if self.scalar == "double" else "float32"
        total, parts, first = 0, [], None
        for name, code in self.files:
            for m in _PRAGMA.finditer(code):
                text = m.group(1)
                if not re.match(r"ALLOCATION\b", text, re.I) or not re.search(
                        r"\boperation\b", text):
                    continue
                options = dict(re.findall(r"(\w+)\s*=\s*(\w+)", text))
                op, limit = options.get("instances"), _evaluate(options.get("limit", ""),
                                                                 self.constants)
                if op not in ALLOCATION_OPS or limit is None:
                    continue
                kind, precision = ALLOCATION_OPS[op]
                dsp = Target(self.part, bind=self.bind).ops(precision or default).op(kind).dsp
                total += limit * dsp
                parts.append(f"{op} {limit}x{dsp}")
                first = first or (name, code, m.start())
        if first and total > device.dsp:
            self.add(*first, "dsp", f"the ALLOCATION limits imply {total} DSP "
                     f"({', '.join(parts)}), more than the {device.dsp} of part "
                     f"{self.part}")


def semantic_issues(files: Iterable[tuple[str, str]], part: str | None = None,
                    scalar: str | None = None, bind=()) -> list[LintIssue]:
    """Semantic-rule issues of synthesised C++ ``files`` ((name, text) pairs, read together so
    that calls across a header and its source resolve). ``part``/``scalar`` set the DSP budget
    and the precision of ALLOCATION operation names without one; ``bind`` the operators'
    binding (``DesignOptions.bind``: a fabric adder has no DSP in the budget)."""
    return _Checker(list(files), part, scalar, bind).run()
