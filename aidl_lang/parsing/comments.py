"""Comments before the parse: ``//`` read as a comment or as floor division (:func:`mask_comments`,
the rule of docs/language.md "Comments"), and the bracket and string patterns the recovery
shares.  Imports nothing of the package."""
from __future__ import annotations

import re

def mask_comments(src: str, record: list | None = None) -> str:
    """Turn ``//`` comments into ``# `` comments (same length, so spans stay valid).

    The rule (docs/language.md, "Comments"): ``//`` is floor division when the code before it
    ends an operand (a name, number, ``)``, ``]``) on the same line -- or on an earlier line
    inside open ``(``/``[`` -- and the rest of the line does not read as prose (two words side
    by side that are not keywords, or characters no expression uses).  Otherwise it starts a
    comment: ``// note`` on its own line, ``x = 5  // half the width``.  So code that parses
    as an expression is never swallowed.  ``record`` (if given) receives ``(offset, is_comment)``
    for every ``//`` seen, for the syntax-error hints.
    """
    if "//" not in src:                         # nothing to decide (and nothing to record)
        return src
    out = list(src)
    i, n = 0, len(src)
    quote = None
    line_start = True
    depth = 0
    prev = ""                # the last code character (outside strings and comments)
    while i < n:
        ch = src[i]
        if quote:
            if ch == "\\":
                i += 2
                continue
            if ch == quote or ch == "\n":
                quote = None
                prev = "a"   # a string ends an operand
            i += 1
            continue
        if ch not in _SPECIAL:                  # a run of ordinary characters at once
            m = _PLAIN.match(src, i)
            seg = m.group()
            if not seg.isspace():
                line_start = False
                prev = seg.rstrip()[-1]
                for b in _BRACKETS.findall(seg):
                    if b in "([":
                        depth += 1
                    elif depth:
                        depth -= 1
            i = m.end()
            continue
        if ch in "\"'":
            quote = ch
            line_start = False
        elif ch == "#":
            j = src.find("\n", i)
            i = n if j < 0 else j
            continue
        elif ch == "/" and src.startswith("/*", i):
            j = src.find("*/", i + 2)
            i = n if j < 0 else j + 2
            continue
        elif ch == "/" and src.startswith("//", i):
            j = src.find("\n", i)
            rest = src[i + 2: (n if j < 0 else j)]
            operand_before = prev.isalnum() or prev in "_)]°"
            division = operand_before and (not line_start or depth > 0) and not _is_prose(rest)
            if record is not None:
                record.append((i, not division))
            if not division:
                out[i], out[i + 1] = "#", " "
                i = n if j < 0 else j
                continue
            prev = "/"
            line_start = False
            i += 2
            continue
        elif ch == "\n":
            line_start = True
        elif not ch.isspace():
            line_start = False
            prev = ch
            if ch in "([":
                depth += 1
            elif ch in ")]" and depth:
                depth -= 1
        i += 1
    return "".join(out)


_SPECIAL = frozenset("\"'#/\n")
_PLAIN = re.compile(r"[^\"'#/\n]+")
_BRACKETS = re.compile(r"[()\[\]]")
_ANY_BRACKET = re.compile(r"[()\[\]{}]")
_BRACKET_STEP = {"(": 1, "[": 1, "{": 1, ")": -1, "]": -1, "}": -1}
_KW = {"if", "else", "and", "or", "not", "for", "in"}
_STRINGS = re.compile(r"[fF]?(\"(\\.|[^\"\\\n])*\"?|'(\\.|[^'\\\n])*'?)")


def _is_prose(rest: str) -> bool:
    """After ``//``: prose (two words side by side, not keywords, or characters no
    expression uses), so a comment.  Strings in the rest are not looked into."""
    code = _STRINGS.sub('""', rest).split("#", 1)[0].split("//", 1)[0]
    if not code.strip():
        return True
    for m in re.finditer(r"(?<![\w.])([A-Za-z_]\w*)[ \t]+(?=([A-Za-z_]\w*))", code):
        if m.group(1) not in _KW and m.group(2) not in _KW:
            return True
    return bool(re.search(r"[^\w\s.()\[\]{}+\-*/%,<>=!:;\"'°]", code))
