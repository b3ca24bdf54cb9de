"""Semantic tokens (``textDocument/semanticTokens/full``): highlighting from the analysis, so
that an LSP client colours AIDL without a grammar (Neovim's built-in client, Helix, ...).

Every word is classified by what it *is* in the document, not by how it looks: a name is looked
up in :class:`~aidl_lang.editor.lsp.analysis.Index` (structure, template, param, variable, loop
variable, template parameter, imported namespace), a member after a dot is a property, a
keyword argument's name a parameter, and only names that are not the user's fall back to the
registry (primitives, constraints, functions, constants). Comments, strings and numbers are
tokens too; a unit after a number (``10 mm``, ``30 deg``) or after ``units`` is a keyword with
the ``unit`` modifier (TextMate: ``keyword.other.unit``).

The legend uses the standard LSP token types and modifiers (so every client has colours for
them) plus one custom modifier, ``unit``:

================== ==========================================================
token type          what
================== ==========================================================
``struct``          structure names (``solid plate``, ``plate.bore``)
``function``        templates (``def``) and built-in functions (``defaultLibrary``)
``class``           primitives (``Rectangle``, ``Circle``; ``defaultLibrary``)
``macro``           constraints (``Coincident``, ``CenterInside``; ``defaultLibrary``)
``parameter``       template parameters and keyword-argument names
``variable``        geometry and other names; ``param`` (``readonly``); constants
``property``        members after a dot (``rect.top_left``, ``bb.width``)
``namespace``       ``import ... as NAME``
``keyword``         keywords, structure kinds, ``self``; units (``unit`` modifier)
``comment``, ``string``, ``number``
================== ==========================================================

Tokens never span lines (a ``/* */`` comment gives one token per line); positions are UTF-16.
"""
from __future__ import annotations

import bisect
import re

from ... import ast as A
from ... import registry as R
from ...parser import mask_comments
from .analysis import Index

TOKEN_TYPES = ["namespace", "struct", "class", "function", "macro", "parameter", "variable",
               "property", "keyword", "comment", "string", "number"]
TOKEN_MODIFIERS = ["declaration", "readonly", "defaultLibrary", "unit"]
_TYPE = {t: i for i, t in enumerate(TOKEN_TYPES)}
_MOD = {m: 1 << i for i, m in enumerate(TOKEN_MODIFIERS)}

_SYM_TOKEN = {"param": ("variable", ("readonly",)), "template": ("function", ()),
              "function": ("function", ()),
              "structure": ("struct", ()), "variable": ("variable", ()),
              "loop": ("variable", ()), "parameter": ("parameter", ()),
              "import": ("namespace", ())}
_UNITS = set(R.UNITS_LENGTH) | set(R.UNITS_ANGLE)
_KEYWORDS = set(R.KEYWORDS) | set(R.STRUCTURE_KINDS) | {"self", "none"}

_LEX = re.compile(r"""
    (?P<block>/\*.*?(?:\*/|\Z))
  | (?P<line>\#[^\n]*)
  | (?P<str>[fF]?(?:"(?:\\.|[^"\\\n])*"?|'(?:\\.|[^'\\\n])*'?))
  | (?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)
  | (?P<deg>°)
  | (?P<id>[A-Za-z_]\w*)
""", re.VERBOSE | re.DOTALL)


def _registry_token(word: str):
    entry = R.lookup(word)
    if entry is not None:
        if entry.category == "primitive":
            return "class", ("defaultLibrary",)
        return "macro", ("defaultLibrary",)
    if word in R.FUNCTIONS:
        return "function", ("defaultLibrary",)
    if word in R.CONSTANTS:
        return "variable", ("readonly", "defaultLibrary")
    if word in _KEYWORDS:
        return "keyword", ()
    return None


def classify(src: str, path: str = "doc.aidl", ix: Index | None = None,
             lexical: bool = False) -> list[tuple[int, int, str, tuple]]:
    """``(start offset, end offset, token type, modifiers)`` for every token of ``src``, in order
    (offsets into ``src``; a token may span lines here, :func:`semantic_tokens` splits it).
    ``lexical=True`` skips name resolution (large documents): user names are left out."""
    at: dict[int, tuple[str, tuple]] = {}
    if not lexical:
        _resolve_names(src, path, ix if ix is not None else Index(src, path), at)
    return _lex(src, at)


def _resolve_names(src: str, path: str, ix: Index, at: dict) -> None:
    for s in ix.scopes:                           # definitions
        for sym in s.names.values():
            if sym.origin is ix and sym.span.file == path:
                kind, mods = _SYM_TOKEN[sym.kind]
                at[sym.span.start] = (kind, mods + ("declaration",))
    for n in A.walk(ix.program):                  # keyword-argument names
        if isinstance(n, A.Keyword) and src.startswith(n.name, n.span.start):
            at.setdefault(n.span.start, ("parameter", ()))
        elif isinstance(n, A.Def):
            for p in n.params:
                at.setdefault(p.span.start, ("parameter", ("declaration",)))
    for sp, node in ix.uses:                      # uses: resolved through the scopes
        if sp.start in at:
            continue
        sym = ix.resolve(node)
        if sym is not None:
            at[sp.start] = _SYM_TOKEN[sym.kind]
        elif isinstance(node, A.Member):
            at[sp.start] = ("property", ())


def _lex(src: str, at: dict) -> list[tuple[int, int, str, tuple]]:
    out = []
    bare = mask_comments(src)
    prev, prev_end = None, 0                      # the previous token's kind / word, end
    for m in _LEX.finditer(bare):
        kind = m.lastgroup
        a, b = m.start(), m.end()
        gap = bare[prev_end:a]
        if gap.strip() or "\n" in gap:
            prev = None                           # punctuation or a line break in between
        prev_end = b
        if kind in ("block", "line"):
            out.append((a, b, "comment", ()))
            continue
        if kind == "str":
            out.append((a, b, "string", ()))
            prev = "str"
            continue
        if kind == "num":
            out.append((a, b, "number", ()))
            prev = "num"
            continue
        if kind == "deg":
            out.append((a, b, "keyword", ("unit",)))
            prev = None
            continue
        word = m.group()
        if word in _UNITS and prev in ("num", "units"):
            tok = ("keyword", ("unit",))
        elif a in at:
            tok = at[a]
        elif word == "self":
            tok = ("keyword", ())
        elif bare[max(0, a - 1):a] == "." and not bare[max(0, a - 2):a - 1].isdigit():
            tok = ("property", ())
        else:
            tok = _registry_token(word)
        if tok is not None:
            out.append((a, b, tok[0], tuple(tok[1])))
        prev = "units" if word == "units" else word
    return out


def semantic_tokens(src: str, path: str = "doc.aidl", ix: Index | None = None,
                    lexical: bool = False) -> list[int]:
    """The LSP ``data`` array (5 integers per token: delta line, delta start, length, type,
    modifier bits), relative encoding, UTF-16 columns, one token per line."""
    starts = [0] + [m.end() for m in re.finditer("\n", src)]
    data: list[int] = []
    last_line = last_col = 0

    def u16(a: int, b: int) -> int:
        seg = src[a:b]
        return len(seg) if seg.isascii() else len(seg.encode("utf-16-le")) // 2

    for a, b, typ, mods in classify(src, path, ix, lexical):
        bits = 0
        for mname in mods:
            bits |= _MOD[mname]
        while a < b:
            line = bisect.bisect_right(starts, a) - 1
            eol = src.find("\n", a)
            e = b if eol < 0 or eol >= b else eol
            if e > a:
                col = u16(starts[line], a)
                length = u16(a, e)
                dl = line - last_line
                dc = col - last_col if dl == 0 else col
                data += [dl, dc, length, _TYPE[typ], bits]
                last_line, last_col = line, col
            a = e + 1 if e < b else b
    return data


def decode(src: str, data: list[int]) -> list[tuple[int, int, str, str, list[str]]]:
    """The tokens of a ``data`` array as ``(line, character, text, type, modifiers)`` (for
    tests and debugging; ``character`` in UTF-16 units, as sent)."""
    lines = src.split("\n")
    out, line, col = [], 0, 0
    for i in range(0, len(data), 5):
        dl, dc, n, t, bits = data[i:i + 5]
        line += dl
        col = col + dc if dl == 0 else dc
        mods = [m for m, bit in _MOD.items() if bits & bit]
        u16 = lines[line].encode("utf-16-le")
        text = u16[2 * col:2 * (col + n)].decode("utf-16-le")
        out.append((line, col, text, TOKEN_TYPES[t], mods))
    return out
