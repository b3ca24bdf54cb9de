"""A picture of a G-code program's toolpath, rebuilt from the file alone (docs/machines.md):
the file is read by ``gcodeparser`` (PyPI; the ``test`` extra) and replayed as GRBL runs it
(modal F and S, G0/G1/G2/G3 with I/J relative to the current point); cuts are drawn in the
order they run, coloured from blue (first) to red (last), each numbered at its start;
travel (G0) is a thin grey line.  A cut is a run of cutting moves between two travels (all
its passes or depths together).  Pillow draws it.

    python docs/toolpath_picture.py box.gcode box.png [laser|router|plotter]
"""
from __future__ import annotations

import io
import math
import sys


def moves(text: str, kind: str = "laser") -> list[tuple]:
    """``(g, (x0, y0), (x1, y1), centre or None, cutting, z0, z1, power)`` of every XY
    motion (``power``: the S in force with the spindle or laser on, else 0); law 1
    (benchmarks/laws/law_machine.py) replays the G-code with it too."""
    import gcodeparser
    x = y = 0.0
    z = None
    s = 0.0
    on = False
    out = []
    for line in gcodeparser.parse_gcode_lines(text):
        letter, code = line.command
        p = line.params
        if "S" in p:
            s = float(p["S"])
        if letter == "M":
            on = code in (3, 4) or (on and code != 5)
            continue
        if letter != "G" or code not in (0, 1, 2, 3):
            continue
        nx, ny = float(p.get("X", x)), float(p.get("Y", y))
        nz = float(p["Z"]) if "Z" in p else z
        c = (x + float(p.get("I", 0)), y + float(p.get("J", 0))) if code in (2, 3) else None
        cutting = code != 0 and ((on and s > 0) if kind == "laser" else (nz is not None and nz <= 0))
        if (nx, ny) != (x, y):
            out.append((code, (x, y), (nx, ny), c, cutting, z, nz, s if on else 0.0))
        x, y, z = nx, ny, nz
    return out


def _points(m) -> list:
    g, p, q, c = m[:4]
    if c is None:
        return [p, q]
    a0 = math.atan2(p[1] - c[1], p[0] - c[0])
    a1 = math.atan2(q[1] - c[1], q[0] - c[0])
    d = (a1 - a0) % (2 * math.pi)
    sweep = (d or 2 * math.pi) if g == 3 else ((d - 2 * math.pi) if d else -2 * math.pi)
    r = math.dist(p, c)
    n = max(2, int(abs(sweep) * 24 / math.pi))
    return [(c[0] + r * math.cos(a0 + sweep * k / n), c[1] + r * math.sin(a0 + sweep * k / n))
            for k in range(n + 1)]


def draw(text: str, kind: str = "laser", width: int = 640) -> bytes:
    """The PNG of the toolpath of G-code ``text``."""
    from PIL import Image, ImageDraw, ImageFont
    ms = moves(text, kind)
    cuts, cur = [], []
    for m in ms:
        if m[4]:
            cur.append(m)
        elif m[0] == 0 and cur:
            cuts.append(cur)
            cur = []
    if cur:
        cuts.append(cur)
    pts = [p for m in ms for p in _points(m)]
    x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
    y0, y1 = min(p[1] for p in pts), max(p[1] for p in pts)
    pad = 14
    k = (width - 2 * pad) / max(x1 - x0, 1e-9)
    height = int((y1 - y0) * k) + 2 * pad

    def px(p):
        return (pad + (p[0] - x0) * k, height - pad - (p[1] - y0) * k)
    img = Image.new("RGB", (width, height), "white")
    d = ImageDraw.Draw(img)
    for m in ms:
        if m[0] == 0:
            d.line([px(m[1]), px(m[2])], fill=(170, 170, 170), width=1)
    n = len(cuts)
    font = ImageFont.load_default(11)
    for i, cut in enumerate(cuts):
        t = i / max(1, n - 1)
        colour = (int(40 + 200 * t), 60, int(220 - 180 * t))
        for m in cut:
            d.line([px(p) for p in _points(m)], fill=colour, width=2)
    for i, cut in enumerate(cuts):
        x, y = px(cut[0][1])
        d.ellipse([x - 2, y - 2, x + 2, y + 2], fill="black")
        d.text((x + 3, y - 12), str(i + 1), fill="black", font=font)
    buf = io.BytesIO()
    img.save(buf, "PNG")
    return buf.getvalue()


if __name__ == "__main__":
    src, dst = sys.argv[1], sys.argv[2]
    kind = sys.argv[3] if len(sys.argv) > 3 else "laser"
    with open(src) as f:
        data = draw(f.read(), kind)
    with open(dst, "wb") as f:
        f.write(data)
