"""The text of a param's new value as ``aidl set`` and MCP ``set_params`` write it into the
file (:func:`aidl_lang.api.set_params`): a value that holds a comment is refused, located at
the value it would replace (issue 92: ``aidl set x.aidl 'w=40 mm # x'`` wrote the comment,
which hid the param's ``min=``/``max=``, and ``w=500 mm`` was then accepted)."""
from __future__ import annotations

from ..base.diagnostics import Diagnostic


def comment_at(text: str) -> int:
    """Where a comment (``#``, ``/*``) starts in the value text ``text``, outside its string
    literals; -1 when it has none."""
    quote = False
    for i, ch in enumerate(text):
        if ch == '"' and (i == 0 or text[i - 1] != "\\"):
            quote = not quote
        elif not quote and (ch == "#" or text.startswith("/*", i)):
            return i
    return -1


def comment_problem(source: str, decl, text: str) -> Diagnostic | None:
    """The located ``E0113`` (at the param's value in ``source``) when the new value ``text``
    of the declaration ``decl`` holds a comment: written in place of the value it would
    comment out the rest of the line, the param's range with it; None when it holds none."""
    i = comment_at(text)
    if i < 0:
        return None
    s = decl.value.span
    rest = source[s.end:].split("\n", 1)[0].strip()
    lost = f" (`{rest}` and its range with it)" if rest.startswith(",") else ""
    alone = text[:i].strip()
    msg = (f"the value `{text}` for `{decl.name}` holds a comment (`{text[i:].strip()}`): "
           f"written in place of `{source[s.start:s.end]}` it would comment out the rest of "
           f"the line{lost}")
    return Diagnostic("E0113", msg, s, "error",
                      hint=(f"give the value alone: `{decl.name}={alone}`" if alone else
                            "give the value alone, without a comment"))
