"""Cut length and text kept by ``aidl import``: the drawing's cut paths against the cut layer of
the DXF the imported program renders to, over a corpus of real drawings (issue 59).

Run:  .venv/bin/python benchmarks/imports/import_cut_length.py [--laser FOLDER ...] [FOLDER ...]
      [--only NAME ...] [--parts] [--budget K] [-v]

For each ``.svg``/``.dxf`` (``.gz`` too) of the folders (those after ``--laser`` imported with
``--roles laser``, Boxes.py's colours):

- **file**: the length (mm) of what the drawing asks to be cut, read by an independent
  reader: for an SVG, every visible shape whose stroke (else fill) is a cut colour
  (``--laser``: black ``#000000`` or blue ``#0000ff``; otherwise every shape), open paths
  included, at the file's mm per user unit, taken segment by segment (svgelements): each
  curve's own ``length()``, and the straight segments as their **union** - a line drawn out
  and back along itself (Boxes.py's overshoots past a corner), or twice, is cut once by a
  laser, so it counts once (:func:`union_length`; segments on one line within 1e-4 mm).
  ``drawn`` (with ``-v``) is every segment's length added up, as the path is drawn; for a DXF, ezdxf's
  ``ezdxf.path.make_path`` of every LINE, ARC, CIRCLE, ELLIPSE, LWPOLYLINE, POLYLINE and
  SPLINE of model space with its blocks placed (``ezdxf.disassemble.recursive_decompose``),
  flattened to 0.001 mm, in mm by ``$INSUNITS``.  Its texts: SVG ``<text>`` with words, not
  red (Boxes.py's annotations); DXF TEXT, and MTEXT's lines.
- **program**: the file imported (:func:`aidl_lang.drawing.program.import_drawing`), the program
  compiled by the real compiler, built into the output model and written as DXF
  (:func:`aidl_lang.output.writers.dxf.to_dxf`), that DXF re-read by ezdxf: the length on its
  ``CUT*`` layers (what the laser cuts) and on ``ENGRAVE``; texts: the ``Text(`` statements of
  the program.

Prints a row per file with ``-v`` (and for the files named by ``--only``), and per corpus: files,
imported, compiled (no error), cut length in the files, cut length on the programs' cut layers
(and its share), engraved length, texts in the files and in the programs.  The lengths add
up over the files whose program compiled.  Curves are compared as flattened polylines (0.001
mm), so a cut kept whole reads within about 1e-4 of its length.
"""
from __future__ import annotations

import argparse
import collections
import gzip
import io
import math
import pathlib
import re
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.drawing.write.program import import_drawing  # noqa: E402
from aidl_lang.drawing.model import DrawingError  # noqa: E402
from aidl_lang.pipeline import compile_source  # noqa: E402
from aidl_lang.base.limits import DEFAULT_BUDGET  # noqa: E402

CUT_RGB = [(0, 0, 0), (0, 0, 255)]        # Boxes.py: OUTER_CUT black, INNER_CUT blue
RED = (255, 0, 0)                         # Boxes.py: ANNOTATIONS
FLAT = 0.001                              # mm: the flattening of DXF curves


def files_of(folder: pathlib.Path) -> list[pathlib.Path]:
    return sorted(p for p in folder.iterdir()
                  if re.search(r"\.(dxf|svg)(\.gz)?$", p.name, re.I) and p.is_file())


def read(p: pathlib.Path) -> tuple[bytes, str]:
    data = p.read_bytes()
    if p.name.endswith(".gz"):
        return gzip.decompress(data), p.name[:-3]
    return data, p.name


def _rgb(el):
    for attr in ("stroke", "fill"):
        c = getattr(el, attr, None)
        if c is not None and getattr(c, "value", None) is not None:
            return (c.red, c.green, c.blue)
    return None


def svg_file_figures(data: bytes, laser: bool) -> tuple[float, int, float]:
    """(cut length mm: the union of the cut paths, texts, drawn length mm: every path's own
    length added up) of an SVG, by svgelements."""
    import svgelements as S
    from aidl_lang.drawing.read.svg import _css_mm
    svg = S.SVG.parse(io.BytesIO(data), reify=True, ppi=96.0)
    vb = svg.viewbox
    k = (float(svg.width) / vb.width) if vb is not None and vb.width and svg.width else 1.0
    mm_user = _css_mm(svg.values.get("width"), vb.width if vb is not None else None)
    mm_px = (mm_user if mm_user is not None else k * 25.4 / 96) / k
    length, texts, lines = 0.0, 0, []
    for el in svg.elements():
        if el.values.get("visibility") in ("hidden", "collapse") or \
                el.values.get("display") == "none":
            continue
        rgb = _rgb(el)
        if isinstance(el, S.Text):
            if (el.text or "").strip() and (not laser or rgb != RED):
                texts += 1
            continue
        if not isinstance(el, S.Shape):
            continue
        if laser and not any(rgb is not None and all(abs(a - b) <= 2 for a, b in zip(rgb, c))
                             for c in CUT_RGB):
            continue
        try:
            for seg in S.Path(el):
                if isinstance(seg, S.Move) or seg.start is None or seg.end is None:
                    continue
                if isinstance(seg, (S.Line, S.Close)):
                    lines.append((seg.start.x * mm_px, seg.start.y * mm_px,
                                  seg.end.x * mm_px, seg.end.y * mm_px))
                else:
                    length += float(seg.length(error=1e-7)) * mm_px
        except (ValueError, ZeroDivisionError, OverflowError):
            pass
    return (length + union_length(lines), texts,
            length + sum(math.dist(a[:2], a[2:]) for a in lines))


def union_length(lines, tol: float = 1e-4) -> float:
    """The length (mm) of the union of straight segments ``(x0, y0, x1, y1)``: segments on one
    line (direction within 1e-6 rad, offset within ``tol`` mm) that overlap count once, as a
    laser cuts a line drawn out and back along itself once."""
    rows = []
    for x0, y0, x1, y1 in lines:
        d = math.hypot(x1 - x0, y1 - y0)
        if d <= 1e-12:
            continue
        ux, uy = (x1 - x0) / d, (y1 - y0) / d
        if uy < -1e-12 or (abs(uy) <= 1e-12 and ux < 0):   # one direction per line: [0, pi)
            ux, uy = -ux, -uy
        ang = math.atan2(uy, ux) % math.pi
        off = ux * y0 - uy * x0                            # signed distance of the line
        t0, t1 = sorted((ux * x0 + uy * y0, ux * x1 + uy * y1))
        rows.append((ang, off, t0, t1))
    rows.sort()
    total, i = 0.0, 0
    while i < len(rows):                                   # runs of one angle
        j = i + 1
        while j < len(rows) and rows[j][0] - rows[j - 1][0] <= 1e-6:
            j += 1
        run = sorted(rows[i:j], key=lambda r: r[1])
        k = 0
        while k < len(run):                                # lines of one offset
            m = k + 1
            while m < len(run) and run[m][1] - run[m - 1][1] <= tol:
                m += 1
            spans = sorted((r[2], r[3]) for r in run[k:m])
            a, b = spans[0]
            for c, e in spans[1:]:
                if c > b:
                    total += b - a
                    a, b = c, e
                else:
                    b = max(b, e)
            total += b - a
            k = m
        i = j
    return total


def _dxf_length(doc, layer=None, entities=None) -> float:
    from ezdxf import path as P
    total = 0.0
    for e in (doc.modelspace() if entities is None else entities):
        if e.dxftype() not in ("LINE", "ARC", "CIRCLE", "ELLIPSE", "LWPOLYLINE", "POLYLINE",
                               "SPLINE"):
            continue
        if layer is not None and not layer(e.dxf.layer):
            continue
        try:
            pts = list(P.make_path(e).flattening(FLAT))
        except Exception:                                   # noqa: BLE001 - not countable
            continue
        total += sum(math.dist(a.vec2, b.vec2) for a, b in zip(pts, pts[1:]))
    return total


def dxf_file_figures(data: bytes) -> tuple[float, int, float]:
    """(length mm, texts, the same length) of a DXF's model space, by ezdxf (in the file's
    units)."""
    import tempfile
    import ezdxf
    from ezdxf import recover
    with tempfile.TemporaryDirectory() as tmp:             # readfile: ASCII or binary
        path = pathlib.Path(tmp) / "f.dxf"
        path.write_bytes(data)
        try:
            doc = ezdxf.readfile(path)
        except Exception:                                   # noqa: BLE001
            doc, _ = recover.readfile(path)
    from ezdxf.disassemble import recursive_decompose
    from aidl_lang.drawing.read.dxf import INSUNITS_MM
    flat = list(recursive_decompose(doc.modelspace()))     # blocks placed, every copy
    texts = 0
    for e in flat:
        if e.dxftype() == "TEXT" and e.dxf.get("text", "").strip():
            texts += 1
        elif e.dxftype() == "MTEXT":                        # one Text per line
            texts += sum(1 for ln in e.plain_text().splitlines() if ln.strip())
    mm = INSUNITS_MM.get(doc.header.get("$INSUNITS", 0), ("mm", 1.0))[1]
    length = _dxf_length(doc, entities=flat) * mm
    return length, texts, length


def program_figures(text: str, name: str, budget=None) -> tuple[bool, float, float, int]:
    """(compiled, cut mm, engraved mm, Text statements) of an imported program: compiled,
    built, written as DXF and that DXF re-read with ezdxf."""
    import ezdxf
    from aidl_lang.output.part.part import build
    from aidl_lang.output.writers.dxf import to_dxf
    n_text = len(re.findall(r"= Text\(", text))
    c = compile_source(text, name, budget=budget or DEFAULT_BUDGET)
    if not c.ok or c.drawing is None:
        return False, 0.0, 0.0, n_text
    doc = ezdxf.read(io.StringIO(to_dxf(build(c.drawing, name))))
    return (True, _dxf_length(doc, lambda ly: ly.upper().startswith("CUT")),
            _dxf_length(doc, lambda ly: ly.upper().startswith("ENGRAVE")), n_text)


def run(folder: pathlib.Path, laser: bool, only: set, verbose: bool,
        parts: bool = False, budget=None) -> collections.Counter:
    row: collections.Counter = collections.Counter()
    for p in files_of(folder):
        data, name = read(p)
        if only and name.rsplit(".", 1)[0] not in only:
            continue
        row["files"] += 1
        t0 = time.perf_counter()
        try:
            text, _notes = import_drawing(data, name, roles="laser" if laser else None,
                                         parts=parts, budget=budget)
        except DrawingError as ex:
            row["refused " + ex.code] += 1
            if verbose or only:
                print(f"  {name:<32} refused {ex.code}", flush=True)
            continue
        row["imported"] += 1
        ok, cut, eng, n_text = program_figures(text, name.rsplit(".", 1)[0] + ".aidl", budget)
        if not ok:
            if verbose or only:
                print(f"  {name:<32} not compiled", flush=True)
            continue
        row["compiled"] += 1
        f_len, f_text, drawn = (svg_file_figures(data, laser) if name.lower().endswith(".svg")
                         else dxf_file_figures(data))
        row["file_mm"] += f_len
        row["drawn_mm"] += drawn
        row["cut_mm"] += cut
        row["engraved_mm"] += eng
        row["file_texts"] += f_text
        row["program_texts"] += n_text
        if verbose or only:
            print(f"  {name:<32} file {f_len:>10.1f} mm  cut {cut:>10.1f} mm "
                  f"({cut / f_len:>7.2%}; drawn {drawn:>10.1f} mm, {cut / drawn:>7.2%})  engraved {eng:>9.1f} mm  texts {f_text} -> "
                  f"{n_text}  ({time.perf_counter() - t0:.1f} s)" if f_len else
                  f"  {name:<32} no cut paths", flush=True)
    return row


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("folders", nargs="*", type=pathlib.Path)
    ap.add_argument("--laser", nargs="*", type=pathlib.Path, default=[],
                    help="folders imported with --roles laser")
    ap.add_argument("--only", nargs="*", default=[], help="file names (no suffix) to measure")
    ap.add_argument("--parts", action="store_true",
                    help="import as `aidl import --parts` (one solid per outer loop)")
    ap.add_argument("--budget", type=float, default=1.0,
                    help="the default budget (import and compile) times K, as `--budget K`")
    ap.add_argument("-v", "--verbose", action="store_true")
    a = ap.parse_args(argv)
    budget = DEFAULT_BUDGET.scaled(a.budget) if a.budget != 1.0 else None
    only = set(a.only)
    for f, laser in [(f, False) for f in a.folders] + [(f, True) for f in a.laser]:
        r = run(f, laser, only, a.verbose, a.parts, budget)
        share = r["cut_mm"] / r["file_mm"] if r["file_mm"] else 0.0
        refused = ", ".join(f"{k} {v}" for k, v in sorted(r.items()) if k.startswith("refused"))
        print(f"{f.name + (' (--roles laser)' if laser else '')}: {r['files']} files, "
              f"{r['imported']} imported, {r['compiled']} compiled"
              + (f" ({refused})" if refused else "") +
              f"; cut paths in the files {r['file_mm']:.0f} mm, on the programs' cut layers "
              f"{r['cut_mm']:.0f} mm ({share:.1%}), engraved {r['engraved_mm']:.0f} mm; "
              f"texts {r['file_texts']} in the files, {r['program_texts']} in the programs",
              flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
