"""Nothing of the design before a pasted program stays on the page, and the page's own notes
say one thing once (issue 113), in Debian's Chromium through Playwright against the test
process's `aidl studio` (tests/conftest.py).

- A program pasted over the board enclosure: the line under the downloads no longer names the
  enclosure's file, the header no longer says "Board enclosure" (the pasted program's own title
  once it compiles), and its 3D model is framed as a fresh design is (it kept the enclosure's
  camera: the disc drawn 2.5 x smaller).
- The kerf's field: -5, 12 and "abc" are not taken, with a note at once and the field back on
  the kerf in use; 9 mm on a disc with a 6 mm hole is tried on the design and the note names
  the hole (before: taken silently, and the download failed); 0.2 mm is taken without a note.
- A download with nothing to make says its reason once (it said it twice).
- A count broken at its odd values: the line under its slider names the clean values its
  label names ("clean at 2, 4, 6, 8, 10"), never "outside the range found clean (4-4)".
- The kerf's placeholder is whole at phone width (390 px): it was clipped to "prograr".
"""
from __future__ import annotations

import pytest

HANG = 120_000          # ms: a guard against a hung page, not a speed limit

DISC = """units mm
param hole_r = 3 mm, min = 1 mm, max = 40 mm, step = 0.5 mm

solid disc {
    body = Circle(center=(0, 0), radius=30)
    hole bore {
        c = Circle(center=(0, 0), radius=hole_r)
    }
}
"""

# a count whose odd values break the design (a located E0405): swept, its clean values 2-10 even
COUNT = """units mm
param n = 4, min = 2, max = 10, step = 1
assert n % 2 == 0, "n is even"

solid plate {
    body = Rectangle(center=(0, 0), width=10 * n, height=20)
}
"""

PASTE = """(text) => { const v = window.studio.editor.view;
    v.dispatch({ changes: { from: 0, to: v.state.doc.length, insert: text } }); }"""


def settle(page, after: int) -> None:
    page.wait_for_function(
        f"() => window.studio.views > {after} && window.studio.idle"
        " && window.studio.glbView === window.studio.views", timeout=HANG)


def paste(page, text: str) -> int:
    n = page.evaluate("window.studio.views")
    page.evaluate(PASTE, text)
    return n


def kerf(page, text: str) -> str:
    page.fill("#kerf", text)
    page.press("#kerf", "Enter")
    return page.inner_text("#kerf-note")


def test_a_pasted_program_keeps_nothing_of_the_design_before(studio_page, tmp_path):
    page = studio_page
    n = page.evaluate("window.studio.views")
    page.click("#open-gallery")
    page.click('#cards .card[data-id="generator/board_enclosure"]')
    settle(page, n)
    assert page.inner_text("#title") == "Board enclosure"
    with page.expect_download() as got:
        page.click('#downloads button[data-ext="dxf"]')
    got.value.save_as(tmp_path / "case.dxf")
    page.wait_for_function("() => /bytes/.test(document.getElementById('download-status').textContent)")
    # the enclosure's 3D turned by the keyboard: the camera away from its framing
    page.focus("#viewer3d canvas")
    for _ in range(6):
        page.keyboard.press("ArrowLeft")
    turned = page.evaluate("window.aidl3d.camera()")
    framed = page.evaluate("window.aidl3d.framed")

    n = paste(page, DISC)
    # at once: nothing of the enclosure in the header or under the downloads
    assert page.inner_text("#title") == ""
    assert page.inner_text("#download-status") == ""
    settle(page, n)
    assert page.inner_text("#title") == "Disc"
    assert page.inner_text("#download-status") == ""
    # the disc framed as a fresh design is: the camera where Fit puts it
    assert page.evaluate("window.aidl3d.framed") > framed
    now = page.evaluate("window.aidl3d.camera()")
    assert now != pytest.approx(turned, abs=1e-6)
    page.evaluate("window.aidl3d.frame()")
    assert page.evaluate("window.aidl3d.camera()") == pytest.approx(now, abs=1e-6)


def test_the_kerf_is_checked_in_its_field(studio_page):
    page = studio_page
    if page.inner_text("#title") != "Disc":
        n = paste(page, DISC)
        settle(page, n)
    assert page.input_value("#kerf") == ""
    note = kerf(page, "-5")
    assert "0 mm or more" in note and "-5" in note and "program's kerf is used" in note, note
    assert page.input_value("#kerf") == ""
    note = kerf(page, "12")
    assert "at most 10 mm" in note, note
    assert kerf(page, "abc").startswith("“abc” is not a number"), page.inner_text("#kerf-note")
    assert page.evaluate("window.studio.state.kerf") is None
    # 9 mm: each outline moves 4.5 mm, more than the 3 mm hole's radius: said at once
    kerf(page, "9")
    page.wait_for_function("() => /cannot be made/.test(document.getElementById('kerf-note').textContent)",
                           timeout=HANG)
    note = page.inner_text("#kerf-note")
    assert "radius 3 mm" in note and "4.5 mm" in note, note
    assert page.evaluate("window.studio.state.kerf") == 9
    # the hole made larger than the offset: the kerf tried again on the settled picture, fine
    n = page.evaluate("window.studio.views")
    page.locator('input[type=range][name="hole_r"]').fill("6")
    settle(page, n)
    page.wait_for_function("() => document.getElementById('kerf-note').textContent === ''", timeout=HANG)
    kerf(page, "0,2")
    assert page.input_value("#kerf") == "0.2"
    page.wait_for_function("() => !/trying/.test(document.getElementById('kerf-note').textContent)",
                           timeout=HANG)
    assert page.inner_text("#kerf-note") == ""
    kerf(page, "")
    assert page.evaluate("window.studio.state.kerf") is None


def test_nothing_to_make_says_its_reason_once(studio_page):
    page = studio_page
    if page.inner_text("#title") != "Disc":
        n = paste(page, DISC)
        settle(page, n)
    # the hole as large as the disc: nothing is left to cut
    n = page.evaluate("window.studio.views")
    page.locator('input[type=range][name="hole_r"]').fill("40")
    page.wait_for_function(f"() => window.studio.views > {n} && window.studio.idle", timeout=HANG)
    page.click('#downloads button[data-ext="dxf"]')
    page.wait_for_function("() => /^DXF: /.test(document.getElementById('download-status').textContent)",
                           timeout=HANG)
    said = page.inner_text("#download-status")
    assert said.startswith("DXF: nothing to make with these values: "), said
    reason = said.removeprefix("DXF: nothing to make with these values: ")
    assert reason and said.count(reason[:24]) == 1, said
    # the page's own rule on a refusal whose sentence lacks its reason: the first message added
    assert page.evaluate("""window.studio.refusal({ error: 'the program does not compile with these values',
        diagnostics: [{ message: 'unknown name `x`' }] }, 422)""") == \
        "the program does not compile with these values: unknown name `x`"


def test_a_counts_notes_name_the_clean_values_its_label_names(studio_page):
    page = studio_page
    n = paste(page, COUNT)
    settle(page, n)
    page.wait_for_function("() => window.studio.sweep && window.studio.sweep.ok"
                           " && /clean at/.test(document.querySelector('[data-name=\"n\"] .unit').textContent)",
                           timeout=HANG)
    unit = page.inner_text('[data-name="n"] .unit')
    assert unit == "(2–10, clean at 2, 4, 6, 8, 10)", unit
    note = page.evaluate("document.querySelector('[data-name=\"n\"] .sweep-note').textContent")
    assert note.startswith("clean at 2, 4, 6, 8, 10; "), note
    n = page.evaluate("window.studio.views")
    page.locator('input[type=range][name="n"]').fill("5")
    page.wait_for_function(f"() => window.studio.views > {n} && window.studio.idle", timeout=HANG)
    note = page.inner_text('[data-name="n"] .sweep-note')
    assert note.startswith("5 is not one of the values the sweep found clean (2, 4, 6, 8, 10)"), note
    assert "(4–4)" not in note and "outside the range" not in note, note


@pytest.mark.parametrize("mobile", [True, False])
def test_the_kerf_placeholder_fits_at_phone_width(chromium_browser, studio_url, mobile):
    # a phone (390 x 844, touch) and a desktop window as narrow: the latter drew a number
    # field's spin buttons inside it, and "program's" was clipped to "prograr"
    ctx = chromium_browser.new_context(viewport={"width": 390, "height": 844}, is_mobile=mobile,
                                       has_touch=mobile, device_scale_factor=2 if mobile else 1)
    try:
        ctx.route("**/api/thumb/**", lambda r: r.abort())
        phone = ctx.new_page()
        phone.goto(studio_url)
        phone.wait_for_function("() => window.studio && window.studio.ready", timeout=HANG)
        phone.keyboard.press("Escape")
        # the placeholder's width in the field's own font against the room inside the field
        # (a text field: no spin buttons take part of it)
        kind, room, text = phone.evaluate("""() => {
            const f = document.getElementById('kerf'), cs = getComputedStyle(f);
            const c = document.createElement('canvas').getContext('2d');
            c.font = `${cs.fontStyle} ${cs.fontWeight} ${cs.fontSize} ${cs.fontFamily}`;
            const room = f.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight);
            return [f.type, room, c.measureText(f.placeholder).width]; }""")
        assert kind == "text" and text <= room, (kind, text, room)
    finally:
        ctx.close()
