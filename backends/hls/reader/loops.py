"""The pipelined loops and the memory / II rules: per ``PIPELINE`` loop its operator instances
at its II, its accesses per iteration against each array's ports and banks, its carried
recurrences against its ``DEPENDENCE`` pragmas (:class:`LoopReading`, :func:`check`)."""

from __future__ import annotations

import math
import re
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, replace

from fgc_backends.cfamily.lint import LintIssue
from fgc_backends.hls.lint.cxx import (
    _Function,
    _line,
    _matching,
    _split_top,
)
from fgc_backends.hls.reader.count import _Counter
from fgc_backends.hls.reader.text import _own_level, _subscripts, _unit, _Var, until_fixed


@dataclass(frozen=True)
class LoopReading:
    """One pipelined loop as the text describes it."""

    file: str
    line: int
    function: str
    label: str | None  # the FGC_CYCLES label after the loop, when there is one
    template: tuple[tuple[str, int], ...]  # the instantiation's integer template arguments
    ii: int  # the II its PIPELINE pragma declares (the plan's)
    ops: tuple[tuple[str, int], ...]  # floating-point operations of one iteration, by kind
    instances: tuple[tuple[str, int], ...]  # operator instances it needs at its II
    accesses: tuple[tuple[str, int, int], ...]  # (global array, accesses an iteration, banks)
    ii_ports: int  # the smallest II its memories' ports allow
    recurrence: tuple[str, ...]  # carried read-modify-writes without DEPENDENCE inter false
    ii_recurrence: int  # the smallest II those recurrences allow (0: none)
    ii_known: bool = True  # False: the pragma's II does not evaluate here (not judged)
    # (what limits them: "ALLOCATION in f" / "ALLOCATION function", operator kind or callee,
    # operations an iteration issues, instances the ALLOCATION allows) of every kind whose
    # instances cannot issue its operations within the II
    allocation: tuple[tuple[str, str, int, int], ...] = ()
    ii_allocation: int = 0  # the smallest II the ALLOCATION limits allow (0: none applies)
    # `DEPENDENCE variable=v inter false` claims the text refutes: (v, the element's subscript,
    # the distance it comes back at: P for [a % P], 1 for an index no iteration moves, 0 when
    # the modulus does not evaluate here, the recurrence's latency: the adder's when the
    # element is updated through an add, else 1, a compare and select)
    false_claims: tuple[tuple[str, str, int, int], ...] = ()
    ii_dependence: int = 0  # the smallest II the refuted claims' true dependences allow
    # claims on a read-modify-write at a data-dependent address (an index read from memory):
    # the text can neither prove nor refute them (v, subscript)
    unproven_claims: tuple[tuple[str, str], ...] = ()

    @property
    def ii_bound(self) -> int:
        return max(1, self.ii_ports, self.ii_recurrence, self.ii_allocation, self.ii_dependence)

    def dsp(self, dsp_of: dict[str, int]) -> int:
        return sum(n * dsp_of.get(kind, 0) for kind, n in self.instances)


def _through_add(body: str, name: str) -> bool:
    """Whether ``body`` updates an element of ``name`` through an add: ``name[...] += / -=``,
    or ``name[...] =`` a right-hand side with a binary + or - (subscripts aside)."""
    for m in re.finditer(rf"\b{name}\s*(?:\[[^\[\]]*(?:\[[^\]]*\][^\[\]]*)*\]\s*)+"
                         r"([-+]?=)(?!=)", body):
        if m.group(1) in ("+=", "-="):
            return True
        rhs = until_fixed(r"\[[^\[\]]*\]", "", body[m.end():body.find(";", m.end())])
        if re.search(r"[\w)\]]\s*[-+](?![-+=>])", rhs):
            return True
    return False


def _header_before(code: str, lo: int, open_: int) -> list[str] | None:
    """The three parts of the ``for (...)`` whose ``)`` is the last thing before ``open_`` (the
    loop body's ``{``), or None (a ``for`` without braces earlier on the line is not it)."""
    end = open_ - 1
    while end > lo and code[end].isspace():
        end -= 1
    if code[end] != ")":
        return None
    start = _matching_back(code, end, lo)
    if start is None or not re.search(r"\bfor\s*$", code[lo:start]):
        return None
    parts = code[start + 1:end].split(";")
    return parts if len(parts) == 3 else None


def _matching_back(code: str, close: int, lo: int) -> int | None:
    """Index of the '(' that the ')' at ``close`` closes (not before ``lo``)."""
    depth = 0
    for i in range(close, lo - 1, -1):
        if code[i] == ")":
            depth += 1
        elif code[i] == "(":
            depth -= 1
            if depth == 0:
                return i
    return None


class _Reader(_Counter):
    # -- pipelined loops -------------------------------------------------------------------------
    def instantiations(self, f: _Function) -> list[dict[str, int]]:
        """The integer template arguments ``f`` is instantiated with (one binding per distinct
        instantiation; ``[{}]`` for a function that is not a template)."""
        if not f.template_ints:
            return [{}]
        seen: dict[tuple, dict[str, int]] = {}
        pattern = re.compile(rf"\b{f.name}\s*<([^;{{}}()]*?)>\s*\(")
        for caller in self.functions.values():
            for m in pattern.finditer(caller.text):
                args = [a for a in _split_top(m.group(1)) if self._value(a, {}) is not None]
                env = {name: self._value(a, {}) for name, a in
                       zip(f.template_ints, args, strict=False)}
                seen.setdefault(tuple(sorted(env.items())), env)
        return list(seen.values()) or [{}]

    def loops(self) -> list[LoopReading]:
        out = []
        for f in self.definitions:
            for env in self.instantiations(f):
                out += self.loops_in(f, env)
        return sorted(out, key=lambda r: (r.file, r.line, r.template))

    def loops_in(self, f: _Function, env: dict[str, int]) -> list[LoopReading]:
        """The pipelined loops of ``f`` instantiated with the integer template arguments
        ``env`` (those of ``f``'s own parameters are kept)."""
        env = {k: v for k, v in env.items() if k in f.template_ints}
        code, (lo, hi) = f.code, f.body
        out = []
        for m in re.finditer(r"#\s*pragma\s+HLS\s+PIPELINE\b([^\n]*)", code[lo:hi], re.I):
            if "off" in m.group(1).lower():
                continue
            ii = re.search(r"II\s*=\s*(\w+(?:\s*::\s*\w+)*)", m.group(1))
            value = self._value(ii.group(1), env) if ii else 1
            reading = self.loop(f, lo + m.start(), value or 1, env)
            if reading is not None:
                # an II this text cannot evaluate (a configuration the design does not define)
                # is read at 1 for its operators and not judged
                out.append(reading if value else replace(reading, ii_known=False))
        return out

    def loop(self, f: _Function, pragma: int, ii: int, template: dict[str, int]
             ) -> LoopReading | None:
        where, self.where = self.where, _unit(f, self.where)
        try:
            return self._loop(f, pragma, ii, template)
        finally:
            self.where = where

    def _loop(self, f: _Function, pragma: int, ii: int, template: dict[str, int]
              ) -> LoopReading | None:
        code = f.code
        depth, open_ = 0, None
        for i in range(pragma - 1, f.body[0], -1):
            if code[i] == "}":
                depth += 1
            elif code[i] == "{":
                if depth == 0:
                    open_ = i
                    break
                depth -= 1
        if open_ is None:
            return None  # a function-level pipeline: not judged here
        header = _header_before(code, f.body[0], open_)
        if header is None:
            return None
        # the arrays each call site binds the parameters to (one reading a distinct binding;
        # the worst is the loop's): a parameter bound to a global at one site and to a local
        # at another is not that global at every site
        variants: list[dict[str, _Var]] = []
        for site in self.sites.get(f.qualname or f.name) or [None]:
            scope: dict[str, _Var] = {}
            for p in f.params:
                v = self._param_var(f, p)
                if v is not None and site is not None and p.name in site:
                    v = _Var(v.is_float, v.dims, site[p.name], "global") \
                        if site[p.name] is not None else _Var(v.is_float, v.dims, p.name, "local")
                if v is not None:
                    scope[p.name] = v
            if scope not in variants:
                variants.append(scope)
        readings = [self._read_loop(f, pragma, ii, template, open_, header, scope)
                    for scope in variants]
        return max(readings, key=lambda r: (r.ii_bound, sum(n for _, n in r.instances)))

    def _read_loop(self, f: _Function, pragma: int, ii: int, template: dict[str, int],
                   open_: int, header: list[str], scope: dict[str, _Var]) -> LoopReading:
        """The loop whose body opens at ``open_`` (its ``for`` header's three parts), its
        parameters bound as ``scope`` says."""
        code = f.code
        scope = dict(scope)
        close = _matching(code, open_, "{", "}")
        body = code[open_ + 1:close]
        var = re.search(r"(\w+)\s*=", header[0])
        # blocks closed before the loop declare nothing that lives into it
        before = _own_level(code[f.body[0] + 1:open_])
        for name, (is_float, dims) in self._declarations(before).items():
            scope[name] = _Var(is_float, dims, name, "local")
        outer = frozenset({v.alias for v in scope.values()} | set(self.globals))
        env: dict[str, int] = dict(template)
        for c in re.finditer(r"(?:^|[;{}])\s*(?:static\s+)?const\s+int\s+(\w+)\s*=\s*([^;,]+);",
                             before):
            value = self._value(c.group(2), env)
            if value is not None:
                env[c.group(1)] = value
        count = self.count(body, scope, env, var.group(1) if var else None, outer)
        count.ops += self._typer(scope).operators(header[1])  # its condition's operators
        limits = self.allocation(f.text)
        instances: Counter = Counter()
        for kind, n in count.ops.items():
            need = math.ceil(n / ii)
            base = kind.split(":")[0]  # a typed kind (add:float, a mixed design's) by its kind
            instances[kind] += min(need, limits[base]) if base in limits else need
        for name, ops in count.capped.items():
            # the callee of this translation unit (two kernels define their own factor_<b>)
            callee = self.local.get(self.where, {}).get(name) or self.functions.get(name)
            cap = self.allocation(callee.text) if callee is not None else {}
            for kind, n in ops.items():
                need = math.ceil(n / ii)
                base = kind.split(":")[0]
                instances[kind] += min(need, cap[base]) if base in cap else need
        def dims_here(name):
            var = scope.get(name) or self.globals.get(name)
            return var.dims if var is not None else None

        banks_here = {scope[name].alias if name in scope else name: banks
                      for name, banks in self._banks(f.text, env, dims_here).items()}
        accesses, ii_ports = [], 1
        for array, n in sorted(count.accesses.items()):
            banks = banks_here.get(array, self.global_banks.get(array, 1))
            if banks is None:
                continue  # registers
            accesses.append((array, n, banks))
            ii_ports = max(ii_ports, math.ceil(n / (2 * banks)))
        free = set(re.findall(r"DEPENDENCE\s+variable\s*=\s*(\w+)[^\n]*inter\s+false", body,
                              re.I))
        false_claims, unproven = self._claims(body, header, env, free)
        ii_dependence = max([0] + [math.ceil(lat / d) if d > 0 else lat
                                   for _, _, d, lat in false_claims])
        free |= {scope[name].alias for name in free if name in scope}
        # DEPENDENCE ... inter true distance=D: the element comes back D iterations later, so
        # the recurrence through the adder allows II ceil(latency / D)
        distance: dict[str, int] = {}
        for d in re.finditer(r"DEPENDENCE\b([^\n]*)", body, re.I):
            args = d.group(1)
            name = re.search(r"variable\s*=\s*(\w+)", args)
            dist = re.search(r"distance\s*=\s*(\w+(?:\s*::\s*\w+)*)", args)
            if name and dist and re.search(r"inter\s+true", args, re.I):
                value = self._value(dist.group(1), env)
                if value is not None and value > 0:
                    for n in {name.group(1), scope[name.group(1)].alias if name.group(1) in
                              scope else name.group(1)}:
                        distance[n] = value
        for alias, uses in count.rw.items():
            kinds = {k for k, _ in uses}
            if kinds == {"r", "w"} and any(fixed for _, fixed in uses):
                count.recurrences.add(alias)
        carried = tuple(sorted(r for r in count.recurrences if r not in free))
        # a declared distance D: the element's recurrence latency over D, the adder's when it
        # is updated through an add (a partial sum), else 1 (a word stored and read back D
        # iterations later, as _claims prices a refuted claim)
        names = {r: {r} | {n for n, v in scope.items() if getattr(v, "alias", None) == r}
                 for r in carried}
        ii_recurrence = max([0] + [
            math.ceil((self.add_latency if any(_through_add(body, n) for n in names[r]) else 1)
                      / distance[r]) if r in distance else self.add_latency for r in carried])
        allocation, ii_allocation = self._allocation_ii(f, count, env, ii)
        label = re.search(r'FGC_CYCLES\(\s*"(\w+)"', code[close:close + 400])
        return LoopReading(
            file=f.file, line=_line(code, pragma), function=f.name,
            template=tuple(sorted(template.items())),
            label=label.group(1) if label else None, ii=ii,
            ops=tuple(sorted(count.ops.items())), instances=tuple(sorted(instances.items())),
            accesses=tuple(accesses), ii_ports=ii_ports, recurrence=carried,
            ii_recurrence=ii_recurrence, allocation=allocation, ii_allocation=ii_allocation,
            false_claims=false_claims, ii_dependence=ii_dependence, unproven_claims=unproven)

    def _claims(self, body: str, header: list[str], env: dict[str, int], names: set[str]
                ) -> tuple[tuple[tuple[str, str, int, int], ...], tuple[tuple[str, str], ...]]:
        """The ``DEPENDENCE ... inter false`` claims on ``names`` against the loop body's
        read-modify-writes of one element (the same subscript read and written): an index
        taken modulo P (``part[a % P]``, interleaved partial sums) brings the element back P
        iterations later, an index that no iteration moves (no loop variable, nothing assigned
        or declared in the body) every iteration: both refute the claim (UG1399: ``inter
        false`` is the designer's promise that no iteration reads what another wrote; the true
        statement is ``inter true distance=P``). An index read from memory (``bank[at[a]]``,
        or a local initialised from an array or a stream) is unproven: the text cannot tell
        whether two iterations meet."""
        moving = set(re.findall(r"\b([A-Za-z_]\w*)\s*=(?!=)", header[0]))
        moving |= set(re.findall(r"\b([A-Za-z_]\w*)\s*(?:[-+*/%&|^]?=(?!=)|\+\+|--)", body))
        moving |= set(re.findall(r"(?:\+\+|--)\s*([A-Za-z_]\w*)", body))
        declared = set(self._declarations(body))
        moving |= declared
        data: set[str] = set()
        for _ in range(4):  # locals initialised from memory, a stream, or such a local
            for name in declared - data:
                init = re.search(rf"\b{name}\s*=(?!=)\s*([^;,]*)", body)
                if init and ("[" in init.group(1) or ".read(" in init.group(1) or any(
                        re.search(rf"\b{d}\b", init.group(1)) for d in data)):
                    data.add(name)
        refuted, unproven = [], []
        for name in sorted(names):
            uses: dict[str, set[str]] = {}
            added: set[str] = set()  # subscripts whose element is updated through an add
            for m in re.finditer(rf"\b{name}\s*((?:\[[^\[\]]*(?:\[[^\]]*\][^\[\]]*)*\]\s*)+)"
                                 r"(\s*[-+*/]?=(?!=))?", body):
                sub = re.sub(r"\s+", "", m.group(1))
                op = (m.group(2) or "").strip()
                uses.setdefault(sub, set()).update({"": "r", "=": "w"}.get(op, "rw"))
                if op in ("+=", "-="):
                    added.add(sub)
                elif op == "=":
                    rhs = until_fixed(r"\[[^\[\]]*\]", "", body[m.end():body.find(";", m.end())])
                    if re.search(r"[\w)\]]\s*[-+](?![-+=>])", rhs):
                        added.add(sub)
            for sub, kinds in sorted(uses.items()):
                if kinds != {"r", "w"}:
                    continue
                words = set(re.findall(r"[A-Za-z_]\w*", sub))
                modulo = re.search(r"%\s*\(?\s*([\w:]+)", sub)
                latency = self.add_latency if sub in added else 1
                if any("[" in index for index in _subscripts(sub)) or words & data:
                    unproven.append((name, sub))
                elif modulo:
                    refuted.append((name, sub, self._value(modulo.group(1), env) or 0, latency))
                elif not words & moving:
                    refuted.append((name, sub, 1, latency))
        return tuple(refuted), tuple(unproven)

    def _allocation_ii(self, f: _Function, count, env: dict[str, int], ii: int
                       ) -> tuple[tuple[tuple[str, str, int, int], ...], int]:
        """The loop's operations against the ALLOCATION limits in scope (UG1399: a pipelined
        loop issues an iteration's operations of a kind through that kind's instances within
        its II, so its II is at least ``ceil(ops / instances)``): ``ALLOCATION operation`` in
        ``f`` (the loop's operations, exclusive branches sharing), in a callee that is its own
        module (its operations a call, one module a call site), and ``ALLOCATION function`` in
        ``f`` (its call sites an iteration on ``limit`` instances, each taking a call a cycle
        at best). Returns the limits the II is short of and the II they allow (0: none)."""
        short, bound = [], 0

        def judge(what: str, kind: str, n: int, instances: int) -> None:
            nonlocal bound
            if instances <= 0 or n <= 0:
                return  # limit=0 (no instance) is not a limit this rule reads
            need = math.ceil(n / instances)
            bound = max(bound, need)
            if need > ii:
                short.append((what, kind, n, instances))

        limits = self.allocation(f.text)
        for kind, n in sorted(count.peak.items()):
            if kind.split(":")[0] in limits:
                judge(f"ALLOCATION in {f.name}", kind, n, limits[kind.split(":")[0]])
        functions = self.function_allocation(f.text, env)
        for name, ops in sorted(count.capped_peak.items()):
            callee = self.local.get(self.where, {}).get(name) or self.functions.get(name)
            cap = self.allocation(callee.text) if callee is not None else {}
            sites = max(1, count.calls.get(name, 0))
            if name in functions and functions[name] > 0:
                sites = min(sites, functions[name])
            for kind, n in sorted(ops.items()):
                if kind.split(":")[0] in cap:
                    judge(f"ALLOCATION in {name}", kind, n, cap[kind.split(":")[0]] * sites)
        for name, limit in sorted(functions.items()):
            if count.calls.get(name):
                judge("ALLOCATION function", name, count.calls[name], limit)
        return tuple(short), bound


def read_project(files: Iterable[tuple[str, str]], add_latency: int) -> list[LoopReading]:
    """Every pipelined loop of the synthesised ``files`` ((name, text) pairs) as Vitis would
    bind and schedule it; ``add_latency``: the adder's stages (a carried sum's II)."""
    return _Reader(files, add_latency).loops()


def check(readings: Iterable[LoopReading], strict: bool = False) -> list[LintIssue]:
    """A loop whose declared II is below what its memories, recurrences or ALLOCATION limits
    allow, or whose ``DEPENDENCE ... inter false`` the text refutes; ``strict``: also the
    claims the text cannot prove (a data-dependent address, rule ``dependence_unproven``)."""
    issues = []
    for r in readings:
        if not r.ii_known:
            continue
        args = ", ".join(f"{k}={v}" for k, v in r.template)
        where = f"'{r.label or r.function}' (in {r.function}{f'<{args}>' if args else ''})"
        if r.ii_ports > r.ii:
            worst = max(r.accesses, key=lambda a: math.ceil(a[1] / (2 * a[2])))
            issues.append(LintIssue(r.file, r.line, "ii_ports", f"loop {where} declares II={r.ii}"
                                    f" but array '{worst[0]}' takes {worst[1]} accesses an "
                                    f"iteration through {2 * worst[2]} ports: II >= "
                                    f"{r.ii_ports}"))
        if r.ii_recurrence > r.ii:
            issues.append(LintIssue(r.file, r.line, "ii_recurrence", f"loop {where} declares "
                                    f"II={r.ii} but reads and writes "
                                    f"{', '.join(repr(x) for x in r.recurrence)} every "
                                    "iteration without 'DEPENDENCE inter false': II >= "
                                    f"{r.ii_recurrence}"))
        for name, sub, d, _ in r.false_claims:
            again = f"again {d} iterations later" if d > 1 else "every iteration" if d == 1 \
                else "again a modulus later"
            state = f"'inter true distance={d}'" if d >= 1 else "'inter true distance=<modulus>'"
            issues.append(LintIssue(r.file, r.line, "dependence_false", f"loop {where} claims "
                                    f"'DEPENDENCE variable={name} inter false' but reads and "
                                    f"writes {name}{sub} {again}: {state} is the truth "
                                    f"(II >= {r.ii_dependence} with it)"))
        for name, sub in r.unproven_claims if strict else ():
            issues.append(LintIssue(r.file, r.line, "dependence_unproven", f"loop {where} "
                                    f"claims 'DEPENDENCE variable={name} inter false' on "
                                    f"{name}{sub}, read and written at an address read from "
                                    "memory: the text cannot prove no two iterations meet"))
        if r.ii_allocation > r.ii:
            worst = max(r.allocation, key=lambda a: math.ceil(a[2] / a[3]))
            what, kind, n, k = worst
            issued = f"{n} calls of {kind}" if what == "ALLOCATION function" else \
                f"{n} {kind} operations"
            issues.append(LintIssue(r.file, r.line, "ii_allocation", f"loop {where} declares "
                                    f"II={r.ii} but issues {issued} an iteration through "
                                    f"{k} instance{'s' if k > 1 else ''} ({what}): II >= "
                                    f"{r.ii_allocation}"))
    # one issue per loop and rule (the instantiations of a template share the text)
    seen, out = set(), []
    for issue in issues:
        if (issue.file, issue.line, issue.rule) not in seen:
            seen.add((issue.file, issue.line, issue.rule))
            out.append(issue)
    return out
