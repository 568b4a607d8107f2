"""What the second reader knows of the whole text before it reads a loop: functions, struct
members and their specialisations, integer constants, global arrays and their partitions,
the arrays each parameter is bound to, ``ALLOCATION`` limits, and which function a call
runs (:class:`_Scope`)."""

from __future__ import annotations

import re
from collections.abc import Iterable

from fgc_backends.cfamily.lint import strip_comments_and_strings, synthesis_view
from fgc_backends.hls.lint.cxx import (
    _constants,
    _evaluate,
    _Function,
    _functions,
    _matching,
    _split_top,
)
from fgc_backends.hls.reader.text import (
    _ALLOCATION_KINDS,
    _CALL,
    _DECL,
    _GLOBAL,
    _PRAGMA,
    FLOAT_TYPES,
    _blank_macros,
    _Count,
    _own_level,
    _Var,
    compiled_view,
)


class _Scope:
    """The design's declarations, constants and bindings; the values of integer
    expressions and which function a call runs."""
    def __init__(self, files: Iterable[tuple[str, str]], add_latency: int):
        files = list(files)
        # file -> lines compiled where T is the linear solver's L (a mixed design's fgc::les)
        self.wide_lines: dict[str, set[int]] = {}
        self.files = [(name, _blank_macros(strip_comments_and_strings(synthesis_view(text))))
                      for name, text in compiled_view(files, self.wide_lines)]
        # the scalar types T (the accelerator's) and L (the linear solver's) name: "float" or
        # "double" (a mixed design: T float, L double)
        self.scalars: dict[str, str] = {}
        for _, code in self.files:
            for m in re.finditer(r"(?<![\w:])typedef\s+(float|double|T)\s+(T|L)\s*;", code):
                if m.group(2) not in self.scalars:
                    self.scalars[m.group(2)] = self.scalars.get(m.group(1), m.group(1))
        # struct name -> (file, where, body, base names)
        self.struct_bodies: dict[str, list[tuple[str, int, str, tuple[str, ...]]]] = {}
        self.functions: dict[str, _Function] = {}
        # every free function's definition, those a name's first one shadows included (a
        # header no kernel includes keeps both branches of its #ifdef: two definitions of one
        # name, each with its own loops)
        self.definitions: list[_Function] = []
        # Struct::name -> [(specialisation's template arguments or None, function)]
        self.members: dict[str, list[tuple[tuple[str, ...] | None, _Function]]] = {}
        self.defaults: dict[str, tuple[str, ...]] = {}  # struct template -> its parameters
        self.structs: set[str] = set()  # every struct's name
        # file -> its functions: a call resolves in its own file first (a kernel's functions
        # live in its .cpp's anonymous namespace: the on-chip stream design's two kernels
        # define the same names), then anywhere
        self.local: dict[str, dict[str, _Function]] = {}
        # the translation unit being read: the .cpp of the kernel function that (directly or
        # through a header's template) is being read
        self.where: str | None = None
        for name, code in self.files:
            structs = []
            for m in re.finditer(r"(?:template\s*<([^{};]*?)>\s*)?\bstruct\s+(\w+)\s*"
                                 r"(<[^{};]*>)?\s*\{", code):
                self.structs.add(m.group(2))
                structs.append((m.start(), _matching(code, m.end() - 1, "{", "}"),
                                tuple(_split_top(m.group(3)[1:-1])) if m.group(3) else None))
                if m.group(1) and not m.group(3):
                    self.defaults[m.group(2)] = tuple(_split_top(m.group(1)))
            # every struct's body and bases (`struct SetConfig : LesConfig {`): its scalar T
            for m in re.finditer(r"\bstruct\s+(\w+)\s*(?:<[^{};]*>)?\s*(?::([^{};]*))?\{", code):
                end = _matching(code, m.end() - 1, "{", "}")
                bases = tuple(b.split()[-1].split("<")[0].split("::")[-1]
                              for b in _split_top(m.group(2) or "") if b.split())
                self.struct_bodies.setdefault(m.group(1), []).append(
                    (name, m.start(), code[m.end():end], bases))
            for f in _functions(name, code):
                if f.qualname != f.name:
                    spec = [s for s in structs if s[0] < f.start < s[1]]
                    self.members.setdefault(f.qualname, []).append(
                        (spec[-1][2] if spec else None, f))
                else:
                    self.functions.setdefault(f.name, f)
                    self.definitions.append(f)
                    self.local.setdefault(name, {}).setdefault(f.name, f)
        self.constants = _constants(code for _, code in self.files)
        # a kernel's own constants (two kernels in one design may give a name two values)
        self.unit_constants = {name: _constants([code]) for name, code in self.files
                               if name.endswith(".cpp")}
        self.add_latency = add_latency
        outside = "\n".join(self._outside_functions(n, c) for n, c in self.files)
        self.globals = {m.group(2): _Var(re.fullmatch(FLOAT_TYPES, m.group(1)) is not None,
                                         tuple(re.findall(r"\[([^\]]*)\]", m.group(3))),
                                         m.group(2), "global")
                        for m in _GLOBAL.finditer(outside)}

        def dims_of(name):
            return self.globals[name].dims if name in self.globals else None

        self.global_banks = self._banks(outside, {}, dims_of)
        # a global partitioned inside a function (Vitis's place for a global's pragma): a
        # pragma naming it where no parameter or local of that name hides it
        for f in self.functions.values():
            own = {p.name for p in f.params} | set(self._declarations(f.text))
            for name, banks in self._banks(f.text, {}, dims_of).items():
                if name in self.globals and name not in own:
                    self.global_banks[name] = banks
        # a global partitioned completely in its first dimension: one of its rows (``work[U]``
        # passed to a function) is one bank, named ``G[]`` where a parameter is bound to it, or
        # as many as a cyclic / block partition of a later dimension gives (``factor=F dim=d``,
        # d >= 2: fgc_qr.h's banks by row parity)
        for _, code in self.files:
            for m in re.finditer(r"#\s*pragma\s+HLS\s+ARRAY_PARTITION\s+variable\s*=\s*(\w+)"
                                 r"\s+complete\s+dim\s*=\s*1\b", code, re.I):
                if m.group(1) in self.globals and len(self.globals[m.group(1)].dims) > 1:
                    row = 1
                    for f in re.finditer(r"#\s*pragma\s+HLS\s+ARRAY_PARTITION\s+variable\s*=\s*"
                                         + m.group(1) + r"\s+(?:cyclic|block)\s+factor\s*=\s*(\w+)"
                                         r"\s+dim\s*=\s*(\d+)", code, re.I):
                        factor = self._value(f.group(1), {})
                        if int(f.group(2)) >= 2 and factor:
                            row *= factor
                    self.global_banks[f"{m.group(1)}[]"] = row
        self.bindings = self._bindings()
        self.memo: dict[tuple, _Count] = {}
        self.flatten = True  # read a callee in place (off: a function's own operations)
        self.returns_float = False  # the function being read returns a floating-point value
        self.scalar = ""  # the scalar of the function being read ("": the accelerator's T)

    # -- scalar types ----------------------------------------------------------------------
    def scalar_of(self, f: _Function, env: dict) -> str:
        """The C++ scalar (``float`` / ``double``) ``T`` names in ``f`` as instantiated with
        ``env`` when it is not the accelerator's (a mixed design's linear solver: its headers
        configured by ``CFG::T`` = ``L``, the kernel's ``namespace les``), else "": ``f``'s own
        ``typedef X T;``, else its ``typename CFG::T`` (CFG: the struct ``env`` binds), else its
        struct's ``typedef`` (a member), else where it is compiled (a line where T is L)."""
        working = self.scalars.get("T")
        if working is None or self.scalars.get("L", working) == working:
            return ""  # one scalar: nothing to tell apart
        if any(re.fullmatch(r"(?:class|typename)\s+T(?:\s*=.*)?", p.strip())
               for p in self._template_params(f)):
            # `template <class T, ...>`: T is what the call passes (the caller's T, or a name)
            bound = str(env.get("type:T", "T"))
            caller = env.get("scalar:caller", self.scalar)
            if bound in ("L", "float", "double"):
                scalar = self._scalar_name(bound, False)
                return "" if scalar in (None, working) else scalar
            return caller
        own = _own_level(f.text)
        m = re.search(r"(?<![\w:])typedef\s+(?:typename\s+)?([\w:]+)\s+T\s*;", own)
        name = m and m.group(1)
        if name and "::" in name and name.split("::")[-1] == "T":
            owner = name.split("::")[-2]
            if owner in ("", "fgc"):  # ::fgc::T: the accelerator's T wherever it is read
                name = "::T"
            else:  # `typename CFG::T`: the T of the struct CFG is bound to
                name = self._struct_scalar(env.get(f"type:{owner}", owner), f.file)
        if not name:
            head = f.code[max(f.code.rfind(c, 0, f.start) for c in ";{}") + 1:f.body[0]]
            cfg = re.search(r"\btypename\s+(\w+)\s*::\s*T\b", head)
            if cfg:
                name = self._struct_scalar(env.get(f"type:{cfg.group(1)}", cfg.group(1)),
                                           f.file)
        if not name and f.qualname != f.name:
            name = self._struct_scalar(f.qualname.split("::")[0], f.file)
        line = f.code.count("\n", 0, f.start)
        wide = line in self.wide_lines.get(f.file, ())
        scalar = self._scalar_name(name or "T", wide)
        return "" if scalar in (None, working) else scalar

    def _scalar_name(self, name: str, wide: bool) -> str | None:
        """The scalar a type name stands for (bare ``T`` where T is L: L's)."""
        base = name.split("::")[-1]
        if base == "T" and wide and not name.startswith("::"):
            base = "L"
        return self.scalars.get(base, base if base in ("float", "double") else None)

    def _struct_scalar(self, struct: str, file: str, depth: int = 0) -> str | None:
        """The scalar struct ``struct``'s ``typedef X T;`` gives (its own, else a base's; the
        struct in ``file`` or the translation unit being read first), resolved where the
        struct is."""
        bodies = self.struct_bodies.get(struct, [])
        bodies = sorted(bodies, key=lambda b: (b[0] not in (file, self.where), b[1]))
        for where, at, body, bases in bodies:
            m = re.search(r"(?<![\w:])typedef\s+(?:typename\s+)?([\w:]+)\s+T\s*;",
                          _own_level(body))
            if m:
                code = dict(self.files)[where]
                wide = code.count("\n", 0, at) in self.wide_lines.get(where, ())
                return self._scalar_name(m.group(1), wide)
            for base in bases if depth < 8 else ():
                found = self._struct_scalar(base, where, depth + 1)
                if found:
                    return found
        return None

    # -- declarations ----------------------------------------------------------------------
    def _outside_functions(self, file: str, code: str) -> str:
        """``code`` with every function body blanked: the declarations at namespace scope."""
        chars = list(code)
        for f in _functions(file, code):
            for i in range(f.body[0], f.body[1] + 1):
                if chars[i] != "\n":
                    chars[i] = " "
        return "".join(chars)

    @staticmethod
    def _declarations(code: str) -> dict[str, tuple[bool, tuple[str, ...]]]:
        """name -> (floating-point, array dimensions) of the variables declared in ``code``."""
        out: dict[str, tuple[bool, tuple[str, ...]]] = {}
        for m in _DECL.finditer(code):
            is_float = re.fullmatch(FLOAT_TYPES, m.group("type").strip()) is not None
            for part in _split_top(m.group("names")):
                d = re.match(r"^\*?\s*([A-Za-z_]\w*)\s*((?:\[[^\]]*\]\s*)*)", part)
                if d:
                    dims = tuple(x.strip() for x in re.findall(r"\[([^\]]*)\]", d.group(2)))
                    out.setdefault(d.group(1), (is_float, dims))
        return out

    def _banks(self, code: str, env: dict[str, int], dims_of=None) -> dict[str, int | None]:
        """array -> banks from the ARRAY_PARTITION pragmas in ``code`` (None: registers, a
        complete partition of every dimension). ``complete dim=k`` (k >= 1) of an array of
        more than one dimension gives as many banks as dimension k has (``dims_of``: name ->
        its dimensions, when known)."""
        out: dict[str, int | None] = {}
        for m in _PRAGMA.finditer(code):
            words = m.group(1)
            if not words.upper().startswith("ARRAY_PARTITION"):
                continue
            var = re.search(r"variable\s*=\s*(\w+)", words)
            if not var:
                continue
            if re.search(r"\bcomplete\b", words):
                dim = re.search(r"\bdim\s*=\s*(\d+)", words)
                dims = dims_of(var.group(1)) if dims_of else None
                k = int(dim.group(1)) if dim else 0
                if k >= 1 and dims and len(dims) > 1 and k <= len(dims):
                    out[var.group(1)] = self._value(dims[k - 1], env)  # None: not known
                else:
                    out[var.group(1)] = None
            else:
                factor = re.search(r"factor\s*=\s*(\w+)", words)
                value = self._value(factor.group(1), env) if factor else None
                prior = out.get(var.group(1), 1)  # a partition of another dimension before it
                out[var.group(1)] = None if prior is None else prior * (value or 1)
        return out

    def _value(self, expr: str, env: dict[str, int]) -> int | None:
        word = expr.strip()
        if word in ("true", "false"):
            return int(word == "true")
        return _evaluate(expr, {**self.constants, **self.unit_constants.get(self.where, {}),
                                **env})

    def _condition(self, expr: str, env: dict[str, int]) -> bool | None:
        m = re.fullmatch(r"\s*(.+?)\s*(<=|>=|==|!=|<|>)\s*(.+?)\s*", expr)
        if not m:
            return None
        a, b = self._value(m.group(1), env), self._value(m.group(3), env)
        if a is None or b is None:
            return None
        return {"<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b, "==": a == b,
                "!=": a != b}[m.group(2)]

    def _bindings(self) -> dict[tuple[str, str], set[str]]:
        """(function, parameter) -> the names its call sites pass (their base names, resolved
        through the callers' own parameters to globals where they lead there)."""
        direct: dict[tuple[str, str], set[tuple[str, str]]] = {}
        calls: list[tuple[str, str, dict[str, str]]] = []  # (callee, caller, param -> base)
        # the callers: the functions and the structs' members (the QR driver's hooks,
        # QrSets::stack / ::level, pass the unit sets' globals WORK<u> on), by qualified name
        callers = {f.qualname or f.name: f for f in self.functions.values()}
        for variants in self.members.values():
            for _, f in variants:
                callers.setdefault(f.qualname, f)
        for qual, caller in callers.items():
            for m in _CALL.finditer(caller.text):
                f = self.functions.get(m.group(1)) or self._member_callee(caller.text, m)
                if f is None:
                    continue
                key = f.qualname or f.name
                open_ = caller.text.index("(", m.end() - 1)
                args = _split_top(caller.text[m.end():_matching(caller.text, open_, "(", ")")])
                site = {}
                for param, arg in zip(f.params, args, strict=False):
                    base = re.match(r"^&?\s*([A-Za-z_]\w*)\s*(\[)?", arg)
                    if base and (param.dims or param.pointer):
                        # `work[U]`: one row of the array (marked `[]`)
                        name = base.group(1) + ("[]" if base.group(2) else "")
                        direct.setdefault((key, param.name), set()).add((qual, name))
                        site[param.name] = name
                calls.append((key, qual, site))
        out: dict[tuple[str, str], set[str]] = {}

        def row(names, sliced):
            """``names`` (globals) as one row of each where ``sliced``: ``G[]`` for a global
            partitioned in its first dimension (one bank), else the global itself (its rows
            share its memories)."""
            if not sliced:
                return set(names)
            return {g if g.endswith("[]") else f"{g}[]" if f"{g}[]" in self.global_banks
                    else g for g in names}

        def resolve(key, seen):
            names = set()
            for caller, marked in direct.get(key, ()):
                name, sliced = marked.removesuffix("[]"), marked.endswith("[]")
                if name in self.globals:
                    names |= row({name}, sliced)
                elif (caller, name) not in seen and any(
                        p.name == name for p in callers[caller].params):
                    names |= row(resolve((caller, name), seen | {key}), sliced)
            return names

        for key in direct:
            out[key] = resolve(key, frozenset())
        # per call site, the global each array parameter is bound to there (None: a local of
        # the caller): a function called with KEPT_S as one argument at one site and as another
        # at the next touches KEPT_S through one of them at a time, not both
        self.sites: dict[str, list[dict[str, str | None]]] = {}
        for callee, caller, site in calls:
            bound = {}
            for param, marked in site.items():
                base, sliced = marked.removesuffix("[]"), marked.endswith("[]")
                if base in self.globals:
                    bound[param] = sorted(row({base}, sliced))[0]
                elif any(p.name == base for p in callers[caller].params):
                    names = sorted(row(out.get((caller, base), ()), sliced))
                    bound[param] = names[0] if names else None
                else:
                    bound[param] = None
            if bound not in self.sites.setdefault(callee, []):
                self.sites[callee].append(bound)
        return out

    def _param_var(self, f: _Function, param) -> _Var | None:
        if param.stream:
            return None
        is_float = re.search(rf"\b{FLOAT_TYPES}\b", param.type) is not None
        if not (param.dims or param.pointer):
            return _Var(is_float, (), param.name, "local")
        bound = sorted(self.bindings.get((f.qualname or f.name, param.name), ()))
        if bound:  # bound to a global: the first (a parameter bound to several: any one)
            return _Var(is_float, param.dims, bound[0], "global")
        return _Var(is_float, param.dims, param.name, "local")

    def _member_callee(self, text: str, m: re.Match) -> _Function | None:
        """The struct member a call ``S<...>::f(`` in ``text`` runs (its primary template's
        definition; a specialisation where there is no primary), or None."""
        owner = re.search(r"\b(\w+)\s*(?:<[^;{}()]*>)?\s*::\s*$", text[max(0, m.start() - 160):
                                                                     m.start()])
        variants = self.members.get(f"{owner.group(1)}::{m.group(1)}") if owner else None
        if not variants:
            return None
        return next((f for spec, f in variants if spec is None), variants[0][1])

    def _lookup(self, name: str, scope: dict) -> _Var | None:
        return scope.get(name) or self.globals.get(name)

    def resolve(self, text: str, m: re.Match, env: dict[str, int], file: str | None = None
                ) -> tuple[_Function, dict[str, int]] | None:
        """The function a call matched by ``_CALL`` in ``text`` runs, and its integer template
        arguments: ``f<...>(``, or ``S<...>::f(`` (a member of a struct template, its partial
        specialisation chosen where the arguments match it)."""
        owner = re.search(r"\b(\w+)\s*(<[^;{}()]*>)?\s*::\s*$", text[max(0, m.start() - 160):
                                                                     m.start()])
        struct = owner and env.get(f"type:{owner.group(1)}", owner.group(1))
        if owner and struct in self.structs:  # a member of a struct (else a namespace's)
            variants = self.members.get(f"{struct}::{m.group(1)}")
            if not variants:
                return None
            # the struct of this translation unit (each kernel defines its own LmConfig)
            variants = [v for v in variants if v[1].file == (file or self.where)] or variants
            args = _split_top(owner.group(2)[1:-1]) if owner.group(2) else []
            values = [self._value(a, env) for a in args]
            params = self.defaults.get(struct, ())
            types = self._bind_types(params, args, env)
            bound = {}
            for param, value in zip(params, values, strict=False):
                name = re.search(r"(\w+)\s*(?:=.*)?$", param)
                if name and value is not None:
                    bound[name.group(1)] = value
            for param in params[len(args):]:  # defaulted parameters, evaluated
                default = re.match(r"^\s*(?:bool|int)\s+(\w+)\s*=\s*\(?(.*?)\)?\s*$", param)
                if not default:
                    break
                value = self._value(default.group(2), {**env, **bound})
                if value is None:
                    truth = self._condition(default.group(2), {**env, **bound})
                    value = None if truth is None else int(truth)
                args.append(default.group(2))
                values.append(value)
                if value is not None:
                    bound[default.group(1)] = value
            chosen = next((f for spec, f in variants if spec is None), variants[0][1])
            for spec, f in variants:
                if spec is None or len(spec) != len(values):
                    continue
                # a specialisation's own parameters are wildcards: its arguments are read
                # with constants only
                if all(self._value(s, {}) in (None, v) or s.strip() == a.strip()
                       for s, a, v in zip(spec, args, values, strict=True)) and \
                        any(self._value(s, {}) is not None for s in spec):
                    chosen = f
                    break
            ints = [v for a, v in zip(args, values, strict=True) if v is not None]
            return chosen, {**dict(zip(chosen.template_ints, ints, strict=False)), **types}
        f = self.local.get(file or self.where, {}).get(m.group(1)) or \
            self.functions.get(m.group(1))
        if f is None:
            return None
        cenv: dict = {}
        if m.group(2):
            args = _split_top(m.group(2)[1:-1])
            params = self._template_params(f)
            cenv.update(self._bind_types(params, args, env))
            if f.template_ints:
                ints = [v for a in args if (v := self._value(a, env)) is not None]
                cenv.update(zip(f.template_ints, ints, strict=False))
        return f, cenv

    @staticmethod
    def _template_params(f: _Function) -> tuple[str, ...]:
        """The parameters of the ``template <...>`` that introduces ``f`` (none: ())."""
        start = max(f.code.rfind(c, 0, f.start) for c in ";{}")
        header = re.search(r"template\s*<([^{};]*?)>", f.code[start + 1:f.start])
        return tuple(_split_top(header.group(1))) if header else ()

    @staticmethod
    def _bind_types(params: tuple[str, ...], args: list[str], env: dict) -> dict:
        """``type:NAME`` -> the struct a class template parameter is bound to (namespaces
        dropped; a parameter passed on, the struct it is bound to)."""
        out = {}
        for param, arg in zip(params, args, strict=False):
            kind = re.match(r"^\s*(class|typename)\s+(\w+)", param)
            if kind:
                name = arg.strip().split("::")[-1].strip()
                out[f"type:{kind.group(2)}"] = env.get(f"type:{name}", name)
        return out

    @staticmethod
    def allocation(text: str) -> dict[str, int]:
        out = {}
        for m in re.finditer(r"#\s*pragma\s+HLS\s+ALLOCATION\s+operation\s+instances=(\w+)\s+"
                             r"limit=(\d+)", text, re.I):
            kind = _ALLOCATION_KINDS.get(m.group(1).lower())
            if kind:
                out[kind] = int(m.group(2))
        return out

    def function_allocation(self, text: str, env: dict[str, int]) -> dict[str, int]:
        """function name -> instances, from ``ALLOCATION function instances=<name> limit=<n>``
        pragmas in ``text`` (a template's name with or without its arguments)."""
        out = {}
        for m in re.finditer(r"#\s*pragma\s+HLS\s+ALLOCATION\s+function\s+instances=([\w:]+)"
                             r"\s*(?:<[^\n]*?>)?\s+limit=(\w+)", text, re.I):
            limit = self._value(m.group(2), env)
            if limit is not None and limit >= 0:
                out[m.group(1).split("::")[-1]] = limit
        return out
