"""`aidl serve` in a real browser: Debian's Chromium driven by Playwright for Python.

The server runs as a real subprocess (`aidl serve FILE --port 0`) on a copy of
examples/telephone.aidl; the page is read back through its SVG coordinates.  The screenshot is
saved as out/serve-telephone.png (AIDL_SCREENSHOT overrides the path).
"""
from __future__ import annotations

import os
import re
import shutil
import statistics
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
pytest.importorskip("starlette")
from conftest import skip_without_chromium  # noqa: E402

skip_without_chromium()

from benchmarks.serve.serve_latency import chromium, move_slider, open_page, p95, save_latency, served  # noqa: E402


@pytest.fixture(scope="module")
def browser():
    """One Chromium for the tests here (a launch costs about 3 s); each test serves its own
    file and opens it in the context's first page (``open_page``).  The 3D view's test, on
    SwiftShader, is tests/test_serve_browser_3d.py (a second sync Playwright cannot start
    inside this one)."""
    with chromium() as ctx:
        yield ctx


def outline(page):
    """The telephone's solid as subpaths of model coordinates (y up), read from the page: the
    end point of every segment (``M``/``L`` points and the end points of ``A`` arcs)."""
    d = page.locator("#viewer svg #part-desk_telephone path").first.get_attribute("d")
    subs, cur, toks = [], None, re.findall(r"[MLAZ]|[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", d)
    i = 0
    while i < len(toks):
        c = toks[i]
        if c in "MLAZ":
            cmd, i = c, i + 1
            if c == "M":
                cur = []
                subs.append(cur)
            continue
        n = 7 if cmd == "A" else 2
        vals = [float(v) for v in toks[i:i + n]]
        cur.append((vals[-2], -vals[-1]))
        i += n
    return subs


def base_and_handset(page):
    """(base width at y = 0, top of the drawing, x centre of the top edge, same outline?)."""
    subs = outline(page)
    outer = max(subs, key=lambda s: max(y for _, y in s))        # holds the highest point
    top = max(y for _, y in outer)
    top_xs = [x for x, y in outer if abs(y - top) < 1e-6]
    bottom_xs = [x for x, y in outer if abs(y) < 1e-6]
    return (max(bottom_xs) - min(bottom_xs), top, (max(top_xs) + min(top_xs)) / 2,
            bool(bottom_xs))


def test_live_preview_of_the_telephone(browser, tmp_path):
    src = (ROOT / "examples" / "telephone.aidl").read_text()
    f = tmp_path / "telephone.aidl"
    f.write_text(src)
    shot = Path(os.environ.get("AIDL_SCREENSHOT", ROOT / "out" / "serve-telephone.png"))
    shot.parent.mkdir(parents=True, exist_ok=True)
    ctx = browser
    with served(f) as url:
        page = open_page(ctx, url)
        # the picture is there, with the file's values
        assert page.locator("#viewer svg #part-desk_telephone").count() == 1
        page.wait_for_function("/degrees of freedom left in 8 structures/"
                               ".test(document.querySelector('#dof-summary').textContent)")
        assert page.locator("#dof tbody tr").count() == 8
        w0, top0, cx0, attached0 = base_and_handset(page)
        assert w0 == pytest.approx(160, abs=1e-3) and attached0
        assert top0 == pytest.approx(90 + 16 + 12, abs=1e-3)        # base_h + prong_h + grip_h
        slider = page.locator('input[type=range][name="base_w"]')
        assert slider.get_attribute("min") == "40" and slider.get_attribute("max") == "320"

        # move base_w: the base widens by exactly the difference, the handset stays on the
        # cradle (same outline, same height) and centred over the base
        lat = [move_slider(page, "base_w", v) for v in (170, 180, 190, 200, 210, 220, 200)]
        w1, top1, cx1, attached1 = base_and_handset(page)
        assert w1 == pytest.approx(200, abs=1e-3)
        assert attached1 and top1 == pytest.approx(top0, abs=1e-3)
        assert cx1 == pytest.approx(0, abs=1e-3)
        assert "--set base_w=200mm" in page.locator("#setline").input_value()
        assert slider.get_attribute("max") == "320"           # the span stays the file's
        assert page.locator('input[name="base_w-value"]').input_value() == "200"
        # the download link carries the chosen value and gives the same picture's SVG
        href = page.locator('#downloads a[data-fmt="svg"]').get_attribute("href")
        assert href == "/download/svg?set=base_w%3D200mm"
        page.screenshot(path=str(shot))

        # a broken edit: the error is shown, the last good picture stays
        save_ms = [save_latency(page, f, src.replace("param base_h = 90 mm",
                                                     "param base_h = 90 mm + lid_h"))]
        assert page.locator("#diagnostics li.error").count() >= 1
        line = next(i for i, s in enumerate(src.splitlines(), 1) if s.startswith("param base_h"))
        assert f"line {line}:24" in page.locator("#diagnostics li.error").first.inner_text()
        assert page.locator("#stale").is_visible()
        assert base_and_handset(page)[0] == pytest.approx(200, abs=1e-3)   # old picture kept
        page.locator("#diagnostics li.error").first.click()
        assert page.locator("#source li.hl").inner_text().startswith("param base_h")
        page.screenshot(path=str(shot.with_name(shot.stem + "-error.png")))

        # fixed: the error goes, the picture is redrawn with the kept slider value
        save_ms.append(save_latency(page, f, src.replace("param base_h = 90 mm",
                                                         "param base_h = 100 mm")))
        assert page.locator("#diagnostics li.error").count() == 0
        assert not page.locator("#stale").is_visible()
        w2, top2, _, attached2 = base_and_handset(page)
        assert w2 == pytest.approx(200, abs=1e-3) and attached2
        assert top2 == pytest.approx(100 + 16 + 12, abs=1e-3)
    print(f"\nslider->picture ms: median {statistics.median(lat):.1f}, p95 {p95(lat):.1f}; "
          f"save->picture ms: {', '.join(f'{s:.0f}' for s in save_ms)}")


KINDS = """units mm
param width = 40 mm, min=20 mm, max=80 mm, step=2 mm
param tilt = 10 deg
param holes = true
param label = "AIDL tag"

solid tag {
    body = Rectangle(center=(0, 0), width=width, height=20, rotation=tilt)
    if holes {
        hole h { c = Circle(center=(0, 0), radius=3) }
    }
}
"""


def test_customizer_controls_zoom_and_set_line(browser, tmp_path):
    (ROOT / "out").mkdir(exist_ok=True)
    f = tmp_path / "tag.aidl"
    f.write_text(KINDS)
    ctx = browser
    with served(f) as url:
        page = open_page(ctx, url)
        r = page.locator('input[type=range][name="width"]')
        assert (r.get_attribute("min"), r.get_attribute("max"), r.get_attribute("step")) == ("20", "80", "2")
        assert "mm · 20…80" in page.locator('.param[data-name="width"] .unit').inner_text()
        assert "deg" in page.locator('.param[data-name="tilt"] .unit').inner_text()
        assert page.locator('input[type=checkbox][name="holes"]').is_checked()
        assert page.locator('input[type=text][name="label"]').input_value() == "AIDL tag"
        loops = lambda: page.locator("#viewer svg #part-tag path").first.get_attribute("d").count("M")
        assert loops() == 2                                  # the outline and the hole
        # the checkbox removes the hole; the text box changes a string param
        n = page.evaluate("window.aidl.sliderMs.length")
        page.locator('input[type=checkbox][name="holes"]').uncheck()
        page.wait_for_function(f"window.aidl.sliderMs.length > {n} && !window.aidlBusy()")
        assert loops() == 1
        page.locator('input[type=text][name="label"]').fill("it's")
        move_slider(page, "width", 60)
        line = page.locator("#setline").input_value()
        assert "--set width=60mm" in line and "--set holes=false" in line
        assert """--set 'label="it'\\''s"'""" in line          # shell-quoted, AIDL string
        # zoom with the wheel, then Fit restores the writer's viewBox
        svg = page.locator("#viewer svg")
        fit = svg.get_attribute("viewBox")
        page.mouse.move(400, 400)
        page.mouse.wheel(0, -400)
        page.wait_for_function(f"document.querySelector('#viewer svg').getAttribute('viewBox') != '{fit}'")
        zoomed = [float(t) for t in svg.get_attribute("viewBox").split()]
        assert zoomed[2] < float(fit.replace(",", " ").split()[2])
        page.screenshot(path=str(ROOT / "out" / "serve-tag-zoomed.png"))
        page.locator("#fit").click()
        assert svg.get_attribute("viewBox") == fit


LOCK = (Path(__file__).resolve().parent / "programs" / "preview" / "lock.aidl").read_text()


def test_shape_checks_follow_the_picture(browser, tmp_path):
    """A slider move shows its picture, then its shape checks (W0501: the shackle refills
    the key hole) arrive in a second message and are listed without moving the slider."""
    f = tmp_path / "lock.aidl"
    f.write_text(LOCK)
    ctx = browser
    with served(f) as url:
        page = open_page(ctx, url)
        assert "W0501" not in page.locator("#diagnostics").inner_text()
        move_slider(page, "shackle_y", 14)
        page.wait_for_function("/W0501/.test(document.querySelector('#diagnostics').textContent)")
        assert page.locator('input[type=range][name="shackle_y"]').input_value() == "14"
        assert "--set shackle_y=14mm" in page.locator("#setline").input_value()
        move_slider(page, "shackle_y", 30)               # moved off the hole: W0501 goes
        page.wait_for_function("!/W0501/.test(document.querySelector('#diagnostics').textContent)")


PLATE = """units mm
param w = 40 mm
solid plate {
    body = Rectangle(center=(0, 0), width=w, height=20)
    hole bore { c = Circle(center=(0, 0), radius=5) }
}
"""


def _wait_ready(page, url):
    page.goto(url)
    page.wait_for_function("window.aidl && window.aidl.ready")


def test_reload_while_broken_shows_the_last_good_picture(browser, tmp_path):
    """Issue 28: a page opened or reloaded while the file is broken draws the picture the
    server kept, marked as the last good one; with no good compile yet it says so."""
    f = tmp_path / "plate.aidl"
    f.write_text(PLATE)
    ctx = browser
    with served(f) as url:
        page = open_page(ctx, url)
        good = page.locator("#viewer svg").inner_html()
        assert page.locator("#viewer svg #part-plate").count() == 1
        save_latency(page, f, PLATE.replace("width=w,", "width=w"))       # a syntax error
        assert page.locator("#diagnostics li.error").count() >= 1
        page.reload()
        page.wait_for_function("window.aidl && window.aidl.ready")
        assert "error" in page.locator("#status").inner_text()
        assert page.locator("#viewer svg #part-plate").count() == 1     # kept by the server
        assert page.locator("#viewer svg").inner_html() == good
        assert page.locator("#stale").is_visible()
        assert page.locator("#stale").inner_text() == \
            "showing the last good picture: the program has errors"
        assert page.locator("#diagnostics li.error").count() >= 1
        (ROOT / "out").mkdir(exist_ok=True)
        page.screenshot(path=str(ROOT / "out" / "serve-reload-broken.png"))
    g = tmp_path / "broken.aidl"
    g.write_text(PLATE.replace("width=w,", "width=w"))
    with served(g) as url:
        page = ctx.pages[0] if ctx.pages else ctx.new_page()
        _wait_ready(page, url)
        assert page.locator("#viewer svg").count() == 0
        assert page.locator("#stale").is_visible()
        assert page.locator("#stale").inner_text().startswith("no picture yet: the program has "
                                                             "not compiled without errors")
        page.reload()
        page.wait_for_function("window.aidl && window.aidl.ready")
        assert page.locator("#stale").inner_text().startswith("no picture yet")
        page.screenshot(path=str(ROOT / "out" / "serve-no-picture-yet.png"))
        # fixed: the picture appears and the note goes
        save_latency(page, g, PLATE)
        assert page.locator("#viewer svg #part-plate").count() == 1
        assert not page.locator("#stale").is_visible()
