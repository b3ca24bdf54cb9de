"""``Text(..., font=...)`` in the interpreter (issue 112): the font found or read before the
Text is built (a family by name, a file through the import sandbox: E0133), where such a
Text may stand (a solid: material; a hole: openings; a drawing: engraved outlines, or its
area with ``fill=true``; E0120 elsewhere), and the characters its font lacks (W0105)."""
from __future__ import annotations

from ..base.diagnostics import EvalError


def text_font(interp, conv: dict, s, node, spans) -> None:
    """Put the :class:`~aidl_lang.geometry.shapes.font.Face` of ``conv["font"]`` in
    ``conv["_font"]`` (a file read relative to the program, the sandbox of ``Drawing2D``);
    E0133 at the argument when it cannot be had.  E0120 for a font Text in a ``cut`` or
    ``assembly``."""
    from ..geometry.shapes import font as F
    spec = conv.get("font")
    at = spans.get("font", node.span)
    if not isinstance(spec, str) or not spec.strip():
        raise EvalError("E0133", "`font=` takes a family or a font file, got "
                        + (f"\"{spec}\"" if isinstance(spec, str) else type(spec).__name__),
                        at, hint="`font=\"sans\"`, `font=\"serif:Bold\"` or "
                                 "`font=\"fonts/MyFont.ttf\"`")
    if conv.get("weight") is not None:
        raise EvalError("E0108", "a Text in a font has the font's own stroke weight: "
                        "`weight=` is the single-stroke stencil's", spans.get("weight", at),
                        hint="leave out weight= and choose a heavier or lighter style: "
                             "`font=\"sans:Bold\"`, `\"sans:Black\"`, `\"sans:Light\"` "
                             "or a number, `\"sans:650\"`")
    if s.kind not in ("solid", "hole", "drawing"):
        raise EvalError("E0120", f"Text in a font must be in a solid (letters as material), a "
                        f"hole (openings) or a drawing (engraved), not in {s.kind} `{s.name}`",
                        node.span, hint="put it in `solid word { ... }`, `hole letters { ... }` "
                                        "or `drawing labels { ... }`")
    try:
        if F.is_path(spec):
            from ..library.sources import ImportRefused, load_font
            path, style = F.split_spec(spec)
            try:
                real, data = load_font(path, interp.file.path)
            except ImportRefused as ex:
                raise EvalError(ex.code, ex.message, at, hint=ex.hint,
                                suggestions=ex.suggestions or None) from None
            weight = F.parse_style(style)[0] if style else None
            face = F.Face(spec, data=data)
            if weight is not None:
                face = F.Face(spec, data=data, variations=F.weight_axis(face, weight))
            F.font_of(face)                      # read now: a damaged file is E0133 here
        else:
            face = F.resolve(spec)
            F.font_of(face)
    except F.FontError as ex:
        raise EvalError("E0133", str(ex), at, hint=ex.hint) from None
    conv["_font"] = face


def font_missing(interp, g, spans, node) -> None:
    """W0105 for the characters of a font Text that its font has no glyph for (left out);
    E0134 when that is every one of them (the text draws nothing)."""
    from ..geometry.shapes import font as F
    lost = F.missing(g.data["font"], g.data["text"])
    if lost:
        shown = ", ".join(f"`{c}` (U+{ord(c):04X})" for c in lost[:8])
        other = F.covering("".join(lost))
        hint = ((f"`font=\"{other}\"` has them (installed here); " if other else
                 "choose a font that has them (`font=\"sans\"` covers Latin, Greek and "
                 "Cyrillic; `fc-list :lang=zh family` lists the fonts installed for a script, "
                 "here Chinese), ") + "or write the text without them")
        at = spans.get("text", node.span)
        if nothing_drawn(g.data["text"], lost):
            raise EvalError("E0134", f"the text draws nothing: the font "
                            f"`{g.data['font'].label}` has no glyph for any of its characters "
                            f"({shown})", at, hint=hint)
        interp.sink.warning("W0105", f"the font `{g.data['font'].label}` has no glyph for "
                            f"{shown}: {'they are' if len(lost) > 1 else 'it is'} left out",
                            at, hint=hint)


def stroke_font_missing(interp, g, lost, at) -> None:
    """W0105 for the characters of a Text the single-stroke font has no glyph for (left out);
    E0134 when that is every one of them: the text draws nothing (run ec's 福, cut as
    nothing with only a warning)."""
    from ..geometry.shapes import font as F
    shown = ", ".join(f"`{c}` (U+{ord(c):04X})" for c in lost[:8])
    hint = "the single-stroke font draws printable ASCII and ° ± × µ Ø ø ⌀ only; write the " \
           "text in ASCII (e.g. `e` for `é`)"
    if nothing_drawn(g.data["text"], lost):
        other = F.covering("".join(lost))
        raise EvalError("E0134", f"the text draws nothing: the single-stroke font has no "
                        f"glyph for any of its characters ({shown})", at,
                        hint=hint + (f", or give a font that has them: `font=\"{other}\"` "
                                     "(installed here)" if other else ", or give `font=` a "
                                     "font that has them (`fc-list :lang=zh family` lists the "
                                     "fonts installed for a script, here Chinese)"))
    interp.sink.warning("W0105", f"the engraving font has no glyph for {shown}: "
                        f"{'they are' if len(lost) > 1 else 'it is'} left out of the drawing",
                        at, hint=hint)


def nothing_drawn(text: str, lost) -> bool:
    """True when every character of ``text`` but white space is one of ``lost`` (and there
    is one): the Text draws nothing (E0134)."""
    gone = set(lost)
    shown = [c for c in text if not c.isspace()]
    return bool(shown) and all(c in gone for c in shown)


def check_fill(conv: dict, s, node, spans, kind: str = "Text") -> None:
    """``Text(..., fill=true)``: the letters' area engraved, which needs letters with an area
    (``font=``) in a ``drawing``; E0108 at ``fill=`` otherwise, its hint what to write.  A
    closed shape's ``fill=true`` (``kind``, not Text): in a drawing only, likewise."""
    at = spans.get("fill", node.span)
    if kind != "Text":
        if s.kind != "drawing":
            raise EvalError("E0108", f"`fill=true` engraves a shape's area in a drawing; in "
                            f"{s.kind} `{s.name}` the shape is "
                            + {"solid": "material already", "hole": "an opening already"}.get(
                                s.kind, "not engraved"), at,
                            hint="leave out fill=, or put the shape in `drawing mark { ... }` "
                                 "to engrave its area on the part")
        return
    if conv.get("font") is None:
        raise EvalError("E0108", "`fill=true` fills the letters of a font; the single-stroke "
                        "engraving font has lines, no area", at,
                        hint="add a font: `Text(..., font=\"sans\", fill=true)` in a drawing")
    if conv.get("stencil"):
        raise EvalError("E0108", "a stencil Text's letters are openings: `fill=true` (an "
                        "engraved area) and `stencil=true` exclude each other", at,
                        hint="leave out fill= to cut the stencil, or stencil= to engrave "
                             "the letters' area in a drawing")
    if s.kind != "drawing":
        what = {"solid": "material already (the letters are the part)",
                "hole": "openings already (cut out)"}.get(s.kind, f"not engraved in a {s.kind}")
        raise EvalError("E0108", f"`fill=true` engraves the letters' area in a drawing; in "
                        f"{s.kind} `{s.name}` they are {what}", at,
                        hint="leave out fill=, or put the Text in `drawing label { ... }` to "
                             "engrave its filled letters on the part")
