"""DXF text as it is shown: the words of a ``TEXT`` or ``MTEXT`` entity with its codes decoded
(:func:`dxf_words`) and its height (:func:`text_height`), for :mod:`.dxf`.

The codes are decoded by ezdxf's own tools: ``\\U+XXXX`` (a Unicode character, as ezdxf's
loader decodes it in files before R2007: ``ezdxf.lldxf.encoding.decode_dxf_unicode``), then
for ``TEXT`` the special characters ``%%c`` (Ø), ``%%d`` (°), ``%%p`` (±), ``%%%`` and the
caret codes (``ezdxf.tools.text.plain_text``), for ``MTEXT`` its inline formatting too
(``\\~`` a space, ``\\\\`` a backslash, ``\\P`` a new line, ``{\\f...;...}``, ``\\S...;``:
``ezdxf.tools.text.plain_mtext``, ezdxf's accurate mode: its fast mode drops the text
after a ``\\~``).  A height that is not above 0 is the text style's fixed height when it has
one, else the text is skipped: neither is silent (the reader's notes)."""
from __future__ import annotations

import math


def dxf_words(e, t: str) -> list[str]:
    """The lines of text of the ``TEXT`` or ``MTEXT`` (``t``) entity ``e``, codes decoded
    (one line for a ``TEXT``; an MTEXT's ``\\P`` breaks lines)."""
    from ezdxf.lldxf.encoding import decode_dxf_unicode
    from ezdxf.tools.text import plain_mtext, plain_text
    if t == "TEXT":
        raw = str(e.dxf.get("text", ""))
        try:
            return [plain_text(decode_dxf_unicode(raw))]
        except Exception:                          # ezdxf's tools on a broken code
            return [raw]
    raw = str(e.text)
    try:
        return plain_mtext(decode_dxf_unicode(raw), split=True)
    except Exception:
        return raw.splitlines()


def text_height(e, t: str, doc) -> tuple[float, str | None]:
    """The height of the ``TEXT`` or ``MTEXT`` (``t``) entity ``e`` in drawing units and,
    when it is not the entity's own, why: ``(height, None)`` for a height above 0;
    ``(style height, "height 0")`` (or ``negative height``, ``no height``) when the entity's
    is not above 0 and its text style (in ``doc``) has a fixed height above 0; ``(0.0,
    why)`` when neither gives one (the text is skipped)."""
    key = "height" if t == "TEXT" else "char_height"
    if e.dxf.hasattr(key):
        try:
            h = float(e.dxf.get(key))
        except (TypeError, ValueError):
            h = math.nan
        if h > 0 and math.isfinite(h):
            return h, None
        why = ("a height that is not a number" if h != h else "negative height" if h < 0
               else "height 0" if h == 0 else "an infinite height")
    else:
        why = "no height"
    try:
        style = doc.styles.get(e.dxf.get("style", "Standard"))
        sh = float(style.dxf.get("height", 0.0)) if style is not None else 0.0
    except Exception:
        sh = 0.0
    if sh > 0 and math.isfinite(sh):
        return sh, why
    return 0.0, why
