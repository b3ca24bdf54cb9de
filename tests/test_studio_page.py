"""The studio's page on a phone, from the keyboard, and its missing pieces (issue 72), in Debian's
Chromium driven by Playwright against one real `aidl studio --port 0` (the test process's,
tests/conftest.py).

* axe-core (tests/vendor/axe-core, MPL-2.0) run in the page: no serious or critical violation on
  the main page and the gallery at 390 x 844 (a phone) and 1440 x 900; screenshots of both
  (out/studio-page-*.png); at 390 px the panes are stacked and usable, nothing is cut off,
  touch targets are 44 px, the gallery's Close button is where a finger taps.
* the keyboard alone: Tab leaves the code pane, the focus is visible, a card chosen from the
  gallery leaves the focus on the parameters, the 3D canvas takes the focus and turns with the
  arrow keys.
* slider ends and a default off the step grid are exact values (480, not 479.6).
* "Open my drawing": a DXF opened as an editable design (its sizes as sliders) and as a drawing.
* the 3D view: Fit, a refit when the part outgrows the view, a share link framed on its values.

Skipped without Chromium (CI step 3 installs it and runs it again)."""
from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "out"
AXE = ROOT / "tests" / "vendor" / "axe-core" / "axe.min.js"
pytest.importorskip("playwright")
if not Path("/usr/bin/chromium").exists():
    pytest.skip("needs Debian's chromium (apt-get install chromium; .ci/run installs it)",
                allow_module_level=True)


PHONE = {"width": 390, "height": 844}
DESKTOP = {"width": 1440, "height": 900}
# ms: each page wait ends on its outcome (the page's answer); this only stops a hung page,
# never a claim on this machine's speed (a loaded machine waits longer, and passes)
HANG_GUARD = 300_000


@pytest.fixture(scope="module")
def server(studio_url):
    return studio_url                   # the test process's studio (tests/conftest.py)


@pytest.fixture(scope="module")
def browser(chromium_browser):
    ctx = chromium_browser.new_context(viewport={"width": 1400, "height": 900})
    try:
        yield ctx
    finally:
        ctx.close()


def opened(ctx, url: str, size: dict, gallery: bool = False):
    """A new page of the studio at ``size`` with axe-core loaded, the tray drawn and its 3D
    there; the gallery left open when ``gallery``."""
    page = ctx.new_page()
    page.set_viewport_size(size)
    page.add_init_script(path=str(AXE))     # before the page's scripts, not under its CSP
    page.goto(url)
    page.wait_for_function("() => (window.studio && window.studio.ready && window.studio.view "
                           "&& window.studio.view.ok && window.studio.idle "
                           "&& window.studio.glbView === window.studio.views)", timeout=HANG_GUARD)
    page.wait_for_selector("#gallery[open] .card")
    if not gallery:
        page.keyboard.press("Escape")
        page.wait_for_selector("#gallery:not([open])", state="attached")
    return page


def serious(page) -> list:
    """axe-core's serious and critical violations of the page as it is now."""
    found = page.evaluate("""async () => {
        const r = await axe.run(document, { resultTypes: ["violations"] });
        return r.violations.map((v) => ({ id: v.id, impact: v.impact, help: v.help,
            nodes: v.nodes.slice(0, 4).map((n) => n.target.join(" ") + ": " + n.failureSummary) }));
    }""")
    return [v for v in found if v["impact"] in ("serious", "critical")]


def idle_after(page, n: int) -> None:
    page.wait_for_function(f"() => (window.studio.views > {n} && window.studio.idle "
                           "&& window.studio.glbView === window.studio.views)", timeout=HANG_GUARD)


def views(page) -> int:
    return page.evaluate("window.studio.views")


def set_program(page, text: str) -> None:
    n = views(page)
    page.evaluate("""(text) => { const v = window.studio.editor.view;
        v.dispatch({changes: {from: 0, to: v.state.doc.length, insert: text}}); }""", text)
    page.wait_for_function(f"() => (window.studio.views > {n} && window.studio.view.ok "
                           "&& window.studio.idle)", timeout=HANG_GUARD)


@pytest.mark.parametrize("size", [PHONE, DESKTOP], ids=["phone", "desktop"])
def test_no_serious_accessibility_violation_and_the_phone_layout(server, browser, size):
    OUT.mkdir(exist_ok=True)
    name = "phone" if size is PHONE else "desktop"
    page = opened(browser, server, size, gallery=True)
    # the first pictures there (or failed: their speed is not what this test is about)
    page.wait_for_function("() => [...document.querySelectorAll('#cards .card img')].slice(0, 2)"
                           ".every(i => i.complete)", timeout=HANG_GUARD)
    found = serious(page)
    assert found == [], "\n".join(f"{v['id']} {v['impact']}: {v['nodes']}" for v in found)
    page.screenshot(path=str(OUT / f"studio-page-{name}-gallery.png"))
    # the gallery's Close: inside the screen, 44 px tall, and the element a tap there hits
    close = page.locator("#gallery-close")
    box = close.bounding_box()
    assert box["x"] >= 0 and box["x"] + box["width"] <= size["width"]
    assert box["y"] >= 0 and box["y"] + box["height"] <= size["height"]
    if size is PHONE:
        assert box["height"] >= 44 and box["width"] >= 44
    hit = page.evaluate(f"document.elementFromPoint({box['x'] + box['width'] / 2}, "
                        f"{box['y'] + box['height'] / 2}).id")
    assert hit == "gallery-close"
    close.click()
    page.wait_for_selector("#gallery:not([open])", state="attached")
    found = serious(page)
    assert found == [], "\n".join(f"{v['id']} {v['impact']}: {v['nodes']}" for v in found)
    page.screenshot(path=str(OUT / f"studio-page-{name}.png"))
    page.screenshot(path=str(OUT / f"studio-page-{name}-full.png"), full_page=True)
    width = size["width"]
    # nothing wider than the screen: no sideways scrolling, no parameter cut off
    assert page.evaluate("document.scrollingElement.scrollWidth") <= width
    cut = page.evaluate(f"""() => [...document.querySelectorAll(
        '#right input, #right select, #right button, #params label')].filter((e) => e.offsetParent !== null)
        .map((e) => [e.id || e.name || e.textContent, e.getBoundingClientRect().right])
        .filter(([, r]) => r > {width} + 0.5)""")
    assert cut == []
    flat = page.locator("#flat").bounding_box()
    view3d = page.locator("#viewer3d").bounding_box()
    if size is PHONE:
        # stacked: each pane nearly the screen's width and a usable height
        for b in (flat, view3d):
            assert b["width"] >= width - 40 and b["height"] >= 240, b
        assert view3d["y"] >= flat["y"] + flat["height"] - 1
        # every control a finger uses is 44 px tall (and buttons as wide)
        small = page.evaluate("""() => [...document.querySelectorAll(
            'button, select, input[type=number], input[type=range], input[type=text], summary')]
            .filter((e) => e.offsetParent !== null && !e.closest('dialog:not([open])'))
            .map((e) => [e.id || e.name || e.textContent.trim().slice(0, 20),
                         e.getBoundingClientRect()])
            .filter(([, r]) => r.height < 43.5 || (r.width < 43.5))
            .map(([n, r]) => [n, Math.round(r.width), Math.round(r.height)])""")
        assert small == []
        canvas = page.locator("#viewer3d canvas").bounding_box()
        assert canvas["width"] >= width - 50 and canvas["height"] >= 230
    else:
        assert flat["width"] > 300 and view3d["width"] > 300 and flat["height"] > 300
    page.close()


def test_the_keyboard_reaches_every_control(server, browser):
    page = opened(browser, server, DESKTOP)
    page.click("#code .cm-content")
    for _ in range(3):
        page.keyboard.press("Tab")
    # Tab left the code pane (it does not indent: the program is unchanged)
    assert page.evaluate("!document.querySelector('#code').contains(document.activeElement)")
    assert "Tab moves on" in page.inner_text("#code-keys")
    # onwards, one Tab at a time, to the 3D view, a slider and a download, each with a ring
    seen, rings = [], []
    for _ in range(60):
        page.keyboard.press("Tab")
        got = page.evaluate("""() => { const e = document.activeElement;
            const s = getComputedStyle(e);
            return [e.tagName, e.id, e.type || "", e.dataset.ext || "",
                    s.outlineStyle !== "none" && parseFloat(s.outlineWidth) >= 2]; }""")
        seen.append(got[:4])
        rings.append(got[4])
        if got[3] == "dxf":
            break
    kinds = {(t, ty) for t, _, ty, _ in seen}
    assert ("CANVAS", "") in kinds and ("INPUT", "range") in kinds and seen[-1][3] == "dxf", seen
    assert all(rings), [s for s, r in zip(seen, rings) if not r]
    # the 3D view turns with the arrow keys and F frames all of it
    page.focus("#viewer3d canvas")
    before = page.evaluate("window.aidl3d.camera()")
    page.keyboard.press("ArrowLeft")
    turned = page.evaluate("window.aidl3d.camera()")
    assert max(abs(a - b) for a, b in zip(turned, before)) > 1.0
    framed = page.evaluate("window.aidl3d.framed")
    page.keyboard.press("f")
    assert page.evaluate("window.aidl3d.framed") == framed + 1
    # a design chosen from the gallery by the keyboard: the focus goes to its parameters
    page.focus("#open-gallery")
    page.keyboard.press("Enter")
    page.wait_for_selector("#gallery[open] .card")
    page.keyboard.type("lid")
    n = views(page)
    for _ in range(6):
        page.keyboard.press("Tab")
        if page.evaluate("document.activeElement.classList.contains('card')"):
            break
    assert page.evaluate("document.activeElement.classList.contains('card')")
    page.keyboard.press("Enter")
    page.wait_for_function(f"() => window.studio.views > {n} && window.studio.view.ok",
                           timeout=HANG_GUARD)
    assert page.evaluate("document.activeElement.id") == "params-summary"
    page.keyboard.press("Tab")
    assert page.evaluate("document.activeElement.closest('#params') !== null")
    page.close()


SLIDER = ("units mm\n"
          "param w = 120 mm, min = 0.4 mm, max = 480 mm, step = 0.8 mm\n"
          "solid plate {\n    body = Rectangle(center=(0, 0), width=w, height=40)\n}\n")


def test_slider_ends_and_an_off_grid_default_are_exact(server, browser):
    """The grid from 0.4 by 0.8 stops at 479.6 and passes 119.6 and 120.4: the slider still
    reaches 480 and the default 120 (before: 479.6, and 120 only by typing)."""
    page = opened(browser, server, DESKTOP)
    set_program(page, SLIDER)
    r = page.locator('#params input[type=range][name="w"]')
    num = page.locator('#params input[name="w-value"]')
    assert "(0.4–480)" in page.inner_text('#params .param[data-name="w"] .unit')

    def press(key: str) -> float:
        n = views(page)
        r.press(key)
        page.wait_for_function(f"() => window.studio.views > {n} && window.studio.idle",
                               timeout=HANG_GUARD)
        return float(num.input_value())
    assert press("End") == 480
    shown = page.evaluate("window.studio.view.params.find((p) => p.name === 'w').value")
    assert shown == 480                   # the server drew 480 mm
    assert press("ArrowLeft") == pytest.approx(479.6)
    assert press("ArrowRight") == 480
    assert press("Home") == pytest.approx(0.4)
    assert press("ArrowRight") == pytest.approx(1.2)
    # dragged near the default: it lands on it (120), the row no longer marked changed
    n = views(page)
    r.fill("120.1")
    page.wait_for_function(f"() => window.studio.views > {n} && window.studio.idle", timeout=HANG_GUARD)
    assert float(num.input_value()) == 120
    assert "changed" not in (page.get_attribute('#params .param[data-name="w"]', "class") or "")
    page.close()


def plate_dxf(path: Path) -> Path:
    import ezdxf
    doc = ezdxf.new(units=4)                    # millimetres
    m = doc.modelspace()
    m.add_lwpolyline([(0, 0), (120, 0), (120, 70), (0, 70)], close=True)
    for x, y in [(10, 10), (110, 10), (10, 60), (110, 60)]:
        m.add_circle((x, y), 3)
    doc.saveas(path)
    return path


def test_open_my_drawing_as_an_editable_design_and_as_a_drawing(server, browser, tmp_path):
    dxf = plate_dxf(tmp_path / "My plate (2).dxf")
    page = opened(browser, server, DESKTOP)
    n = views(page)
    page.click("#open-drawing")
    page.check('input[name="open-as"][value="infer"]')
    page.set_input_files("#drawing-file", str(dxf))
    idle_after(page, n)
    assert page.inner_text("#title") == "My_plate_2_"       # (its files: My_plate_2_.dxf)
    names = page.eval_on_selector_all("#params input[type=range]", "els => els.map(e => e.name)")
    assert {"width", "height"} <= set(names), names
    width = page.evaluate("window.studio.view.params.find((p) => p.name === 'width')")
    assert width["value"] == 120 and width["unit"] == "mm"
    assert page.evaluate("document.activeElement.id") == "params-summary"
    # its own size as a slider: 150 mm wide now, and the picture is 150 mm wide
    n = views(page)
    page.locator('#params input[type=range][name="width"]').fill("150")
    idle_after(page, n)
    assert page.evaluate("window.studio.view.ok")
    assert "width" in page.evaluate("Object.keys(window.studio.state.values)")
    # as the drawing itself
    n = views(page)
    page.click("#open-drawing")
    page.check('input[name="open-as"][value="drawing"]')
    page.set_input_files("#drawing-file", str(dxf))
    idle_after(page, n)
    src = page.evaluate("window.studio.state.source")
    assert 'Drawing2D("My_plate_2_.dxf")' in src and "120 x 70 mm" in src
    assert page.evaluate("window.aidl3d.parts").__len__() == 1
    page.close()


def test_the_3d_view_fits_and_refits(server, browser):
    page = opened(browser, server, DESKTOP)
    reach = "window.aidl3d.reach()"
    assert 0.3 < page.evaluate(reach) <= 1
    # zoomed in by the keyboard, the tray runs out of the pane; Fit brings all of it back
    page.focus("#viewer3d canvas")
    for _ in range(6):
        page.keyboard.press("+")
    assert page.evaluate(reach) > 1
    page.click("#fit3d")
    assert 0.3 < page.evaluate(reach) <= 1
    camera = page.evaluate("window.aidl3d.camera()")
    # a longer tray outgrows the view: framed again (before: it ran out of the pane)
    n = views(page)
    page.locator('#params input[type=range][name="length"]').fill("640")
    idle_after(page, n)
    assert page.evaluate(reach) <= 1
    assert page.evaluate("window.aidl3d.camera()") != camera
    # a shorter one stays as it was framed (the camera is the user's)
    camera = page.evaluate("window.aidl3d.camera()")
    n = views(page)
    page.locator('#params input[type=range][name="length"]').fill("500")
    idle_after(page, n)
    assert page.evaluate("window.aidl3d.camera()") == pytest.approx(camera, abs=1e-9)
    # a share link of the long tray opens framed on the long tray, not on the default one
    page.evaluate("window.studio.shared = null")
    page.click("#share")
    page.wait_for_function("() => window.studio.shared")
    link = page.evaluate("window.studio.shared")
    other = browser.new_page()
    other.set_viewport_size(DESKTOP)
    other.goto(link)
    other.wait_for_function("() => (window.studio.ready && window.studio.view && window.studio.view.ok "
                            "&& window.studio.idle && window.studio.glbView === window.studio.views "
                            "&& window.studio.state.params.length)", timeout=HANG_GUARD)
    assert other.evaluate("window.studio.state.values.length") == 500
    at = other.evaluate("window.aidl3d.camera()")
    other.evaluate("window.aidl3d.frame()")
    assert other.evaluate("window.aidl3d.camera()") == pytest.approx(at, abs=1e-6)
    other.close()
    page.close()
