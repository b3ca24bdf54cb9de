"""The compiler's messages worded for the form of ``aidl serve`` and the studio (issue 83).

The compiler names a param value the way the command line gives it (``--set width=40mm``); on
the page the value comes from the param's field and slider, and a form user has no ``--set``.
:func:`for_forms` rewrites each such phrase to name the field instead; the command line's, the
API's and the MCP tools' own text is left as it is (the MCP server words it for agents:
``aidl_lang/mcp/wording.py``).  The phrases are those the interpreter writes for a param value
(``aidl_lang/interpreter/statements.py``, ``aidl_lang/interp.py``: grep ``--set``).
"""
from __future__ import annotations

import re

# (pattern, replacement), applied in order: the specific phrases before the general ones
_PHRASES: list[tuple[re.Pattern, str]] = [(re.compile(p), r) for p, r in [
    # the example of a hint: "e.g. `--set w=40mm`"
    (r"e\.g\. `--set ([\w.]+)=([^`]*)`", r"e.g. `\2` in the field `\1`"),
    # a value not given: "`--set nosuch=...`: the model has no param `nosuch`"
    (r"`--set ([\w.]+)=\.\.\.`", r"the field `\1`"),
    # the value given: "`--set w=95mm`: 95 mm is outside the range ..."
    (r"`--set ([\w.]+)=([^`]*)`", r"the field `\1` = `\2`"),
    (r"`--set`", "the form"),
]]


def for_forms(text: str | None) -> str | None:
    """``text`` with the command line's ``--set NAME=VALUE`` named as the form's field
    ``NAME`` (see the module text); None stays None."""
    if not text:
        return text
    for pattern, replacement in _PHRASES:
        text = pattern.sub(replacement, text)
    return text
