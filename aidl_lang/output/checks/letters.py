"""The letters of a Text in a font (issue 112) named in W0504: which letters make each
piece of a solid that falls apart (a word not joined to the rest), and whose counters (the
inside of an O, A, B, P, 0, 4, 6, 8, 9) fall out of a plate the word is cut from."""
from __future__ import annotations


def _glyph_boxes(g, bounds) -> list[tuple[str, tuple]]:
    """Each glyph of font Text ``g`` with its box placed where the text's face (``bounds``:
    its solved box, x0, y0, x1, y1) puts it: the local extent moved onto it."""
    from ...geometry.shapes import font as F
    from ...geometry.shapes.text_outlines import _turned, along_local
    d = g.data
    ex = d.get("extent")
    if ex is None:
        return []
    dx, dy = bounds[0] - ex[0], bounds[1] - ex[2]
    if d.get("along") is not None:    # each glyph where the curve lays it (as its extent)
        loops = along_local(g)
    else:
        loops = _turned(F.outlines(d["font"], d["text"], d["size"], d["anchor"], d["valign"]),
                        d.get("rotation", 0.0))
    sh = F.shaped(d["font"], d["text"], d["size"])
    out = []
    for chars, idx, _ in sh.glyphs:
        bs = [s.box() for i in idx for s in loops[i].segments]
        if bs:
            out.append((chars, (min(b[0] for b in bs) + dx, min(b[1] for b in bs) + dy,
                                max(b[2] for b in bs) + dx, max(b[3] for b in bs) + dy)))
    return out


def letters_in(g, face, piece) -> str:
    """`` ("HA")``: the letters of font Text ``g`` (its face ``face``) in ``piece`` (a
    CrossSection) by their boxes: each whose box's middle is in the piece's box, or whose box
    holds the piece's middle (the dot of an i, an accent); empty for any other geometry."""
    if getattr(g, "kind", None) != "Text" or not g.data.get("font"):
        return ""
    b = piece.bounds()
    px, py = (b[0] + b[2]) / 2, (b[1] + b[3]) / 2
    chars = [c for c, (x0, y0, x1, y1) in _glyph_boxes(g, face.bounds())
             if (b[0] <= (x0 + x1) / 2 <= b[2] and b[1] <= (y0 + y1) / 2 <= b[3])
             or (x0 <= px <= x1 and y0 <= py <= y1)]     # its middle in the piece, or the
    return f" (\"{''.join(chars)}\")" if chars else ""  # piece's in its box (an accent)


def fallen_counters(d, holes) -> tuple[list[str], list]:
    """``(letters, texts)``: the letters whose counters fall out of a part, of the font
    Texts (not stencils) in ``holes`` (the holes that cut it apart), each letter once."""
    from ...geometry.shapes.text_outlines import counter_letters
    letters: list[str] = []
    texts = []
    for h in holes:
        for g, _ in d.own.get(h, []):
            if g.kind == "Text" and g.data.get("font") and not g.data.get("stencil"):
                got = counter_letters(g)
                if got:
                    texts.append(g)
                letters += [c for c in got if c not in letters]
    return letters, texts


def letter_at(d, g, x: float, y: float) -> str:
    """`` (its "L")``: the letter of font Text ``g`` whose glyph box holds ``(x, y)`` (the
    nearest box's when none does), placed by the text's face in ``d``; empty for any other
    geometry or when the face is not found."""
    if getattr(g, "kind", None) != "Text" or not g.data.get("font"):
        return ""
    face = next((f for faces in d.own.values() for h, f in faces if h is g), None)
    if face is None or face.is_empty():
        return ""
    boxes = _glyph_boxes(g, face.bounds())
    if not boxes:
        return ""

    def far(b):
        x0, y0, x1, y1 = b[1]
        return max(x0 - x, 0.0, x - x1) ** 2 + max(y0 - y, 0.0, y - y1) ** 2
    return f" (its \"{min(boxes, key=far)[0]}\")"
