"""Signature help (``textDocument/signatureHelp``): inside a call, the forms of what is called
(a primitive's or constraint's variants from :mod:`aidl_lang.registry`, a user template's
``def`` line) with the argument under the cursor highlighted.

The call is found lexically (the innermost ``(`` that is still open before the cursor, comments
and strings skipped), so it works while the line being typed does not parse. The active
argument is the keyword being typed (``width=``) or, for positional arguments, the number of
commas before the cursor; the active form is the first one that has every keyword already
given.
"""
from __future__ import annotations

import re

from lsprotocol import types as T

from ... import registry as R
from ...parser import mask_comments
from .analysis import Index, offset_at

LOOKBACK = 4000            # characters searched backwards for the open parenthesis

_STR = re.compile(r"[fF]?(\"(\\.|[^\"\\\n])*\"|'(\\.|[^'\\\n])*')")


def _bare(text: str) -> str:
    """``text`` with comments and strings blanked (same length)."""
    text = mask_comments(text)
    text = _STR.sub(lambda m: " " * len(m.group()), text)
    text = re.sub(r"#[^\n]*", lambda m: " " * len(m.group()), text)
    return re.sub(r"/\*.*?(\*/|\Z)", lambda m: re.sub(r"[^\n]", " ", m.group()), text,
                  flags=re.DOTALL)


def open_call(src: str, off: int) -> tuple[str, int, list[str], str | None] | None:
    """``(callee, offset of "(", keywords given, keyword being typed)`` of the innermost call
    open at ``off``, with the positional index as ``int`` in place of the keyword when the
    cursor is on a positional argument; None outside calls."""
    start = max(0, off - LOOKBACK)
    text = _bare(src[start:off])
    depth = 0
    for i in range(len(text) - 1, -1, -1):
        ch = text[i]
        if ch in ")]}":
            depth += 1
        elif ch in "([{":
            if depth == 0:
                if ch == "{":
                    return None
                m = re.search(r"([A-Za-z_][\w.]*)\s*$", text[:i]) if ch == "(" else None
                if m is None:
                    continue                  # a list or a parenthesised expression
                args = _split_top(text[i + 1:])
                given = [a.split("=", 1)[0].strip() for a in args[:-1]
                         if re.match(r"\s*[A-Za-z_]\w*\s*=(?!=)", a)]
                cur = args[-1]
                km = re.match(r"\s*([A-Za-z_]\w*)\s*=(?!=)", cur)
                active = km.group(1) if km else len(args) - 1
                return m.group(1), start + i, given, active
            depth -= 1
    return None


def _split_top(text: str) -> list[str]:
    out, depth, cur = [], 0, []
    for ch in text:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        if ch == "," and depth == 0:
            out.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    out.append("".join(cur))
    return out


def _signature(name: str, params: list[tuple[str, str]], doc: str | None) -> T.SignatureInformation:
    """``params``: (label, name) pairs; the label is built here so offsets are exact."""
    label, infos = f"{name}(", []
    for i, (plabel, _) in enumerate(params):
        if i:
            label += ", "
        if plabel == "*":
            label += "*"
            continue
        infos.append(T.ParameterInformation(label=(len(label), len(label) + len(plabel))))
        label += plabel
    label += ")"
    return T.SignatureInformation(
        label=label, parameters=infos,
        documentation=T.MarkupContent(kind=T.MarkupKind.Markdown, value=doc) if doc else None)


def signature_help(src: str, line: int, character: int, path: str = "doc.aidl") -> T.SignatureHelp | None:
    """The forms of the call around the position, or None outside a call / for unknown names."""
    off = offset_at(src, line, character)
    call = open_call(src, off)
    if call is None:
        return None
    callee, _, given, active = call
    forms: list[tuple[list[tuple[str, str]], str | None]] = []
    short = callee.rsplit(".", 1)[-1]
    entry = R.lookup(short) if "." not in callee else None
    if entry is not None:
        for v in entry.variants:
            params = []
            for i, a in enumerate(v):
                if a.kw_only and (i == 0 or not v[i - 1].kw_only):
                    params.append(("*", ""))
                text = f"{a.name}: {a.type}" if a.required else f"{a.name}: {a.type} = {a.default_text}"
                params.append((text, a.name))
            if entry.varargs:            # Rigid(a, b, ...): the extras are gathered into b
                npos = sum(not a.kw_only for a in v)
                params.insert(npos, ("...", ""))
                if isinstance(active, int):
                    active = min(active, npos - 1)
            forms.append((params, entry.doc))
        title = entry.name
    elif short in R.FUNCTIONS and "." not in callee:
        lo, hi, doc = R.FUNCTIONS[short]
        forms.append(([(f"x{i + 1}", f"x{i + 1}") for i in range(max(hi, 1))], doc))
        title = short
    else:
        sym = _resolve_chain(Index(src, path), callee, off)
        if sym is not None and sym.kind in ("template", "function"):
            d = sym.node
            osrc = sym.origin.src if sym.origin is not None else src
            forms.append(([(osrc[p.span.start:p.span.end], p.name) for p in d.params],
                          f"template -> {d.kind}" if sym.kind == "template" else
                          "function = " + osrc[d.value.span.start:d.value.span.end]))
            title = d.name
        else:             # the document does not parse: read the `def` line itself
            m = re.search(rf"^\s*def\s+{re.escape(short)}\s*\(([^()]*)\)\s*->\s*(\w+)",
                          _bare(src), re.M)
            if m is None:
                return None
            params = [p.strip() for p in src[m.start(1):m.end(1)].split(",") if p.strip()]
            forms.append(([(p, p.split("=")[0].strip()) for p in params],
                          f"template -> {m.group(2)}"))
            title = short
    sigs, best = [_signature(title, params, doc) for params, doc in forms], 0
    for k, (params, _) in enumerate(forms):       # first form that has every keyword given
        names = [n for _, n in params if n]
        if all(g in names for g in given) and (not isinstance(active, str) or active in names):
            best = k
            break
    names = [n for _, n in forms[best][0] if n]
    if isinstance(active, str):
        act = names.index(active) if active in names else None
    else:
        act = active if active < len(names) else None
    return T.SignatureHelp(signatures=sigs, active_signature=best,
                           active_parameter=act if act is not None else len(names))


def _resolve_chain(ix: Index, chain: str, off: int):
    parts = chain.split(".")
    sym = ix.scope_at(off).lookup(parts[0])
    for p in parts[1:]:
        sc = ix.member_scope(sym)
        sym = sc.names.get(p) if sc is not None else None
    return sym
