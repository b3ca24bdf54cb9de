"""Regenerate the documentation's pictures: the tutorial's steps and the example gallery.

    python docs/make_pictures.py            # write docs/images/tutorial-*.png, gallery-*.png
                                            # and docs/gallery.md
    python docs/make_pictures.py --check    # write nothing; list what is out of date (exit 1)

*Tutorial.*  In docs/tutorial.md a picture line ``![...](images/tutorial-NN.png)`` shows the
nearest ```aidl block above it, rendered by ``aidl render BLOCK -o PNG --png-width 480``; an
HTML comment on the same line adds render options, e.g.
``<!-- render: --layout sheet --sheet 180x120mm -->``.

*Gallery.*  Every ``examples/*.aidl`` is rendered to ``docs/images/gallery-NAME.png`` and
listed in docs/gallery.md with the first sentence of its leading comment; every stdlib
generator's demo ``examples/generators/*.aidl`` to ``gen-NAME.png`` (flat) and
``gen-NAME-3d.png`` (``--assembled``), listed below them.

*Figures.*  Every other picture of the docs comes from a program: ``docs/figures/NAME.aidl``
is rendered to ``docs/images/NAME.png`` (its ``# render: OPTIONS`` line, if any, adds
``aidl render`` options such as ``--png-width 654``), and the pictures of bundled examples
with options (:data:`EXAMPLE_FIGURES`, e.g. the laser box's cutting sheet).  The editor
screenshots (``vscode-*.png``) are taken by editors/vscode/test/code_server_screenshots.py
instead.

*Up to date.*  tests/test_pictures.py re-renders every picture and compares it with the
committed PNG pixel by pixel, allowing for anti-aliasing: a picture is out of date when more
than ``TOLERANCE`` of its pixels differ by more than ``LEVELS`` (of 255) in some channel, or
its size differs.  Byte equality would fail across cairo and zlib versions, and anti-aliasing
moves edge pixels by a few levels; a missing 3.2 mm hole turns ~250 pixels of a 480 px
picture from the fill to white (~50 levels), which is caught (tests/test_pictures.py checks
exactly that).
Needs the ``png`` extra (cairosvg) and ``layout`` (spyrrow) for the cutting sheet.
"""
from __future__ import annotations

import argparse
import contextlib
import io
import re
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"
IMAGES = DOCS / "images"
WIDTH = 480                      # px: every picture
LEVELS = 24                      # a pixel differs when a channel moves by more than this ...
TOLERANCE = 0.0005               # ... and a picture when more than 0.05 % of its pixels do

PICTURE = re.compile(r"!\[[^\]]*\]\(images/(tutorial-\d+)\.png\)(?:\s*<!--\s*render:(.*?)-->)?")


@dataclass(frozen=True)
class Picture:
    name: str                    # file stem in docs/images
    source: str | None           # program text (tutorial), or None: render `path` in place
    path: Path                   # where the program is (gallery) or is said to be (tutorial)
    options: tuple[str, ...]     # extra `aidl render` options
    line: int = 0                # the picture line in docs/tutorial.md (tutorial only)

    @property
    def png(self) -> Path:
        return IMAGES / f"{self.name}.png"


def tutorial_pictures() -> list[Picture]:
    """Each picture line of docs/tutorial.md with the ```aidl block above it."""
    lines = (DOCS / "tutorial.md").read_text(encoding="utf-8").split("\n")
    out, block, i = [], None, 0
    while i < len(lines):
        if lines[i].strip() == "```aidl":
            j = i + 1
            while lines[j].strip() != "```":
                j += 1
            block = "\n".join(lines[i + 1:j]) + "\n"
            i = j
        else:
            m = PICTURE.search(lines[i])
            if m:
                if block is None:
                    raise SystemExit(f"docs/tutorial.md:{i + 1}: a picture with no ```aidl "
                                     f"block above it")
                out.append(Picture(m[1], block, DOCS / f"{m[1]}.aidl",
                                   tuple((m[2] or "").split()), i + 1))
        i += 1
    return out


# pictures of bundled examples with render options: (name, example, options)
EXAMPLE_FIGURES = [
    ("laser_box_assembly", "laser_box", ("--png-width", "420")),
    ("laser_box_sheet", "laser_box", ("--layout", "sheet", "--sheet", "300x200mm",
                                      "--kerf", "0.15mm")),
    ("stdlib_gear_pair", "gear_pair", ("--png-width", "520")),
    # G-code toolpaths (docs/machines.md): `--toolpath KIND` writes the example's G-code
    # with that built-in machine profile and draws it back (docs/toolpath_picture.py)
    ("gcode_laser", "mounting_plate", ("--toolpath", "laser")),
    ("gcode_router", "mounting_plate", ("--toolpath", "router")),
]
RENDER_LINE = re.compile(r"^#\s*render:(.*)$", re.M)
SCREENSHOTS = "vscode-*.png"     # taken by editors/vscode/test/code_server_screenshots.py


def figure_pictures() -> list[Picture]:
    """docs/figures/*.aidl (options from a ``# render:`` line) and :data:`EXAMPLE_FIGURES`."""
    out = []
    for p in sorted((DOCS / "figures").glob("*.aidl")):
        m = RENDER_LINE.search(p.read_text(encoding="utf-8"))
        out.append(Picture(p.stem, None, p, tuple(m[1].split()) if m else ()))
    for name, example, options in EXAMPLE_FIGURES:
        out.append(Picture(name, None, ROOT / "examples" / f"{example}.aidl", options))
    return out


def all_pictures() -> list[Picture]:
    return tutorial_pictures() + gallery_pictures() + generator_pictures() + figure_pictures()


def generators() -> list[Path]:
    """The stdlib generators' demo programs (examples/generators/*.aidl)."""
    return sorted((ROOT / "examples" / "generators").glob("*.aidl"))


def generator_pictures() -> list[Picture]:
    """Each generator's flat sheet (``gen-NAME.png``) and assembled product
    (``gen-NAME-3d.png``, ``--assembled``)."""
    out = []
    for p in generators():
        out.append(Picture(f"gen-{p.stem}", None, p, ()))
        out.append(Picture(f"gen-{p.stem}-3d", None, p, ("--assembled",)))
    return out


def examples() -> list[Path]:
    return sorted((ROOT / "examples").glob("*.aidl"))


def gallery_pictures() -> list[Picture]:
    return [Picture(f"gallery-{p.stem}", None, p, ()) for p in examples()]


def summary(path: Path) -> str:
    """The first sentence of an example's leading comment."""
    text = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith("#"):
            break
        text.append(line.lstrip("#").strip())
    words = " ".join(text)
    m = re.match(r"(.+?[.!?])(\s|$)", words)
    return (m[1] if m else words) or path.stem.replace("_", " ")


def gallery_markdown() -> str:
    """docs/gallery.md, generated: every example with its picture."""
    rows = ["# Gallery", "",
            "Every program in [`examples/`](../examples), rendered by `aidl render FILE -o "
            "FILE.png`.  This page and its", "pictures are generated by "
            "`python docs/make_pictures.py`; `tests/test_pictures.py` checks that they are "
            "up to", "date.  Start with the [tutorial](tutorial.md) to write your own.", ""]
    for p in examples():
        rows += [f"## {p.stem.replace('_', ' ')}", "",
                 f"[`examples/{p.name}`](../examples/{p.name}) — {summary(p)}", "",
                 f"![{p.stem.replace('_', ' ')}](images/gallery-{p.stem}.png)", ""]
    if generators():
        rows += ["# Generators", "",
                 "The standard library's generators (boxes, trays, joints, stands, enclosures, "
                 "gear trains), each", "called by a short program in "
                 "[`examples/generators/`](../examples/generators): the flat parts as cut, "
                 "and the", "product assembled (`aidl render FILE --assembled -o FILE.png`).  "
                 "[docs/generators.md](generators.md) compares", "them with the best-known "
                 "laser-box generator's catalogue.", ""]
    for p in generators():
        rows += [f"## {p.stem.replace('_', ' ')}", "",
                 f"[`examples/generators/{p.name}`](../examples/generators/{p.name}) — "
                 f"{summary(p)}", "",
                 f"![{p.stem.replace('_', ' ')}, flat](images/gen-{p.stem}.png) "
                 f"![{p.stem.replace('_', ' ')}, assembled](images/gen-{p.stem}-3d.png)", ""]
    return "\n".join(rows)


def render(pic: Picture) -> bytes:
    """The PNG of a picture, by the real command line (in this process)."""
    from aidl_lang.cli.main import main
    with tempfile.TemporaryDirectory() as tmp:
        prog = pic.path
        if pic.source is not None:
            prog = Path(tmp) / f"{pic.name}.aidl"
            prog.write_text(pic.source, encoding="utf-8")
        out = Path(tmp) / f"{pic.name}.png"
        err = io.StringIO()
        if pic.options[:1] == ("--toolpath",):
            return _toolpath(prog, pic.options[1], Path(tmp), err)
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            width = () if "--png-width" in pic.options else ("--png-width", str(WIDTH))
            rc = main(["render", str(prog), "-o", str(out), *width, *pic.options])
        if rc != 0 or not out.exists():
            where = (f"docs/tutorial.md:{pic.line}" if pic.line
                     else str(pic.path.relative_to(ROOT)))
            raise RuntimeError(f"{where}: `aidl render` failed (exit {rc}):\n{err.getvalue()}")
        return out.read_bytes()


def _toolpath(prog: Path, kind: str, tmp: Path, err) -> bytes:
    """The toolpath picture of ``prog``'s G-code on the built-in ``kind`` profile."""
    from aidl_lang.cli.main import main
    sys.path.insert(0, str(DOCS))
    from toolpath_picture import draw
    out = tmp / "job.gcode"
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        rc = main(["render", str(prog), "-o", str(out), "--machine", kind])
    if rc != 0:
        raise RuntimeError(f"{prog}: `aidl render --machine {kind}` failed:\n{err.getvalue()}")
    return draw(out.read_text(), kind, 560)


def difference(png: bytes, reference: Path) -> str | None:
    """Why ``png`` is not the picture ``reference`` holds (None: it is, within tolerance)."""
    import numpy as np
    from PIL import Image
    if not reference.exists():
        return f"{reference.relative_to(ROOT)} does not exist"
    with Image.open(io.BytesIO(png)) as a, Image.open(reference) as b:
        x = np.asarray(a.convert("RGBA"), dtype=np.int16)
        y = np.asarray(b.convert("RGBA"), dtype=np.int16)
    if x.shape != y.shape:
        return f"{reference.relative_to(ROOT)} is {y.shape[1]}x{y.shape[0]} px, now {x.shape[1]}x{x.shape[0]}"
    bad = int((np.abs(x - y).max(axis=2) > LEVELS).sum())
    if bad > TOLERANCE * x.shape[0] * x.shape[1]:
        return (f"{reference.relative_to(ROOT)}: {bad} pixels "
                f"({100 * bad / (x.shape[0] * x.shape[1]):.2f} %) differ")
    return None


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true", help="write nothing; list what is out of date")
    args = ap.parse_args(argv)
    stale = []
    for pic in all_pictures():
        png = render(pic)
        why = difference(png, pic.png)
        if why is None:
            continue                 # keep the committed file: no churn from anti-aliasing
        stale.append(why)
        if not args.check:
            pic.png.write_bytes(png)
            print(f"wrote {pic.png.relative_to(ROOT)} ({why})")
    made = {pic.png.name for pic in all_pictures()}
    stale += [f"docs/images/{p.name} is made by nothing: add its program to docs/figures/"
              for p in sorted(IMAGES.glob("*.png"))
              if p.name not in made and not p.match(SCREENSHOTS)]
    gallery = DOCS / "gallery.md"
    text = gallery_markdown()
    if not gallery.exists() or gallery.read_text(encoding="utf-8") != text:
        stale.append("docs/gallery.md")
        if not args.check:
            gallery.write_text(text, encoding="utf-8")
            print("wrote docs/gallery.md")
    if args.check:
        print("\n".join(stale) or "all pictures up to date")
        return 1 if stale else 0
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    raise SystemExit(main())
