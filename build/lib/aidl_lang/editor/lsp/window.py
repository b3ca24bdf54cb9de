"""Large documents: what the interactive requests analyse when the whole file would take too long.

Parsing and indexing cost about 20 ms per kilobyte, so on a 10 MB document a completion that
re-analysed everything would take minutes. Above :data:`LARGE` characters the position-based
requests (hover, completion, signature help, definition, references) analyse a *view* of the
document instead: the top-level statement around the cursor (at most :data:`MAX_BLOCK` lines of
it) and the top-level declarations (``units``, ``import``, ``param``, ``def`` lines and the last
:data:`MAX_NAMES` one-line top-level assignments before the cursor); every other line is
emptied, so line and column numbers are those of the document. Above :data:`LARGE` the outline
comes from a regular expression (the first :data:`MAX_OUTLINE` top-level declarations), semantic tokens are lexical only
(no name resolution) and above :data:`HUGE` none are sent (the TextMate grammar still colours
VS Code); rename and formatting are refused with a message.
"""
from __future__ import annotations

import re

from lsprotocol import types as T

LARGE = 50_000            # characters: above this, requests analyse a view
HUGE = 1_000_000          # characters: above this, no semantic tokens
MAX_BLOCK = 2_000         # lines of the enclosing top-level statement kept
MAX_NAMES = 500           # one-line top-level assignments kept
MAX_OUTLINE = 5_000       # symbols in the outline of a large document

_BARE = re.compile(r"""#.*|//.*|"(?:\\.|[^"\\])*"|'(?:\\.|[^'\\])*'""")
_DECL = re.compile(r"\s*(units|import|param|def)\b")
_ASSIGN = re.compile(r"[A-Za-z_]\w*\s*=(?!=)")


def _depths(lines: list[str]) -> list[int]:
    """Brace depth at the start of each line (comments and strings ignored)."""
    out, d = [], 0
    for ln in lines:
        out.append(d)
        if "{" in ln or "}" in ln:
            bare = _BARE.sub("", ln)
            d = max(0, d + bare.count("{") - bare.count("}"))
    return out


def view(src: str, line: int) -> str:
    """``src`` itself if it is small, else the view described in the module doc for a request
    at ``line`` (0-based): same number of lines, the kept ones verbatim."""
    if len(src) <= LARGE:
        return src
    lines = src.split("\n")
    line = max(0, min(line, len(lines) - 1))
    depth = _depths(lines)
    keep = [False] * len(lines)
    b0 = line
    while b0 > 0 and depth[b0] > 0:
        b0 -= 1
    b1 = line + 1
    while b1 < len(lines) and depth[b1] > 0:
        b1 += 1
    for i in range(max(b0, line - MAX_BLOCK), min(b1, line + MAX_BLOCK)):
        keep[i] = True
    keep[b0] = True
    names = 0
    for i in range(len(lines) - 1, -1, -1):
        if depth[i] != 0 or keep[i]:
            continue
        nxt = depth[i + 1] if i + 1 < len(lines) else 0
        ln = lines[i]
        if _DECL.match(ln):
            keep[i] = True
            if nxt > 0:                   # a def: keep its header, close it
                lines[i] = ln + " }" if ln.rstrip().endswith("{") else ln
        elif nxt == 0 and i < line and names < MAX_NAMES and _ASSIGN.match(ln):
            keep[i] = True
            names += 1
    return "\n".join(ln if k else "" for ln, k in zip(lines, keep))


_TOP = re.compile(r"^(param|def|solid|hole|drawing|assembly)\s+([A-Za-z_]\w*)|^([A-Za-z_]\w*)\s*=(?!=)",
                  re.M)


def outline(src: str) -> list[T.DocumentSymbol]:
    """Top-level declarations found by a regular expression (for large documents), the first
    :data:`MAX_OUTLINE` of them."""
    out, seen = [], set()
    line, last = 0, 0
    for m in _TOP.finditer(src):
        if len(out) >= MAX_OUTLINE:
            break
        kw, name = (m.group(1), m.group(2)) if m.group(1) else ("", m.group(3))
        if name in seen:
            continue
        seen.add(name)
        line += src.count("\n", last, m.start())
        last = m.start()
        col = (m.start(2) if m.group(1) else m.start(3)) - m.start()
        rng = T.Range(start=T.Position(line=line, character=col),
                      end=T.Position(line=line, character=col + len(name)))
        kind = {"param": T.SymbolKind.Constant, "def": T.SymbolKind.Function,
                "": T.SymbolKind.Variable}.get(kw, T.SymbolKind.Struct)
        out.append(T.DocumentSymbol(name=name, kind=kind, detail=kw, range=rng,
                                    selection_range=rng))
    return out
