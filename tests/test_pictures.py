"""The documentation's pictures are up to date: every tutorial step (docs/tutorial.md), every
example of the gallery (docs/gallery.md) and every figure (docs/figures/*.aidl and the
examples' figures) is rendered again by the real command line
and compared with the committed PNG in docs/images, pixel by pixel within the anti-aliasing
tolerance of docs/make_pictures.py (which regenerates them: ``python docs/make_pictures.py``)."""
import importlib.util
import re
import sys
from pathlib import Path

import pytest

pytest.importorskip("cairosvg")
pytest.importorskip("PIL")

ROOT = Path(__file__).resolve().parent.parent
_spec = importlib.util.spec_from_file_location("make_pictures", ROOT / "docs" / "make_pictures.py")
mp = importlib.util.module_from_spec(_spec)
sys.modules["make_pictures"] = mp          # its dataclasses look their module up
_spec.loader.exec_module(mp)

PICTURES = mp.all_pictures()
FIX = "; regenerate with `python docs/make_pictures.py` and look at the picture before committing"


def test_the_tutorial_has_ten_steps_each_with_its_picture():
    text = (ROOT / "docs" / "tutorial.md").read_text()
    steps = re.findall(r"^## (\d+) ", text, flags=re.M)
    pics = mp.tutorial_pictures()
    assert steps == [str(i) for i in range(1, len(steps) + 1)] and len(steps) >= 8, steps
    assert [p.name for p in pics] == [f"tutorial-{i:02d}" for i in range(1, len(steps) + 1)]
    assert len({p.source for p in pics}) >= len(steps) - 1      # a new program nearly every step
    assert any("--layout" in p.options for p in pics)           # it ends on the cutting sheet


def test_the_gallery_shows_every_example_and_is_generated():
    text = (ROOT / "docs" / "gallery.md").read_text()
    assert text == mp.gallery_markdown(), "docs/gallery.md is out of date" + FIX
    for p in mp.examples():
        assert f"(images/gallery-{p.stem}.png)" in text, p.name


def test_every_picture_of_the_docs_is_made_by_a_program():
    """Each docs/images/*.png (but the editor screenshots) is rendered from a program, and each
    picture a page shows exists: no picture that nobody can regenerate."""
    made = {p.png.name for p in PICTURES}
    images = {p.name for p in (ROOT / "docs" / "images").glob("*.png")}
    assert sorted(n for n in images - made if not n.startswith("vscode-")) == []
    shown = set()
    for page in [ROOT / "README.md", *(ROOT / "docs").glob("*.md")]:
        shown |= set(re.findall(r"\]\((?:docs/)?images/([\w.-]+\.png)\)", page.read_text()))
    assert shown and sorted(shown - images) == []
    assert len(made & shown) >= 30


def test_the_readme_shows_the_telephone():
    assert "](docs/images/gallery-telephone.png)" in (ROOT / "README.md").read_text()


@pytest.mark.parametrize("pic", PICTURES, ids=[p.name for p in PICTURES])
def test_the_picture_is_up_to_date(pic):
    why = mp.difference(mp.render(pic), pic.png)
    assert why is None, why + FIX


def test_the_comparison_sees_a_missing_screw_hole():
    """The tolerance passes anti-aliasing noise but not a change to the design: step 5 with one
    3.2 mm screw hole left out differs from its picture."""
    (pic,) = [p for p in mp.tutorial_pictures() if p.name == "tutorial-05"]
    assert mp.difference(mp.render(pic), pic.png) is None
    changed = pic.source.replace("for sy in [-1, 1]", "for sy in [-1]")
    assert changed != pic.source
    why = mp.difference(mp.render(mp.Picture(pic.name, changed, pic.path, pic.options)), pic.png)
    assert why is not None and "differ" in why
