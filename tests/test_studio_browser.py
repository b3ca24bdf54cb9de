"""`aidl studio` in a real browser, as a person uses it: Debian's Chromium driven by Playwright.

The studio runs as a real subprocess (`aidl studio --port 0`).  The test picks the divider tray
from the gallery, moves its sliders to 3 x 4 compartments and the thickness to 3 mm, edits the
code (an error appears under the code and in the editor, then goes away), downloads the cutting
sheet's DXF and re-reads it with ezdxf, checks the 3D view loaded the assembled tray, opens
the share link in a new page and gets the same part, and runs "Describe the part" against a
local test double that replays recorded model answers.  Screenshots: out/studio-*.png.

Issue 84: a visitor's own program with a known bad range is swept in the background after its
picture; its slider shows the part of its range the sweep did not find clean hatched, with a
title and an accessible description naming what happens there; moved there from the
keyboard, the slider says so (its aria-valuetext and a line under it) and the picture is still
drawn.  Screenshots at a phone's 390 px and a desktop's 1280 px: out/studio-sweep-*.png.
"""
from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "out"
pytest.importorskip("playwright")
if not Path("/usr/bin/chromium").exists():
    pytest.skip("needs Debian's chromium (apt-get install chromium; .ci/run installs it)",
                allow_module_level=True)

from benchmarks.serve.studio_server import studio  # noqa: E402
from test_studio_sweep import SLID  # noqa: E402

# ms: each page wait ends on its outcome (the page's answer); this only stops a hung page,
# never a claim on this machine's speed (a loaded machine waits longer, and passes)
HANG_GUARD = 300_000


@pytest.fixture(scope="module")
def shared(studio_url, chromium_browser):
    """The test process's studio (no model endpoint) and Chromium (tests/conftest.py), a
    context of this module's: ``(url, ctx)``; each test opens its own pages and closes them
    (a studio and a browser each cost a test about 5 s of start-up)."""
    ctx = chromium_browser.new_context(viewport={"width": 1400, "height": 900})
    try:
        yield studio_url, ctx
    finally:
        ctx.close()


@pytest.fixture
def pages(shared):
    """The shared ``(url, ctx)``; the pages the test opened are closed after it."""
    url, ctx = shared
    before = set(ctx.pages)
    yield url, ctx
    for page in ctx.pages:
        if page not in before:
            page.close()


def ready(page, views: int = 1, timeout: float = 60_000) -> None:
    page.wait_for_function(f"() => (window.studio && window.studio.ready && window.studio.views >= {views} "
                           "&& window.studio.view && window.studio.view.ok)", timeout=timeout)


def views(page) -> int:
    return page.evaluate("window.studio.views")


def set_slider(page, name: str, value) -> None:
    """Move the slider ``name`` to ``value`` as a drag ends (an input event), wait for the
    picture drawn with it and its 3D view."""
    n = views(page)
    page.locator(f'input[type=range][name="{name}"]').fill(str(value))
    page.wait_for_function(f"() => (window.studio.views > {n} && window.studio.idle "
                           "&& window.studio.glbView === window.studio.views)", timeout=60_000)


def cut_loops(path: Path) -> list:
    """The closed outlines of a DXF as ezdxf reads them: (layer, bounding-box width, height)."""
    import ezdxf
    from ezdxf import bbox
    doc = ezdxf.readfile(str(path))
    out = []
    for e in doc.modelspace():
        if e.dxftype() in ("LWPOLYLINE", "POLYLINE", "CIRCLE"):
            b = bbox.extents([e])
            out.append((e.dxf.layer, round(b.size.x, 6), round(b.size.y, 6)))
    return out


def test_from_the_gallery_to_a_cutting_sheet(pages, tmp_path):
    OUT.mkdir(exist_ok=True)
    url, ctx = pages
    page = ctx.new_page()
    page.goto(url)
    ready(page)
    # the gallery opens at the start: every card has a picture and a purpose
    page.wait_for_selector("#gallery[open] .card")
    cards = page.locator("#cards .card")
    assert cards.count() >= 30
    page.wait_for_function("() => [...document.querySelectorAll('#cards .card img')].slice(0, 8)"
                           ".every(i => i.complete && i.naturalWidth > 0)", timeout=HANG_GUARD)
    page.screenshot(path=str(OUT / "studio-gallery.png"))
    page.fill("#gallery-search", "tray")
    tray = page.locator('#cards .card[data-id="generator/divider_tray"]')
    assert tray.is_visible()
    page.wait_for_function("() => (document.querySelector('#cards .card[data-id=\"generator/divider_tray\"] img').naturalWidth > 0)",
                           timeout=60_000)
    n = views(page)
    tray.click()
    page.wait_for_function(f"() => (window.studio.views > {n} && window.studio.view.ok)", timeout=60_000)
    assert page.inner_text("#title") == "Divider tray"
    names = page.eval_on_selector_all("#params input[type=range]", "els => els.map(e => e.name)")
    assert {"rows", "cols", "thickness"} <= set(names), names
    # turn the 3D view by dragging it: the camera stays where it was left on the next picture
    page.wait_for_function("() => window.studio.glbView === window.studio.views", timeout=60_000)
    box = page.locator("#viewer3d canvas").bounding_box()
    before = page.evaluate("window.aidl3d.camera()")
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.down()
    page.mouse.move(box["x"] + box["width"] / 2 + 120, box["y"] + box["height"] / 2 - 40, steps=8)
    page.mouse.up()
    turned = page.evaluate("window.aidl3d.camera()")
    assert max(abs(a - b) for a, b in zip(turned, before)) > 1.0, (before, turned)
    # the gallery's tray is 3 x 4 already: try 2 x 5, then back to what was asked for
    set_slider(page, "rows", 2)
    assert page.evaluate("window.aidl3d.camera()") == pytest.approx(turned, abs=1e-9)
    set_slider(page, "cols", 5)
    parts3d = page.evaluate("window.aidl3d.parts")
    assert sum("row_divider" in p for p in parts3d) == 1, parts3d
    assert sum("col_divider" in p for p in parts3d) == 4, parts3d
    set_slider(page, "rows", 3)
    set_slider(page, "cols", 4)
    set_slider(page, "thickness", 4)
    set_slider(page, "thickness", 3)
    assert page.evaluate("window.studio.view.values") == {}     # the program's own values
    parts3d = page.evaluate("window.aidl3d.parts")
    # 3 x 4 compartments: 2 row dividers and 3 column dividers besides the box's panels
    assert sum("row_divider" in p for p in parts3d) == 2, parts3d
    assert sum("col_divider" in p for p in parts3d) == 3, parts3d
    page.screenshot(path=str(OUT / "studio-tray.png"))

    # the cutting sheet: every part nested on 600 x 400 mm, as DXF, re-read by ezdxf
    with page.expect_download() as got:
        page.click('#downloads button[data-ext="dxf"]')
    dxf = tmp_path / got.value.suggested_filename
    got.value.save_as(dxf)
    assert dxf.name.endswith("-sheet.dxf")
    outlines = [l for l in cut_loops(dxf) if l[0].upper().startswith("CUT")]
    # the design's numbers: a 160 x 110 x 40 mm tray (outside) of 3 mm sheet, dividers
    # 2 x 0.3 mm clearance short of the inside (154 - 0.6, 104 - 0.6) and 3 mm lower than
    # the walls; each outline grown by the program's kerf (0.15 mm), turned 0 or 90 degrees
    k = 0.15
    design = [(160, 110), (160, 40), (160, 40), (40, 110), (40, 110),
              (153.4, 37), (153.4, 37), (103.4, 37), (103.4, 37), (103.4, 37)]
    want = sorted(sorted((w + k, h + k)) for w, h in design)
    got_sizes = sorted(sorted((w, h)) for _, w, h in outlines)
    assert len(got_sizes) == len(want)
    for g, w in zip(got_sizes, want):
        assert g == pytest.approx(w, abs=1e-6)
    assert {l[0] for l in outlines} >= {"CUT-kit.tray.row_divider[1]", "CUT-kit.tray.col_divider[2]"}

    # hover: `aidl docs` for the name under the mouse
    at = page.evaluate("""() => { const v = window.studio.editor.view;
        const i = v.state.doc.toString().indexOf('divider_tray(') + 3;
        const c = v.coordsAtPos(i); return [c.left + 2, (c.top + c.bottom) / 2]; }""")
    page.mouse.move(at[0], at[1])
    page.wait_for_selector(".cm-tooltip", timeout=20_000)
    assert "compartments" in page.inner_text(".cm-tooltip")
    page.mouse.move(5, 5)

    # edit the code: a misspelt call gives a located error under the code and in the editor
    page.evaluate("""() => { const v = window.studio.editor.view;
        const at = v.state.doc.toString().indexOf('divider_tray(');
        v.dispatch({changes: {from: at, to: at + 'divider_tray'.length, insert: 'divider_trey'}}); }""")
    page.wait_for_function("() => (window.studio.view && !window.studio.view.ok)", timeout=60_000)
    page.wait_for_selector("#diagnostics li.error")
    text = page.inner_text("#diagnostics li.error")
    assert "divider_trey" in text and "divider_tray" in text, text    # did you mean
    page.wait_for_selector(".cm-lintRange-error")
    page.screenshot(path=str(OUT / "studio-error.png"))
    page.evaluate("""() => { const v = window.studio.editor.view;
        const at = v.state.doc.toString().indexOf('divider_trey(');
        v.dispatch({changes: {from: at, to: at + 'divider_trey'.length, insert: 'divider_tray'}}); }""")
    page.wait_for_function("() => (window.studio.view && window.studio.view.ok)", timeout=60_000)
    svg = page.evaluate("window.studio.view.svg")

    # the share link carries the program and the values: a new page draws the same part
    page.evaluate("window.studio.shared = null")
    page.click("#share")
    page.wait_for_function("() => window.studio.shared")
    link = page.evaluate("window.studio.shared")
    assert "#p=" in link and len(link) < 8000
    other = ctx.new_page()
    other.goto(link)
    ready(other)
    other.wait_for_function("() => (window.studio.idle)", timeout=60_000)
    assert other.evaluate("window.studio.view.values") == page.evaluate("window.studio.view.values")
    assert other.evaluate("window.studio.view.svg") == svg
    # the embed shows the same part with its sliders and no code pane
    page.keyboard.press("Escape")                   # close the share dialog
    page.evaluate("window.studio.shared = null")
    page.click("#embed")
    page.wait_for_function("() => window.studio.shared")
    iframe = page.evaluate("window.studio.shared")
    assert iframe.startswith("<iframe src=\"") and "/embed#p=" in iframe
    embed_url = iframe.split('"')[1]
    emb = ctx.new_page()
    emb.goto(embed_url)
    ready(emb)
    assert emb.evaluate("window.studio.view.svg") == svg
    assert not emb.locator("#code").is_visible()
    assert emb.locator('#params input[type=range][name="rows"]').is_visible()
    emb.wait_for_function("() => window.studio.glbView === window.studio.views", timeout=60_000)
    emb.screenshot(path=str(OUT / "studio-embed.png"))


def test_describe_the_part_with_a_replayed_model(pages, tmp_path):
    """The "Describe the part" box against a TEST DOUBLE of a model endpoint: a local server
    that replays two recorded answers (the first with a mistake the loop sends back)."""
    from model_double import recorded, replaying
    answers = recorded("tray_3x4")["answers"]
    with replaying(answers) as (base, requests):
        env = {"AIDL_STUDIO_MODEL_URL": base, "AIDL_STUDIO_MODEL": "replay"}
        with studio(env=env) as (url, _proc):
            ctx = pages[1]
            page = ctx.new_page()
            page.goto(url)
            ready(page)
            page.keyboard.press("Escape")               # close the gallery
            assert page.locator("#describe").is_visible()
            page.fill("#describe-text", "a tray with 3 x 4 compartments, 3 mm plywood")
            n = views(page)
            page.click("#describe-go")
            page.wait_for_function(f"() => (window.studio.views > {n} && window.studio.view.ok "
                                   "&& document.querySelectorAll('#rounds li').length >= 2)",
                                   timeout=HANG_GUARD)
            rounds = page.locator("#rounds li")
            assert "error" in rounds.nth(0).inner_text()
            assert "checks" in rounds.nth(1).inner_text()
            assert "divider_tray" in page.evaluate("window.studio.state.source")
            page.screenshot(path=str(OUT / "studio-describe.png"))
        assert len(requests) == 2


def test_without_a_model_endpoint_the_box_is_hidden(pages):
    url, ctx = pages                        # the shared studio: AIDL_STUDIO_MODEL_URL=""
    page = ctx.new_page()
    page.goto(url)
    ready(page)
    assert page.locator("#describe").is_hidden()


def test_a_drawing_uploaded_in_the_page_is_read_by_the_program(pages, tmp_path):
    """"Your drawings": a program naming a DXF that is not there gets E0130 under the code;
    uploading the file through the page's file field compiles it, and the file is listed."""
    board = tmp_path / "board.dxf"
    board.write_bytes((ROOT / "examples" / "parts" / "pcb_board.dxf").read_bytes())
    prog = ('units mm\nsolid lid {\n    d = Drawing2D("board.dxf", layer="Edge.Cuts")\n'
            '    Fixed(d.origin)\n}\n')
    url, ctx = pages
    page = ctx.new_page()
    page.goto(url)
    ready(page)
    page.keyboard.press("Escape")
    page.evaluate("""(text) => { const v = window.studio.editor.view;
        v.dispatch({changes: {from: 0, to: v.state.doc.length, insert: text}}); }""", prog)
    page.wait_for_function("() => window.studio.view && !window.studio.view.ok "
                           "&& window.studio.idle", timeout=60_000)
    assert "E0130" in page.inner_text("#diagnostics li.error")
    n = views(page)
    page.click("#uploads summary")
    page.set_input_files("#upload", str(board))
    page.wait_for_function(f"() => window.studio.views > {n} && window.studio.view.ok",
                           timeout=60_000)
    page.wait_for_selector("#files li")
    assert "board.dxf" in page.inner_text("#files")
    assert "<path" in page.evaluate("window.studio.view.svg")


# ---------------------------------------------------------------- issue 84: the sweep
ZONE = '.param[data-name="off"] .unclean.above'
SLIDER = '#params input[type=range][name="off"]'


def load(page, url: str, width: int) -> None:
    page.set_viewport_size({"width": width, "height": 844 if width < 500 else 900})
    page.goto(url)
    page.wait_for_function("() => window.studio && window.studio.ready", timeout=HANG_GUARD)
    page.wait_for_selector("#gallery[open]", timeout=HANG_GUARD)
    page.keyboard.press("Escape")                   # the gallery (a modal dialog)
    page.wait_for_selector("#gallery:not([open])", state="attached")
    page.evaluate("""(text) => { const v = window.studio.editor.view;
        v.dispatch({changes: {from: 0, to: v.state.doc.length, insert: text}}); }""", SLID)
    page.wait_for_function("() => window.studio.sweep && window.studio.sweep.ok "
                           "&& window.studio.state.sweep.source === window.studio.state.source "
                           "&& window.studio.view && window.studio.view.ok", timeout=HANG_GUARD)


def moved(page, key: str) -> None:
    n = page.evaluate("window.studio.views")
    page.keyboard.press(key)
    page.wait_for_function(f"() => window.studio.views > {n} && window.studio.idle "
                           "&& window.studio.view.ok", timeout=HANG_GUARD)


def test_a_visitors_program_is_swept_and_its_slider_marks_the_bad_range(pages):
    OUT.mkdir(exist_ok=True)
    url, ctx = pages
    page = ctx.new_page()
    load(page, url, 1280)
    swept = page.evaluate("window.studio.sweep.params.off")
    lo, hi = swept["clean"]
    assert lo == 0 and 26.0 <= hi <= 26.5 and swept["below"] is None
    # the hatched part: from the clean end to the track's end, drawn over the slider
    zone = page.locator(ZONE)
    assert zone.is_visible()
    assert page.locator('.param[data-name="off"] .unclean.below').is_hidden()
    track = page.locator('.param[data-name="off"] .track').bounding_box()
    box = zone.bounding_box()
    thumb = 16
    want_left = track["x"] + thumb / 2 + (track["width"] - thumb) * hi / 40
    assert box["x"] == pytest.approx(want_left, abs=1.5)
    assert box["x"] + box["width"] == pytest.approx(track["x"] + track["width"] - thumb / 2,
                                                    abs=1.5)
    title = zone.get_attribute("title")
    assert title.startswith(f"above {hi:g} mm: a wall of “plate”") and "cuts nothing" in title
    assert page.inner_text('.param[data-name="off"] .unit') == f"mm (0–40, clean 0–{hi:g})"
    # its accessible description names the clean range and what is past it
    slider = page.locator(SLIDER)
    described = page.evaluate(f"""() => document.getElementById(
        document.querySelector('{SLIDER}').getAttribute('aria-describedby')).textContent""")
    assert described.startswith(f"clean from 0 to {hi:g} mm; above {hi:g} mm: a wall")
    assert slider.get_attribute("aria-valuetext") == "10 mm"
    assert page.locator('.param[data-name="off"] .sweep-note.past').count() == 0
    assert "hatched" in page.inner_text("#sweep-status")
    # the radius's whole range is clean: nothing hatched
    assert page.locator('.param[data-name="r"] .unclean:not([hidden])').count() == 0
    page.screenshot(path=str(OUT / "studio-sweep-desktop.png"))

    # from the keyboard: End takes the slider to 40 mm, into the hatched part: allowed
    # (the picture is drawn there) and said
    slider.focus()
    moved(page, "End")
    assert page.evaluate("window.studio.view.values") == {"off": "40mm"}
    assert slider.get_attribute("aria-valuetext").startswith(
        "40 mm, outside the clean range: above")
    note = page.locator('.param[data-name="off"] .sweep-note.past')
    assert note.is_visible()
    assert "40 mm is outside the range the sweep found clean (0–" in note.inner_text()
    assert "cuts nothing" in note.inner_text()
    page.screenshot(path=str(OUT / "studio-sweep-past-desktop.png"))
    moved(page, "Home")                         # back to 0 mm: clean again
    assert slider.get_attribute("aria-valuetext") == "0 mm"
    assert note.count() == 0

    # an edit: the marks are the old program's until its sweep answers, then the new one's
    sweeps = page.evaluate("window.studio.sweeps")
    page.evaluate("""() => { const v = window.studio.editor.view;
        const at = v.state.doc.toString().indexOf('width=60');
        v.dispatch({changes: {from: at, to: at + 'width=60'.length, insert: 'width=90'}}); }""")
    page.wait_for_function(f"() => window.studio.sweeps > {sweeps} && window.studio.sweep.ok",
                           timeout=HANG_GUARD)
    # a 90 mm plate: the hole leaves 45 - off - 3 mm of wall, over 0.5 mm across 0..40
    assert page.evaluate("window.studio.sweep.params.off.above") is None
    assert page.locator(ZONE).is_hidden()

    phone = ctx.new_page()
    load(phone, url, 390)
    assert phone.locator(ZONE).is_visible()
    phone.locator(SLIDER).scroll_into_view_if_needed()
    phone.screenshot(path=str(OUT / "studio-sweep-phone.png"), full_page=True)

    # holes at x = 18 and 34 mm: `off` slides through them, merging while |off - x| < 6.5
    # mm: the band next to its clean range is the `above` mark, the one past the clean
    # values between them a mark of its own
    sweeps = page.evaluate("window.studio.sweeps")
    page.evaluate("""() => { const v = window.studio.editor.view;
        const at = v.state.doc.toString().lastIndexOf('}');
        v.dispatch({changes: {from: at, to: at,
            insert: '    hole k { c = Circle(center=(18, 0), radius=3) }\\n'
                  + '    hole m { c = Circle(center=(34, 0), radius=3) }\\n'}}); }""")
    page.wait_for_function(f"() => window.studio.sweeps > {sweeps} && window.studio.sweep.ok",
                           timeout=HANG_GUARD)
    first, second = page.evaluate("window.studio.sweep.params.off.bands")
    assert 10.9 <= first["from"] <= 11.5 and 24.5 <= first["to"] <= 25.1, first
    assert 26.9 <= second["from"] <= 27.5 and second["to"] is None, second
    assert page.locator(ZONE).get_attribute("title") == first["text"]
    band = page.locator('.param[data-name="off"] .unclean.band')
    assert band.count() == 1 and band.is_visible()
    assert band.get_attribute("title") == second["text"]
    assert second["text"].startswith(f"above {second['from']:g} mm: ")
