"""The studio's wording: every text a visitor reads is written for the page (issue 94).

The compiler writes for the command line (``use a sheet of 847 x 214 mm or larger (--sheet
847x214mm)``, ``--rotate any``, ``see --dof``, ``--budget 2``) and for people who edit the
program (``write `AllowOverlap(NAME)` after it``, ``declare the param's `min=`/`max=```).  A
studio visitor has sliders, a sheet size and a Download button: :func:`for_page` says each
known phrase as what to change on the page, drops the advice that only a program's author can
follow (the remedies the page offers stay), and shows the names the messages quote
(```plate.h```) in quotation marks, not as code.  It first applies
:func:`aidl_lang.serve.wording.for_forms` (``--set w=40mm`` -> the field ``w``), as the MCP
server's :func:`aidl_lang.mcp.wording.for_agents` words the same phrases for agents.

:func:`page_answer` rewords the texts of a worker's answer (``message``, ``hint``, ``error``,
``text``, ``summary``, ``notes``, ``import_error``; never the SVG, the program or a rendered
source excerpt); an error's message and hint keep their code (the visitor is editing the
program: ``did you mean `divider_tray`? `divider_tray(length=...)```), its options reworded.  :func:`page_program` drops a gallery program's comment lines that are
command lines (``# aidl render tray.aidl --assembled -o tray.png``, ``# Try: --set bolts=5``).
"""
from __future__ import annotations

import re

from ..serve.wording import for_forms

# code: a backticked call, assignment or option (`AllowOverlap(a, b)`, `min=`, `NAME = `), a
# construct's name (`Place`, `Drawing2D`) or a command (`aidl ...`); a quoted name of the
# visitor's design (`plate.h`) is no code
_CODE = re.compile(r"[^`]*[(=][^`]*|[A-Z]\w*|aidl .*|(?:min_wall|thickness|kerf|units) .*")
_QUOTED = re.compile(r"`([^`\n]*)`")


def _has_code(text: str) -> bool:
    return any(_CODE.fullmatch(m.group(1)) for m in _QUOTED.finditer(text))
# advice in words that only a program's author can follow
_AUTHOR_ONLY = [re.compile(p) for p in [
    r",? derive the spacing from the param so that the design follows it",
    # a hole cut by its own solid only: where it is declared is the program's
    r"declare the hole in `[^`]*`, the common parent, so that it cuts everything united "
    r"there, or (?=move)",
    r",? or declare it in the solid it should cut",
    r",? or, if they are separate parts, make the structure an `assembly`",
    # an example in code, in parentheses: "move the hole inside `p` (for example `X(a, b)`)"
    r"\s*\((?:for example|e\.g\.) `[^`]*`[^()]*\)",
]]


def _outside_quotes(text: str, sep: str) -> list[str]:
    """``text`` split at each ``sep`` that is neither between backticks nor in parentheses."""
    out, start, inside, depth, i = [], 0, False, 0, 0
    while i < len(text):
        if text[i] == "`":
            inside = not inside
        elif not inside and text[i] in "()":
            depth = max(0, depth + (1 if text[i] == "(" else -1))
        elif not inside and depth == 0 and text.startswith(sep, i):
            out.append(text[start:i])
            start = i + len(sep)
            i = start
            continue
        i += 1
    return out + [text[start:]]


def _plain(clause: str) -> str:
    """One ``; ``-separated clause without its code advice: a conditional clause (``if ... is
    meant, write `X(...)```) goes whole; else its ``, ``-separated parts that hold code."""
    if not _has_code(clause):
        return clause
    if re.match(r"\s*(?:if|else|or|write|add|declare|name)\b", clause):
        return ""
    parts = [q for q in _outside_quotes(clause, ", ") if not _has_code(q)]
    if parts and re.match(r"\s*or\b", parts[0]):
        return ""
    return ", ".join(parts)


# (pattern, replacement), in order: the command line's options said as what the page offers
_PHRASES: list[tuple[re.Pattern, str]] = [(re.compile(p), r) for p, r in [
    # the cutting layout (output/fabrication/layout.py _too_big)
    (r"or larger \(--sheet \d+x\d+mm\)", "or larger (set the sheet size)"),
    (r", or a smaller --gap", ""),              # the page has no gap, and no rotation:
    (r", or --rotate any", ""),                 # the sheet size is what it can change
    (r"--rotate any", "another sheet size"),
    (r"`?aidl render --layout sheet`?", "“Nest the parts on sheets”"),
    (r"`?--layout sheet`?", "“Nest the parts on sheets”"),
    # the solver's freedom summary
    (r"(?:,\s*|\s|^)see --dof", ""),
    # the evaluation budget: a visitor cannot raise it
    (r"build less or raise the budget \(`--budget \d+`\)", "build less"),
    (r",? ?(?:or )?raise (?:the budget|every figure) with `--budget \d+`(?: \(or more\))?",
     ""),
    (r",? ?(?:or )?raise the budget \(`--budget \d+`\)", ""),
    (r",? ?(?:or )?raise `--budget`(?: \(`--budget \d+`\))?", ""),
    (r"`--budget \d+` \(or more\) gives every check [^.;]*", "a smaller design"),
    (r";? ?--budget K gives K times more", ""),
    (r"\(?`?--budget( K| \d+)?`?\)?", ""),
    # the minimum wall
    (r"set by `min_wall` or --min-wall", "set by the program's minimum wall"),
    (r"; the minimum is set with --min-wall", ""),
    (r",? ?(?:or )?set a smaller minimum with --min-wall", ""),
    # the reference
    (r"\(?see `aidl explain ([^`]+)`\)?", ""),
    (r"\(?`aidl docs ([^`]+)`\)?", r"the reference of \1"),
    # the G-code format's note (a download button's tooltip, issue 104)
    (r"\(--machine\)", "(the Machine field)"),
    # any other option left: never a flag on the page
    (r"\s?\(?--[a-z][\w-]*(?:[ =][\w.,x]+)?\)?", ""),
    (r"\s?``", ""),                              # (a quoted flag, now gone)
]]

# a space left before punctuation by a phrase taken out ("the sheet , or" -> "the sheet, or");
# a dot that starts a word is no punctuation (".dxf", ".5 mm": "is not a .dxf or .svg drawing")
_TIGHT = re.compile(r"\s+([,;:)]|\.(?![.\w]))")


# numbers as a visitor reads them (issue 104), outside code quotes (what was typed stays as
# typed): a unit after a space ("with d = 60 mm", not "with d=60mm"), no trailing zeros ("0.5 mm
# wide, thinner than 0.5 mm", not "0.50 mm")
_NUMBERS = [(re.compile(p), r) for p, r in [
    (r"(?<![\w.])([A-Za-z_][\w.]*)=(-?\d+(?:\.\d+)?) ?(mm|deg|cm|in)\b", r"\1 = \2 \3"),
    (r"(?<![\w.])(-?\d+)\.0+(?= ?(?:mm|deg|cm|in)\b)", r"\1"),
    (r"(?<![\w.])(-?\d+\.\d*?[1-9])0+(?= ?(?:mm|deg|cm|in)\b)", r"\1"),
    (r"(?<=\d)(mm|deg)\b", r" \1"),
]]


def _numbers(text: str) -> str:
    """``text`` with :data:`_NUMBERS` applied outside backticks."""
    parts = text.split("`")
    for i in range(0, len(parts), 2):           # the even parts: outside the quotes
        for p, r in _NUMBERS:
            parts[i] = p.sub(r, parts[i])
    return "`".join(parts)


def for_page(text: str | None, code: bool = False) -> str | None:
    """``text`` written for the studio's page (see the module text); None stays None.
    ``code``: the text of an error in the program the visitor is editing (an unknown name, a
    call's arguments): only the command line's options are reworded, its code stays."""
    if not text:
        return text
    text = for_forms(text)
    for p, r in _PHRASES:
        text = p.sub(r, text)
    text = _numbers(text)
    if code:
        return _TIGHT.sub(r"\1", re.sub(r" {2,}", " ", text)).strip(" ;,")
    for p in _AUTHOR_ONLY:
        text = p.sub("", text)
    clauses = [_plain(c) for c in _outside_quotes(text, "; ")]
    text = "; ".join(re.sub(r"^\s*else\s+", "", c) for c in clauses if c.strip())
    text = _QUOTED.sub(lambda m: f"“{m.group(1)}”", text)
    text = re.sub(r" {2,}", " ", text)
    return _TIGHT.sub(r"\1", text).strip(" ;,")


# the answer's keys whose strings a visitor reads
_TEXTS = frozenset(("message", "hint", "error", "text", "summary", "notes", "import_error",
                    "problem", "combinations"))
# never reworded: pictures, programs, source excerpts
_KEEP = frozenset(("svg", "source", "program", "code", "rendered", "values", "clamped",
                   "dropped", "span"))


# a fault of the compiler (E0900) as a visitor reads it: no Python name, no "save" (issue 113:
# "internal error ... RecursionError ... the next save is compiled again" in the studio)
FAULT = ("the studio met a fault of its own while making this design (not a mistake in it); "
         "it is logged for the studio's operator")
FAULT_HINT = "change a value or the program and it is made again"
# an assertion's own words: `assertion failed: `COND` (REASON): FOUND` -> REASON (issue 113:
# a template's condition and its values were shown: "`(1 if fine or medium or coarse else 0)
# == 1` ... 0 == 1 is false")
_ASSERTION = re.compile(r"assertion failed: `[^`]*` \((?P<why>.+?)\): .*$", re.S)


def _reasoned(d: dict) -> dict:
    """A diagnostic ``d`` whose assertion states its reason said by that reason alone, and a
    fault of the compiler said as :data:`FAULT`."""
    if d.get("code") == "E0900":
        return {**d, "message": FAULT, "hint": FAULT_HINT, "rendered": f"{FAULT}; {FAULT_HINT}"}
    msg = d.get("message")
    m = _ASSERTION.search(msg) if isinstance(msg, str) else None
    if m is None:
        return d
    # a template's argument is not the visitor's to name (the span says where it is)
    lead = re.sub(r"^argument `[^`]*` of `[^`]*`: $", "", msg[:m.start()])
    return {**d, "message": lead + m.group("why"), "hint": "choose a value for which this holds"}


def page_answer(obj, key: str | None = None):
    """``obj`` (a worker's JSON-ready answer) with the texts a visitor reads reworded by
    :func:`for_page`; bytes, numbers, pictures and programs as they are."""
    if isinstance(obj, dict) and isinstance(obj.get("code"), str) and "message" in obj:
        obj = _reasoned(obj)
    if isinstance(obj, dict):
        if obj.get("severity") == "error" and "message" in obj:     # a diagnostic of the code
            return {k: for_page(v, code=True) if k in ("message", "hint") and isinstance(v, str)
                    else v if k in _KEEP else page_answer(v, k) for k, v in obj.items()}
        return {k: v if k in _KEEP else page_answer(v, k) for k, v in obj.items()}
    if isinstance(obj, list):
        return [page_answer(x, key) for x in obj]
    if isinstance(obj, str) and key in _TEXTS:
        return for_page(obj)
    return obj


_COMMAND_COMMENT = re.compile(r"^\s*#\s*(?:aidl\s|Try:|\$ aidl|python\s).*$|^\s*#.*\s--[a-z][\w-]*.*$")


# a command line inside a comment's sentence, said as what the page has (a line break and its
# `#` may fall inside the phrase: `aidl render\n# --assembled`)
_NL = r"\s*(?:\n#\s*)?"
_COMMENT_PHRASES = [(re.compile(p), r) for p, r in [
    (rf"\(`aidl{_NL}render{_NL}--assembled`\)", "(the Assembled view)"),
    (rf"`aidl{_NL}parts`{_NL}lists them", "the cutting sheet lists them"),
    (rf"`--kerf{_NL}([\d.]+) ?mm`", r"a kerf of \1 mm (Material and machine)"),
]]


def page_program(source: str) -> str:
    """``source`` without its comment lines that are command lines (``#   aidl render
    x.aidl -o x.png``, ``# Try: --set bolts=5``), and a command line in a comment's sentence
    said as what the page has (``(`aidl render --assembled`)``: the Assembled view): the
    studio's visitor has sliders."""
    for p, r in _COMMENT_PHRASES:
        source = p.sub(r, source)
    lines = source.splitlines(keepends=True)
    kept = [ln for ln in lines if not _COMMAND_COMMENT.match(ln)]
    return "".join(kept)
