"""The values a text param takes, for the page's list (issue 104: `fit` and `vent` were free-text
fields; typing `tight` showed the template's assertion, ``(1 if fine or medium or coarse else
0) == 1 ... 0 == 1 is false``).

A text param is enumerated when the program, or a standard-library template it is passed to
(``board_enclosure(vent=vent)``, and on through ``clearance_hole(fit=fit)``), compares it with
text literals: its choices are the ones an ``assert``'s message names (``"fit is \\"fine\\",
\\"medium\\" or \\"coarse\\""``: the synonyms ``close``, ``normal``, ``loose`` stay out of the
list), else every literal it is compared with (``vent == "slots"``).  Read from the program's
text and the standard library's files (no compile); a param compared with fewer than two
values stays a text field (a name tag's name).
"""
from __future__ import annotations

import functools
import re
from importlib import resources

_LIT = r'"((?:[^"\\\n]|\\.)*)"'
_PARAM = re.compile(r'^[ \t]*param[ \t]+([A-Za-z_]\w*)[ \t]*=[ \t]*' + _LIT, re.M)
_DEF = re.compile(r"^def[ \t]+([A-Za-z_]\w*)[ \t]*\(", re.M)
MAX_CHOICES = 24
DEPTH = 4                   # templates that pass the argument on (mounting_plate -> clearance_hole)


def _compared(text: str, name: str) -> list[str]:
    """The literals ``name`` is compared with in ``text`` (``name == "x"``, ``"x" == name``,
    ``!=`` too), in order, once each."""
    n = re.escape(name)
    found = re.findall(rf"(?<![\w.])(?:{n}[ \t]*[!=]=[ \t]*{_LIT}|{_LIT}[ \t]*[!=]=[ \t]*{n}(?![\w(]))",
                       text)
    return list(dict.fromkeys(a or b for a, b in found))


def _named(text: str, name: str) -> list[str] | None:
    """The literals an assert's message lists for ``name`` (``"fit is \\"fine\\", \\"medium\\"
    or \\"coarse\\""``), or None."""
    n = re.escape(name)
    for m in re.finditer(rf'assert\b[^\n]*,[ \t]*"{n} is ((?:[^"\\\n]|\\.)*)"', text):
        said = re.findall(r'\\"([^"\\]*)\\"', m.group(1))
        if len(said) >= 2:
            return said
    return None


def _passed(text: str, name: str) -> list[tuple[str, str]]:
    """``(function, argument)`` of each call in ``text`` that passes ``name`` as the keyword
    argument ``argument`` (``board_enclosure(..., vent=vent)``)."""
    out = []
    for m in re.finditer(rf"(?<![\w.=!<>])([A-Za-z_]\w*)[ \t]*=[ \t]*{re.escape(name)}(?![\w.(])", text):
        depth, i = 0, m.start() - 1
        while i >= 0:                       # back to the call's open parenthesis
            c = text[i]
            if c == ")":
                depth += 1
            elif c == "(":
                if depth == 0:
                    call = re.search(r"([A-Za-z_]\w*)[ \t]*$", text[:i])
                    if call:
                        out.append((call.group(1), m.group(1)))
                    break
                depth -= 1
            elif c in "{}":
                break
            i -= 1
    return out


@functools.lru_cache(maxsize=1)
def _library() -> dict[str, str]:
    """Each standard-library template's text (its ``def`` to the next): ``{name: text}``."""
    blocks: dict[str, str] = {}
    for f in sorted(resources.files("aidl_lang.stdlib").iterdir(), key=lambda f: f.name):
        if not f.name.endswith(".aidl"):
            continue
        text = f.read_text(encoding="utf-8")
        starts = list(_DEF.finditer(text))
        for k, m in enumerate(starts):
            end = starts[k + 1].start() if k + 1 < len(starts) else len(text)
            blocks.setdefault(m.group(1), text[m.start():end])
    return blocks


def _values(text: str, name: str, depth: int) -> list[str]:
    said = _named(text, name)
    if said:
        return said
    found = _compared(text, name)
    if depth <= 0:
        return found
    lib = _library()
    for func, arg in _passed(text, name):
        if func in lib:
            found += [v for v in _values(lib[func], arg, depth - 1) if v not in found]
    return found


@functools.lru_cache(maxsize=64)
def choices(source: str) -> dict[str, list[str]]:
    """``{param: [values]}`` for the program's text params that take one of a few values (see
    the module text), each list with the param's own default first when it is not among them."""
    out = {}
    for m in _PARAM.finditer(source):
        name, default = m.group(1), m.group(2)
        vals = _values(source, name, DEPTH)
        if len(vals) >= 2:
            if default not in vals:
                vals = [default] + vals
            out[name] = vals[:MAX_CHOICES]
    return out
