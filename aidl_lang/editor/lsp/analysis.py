"""What the language server knows about a document: pure functions over its source text.

Every public function takes the document text (and its file path, for diagnostics and imports)
and LSP positions (0-based line, UTF-16 character), and returns :mod:`lsprotocol` values; none
keeps state, none raises on malformed input (a document that does not parse gives what its
recoverable parts allow: the parser blanks bad lines and goes on).

* :func:`diagnostics` — the pipeline's diagnostics (parse, check, interpret, optionally solve);
* :func:`hover` — signature and doc of primitives, constraints, functions, keywords, units, user
  templates, structures and names; the type of a member such as ``rect.top_left``;
* :func:`completions` — keywords, structure kinds, the registry's vocabulary, names in scope;
  after a dot, the members of what is before it (``rect.`` -> ``top_left``, ``width``, ``bb``;
  a structure -> its children and ``bb``);
* :func:`definition`, :func:`references` — of user names (params, templates, structures,
  variables, loop variables, template parameters), following ``a.b.c`` into structures and
  names brought in by ``import`` into the imported file;
* :func:`document_symbols` — the structure tree; :func:`formatting` — through ``aidl fmt``.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field

from lsprotocol import types as T

from ... import ast as A
from ... import registry as R
from ...base.diagnostics import DiagnosticSink, Span, as_lf
from ...parser import mask_comments, parse
from ...parsing.recovery import _blank_logical_line
from . import plain
from .worker import diagnostics_json

TYPE_MEMBERS = {"point": R.POINT_MEMBERS, "line": R.LINE_MEMBERS, "bbox": R.BBOX_MEMBERS}

KEYWORD_DOCS = {
    "units": "`units mm|cm|m|in|ft` — the unit of bare lengths in this file.",
    "import": "`import \"file.aidl\" [as name]` — bring in another file's templates and constants.",
    "as": "`import \"file.aidl\" as name` — import under a namespace.",
    "param": "`param NAME = value` — a model parameter, overridable with `--set NAME=VALUE`.",
    "def": "`def name(params) -> kind { ... }` — a template: a structure made by a call.",
    "for": "`for x in list { ... }` — repeat; names assigned inside become lists.",
    "assert": "`assert cond, \"reason\"` — checked at the solved values, never solved for; "
              "false is E0405.",
    "in": "`for x in list` / `[e for x in list]`.",
    "if": "`if cond { ... } else { ... }`, or `a if cond else b`.",
    "else": "the other branch of `if`.", "elif": "`else if`.",
    "and": "logical and.", "or": "logical or.", "not": "logical not.",
    "self": "the structure whose body this is (`self.bb`, `self.child`).",
    "true": "boolean true.", "false": "boolean false.",
}
KIND_DOCS = {
    "solid": "`solid NAME { ... }` — filled material; children are unioned, `hole` children cut.",
    "hole": "`hole NAME { ... }` — a cut-out: subtracted from the enclosing solid.",
    "cut": "`cut NAME { ... }` — through-cuts inside a solid: the laser cuts along each curve "
           "as written (open curves too, zero width); a closed curve cuts a hole. Directly in "
           "an assembly: a sheet-level cut, cut where drawn, in no part.",
    "drawing": "`drawing NAME { ... }` — engraved lines and text: drawn, not filled.",
    "assembly": "`assembly NAME { ... }` — a group of parts laid out side by side.",
}


# ------------------------------------------------------------------ positions
def _line_starts(src: str) -> list[int]:
    src = as_lf(src)                # a lone CR ends a line (diagnostics.LINE_BREAK)
    starts = [0]
    for m in re.finditer("\n", src):
        starts.append(m.end())
    return starts


def _u16len(s: str) -> int:
    return len(s.encode("utf-16-le")) // 2


def offset_at(src: str, line: int, character: int) -> int:
    """The string offset of an LSP position (0-based line, UTF-16 character), clamped."""
    src = as_lf(src)
    starts = _line_starts(src)
    if line >= len(starts):
        return len(src)
    s = starts[max(0, line)]
    e = src.find("\n", s)
    e = len(src) if e < 0 else e
    n = 0
    for i in range(s, e):
        if n >= character:
            return i
        n += 2 if ord(src[i]) > 0xFFFF else 1
    return e


def position_at(src: str, offset: int) -> T.Position:
    offset = max(0, min(offset, len(src)))
    src = as_lf(src)                # a lone CR ends a line (diagnostics.LINE_BREAK)
    line = src.count("\n", 0, offset)
    s = src.rfind("\n", 0, offset) + 1
    return T.Position(line=line, character=_u16len(src[s:offset]))


def span_range(src: str, sp: Span) -> T.Range:
    """The LSP range of a :class:`Span` (1-based lines/columns, end column exclusive)."""
    r = plain.span_range(src, sp)
    return T.Range(start=T.Position(**r["start"]), end=T.Position(**r["end"]))


# ------------------------------------------------------------------ diagnostics
def diagnostics(src: str, path: str, solve: bool = True, uri: str | None = None,
                values: dict[str, str] | None = None) -> list[T.Diagnostic]:
    """The pipeline's diagnostics for ``src`` (a file at ``path``) as LSP diagnostics
    (:func:`diagnostics_json`, structured)."""
    from lsprotocol import converters
    return converters.get_converter().structure(
        diagnostics_json(src, path, solve, uri, values), list[T.Diagnostic])


def fix_edits(src: str, path: str, d) -> list[dict]:
    """:func:`.plain.fix_edits` (kept here for callers)."""
    return plain.fix_edits(src, path, d)


# ------------------------------------------------------------------ the symbol index
@dataclass(eq=False)
class Sym:
    """A name defined in a document, with where and what it is."""
    name: str
    kind: str                 # param | template | structure | variable | loop | parameter | import
    span: Span                # the defining name
    node: A.Node              # the defining statement
    scope: "Scope | None" = None        # members: structures and templates
    value: A.Node | None = None         # variables and params: the assigned expression
    detail: str = ""                    # structure kind, template kind
    origin: "Index | None" = None       # the document it is defined in


@dataclass(eq=False)
class Scope:
    """A lexical scope: its text range and the names defined in it."""
    parent: "Scope | None"
    start: int
    end: int
    owner: Sym | None = None
    names: dict[str, Sym] = field(default_factory=dict)

    def lookup(self, name: str) -> Sym | None:
        s = self
        while s is not None:
            if name in s.names:
                return s.names[name]
            s = s.parent
        return None

    def visible(self) -> dict[str, Sym]:
        out: dict[str, Sym] = {}
        s = self
        while s is not None:
            for k, v in s.names.items():
                out.setdefault(k, v)
            s = s.parent
        return out


_STRINGS = re.compile(r"[fF]?(\"(\\.|[^\"\\\n])*\"|'(\\.|[^'\\\n])*')")


def parse_tolerant(src: str, path: str) -> A.Program:
    """Parse for the editor: a document being typed often ends in an unfinished line or an
    unclosed ``{``. When the parser gives up with nothing, blank the offending lines, close the
    open blocks and try again (offsets are kept, so spans still point into ``src``)."""
    text = src
    prog = A.Program(Span(path, 1, 1, 1, 1), path, src, [])
    for _ in range(4):
        sink = DiagnosticSink()
        prog = parse(text, path, sink)
        errs = [d for d in sink.items if d.is_error and d.span is not None]
        if prog.stmts or not errs:
            break
        for d in errs:
            if text:
                text = _blank_logical_line(text, max(0, min(d.span.start, len(text) - 1)))
        bare = _STRINGS.sub(lambda m: " " * len(m.group()), mask_comments(text))
        bare = re.sub(r"#[^\n]*", "", bare)
        depth = bare.count("{") - bare.count("}")
        if depth > 0:
            text = text + "\n" + "}" * depth
    prog.source = src
    return prog


def _resolved(path: str) -> str:
    try:
        from pathlib import Path
        return str(Path(path).resolve())
    except (OSError, ValueError):
        return path


def _name_span(sp: Span, name: str) -> Span:
    return Span(sp.file, sp.line, sp.col, sp.line, sp.col + len(name), sp.start,
                sp.start + len(name))


class Index:
    """Definitions, scopes and name uses of one parsed document."""

    MAX_IMPORT_DEPTH = 4

    def __init__(self, src: str, path: str = "doc.aidl", _seen: frozenset = frozenset()):
        self.src = src
        self.path = path
        self._seen = _seen | {_resolved(path)}
        self.program = parse_tolerant(src, path)
        self.scopes: list[Scope] = []
        self.file = self._scope(None, 0, len(src) + 1)
        self.uses: list[tuple[Span, A.Node]] = []      # (name span, Name or Member node)
        self._build()

    def _scope(self, parent, start, end, owner=None) -> Scope:
        s = Scope(parent, start, end, owner)
        self.scopes.append(s)
        return s

    def _define(self, scope: Scope, sym: Sym) -> None:
        if sym.origin is None:
            sym.origin = self
        scope.names.setdefault(sym.name, sym)

    def _import(self, st: A.Import) -> None:
        """Bind what ``import`` brings: the other file's templates, params and top-level
        constants (or, with ``as``, a namespace holding them)."""
        from ...library.sources import ImportRefused, load_import
        if len(self._seen) > self.MAX_IMPORT_DEPTH:
            return
        try:
            p, text = load_import(st.path, self.path)
        except ImportRefused:
            return
        if _resolved(str(p)) in self._seen:
            return
        other = Index(text, str(p), self._seen)
        if st.alias:
            self._define(self.file, Sym(st.alias, "import", st.span, st, scope=other.file))
            return
        for name, sym in other.file.names.items():
            if sym.kind in ("template", "function", "param", "variable"):
                self._define(self.file, sym)

    def _build(self) -> None:
        for st in self.program.stmts:
            if isinstance(st, A.ParamDecl):
                self._define(self.file, Sym(st.name, "param", st.name_span, st, value=st.value))
            elif isinstance(st, A.Def):
                sym = Sym(st.name, "template", st.name_span, st, detail=st.kind)
                self._define(self.file, sym)
                sym.scope = self._scope(self.file, st.span.start, st.span.end, sym)
                for p in st.params:
                    self._define(sym.scope, Sym(p.name, "parameter", _name_span(p.span, p.name),
                                                p, value=p.default))
            elif isinstance(st, A.Func):       # def f(x) = expr: its parameters are its own
                sym = Sym(st.name, "function", st.name_span, st, detail="= value")
                self._define(self.file, sym)
                sym.scope = self._scope(self.file, st.span.start, st.span.end, sym)
                for p in st.params:
                    self._define(sym.scope, Sym(p.name, "parameter", _name_span(p.span, p.name),
                                                p, value=p.default))
            elif isinstance(st, A.Import):
                self._import(st)
        for st in self.program.stmts:
            if isinstance(st, A.Func):
                continue
            if isinstance(st, A.Def):
                sym = self.file.names.get(st.name)
                if sym is not None and sym.node is st:
                    self._stmts(st.body.stmts, sym.scope, sym.scope)
            elif not isinstance(st, (A.ParamDecl, A.Import, A.UnitsDecl)):
                self._stmts([st], self.file, self.file)
        for n in A.walk(self.program):
            if isinstance(n, A.Name):
                self.uses.append((n.span, n))
            elif isinstance(n, A.Member):
                self.uses.append((n.name_span, n))
        self.uses.sort(key=lambda u: u[0].start)

    def _stmts(self, stmts, scope: Scope, target: Scope) -> None:
        """Bind names of ``stmts``: assignments go to ``target`` (the structure's scope),
        loop variables to a scope of their own; child structures get their own scopes."""
        for st in stmts:
            if isinstance(st, A.Assign):
                self._define(target, Sym(st.name, "variable", st.name_span, st, value=st.value))
                self._exprs(st.value, scope)
            elif isinstance(st, A.StructDecl):
                sym = Sym(st.name, "structure", st.name_span, st, detail=st.kind)
                self._define(target, sym)
                sym.scope = self._scope(scope, st.body.span.start, st.body.span.end, sym)
                self._stmts(st.body.stmts, sym.scope, sym.scope)
            elif isinstance(st, A.For):
                self._exprs(st.iter, scope)
                inner = self._scope(scope, st.body.span.start, st.body.span.end)
                self._define(inner, Sym(st.var, "loop", st.var_span, st))
                self._stmts(st.body.stmts, inner, target)
            elif isinstance(st, A.If):
                self._exprs(st.cond, scope)
                self._stmts(st.body.stmts, scope, target)
                if st.orelse is not None:
                    self._stmts(st.orelse.stmts, scope, target)
            elif isinstance(st, A.Block):
                self._stmts(st.stmts, scope, target)
            elif isinstance(st, A.ExprStmt):
                self._exprs(st.expr, scope)

    def _exprs(self, e, scope: Scope) -> None:
        made: dict = {}         # a comprehension's span -> its scope (each `for` of
        for n in A.walk(e):     # `[... for a in xs for b in ys]` is a ListComp of that span)
            if isinstance(n, A.ListComp):
                key = (n.span.start, n.span.end)
                if key not in made:
                    made[key] = self._scope(scope, n.span.start, n.span.end)
                self._define(made[key], Sym(n.var, "loop", n.var_span, n))

    # ------------------------------------------------------------ queries
    def scope_at(self, offset: int) -> Scope:
        best = self.file
        for s in self.scopes:
            if s.start <= offset <= s.end and (s.end - s.start) <= (best.end - best.start):
                best = s
        return best

    def enclosing_structure(self, offset: int) -> Sym | None:
        s = self.scope_at(offset)
        while s is not None:
            if s.owner is not None:
                return s.owner
            s = s.parent
        return None

    def use_at(self, offset: int):
        for sp, node in self.uses:
            if sp.start <= offset <= sp.end and sp.end > sp.start:
                return sp, node
        return None

    def resolve(self, node, offset: int | None = None) -> Sym | None:
        """The definition a Name / Member / Index expression refers to, if a user one."""
        if isinstance(node, A.Name):
            off = node.span.start if offset is None else offset
            if node.id == "self":
                return self.enclosing_structure(off)
            return self.scope_at(off).lookup(node.id)
        if isinstance(node, A.Member):
            base = self.resolve(node.obj, offset)
            sc = self.member_scope(base)
            return sc.names.get(node.name) if sc is not None else None
        if isinstance(node, A.Index):
            return self.resolve(node.obj, offset)
        return None

    def member_scope(self, sym: Sym | None) -> Scope | None:
        if sym is None:
            return None
        if sym.origin is not None and sym.origin is not self:
            return sym.origin.member_scope(sym)
        if sym.kind in ("structure", "template", "import"):
            return sym.scope
        if sym.kind == "variable" and isinstance(sym.value, A.Call):
            t = self.resolve(sym.value.func)
            if t is not None and t.kind == "template":
                return t.scope
        return None

    # type of an expression, for members: ("struct", Scope) | ("members", dict, label)
    def type_of_sym(self, sym: Sym | None, depth: int = 0):
        if sym is None or depth > 20:
            return None
        if sym.origin is not None and sym.origin is not self:
            return sym.origin.type_of_sym(sym, depth + 1)
        sc = self.member_scope(sym)
        if sc is not None:
            return ("struct", sc)
        if sym.kind == "variable" and sym.value is not None:
            return self.type_of_expr(sym.value, depth + 1)
        return None

    def type_of_expr(self, e, depth: int = 0):
        if depth > 20:
            return None
        if isinstance(e, A.Call) and isinstance(e.func, A.Name):
            entry = R.lookup(e.func.id)
            if entry is not None and entry.category == "primitive":
                return ("members", entry.members, entry.name)
            return self.type_of_sym(self.resolve(e.func), depth + 1)
        if isinstance(e, A.Name):
            return self.type_of_sym(self.resolve(e), depth + 1)
        if isinstance(e, A.Member):
            return member_type(self, self.type_of_expr(e.obj, depth + 1), e.name, depth + 1)
        if isinstance(e, A.Index):
            return self.type_of_expr(e.obj, depth + 1)
        return None

    def references(self, sym: Sym) -> list[Span]:
        out = []
        for sp, node in self.uses:
            if isinstance(node, A.Name) and node.id != sym.name:
                continue
            if isinstance(node, A.Member) and node.name != sym.name:
                continue
            if self.resolve(node) is sym:
                out.append(sp)
        return out


def member_type(ix: Index, t, name: str, depth: int = 0):
    if t is None:
        return None
    if t[0] == "struct":
        if name in t[1].names:
            return ix.type_of_sym(t[1].names[name], depth + 1)
        if name == "bb":
            return ("members", R.BBOX_MEMBERS, "bbox")
        return None
    typ = t[1].get(name)
    return ("members", TYPE_MEMBERS[typ], typ) if typ in TYPE_MEMBERS else None


def members_of(ix: Index, t) -> dict[str, str]:
    """member -> description, for a type from :meth:`Index.type_of_expr`."""
    if t is None:
        return {}
    if t[0] == "struct":
        out = {}
        for k, s in t[1].names.items():
            if s.kind in ("loop", "parameter") or (t[1].owner is not None and k == t[1].owner.name):
                continue
            out[k] = f"{s.detail} structure" if s.kind == "structure" else s.kind
        out.setdefault("bb", "bbox")
        return out
    return dict(t[1])


# ------------------------------------------------------------------ helpers
_WORD = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")
_CHAIN_BEFORE = re.compile(
    r"((?:[A-Za-z_]\w*)(?:\s*\[[^\[\]]*\])*(?:\.[A-Za-z_]\w*(?:\s*\[[^\[\]]*\])*)*)\.(\w*)$")


def _word_at(src: str, offset: int) -> tuple[str, int, int] | None:
    s = src.rfind("\n", 0, offset) + 1
    e = src.find("\n", offset)
    e = len(src) if e < 0 else e
    for m in _WORD.finditer(src, s, e):
        if m.start() <= offset <= m.end():
            return m.group(), m.start(), m.end()
    return None


def _parse_chain(text: str) -> list[str]:
    return re.findall(r"[A-Za-z_]\w*", re.sub(r"\[[^\[\]]*\]", "", text))


def _registry_doc(name: str) -> str | None:
    entry = R.lookup(name)
    if entry is not None:
        syn = f" (synonym of `{entry.name}`)" if name != entry.name else ""
        md = f"```aidl_cad\n{entry.signature()}\n```\n{entry.category}{syn}: {entry.doc}"
        canon = {a.name for v in entry.variants for a in v}
        alias = [f"`{k}`→`{next(c for c in cs if c in canon)}`"
                 for k, cs in R.arg_synonyms(entry.name).items()
                 if k not in canon and any(c in canon for c in cs)]
        if alias:
            md += "\n\nargument synonyms: " + ", ".join(alias)
        if entry.members:
            md += "\n\nmembers: " + ", ".join(f"`{k}` ({v})" for k, v in entry.members.items())
        return md
    if name in R.FUNCTIONS:
        lo, hi, doc = R.FUNCTIONS[name]
        return f"```aidl_cad\n{name}(...)\n```\nfunction ({lo if lo == hi else f'{lo}-{hi}'} " \
               f"argument{'s' if hi > 1 else ''}): {doc}"
    if name in R.CONSTANTS:
        return f"constant `{name}` ({R.CONSTANTS[name]})"
    if name in KEYWORD_DOCS:
        return f"keyword: {KEYWORD_DOCS[name]}"
    if name in KIND_DOCS:
        return f"structure kind: {KIND_DOCS[name]}"
    if name in R.UNITS_LENGTH:
        return f"length unit: 1 {name} = {R.UNITS_LENGTH[name]:g} mm"
    if name in R.UNITS_ANGLE:
        return f"angle unit `{name}`"
    return None


def _leading_comment(src: str, offset: int) -> str:
    lines = src[:offset].split("\n")[:-1]
    out = []
    for ln in reversed(lines):
        s = ln.strip()
        if s.startswith("#") or s.startswith("//"):
            out.append(s.lstrip("#/ ").rstrip())
        else:
            break
    return " ".join(reversed(out))


def _sym_doc(ix: Index, sym: Sym) -> str:
    if sym.origin is not None:
        ix = sym.origin
    src = ix.src
    if sym.kind == "template":
        d: A.Def = sym.node
        params = ", ".join(src[p.span.start:p.span.end] for p in d.params)
        doc = _leading_comment(src, d.span.start - (d.span.col - 1))
        return f"```aidl_cad\ndef {d.name}({params}) -> {d.kind}\n```\ntemplate" + (f": {doc}" if doc else "")
    if sym.kind == "function":
        f: A.Func = sym.node
        return f"```aidl_cad\n{src[f.span.start:f.span.end]}\n```\nfunction"
    if sym.kind == "structure":
        kids = [k for k, s in sym.scope.names.items() if s.kind == "structure" and k != sym.name]
        text = f"```aidl_cad\n{sym.detail} {sym.name}\n```\nstructure"
        if kids:
            text += "; children: " + ", ".join(f"`{k}`" for k in kids)
        return text
    first = src[sym.node.span.start:sym.node.span.end].split("\n")[0]
    if len(first) > 120:
        first = first[:117] + "..."
    if sym.kind == "import":
        return f"```aidl_cad\n{first}\n```\nimported namespace"
    label = {"param": "model parameter (`--set` overrides it)", "variable": "name",
             "loop": "loop variable", "parameter": "template parameter", "import": "import"}[sym.kind]
    text = f"```aidl_cad\n{first}\n```\n{label}"
    t = ix.type_of_sym(sym)
    if t is not None and t[0] == "members":
        text += f": a {t[2]}"
    return text


# ------------------------------------------------------------------ features
def hover(src: str, line: int, character: int, path: str = "doc.aidl") -> T.Hover | None:
    """Markdown hover for the word at the position, or None."""
    off = offset_at(src, line, character)
    w = _word_at(src, off)
    if w is None:
        return None
    word, ws, we = w
    ix = Index(src, path)
    rng = T.Range(start=position_at(src, ws), end=position_at(src, we))
    use = ix.use_at(off)
    md = None
    if use is not None:
        sym = ix.resolve(use[1])
        if sym is not None:
            md = _sym_doc(ix, sym)
        elif isinstance(use[1], A.Member):
            t = ix.type_of_expr(use[1].obj)
            if t is not None:
                if t[0] == "members" and word in t[1]:
                    md = f"```aidl_cad\n{word}: {t[1][word]}\n```\nmember of {t[2]}"
                elif t[0] == "struct" and word == "bb":
                    md = "```aidl_cad\nbb: bbox\n```\nthe structure's bounding box: " + \
                         ", ".join(R.BBOX_MEMBERS)
    if md is None:
        sym = ix.scope_at(off).lookup(word)
        if sym is not None and sym.span.start == ws:
            md = _sym_doc(ix, sym)
    if md is None:
        md = _registry_doc(word)
    if md is None:
        return None
    return T.Hover(contents=T.MarkupContent(kind=T.MarkupKind.Markdown, value=md), range=rng)


def value_hover(src: str, line: int, character: int, values: dict[str, str],
                path: str = "doc.aidl", limit: int = 8) -> str | None:
    """Markdown of the solved values (``values``: name -> text, from :func:`diagnostics`) of
    the entity named at the position: the dotted chain ending at the word (``shaft.boss``,
    ``boss.center``, a structure's name); values of the entity itself (a point, a size) or one
    level below it (a structure's ``origin`` and ``bbox``, a circle's ``center`` and
    ``radius``).  Names made in loops (``corner[2]``) match without their index; when several
    entities match, those inside the structure around the position come first.  None when
    nothing matches."""
    off = offset_at(src, line, character)
    ls = src.rfind("\n", 0, off) + 1
    le = src.find("\n", off)
    text = src[ls:len(src) if le < 0 else le]
    col = off - ls
    chain = None
    for m in re.finditer(r"[A-Za-z_]\w*(?:\s*\.\s*[A-Za-z_]\w*)*", text):
        if m.start() <= col <= m.end():
            words = [(w.start(), w.end(), w.group()) for w in re.finditer(r"[A-Za-z_]\w*", m.group())]
            chain = [w for a, b, w in words if a + m.start() <= col] or [words[0][2]]
            break
    if not chain:
        return None
    chain = [w for w in chain if w != "self"]
    if chain and chain[-1] == "bb":
        chain[-1] = "bbox"
    if not chain:
        return None
    key = ".".join(chain)

    def norm(n: str) -> str:
        return re.sub(r"\[\d+\]", "", n)

    def at(n: str, k: str) -> bool:
        return n == k or n.endswith("." + k)
    hits = [n for n in values if at(norm(n), key)]
    if not hits:
        hits = [n for n in values if "." in n and at(norm(n).rsplit(".", 1)[0], key)]
    if not hits:
        return None
    try:
        enc = Index(src, path).enclosing_structure(off)
    except Exception:
        enc = None
    if enc is not None:
        inside = [n for n in hits if f".{enc.name}." in "." + norm(n)]
        hits = inside or hits
    shown = [values[n] for n in hits[:limit]]
    more = f"\n... ({len(hits) - limit} more)" if len(hits) > limit else ""
    return "solved:\n```\n" + "\n".join(shown) + more + "\n```"


_SYM_KIND = {"param": T.CompletionItemKind.Constant, "template": T.CompletionItemKind.Function,
             "function": T.CompletionItemKind.Function,
             "structure": T.CompletionItemKind.Struct, "variable": T.CompletionItemKind.Variable,
             "loop": T.CompletionItemKind.Variable, "parameter": T.CompletionItemKind.Variable,
             "import": T.CompletionItemKind.Module}


def completions(src: str, line: int, character: int, path: str = "doc.aidl") -> list[T.CompletionItem]:
    """Completion items at the position (members after a dot, else everything in scope)."""
    off = offset_at(src, line, character)
    ls = src.rfind("\n", 0, off) + 1
    before = src[ls:off]
    ix = Index(src, path)
    m = _CHAIN_BEFORE.search(before)
    if m:
        chain = _parse_chain(m.group(1))
        head = chain[0]
        if head == "self":
            sym = ix.enclosing_structure(off)
            t = ("struct", sym.scope) if sym is not None else None
        else:
            sym = ix.scope_at(off).lookup(head)
            t = ix.type_of_sym(sym)
        for name in chain[1:]:
            t = member_type(ix, t, name)
        return [T.CompletionItem(label=k, kind=T.CompletionItemKind.Field, detail=v)
                for k, v in members_of(ix, t).items()]
    if re.search(r"^\s*units\s+\w*$", before):
        return [T.CompletionItem(label=u, kind=T.CompletionItemKind.Unit) for u in R.UNITS_LENGTH]
    items: list[T.CompletionItem] = []
    seen = set()

    def add(label, kind, detail=None, doc=None):
        if label in seen:
            return
        seen.add(label)
        items.append(T.CompletionItem(label=label, kind=kind, detail=detail,
                                      documentation=T.MarkupContent(kind=T.MarkupKind.Markdown,
                                                                    value=doc) if doc else None))

    for name, sym in ix.scope_at(off).visible().items():
        add(name, _SYM_KIND[sym.kind], sym.detail or sym.kind)
    if ix.enclosing_structure(off) is not None:
        add("self", T.CompletionItemKind.Keyword, "this structure")
    for name, e in R.ENTRIES.items():
        add(name, T.CompletionItemKind.Class if e.category == "primitive" else T.CompletionItemKind.Function,
            e.signature().split("\n")[0], e.doc)
    for syn, canon in R.SYNONYMS.items():
        add(syn, T.CompletionItemKind.Function, f"synonym of {canon}", R.ENTRIES[canon].doc)
    for name, (_, _, doc) in R.FUNCTIONS.items():
        add(name, T.CompletionItemKind.Function, "function", doc)
    for name, typ in R.CONSTANTS.items():
        add(name, T.CompletionItemKind.Constant, typ)
    for k in R.STRUCTURE_KINDS:
        add(k, T.CompletionItemKind.Keyword, "structure kind", KIND_DOCS.get(k))
    for k in R.KEYWORDS:
        add(k, T.CompletionItemKind.Keyword, "keyword", KEYWORD_DOCS.get(k))
    for u in list(R.UNITS_LENGTH) + list(R.UNITS_ANGLE):
        add(u, T.CompletionItemKind.Unit, "unit")
    return items


def _sym_at(ix: Index, off: int) -> Sym | None:
    use = ix.use_at(off)
    if use is not None:
        return ix.resolve(use[1])
    w = _word_at(ix.src, off)
    if w is None:
        return None
    sym = ix.scope_at(off).lookup(w[0])
    if sym is not None and sym.span.start == w[1]:
        return sym           # on the definition itself
    for s in ix.scopes:      # a definition whose name is outside the scope it opens
        for cand in s.names.values():
            if cand.span.start == w[1] and cand.name == w[0]:
                return cand
    return None


def definition(src: str, line: int, character: int, uri: str, path: str = "doc.aidl") -> T.Location | None:
    """Where the user name at the position is defined (same document), or None."""
    ix = Index(src, path)
    sym = _sym_at(ix, offset_at(src, line, character))
    if sym is None:
        return None
    if sym.origin is not None and sym.origin is not ix:       # defined in an imported file
        from pathlib import Path
        return T.Location(uri=Path(sym.origin.path).resolve().as_uri(),
                          range=span_range(sym.origin.src, sym.span))
    return T.Location(uri=uri, range=span_range(src, sym.span))


def references(src: str, line: int, character: int, uri: str, include_declaration: bool = True,
               path: str = "doc.aidl") -> list[T.Location]:
    """Every use of the user name at the position (and its definition)."""
    ix = Index(src, path)
    sym = _sym_at(ix, offset_at(src, line, character))
    if sym is None:
        return []
    own = sym.origin is None or sym.origin is ix
    spans = ([sym.span] if include_declaration and own else []) + ix.references(sym)
    return [T.Location(uri=uri, range=span_range(src, sp)) for sp in spans]


def document_symbols(src: str, path: str = "doc.aidl") -> list[T.DocumentSymbol]:
    """The file's outline: params, templates and the structure tree with its named geometry."""
    prog = parse_tolerant(src, path)

    def sym(name, detail, kind, node, name_span, children=None):
        return T.DocumentSymbol(name=name, detail=detail, kind=kind,
                                range=span_range(src, node.span),
                                selection_range=span_range(src, name_span), children=children or [])

    def body(stmts) -> list[T.DocumentSymbol]:
        out, seen = [], set()
        for st in stmts:
            if isinstance(st, A.StructDecl):
                out.append(sym(st.name, st.kind, T.SymbolKind.Struct, st, st.name_span,
                               body(st.body.stmts)))
            elif isinstance(st, A.Assign) and st.name not in seen:
                seen.add(st.name)
                what = st.value.func.id if isinstance(st.value, A.Call) and isinstance(st.value.func, A.Name) else ""
                out.append(sym(st.name, what, T.SymbolKind.Variable, st, st.name_span))
            elif isinstance(st, (A.For, A.If)):
                out.extend(body(st.body.stmts))
                if isinstance(st, A.If) and st.orelse is not None:
                    out.extend(body(st.orelse.stmts))
            elif isinstance(st, A.Block):
                out.extend(body(st.stmts))
        return out

    out = []
    for st in prog.stmts:
        if isinstance(st, A.ParamDecl):
            out.append(sym(st.name, "param", T.SymbolKind.Constant, st, st.name_span))
        elif isinstance(st, A.Def):
            out.append(sym(st.name, f"-> {st.kind}", T.SymbolKind.Function, st, st.name_span,
                           body(st.body.stmts)))
        elif isinstance(st, A.Func):
            out.append(sym(st.name, "= value", T.SymbolKind.Function, st, st.name_span))
    out.extend(body([s for s in prog.stmts if not isinstance(s, (A.ParamDecl, A.Def, A.Func))]))
    return out


def formatting(src: str, path: str = "doc.aidl", newline: str | None = None) -> list[T.TextEdit]:
    """One edit replacing the document with its ``aidl fmt`` layout (:func:`.fmt.format_file_text`:
    every line ending as the document's first, or ``newline``); none if it has errors or is
    already formatted.  The edit's end is the document's end as a client counts lines (CR LF,
    CR or LF), so applied it leaves exactly the formatted text."""
    from ..fmt import FormatError, format_file_text
    try:
        out = format_file_text(src, path, newline)
    except FormatError:
        return []
    if out == src:
        return []
    end = position_at(src, len(src))
    return [T.TextEdit(range=T.Range(start=T.Position(line=0, character=0), end=end), new_text=out)]
