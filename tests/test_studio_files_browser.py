"""The studio, round five (issue 104), in Debian's Chromium through Playwright: the files a maker
downloads and what the page says, at a desktop's 1280 x 800 and a phone's 390 x 844.

- Downloads: the finger box nested on 150 x 120 mm sheets (four sheets) downloads its DXF, SVG
  and PDF under three names (all three were `finger_box-sheets.zip`, the second download
  overwrote the first); the SVG is the cutting file (red hairlines, nothing filled, no sheet
  outline: read by svgelements), the picture a choice (`-preview`); after another program is
  pasted over the gallery design, the header and the downloads follow its title; an opened
  drawing's files are named without `.dxf`; the line under the buttons is cleared when a value
  changes (it named the 3 mm STL after the thickness went to 6); issue 113: the kerf, the
  sheet's size, the G-code's machine and the PDF's paper are in the names.

Screenshots: out/studio-files-*.png.
"""
from __future__ import annotations

import io
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "out"
pytest.importorskip("playwright")
if not Path("/usr/bin/chromium").exists():
    pytest.skip("needs Debian's chromium (apt-get install chromium; .ci/run installs it)",
                allow_module_level=True)

from test_studio_maker_browser import DESKTOP, PHONE, opened, settled, views  # noqa: E402

from benchmarks.serve.studio_server import studio  # noqa: E402

BRACKET = (ROOT / "examples" / "bracket.aidl").read_text()


@pytest.fixture(scope="module")
def server():
    with studio("--compilers", "2") as (url, _proc):
        yield url


@pytest.fixture(scope="module")
def chromium(chromium_browser):
    return chromium_browser


def shot(page, name: str) -> None:
    OUT.mkdir(exist_ok=True)
    page.screenshot(path=str(OUT / f"studio-files-{name}.png"))


def download(page, ext: str):
    """Click the format's button: ``(suggested name, bytes)``."""
    with page.expect_download() as got:
        page.click(f'#downloads button[data-ext="{ext}"]')
    return got.value.suggested_filename, Path(got.value.path()).read_bytes()


def paste(page, text: str) -> None:
    """Select the whole program in the code pane and paste ``text`` over it."""
    n = views(page)
    page.click("#code .cm-content")
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(text)
    settled(page, n)


@pytest.mark.parametrize("how", [DESKTOP, PHONE], ids=["desktop", "phone"])
def test_each_file_is_named_for_what_it_holds_and_the_svg_is_a_cutting_file(server, chromium,
                                                                            how, tmp_path):
    import svgelements
    page = opened(chromium, server, how, "generator/finger_box")
    try:
        page.fill("#sheet-w", "150")
        page.fill("#sheet-h", "120")
        got = {ext: download(page, ext) for ext in ("dxf", "svg", "pdf")}
        assert {ext: name for ext, (name, _) in got.items()} == {
            ext: f"finger_box-sheets-150x120-{ext}.zip" for ext in ("dxf", "svg", "pdf")}
        sheets = zipfile.ZipFile(io.BytesIO(got["svg"][1]))
        assert sheets.namelist() == [f"finger_box-sheet-{i}-150x120.svg" for i in range(1, 5)]
        for name in sheets.namelist():
            svg = svgelements.SVG.parse(io.BytesIO(sheets.read(name)))
            shapes = [e for e in svg.elements() if isinstance(e, svgelements.Shape)]
            assert shapes and not any(isinstance(e, svgelements.Rect) for e in shapes)
            assert all(e.fill is None or e.fill.value is None for e in shapes), name
            assert {e.stroke.hex for e in shapes} == {"#ff0000"}
        # the picture, asked for: filled, under its own name
        page.select_option("#svg-style", "preview")
        name, data = download(page, "svg")
        assert name == "finger_box-preview-sheets-150x120-svg.zip"
        assert b'fill="#cfd8dc"' in zipfile.ZipFile(io.BytesIO(data)).read(
            "finger_box-preview-sheet-1-150x120.svg")
        page.select_option("#svg-style", "laser")
        assert page.inner_text("#download-status").startswith(name)
        # a value changed: the line no longer names the file of the old values
        n = views(page)
        page.locator('input[type=range][name="thickness"]').fill("6")
        settled(page, n)
        assert page.inner_text("#download-status") == ""
        name, _ = download(page, "dxf")
        assert name == "finger_box-thickness_6-sheets-150x120-dxf.zip"
        # issue 113: what the settings change is in the name (the kerf, the sheet, the machine,
        # the paper): no two files of different settings share one
        page.fill("#kerf", "0.2")
        page.dispatch_event("#kerf", "change")
        assert download(page, "dxf")[0] == "finger_box-thickness_6-sheets-kerf0.2-150x120-dxf.zip"
        page.fill("#kerf", "")
        page.dispatch_event("#kerf", "change")
        page.uncheck("#layout")
        page.select_option("#machine", "router")
        assert download(page, "gcode")[0] == "finger_box-thickness_6-router.gcode"
        page.select_option("#machine", "laser")
        assert download(page, "gcode")[0] == "finger_box-thickness_6.gcode"
        page.select_option("#page", "A4")
        assert download(page, "pdf")[0] == "finger_box-thickness_6-a4tiles.pdf"
        page.select_option("#page", "")
        assert download(page, "pdf")[0] == "finger_box-thickness_6.pdf"
        page.check("#layout")
        shot(page, f"finger-box-{'phone' if how is PHONE else 'desktop'}")
        if how is PHONE:
            return
        # another program pasted over the design: its title in the header and the file names
        paste(page, BRACKET)
        assert page.inner_text("#title") == "Bracket"
        page.uncheck("#layout")
        name, _ = download(page, "dxf")
        assert name == "bracket.dxf"
        # an opened drawing's files: its name without `.dxf`
        from maker_drawings import flange
        dxf = tmp_path / "flange80.dxf"
        dxf.write_bytes(flange())
        n = views(page)
        page.click("#open-drawing")
        page.check('input[name="open-as"][value="infer"]')
        page.set_input_files("#drawing-file", str(dxf))
        settled(page, n)
        assert page.inner_text("#title") == "flange80"
        name, _ = download(page, "dxf")
        assert name == "flange80.dxf"
        shot(page, "pasted-desktop")
    finally:
        page.context.close()


def decimals(x) -> int:
    text = f"{float(x):.9f}".rstrip("0").rstrip(".")
    return len(text.split(".")[1]) if "." in text else 0


@pytest.mark.parametrize("how", [DESKTOP, PHONE], ids=["desktop", "phone"])
def test_nothing_internal_reaches_the_page(server, chromium, how):
    """An enumerated param is a list of its values (the mounting plate's `fit`, the board
    enclosure's `vent`: free-text fields before, `tight` answered with the template's
    assertion); a length typed with its unit is converted ("150 mm", "15cm"); the Material field
    does not keep "abc"; every range end is on its slider's step; no tooltip names a flag."""
    page = opened(chromium, server, how, "generator/mounting_plate")
    try:
        assert page.eval_on_selector_all('select[name="fit"] option', "os => os.map(o => o.value)") \
            == ["fine", "medium", "coarse"]
        assert page.input_value('select[name="fit"]') == "medium"
        n = views(page)
        page.select_option('select[name="fit"]', "coarse")
        settled(page, n)
        assert page.evaluate("window.studio.view.values") == {"fit": '"coarse"'}
        for typed, want in [("150 mm", 150), ("12cm", 120), ("9,5 cm", 95)]:
            n = views(page)
            field = page.locator('#params input[name="width-value"]')
            field.fill(typed)
            field.press("Enter")
            settled(page, n)
            assert page.evaluate("window.studio.view.params.find((p) => p.name === 'width').value") \
                == pytest.approx(want), typed
            assert page.input_value('#params input[name="width-value"]') == f"{want:g}"
        field = page.locator('#params input[name="width-value"]')
        field.fill("40 deg")
        field.press("Enter")
        said = page.inner_text('#params .param[data-name="width"] .typed-note')
        assert said.startswith("“40 deg” is not in mm") and "width stays at 95 mm" in said, said
        for p in page.evaluate("window.studio.view.params"):
            if p.get("step") and p["kind"] in ("length", "number", "angle"):
                unit = page.inner_text(f'#params .param[data-name="{p["name"]}"] .unit')
                for x in __import__("re").findall(r"-?\d+(?:\.\d+)?", unit):
                    assert decimals(x) <= decimals(p["step"]), (p["name"], unit)
        titles = page.eval_on_selector_all("#downloads button", "bs => bs.map(b => b.title)")
        assert titles and not [t for t in titles if "--" in t], titles
        # the board enclosure's vents: a list too
        n = views(page)
        page.click("#open-gallery")
        page.click('#cards .card[data-id="generator/board_enclosure"]')
        settled(page, n)
        assert page.eval_on_selector_all('select[name="vent"] option', "os => os.map(o => o.value)") \
            == ["slots", "hex", "none"]
        assert page.input_value('select[name="vent"]') == "hex"
        page.fill("#thickness", "abc")
        page.press("#thickness", "Enter")
        assert page.input_value("#thickness") == "3"
        assert page.inner_text("#thickness-note").startswith("“abc” is not a number")
        page.locator('select[name="vent"]').scroll_into_view_if_needed()
        shot(page, f"lists-{'phone' if how is PHONE else 'desktop'}")
    finally:
        page.context.close()
