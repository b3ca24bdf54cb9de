"""The picture of docs/machines.md, "Vinyl cutter and pen plotter": what an independent HP-GL
interpreter (ezhpgl, in the test extra) re-reads from the HPGL of examples/gear.aidl and
name_tag.aidl, drawn with Pillow: arcs (AA) blue, lines (PD) orange, pen-up moves grey.

    python docs/figures/hpgl_reread.py      # writes docs/images/machines/hpgl_reread.png
"""
import sys
import ezhpgl
from PIL import Image, ImageDraw
from pathlib import Path
ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
import aidl_lang
from aidl_lang.output import encode, for_cutting
imgs = []
for name in ("gear", "name_tag"):
    res = aidl_lang.compile(path=str(ROOT / "examples" / f"{name}.aidl"))
    data = encode(for_cutting(res.output, None), ".plt")
    plot = ezhpgl.parse(data)
    page = plot.pages[0]
    b = page.bounds
    s = 420 / max(b.max.x - b.min.x, b.max.y - b.min.y)
    W, H = int((b.max.x - b.min.x) * s) + 40, int((b.max.y - b.min.y) * s) + 40
    im = Image.new("RGB", (W, H), "white")
    d = ImageDraw.Draw(im)
    last = None
    colours = {}
    for k, op in enumerate(page.operations):
        pts = [(20 + (q.x - b.min.x) * s, H - 20 - (q.y - b.min.y) * s) for q in op.geometry.points]
        # pen-up travel: thin grey from the last path's end
        if last is not None and op.path_id != last[0]:
            d.line([last[1], pts[0]], fill=(200, 200, 200), width=1)
        col = (0, 114, 178) if op.geometry.kind == "curve" else (213, 94, 0)
        if len(pts) > 1:
            d.line(pts, fill=col, width=2)
        last = (op.path_id, pts[-1])
    imgs.append(im)
W = sum(i.width for i in imgs) + 20
H = max(i.height for i in imgs)
out = Image.new("RGB", (W, H), "white")
x = 0
for i in imgs:
    out.paste(i, (x, (H - i.height) // 2)); x += i.width + 20
out.save(ROOT / "docs" / "images" / "machines" / "hpgl_reread.png")
print(out.size)
