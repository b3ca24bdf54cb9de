"""Issue 84 in a real browser (Debian's Chromium driven by Playwright, as
tests/test_studio_browser.py): a visitor's own program with a known bad range is swept in the
background after its picture; its slider shows the part of its range the sweep did not find
clean hatched, with a title and an accessible description naming what happens there; moved
there from the keyboard, the slider says so (its aria-valuetext and a line under it) and the
picture is still drawn.  Screenshots at a phone's 390 px and a desktop's 1280 px:
out/studio-sweep-phone.png, out/studio-sweep-desktop.png."""
from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "out"
pytest.importorskip("playwright")
if not Path("/usr/bin/chromium").exists():
    pytest.skip("needs Debian's chromium (apt-get install chromium; .ci/run installs it)",
                allow_module_level=True)

from benchmarks.serve_latency import chromium  # noqa: E402
from benchmarks.studio_server import studio  # noqa: E402
from test_studio_sweep import SLID  # noqa: E402

# ms: each wait ends on the page's answer; this only stops a hung page (no speed claim)
HANG_GUARD = 300_000
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


def test_a_visitors_program_is_swept_and_its_slider_marks_the_bad_range():
    OUT.mkdir(exist_ok=True)
    with studio() as (url, _proc), chromium() as ctx:
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
        assert title.startswith(f"above {hi:g} mm: a wall of `plate`") and "cuts nothing" in title
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
