"""What the checker's and the interpreter's argument errors add for a name a model guesses
(E0105: an argument the entry does not have, :data:`ARG_NOTES`) or an argument given with
another form's (E0104, :data:`FORM_NOTES`): the words of those hints, by ``(entry, argument)``.
Data only, read by :mod:`aidl_lang.typecheck` and :mod:`aidl_lang.interpreter.calls`."""
from __future__ import annotations

# argument names a model guesses for something the language does not have: the E0105 hint
# says so instead of a did-you-mean on the spelling (`font` is not `on`); issue 61
ARG_NOTES: dict[tuple[str, str], str] = {
    ("Text", n): "a Text's font is `font=`: a family with its style after a colon "
                 "(`font=\"sans:Bold Italic\"`, `\"serif\"`) or a .ttf/.otf/.ttc file; "
                 "without it the letters are the single-stroke engraving font"
    for n in ("font_family", "family", "typeface", "fontname", "font_name", "face",
              "bold", "italic", "style")}
# a form's argument given with another form's (E0104; run am's `RoundedRectangle(corner=(40,
# 20), width=20, height=30)`, offered `corner_r` before `corner=` had a form of its own)
FORM_NOTES: dict[tuple[str, str], str] = {(k, "corner"): (
    "`corner=` goes with `opposite=` (two opposite corners, which set the size); with `width` "
    "and `height` a corner point is `bottom_left=(x, y)` (or `center=`)" + (
        ", a corner's rounding `corner_radius=`" if k == "RoundedRectangle" else ""))
    for k in ("Rectangle", "RoundedRectangle")}
