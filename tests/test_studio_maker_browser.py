"""The studio as makers meet it, round four (issue 94), in Debian's Chromium through Playwright:
one `aidl studio` (two compile workers, a rate limit of 30 requests per 5 s: the page paces
itself by the rate the server states, so a window of 5 s proves what a minute proves at the
default 300/minute, in a twelfth of the time), one page per test, at a desktop's 1280 x 800 and a
phone's 390 x 844 (touch), in en-US and de-DE.

- A typed value is the value used, or a line under the field says what was used: rows (1-12)
  typed 999 is 12 ("12 is the most"), a height of -20 is 10 mm ("10 mm is the least"), "12,5"
  is 12.5 (never 125) in both locales; the server drew what the field shows.
- One thickness: the Material field sets the design's `thickness` param (the slider follows, and
  the finger box's assembled STL, re-read by trimesh, is closed and its panels that thick); a
  design without one hides the field.
- The 3D view draws on change only: no frame in 2 s of idle after its model is shown.
- Phone: a one-finger swipe over either picture scrolls the page (the picture does not pan); two
  fingers zoom the flat view; checkboxes 44 px.
- A minute of dragging one slider: 3 s against the server (no answer 429 or 503, the picture at
  the end is the slider's, the download named with the design and its values), then 60 s on
  the page's simulated clock (Playwright's clock; the page's own answers replayed): at most 28
  requests in any 5 s, under the limit of 30 (before: 31, the sweeps were not paced).
- An imported flange's bolt circle follows its diameter (70 mm: the pitch circle 75 -> 60 mm,
  the DXF re-read by ezdxf); every generator's sizes are sliders, each at its top end drawn
  with no warning (a spur gear's bore from 0 mm: no W0510).

Screenshots: out/studio-maker-*.png.
"""
from __future__ import annotations

import io
import re
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "out"
pytest.importorskip("playwright")
if not Path("/usr/bin/chromium").exists():
    pytest.skip("needs Debian's chromium (apt-get install chromium; .ci/run installs it)",
                allow_module_level=True)

from benchmarks.serve.studio_server import studio  # noqa: E402

HANG = 180_000          # ms: a guard against a hung page, not a speed limit
DESKTOP = {"viewport": {"width": 1280, "height": 800}}
PHONE = {"viewport": {"width": 390, "height": 844}, "has_touch": True, "is_mobile": True,
         "device_scale_factor": 2}


@pytest.fixture(scope="module")
def server():
    with studio("--compilers", "2", "--rate", "30/5 seconds") as (url, _proc):
        yield url


@pytest.fixture(scope="module")
def chromium(chromium_browser):
    return chromium_browser             # the test process's (tests/conftest.py)


def opened(chromium, url: str, how: dict, eid: str, locale: str = "en-US"):
    """A new page (its own context: size, touch, locale) with design ``eid`` open, its picture
    and its 3D shown."""
    ctx = chromium.new_context(locale=locale, accept_downloads=True, **how)
    ctx.route("**/api/thumb/**", lambda r: r.abort())      # the gallery's pictures: not here
    page = ctx.new_page()
    page.on("response", lambda r: page.refused.append((r.status, r.url))
            if r.status in (429, 503) else None)
    page.refused = []
    page.asked = []         # (seconds, path) of every compile request the page sends
    page.on("request", lambda r: page.asked.append((time.monotonic(), r.url.split("/api/", 1)[1]))
            if "/api/" in r.url and r.url.rsplit("/", 1)[1].split("?")[0] in ("view", "glb", "sweep")
            else None)
    page.goto(url)
    page.wait_for_function("() => window.studio && window.studio.ready && window.studio.view"
                           " && window.studio.view.ok", timeout=HANG)
    page.keyboard.press("Escape")
    n = views(page)
    page.click("#open-gallery")
    page.click(f'#cards .card[data-id="{eid}"]')
    settled(page, n)
    return page


def views(page) -> int:
    return page.evaluate("window.studio.views")


def settled(page, n: int | None = None) -> None:
    cond = ("window.studio.idle && window.studio.view && window.studio.view.ok "
            "&& window.studio.glbView === window.studio.views")
    if n is not None:
        cond += f" && window.studio.views > {n}"
    try:
        page.wait_for_function(f"() => {cond}", timeout=HANG)
    except Exception as e:      # what the page was waiting for, said
        state = page.evaluate("""() => ({ idle: window.studio.idle, views: window.studio.views,
            glbView: window.studio.glbView, ok: !!(window.studio.view && window.studio.view.ok),
            status: (document.getElementById('upload-status') || {}).textContent,
            drawing: (document.getElementById('drawing-status') || {}).textContent })""")
        raise AssertionError(f"the page never settled: {state}, refused {page.refused}") from e


def drawn(page, name: str) -> float:
    """The value the server drew param ``name`` with (its answer's params)."""
    return page.evaluate(f"window.studio.view.params.find((p) => p.name === {name!r}).value")


def type_value(page, name: str, text: str) -> None:
    n = views(page)
    field = page.locator(f'#params input[name="{name}-value"]')
    field.fill(text)
    field.press("Enter")
    settled(page, n)


def note(page, name: str) -> str:
    return page.inner_text(f'#params .param[data-name="{name}"] .typed-note')


def shot(page, name: str) -> None:
    OUT.mkdir(exist_ok=True)
    page.screenshot(path=str(OUT / f"studio-maker-{name}.png"))


@pytest.mark.parametrize("how,locale", [(DESKTOP, "en-US"), (PHONE, "de-DE")],
                         ids=["desktop-en", "phone-de"])
def test_a_typed_value_is_the_value_used_or_said(server, chromium, how, locale):
    page = opened(chromium, server, how, "generator/divider_tray", locale)
    try:
        type_value(page, "rows", "999")
        assert page.input_value('#params input[name="rows-value"]') == "12"
        assert "12 is the most" in note(page, "rows")
        assert drawn(page, "rows") == 12 and page.input_value('input[type=range][name="rows"]') == "12"
        type_value(page, "height", "-20")
        assert page.input_value('#params input[name="height-value"]') == "10"
        assert "10 mm is the least" in note(page, "height")
        assert drawn(page, "height") == 10
        assert "12 is the most" in note(page, "rows")      # still said, under its own field
        type_value(page, "height", "12,5")           # a comma as the decimal mark: 12.5
        assert page.input_value('#params input[name="height-value"]') == "12.5"
        assert note(page, "height") == "" and drawn(page, "height") == 12.5
        type_value(page, "height", "1,234.5")        # grouped (en): 1234.5 -> the most, said
        assert drawn(page, "height") == 160 and "160 mm is the most" in note(page, "height")
        page.locator('#params input[name="height-value"]').fill("abc")
        page.locator('#params input[name="height-value"]').press("Enter")
        assert "is not a number" in note(page, "height")
        assert page.input_value('#params input[name="height-value"]') == "160"
        page.locator('#params .param[data-name="rows"]').scroll_into_view_if_needed()
        shot(page, f"typed-{'phone' if how is PHONE else 'desktop'}")
    finally:
        page.context.close()


def test_one_thickness_the_material_field_sets_the_design(server, chromium, tmp_path):
    import trimesh
    page = opened(chromium, server, DESKTOP, "generator/finger_box")
    try:
        assert page.is_visible("#thickness")
        assert page.input_value("#thickness") == page.input_value('#params input[name="thickness-value"]')
        n = views(page)
        page.fill("#thickness", "4,5")
        page.press("#thickness", "Enter")
        settled(page, n)
        assert drawn(page, "thickness") == 4.5           # the design's param: the joints follow
        assert page.input_value('#params input[name="thickness-value"]') == "4.5"
        assert page.evaluate("window.studio.view.values") == {"thickness": "4.5mm"}
        with page.expect_download() as got:
            page.click('#downloads button[data-ext="stl"]')
        assert got.value.suggested_filename == "finger_box-thickness_4.5.stl"
        path = tmp_path / "box.stl"
        got.value.save_as(path)
        mesh = trimesh.load(io.BytesIO(path.read_bytes()), file_type="stl")
        assert mesh.is_watertight and mesh.volume > 0
        # every wall 4.5 mm: the box's outside is its inside plus two walls
        from aidl_lang import api
        from aidl_lang.studio import gallery
        res = api.compile(source=gallery.entry("generator/finger_box").source, path="x/main.aidl",
                          overrides={"thickness": "4.5mm"})
        assert {round(p.thickness, 6) for p in res.output.parts if p.kind == "solid"} == {4.5}
        shot(page, "thickness")
        # a design without a thickness param: no field to disagree with it
        n = views(page)
        page.click("#open-gallery")
        page.click('#cards .card[data-id="generator/spur_gear"]')
        settled(page, n)
        assert not page.is_visible("#thickness")
    finally:
        page.context.close()


def test_the_3d_view_draws_on_change_only(server, chromium):
    page = opened(chromium, server, DESKTOP, "generator/sliding_lid_box")
    try:
        page.wait_for_timeout(300)                        # the model's own frame
        before = page.evaluate("window.aidl3d.frames")
        assert before >= 1
        page.wait_for_timeout(2000)
        assert page.evaluate("window.aidl3d.frames") == before      # idle: 0 frames in 2 s
        page.focus("#viewer3d canvas")
        page.keyboard.press("ArrowLeft")                  # a turn: drawn again
        page.wait_for_function(f"() => window.aidl3d.frames > {before}", timeout=HANG)
    finally:
        page.context.close()


def swipe(page, selector: str, dy: float, fingers: int = 1) -> None:
    """A touch swipe of ``fingers`` fingers up by ``dy`` px over ``selector`` (CDP touch events,
    as a phone's screen sends them)."""
    b = page.locator(selector).bounding_box()
    x, y = b["x"] + b["width"] / 2, b["y"] + b["height"] * 0.7
    cdp = page.context.new_cdp_session(page)

    def points(k):
        return [{"x": x + 60 * i, "y": y - dy * k, "id": i} for i in range(fingers)]
    cdp.send("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": points(0)})
    for k in range(1, 11):
        cdp.send("Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": points(k / 10)})
        page.wait_for_timeout(16)
    cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
    page.wait_for_timeout(400)


def test_on_a_phone_a_swipe_scrolls_and_two_fingers_zoom(server, chromium):
    page = opened(chromium, server, PHONE, "generator/divider_tray")
    try:
        for pane in ("#flat", "#viewer3d canvas"):
            page.evaluate("window.scrollTo(0, 0)")
            camera = page.evaluate("window.aidl3d.camera()")
            flat = page.evaluate("[window.studio.flat.x, window.studio.flat.y, window.studio.flat.s]")
            swipe(page, pane, 200)
            assert page.evaluate("window.scrollY") > 100, pane          # the page scrolled
            assert page.evaluate("[window.studio.flat.x, window.studio.flat.y, window.studio.flat.s]") == flat
            assert page.evaluate("window.aidl3d.camera()") == pytest.approx(camera)
        page.evaluate("window.scrollTo(0, 0)")
        s = page.evaluate("window.studio.flat.s")
        b = page.locator("#flat").bounding_box()
        cdp = page.context.new_cdp_session(page)
        cx, cy = b["x"] + b["width"] / 2, b["y"] + b["height"] / 2
        cdp.send("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [
            {"x": cx - 20, "y": cy, "id": 0}, {"x": cx + 20, "y": cy, "id": 1}]})
        for k in range(1, 11):          # the fingers move apart: zoom in, the page stays
            cdp.send("Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": [
                {"x": cx - 20 - 8 * k, "y": cy, "id": 0}, {"x": cx + 20 + 8 * k, "y": cy, "id": 1}]})
            page.wait_for_timeout(16)
        cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
        assert page.evaluate("window.studio.flat.s") > s * 2
        assert page.evaluate("window.scrollY") == 0
        # a checkbox: 44 px each way
        box = page.locator('#params input[type=checkbox][name="outside"]').bounding_box()
        assert box["width"] >= 44 and box["height"] >= 44, box
        box = page.locator("#layout").bounding_box()
        assert box["width"] >= 44 and box["height"] >= 44, box
        page.locator('#params .param[data-name="outside"]').scroll_into_view_if_needed()
        shot(page, "phone-params")
    finally:
        page.context.close()


DRAG = """async (seconds) => {
    const r = document.querySelector('input[type=range][name="length"]');
    const lo = Number(r.min), hi = Number(r.max);
    let k = 0;
    const t0 = performance.now();
    while (performance.now() - t0 < seconds * 1000) {       // back and forth, 30 moves a second
      const f = (Math.sin(k / 15) + 1) / 2;
      r.value = lo + f * (hi - lo) * 0.5; r.dispatchEvent(new Event('input', { bubbles: true }));
      k += 1;
      await new Promise((ok) => setTimeout(ok, 33));
    }
    window.dragged = k;
    return k; }"""


def most_in(times: list[float], window: float) -> int:
    return max(sum(1 for u in times if t <= u < t + window) for t in times)


def test_a_long_drag_stays_under_the_rate_limit(server, chromium, tmp_path):
    """Dragging one slider for a minute stays under the rate limit: 3 s of real dragging
    against the server (no 429 or 503 from its 30 per 5 s; the picture at the end
    is the slider's, the download named with its value), then 60 s on the page's simulated
    clock (Playwright's clock: the page's timers, performance.now and its pacing run on it;
    the answers come from the page's own last ones, so the server's limit is not spent in a
    twelfth of the time): every 5 s of the minute holds at most 28 of the page's requests (60 %
    of the rate and a burst of 10), so a moving window of 30 per 5 s refuses none."""
    page = opened(chromium, server, DESKTOP, "generator/divider_tray")
    try:
        assert page.evaluate("window.studio.paceGap()") == pytest.approx(5_000 / 18)
        sent = page.evaluate(DRAG, 3)
        assert sent > 45
        settled(page)
        assert page.refused == []                          # no 429, no 503
        times = [t for t, _ in page.asked]
        assert most_in(times, 5) <= 28
        want = float(page.input_value('#params input[name="length-value"]'))
        assert drawn(page, "length") == pytest.approx(want)
        with page.expect_download() as got:
            page.click('#downloads button[data-ext="svg"]')
        name = got.value.suggested_filename
        assert re.fullmatch(rf"divider_tray-length_{re.escape(f'{want:g}')}-sheet\.svg", name), name
        assert page.inner_text("#download-status").startswith(name)
        shot(page, "drag")
        minute_on_the_page_s_clock(page)
        n = views(page)
        page.click("#open-gallery")
        page.click('#cards .card[data-id="generator/spur_gear"]')
        settled(page, n)
        assert page.inner_text("#download-status") == ""    # not the tray's file any more
    finally:
        page.context.close()


def minute_on_the_page_s_clock(page) -> None:
    """60 s of dragging on the page's simulated clock, advanced 250 ms at a time (each step
    lets the answers of the last one in); the page's requests answered by the route with the
    page's last view (its values those asked for), 3D model and sweep."""
    import json
    canned = {"view": json.loads(page.evaluate("JSON.stringify(window.studio.view)")),
              "sweep": json.loads(page.evaluate(
                  "JSON.stringify(window.studio.state.sweep.answer || {params: {}})"))}

    from playwright.sync_api import Error

    def answer(route):
        kind = route.request.url.rsplit("/", 1)[1].split("?")[0]
        try:
            if kind == "glb":
                if "glb" not in canned:
                    canned["glb"] = route.fetch().body()        # the one real request
                return route.fulfill(body=canned["glb"], content_type="model/gltf-binary")
            doc = dict(canned[kind])
            if kind == "view":
                doc.update(values=route.request.post_data_json.get("values", {}), dropped=[])
                doc.pop("clamped", None)
            return route.fulfill(json=doc)
        except Error as e:          # a request the page stopped meanwhile (a newer sweep)
            assert "already handled" in str(e) or "aborted" in str(e).lower(), e
    page.route(re.compile(r".*/api/(view|glb|sweep)$"), answer)
    page.evaluate("""() => {
        const real = window.fetch; window.asked = [];
        window.fetch = (u, o) => { if (/api\\/(view|glb|sweep)/.test(String(u))) window.asked.push([performance.now(), String(u)]); return real(u, o); };
    }""")
    page.clock.install()
    page.clock.pause_at(time.time() + 1)                    # (a wall-clock time: seconds)
    page.evaluate("() => { window.studio.state.tat = 0; window.dragged = null; }")
    page.evaluate(f"() => {{ ({DRAG})(60); }}")             # not awaited: the clock drives it
    for _ in range(244):
        page.clock.run_for(250)
    assert page.evaluate("window.dragged") >= 1_800           # 30 moves a second for 60 s
    asked = page.evaluate("window.asked")
    times = [t / 1000 for t, _ in asked]
    most = most_in(times, 5)
    kinds = {k: sum(1 for _, u in asked if u.endswith(k)) for k in ("view", "glb", "sweep")}
    print(f"a simulated minute: {page.evaluate('window.dragged')} moves, {len(times)} requests "
          f"{kinds}, at most {most} in 5 s")
    assert times[-1] - times[0] >= 55 and len(times) >= 150 and most <= 28
    page.unroute(re.compile(r".*/api/(view|glb|sweep)$"))
    page.clock.resume()


@pytest.mark.parametrize("how", [DESKTOP, PHONE], ids=["desktop", "phone"])
def test_an_imported_bolt_circle_follows_its_diameter(server, chromium, how, tmp_path):
    """A flange opened as an editable design: at 70 mm its 75 mm bolt circle moves to 60 mm
    (its range follows the diameter: 1 mm of material to the edge), said under its field; the
    DXF downloaded, re-read by ezdxf, has the 8 holes inside the 35 mm outline."""
    import math

    import ezdxf

    from maker_drawings import flange
    dxf = tmp_path / "flange.dxf"
    dxf.write_bytes(flange())
    page = opened(chromium, server, how, "generator/spur_gear")
    try:
        n = views(page)
        page.click("#open-drawing")
        page.check('input[name="open-as"][value="infer"]')
        page.set_input_files("#drawing-file", str(dxf))
        settled(page, n)
        assert "bolt circle follows" in page.text_content("#upload-status")
        type_value(page, "diameter", "70")
        assert drawn(page, "diameter") == 70 and drawn(page, "bolt_circle_pcd") == 60
        assert page.input_value('#params input[name="bolt_circle_pcd-value"]') == "60"
        assert "moved to 60 mm" in note(page, "bolt_circle_pcd")
        assert not [d for d in page.evaluate("window.studio.view.diagnostics")
                    if d["severity"] == "warning"]
        page.locator('#params .param[data-name="bolt_circle_pcd"]').scroll_into_view_if_needed()
        shot(page, f"flange-{'phone' if how is PHONE else 'desktop'}")
        if how is PHONE:
            return
        with page.expect_download() as got:
            page.click('#downloads button[data-ext="dxf"]')
        doc = ezdxf.read(io.StringIO(Path(got.value.path()).read_text()))
        found = sorted(((c.dxf.center.x, c.dxf.center.y, c.dxf.radius)
                        for c in doc.modelspace().query("CIRCLE")), key=lambda c: -c[2])
        (cx, cy, r), holes = found[0], [c for c in found if c[2] == pytest.approx(4)]
        assert r == pytest.approx(35) and len(holes) == 8
        assert all(math.hypot(x - cx, y - cy) + 4 == pytest.approx(34) for x, y, _ in holes)
    finally:
        page.context.close()


SIZES = {   # every generator's sizes as sliders (issue 94: these five had none but the text)
    "generator/cross_halving": ("height", {"thickness", "height", "length_a", "length_b"}),
    "generator/dovetail": ("tails", {"length", "tails", "depth", "angle", "clearance"}),
    "generator/finger_edge": ("finger", {"thickness", "length", "finger", "depth", "height"}),
    "generator/tab_and_slot": ("tabs", {"screw", "thickness", "tabs", "length", "tab", "height"}),
    "example/logo_plate": ("text_size", {"width", "height", "corner_radius", "screw_d", "text_size"}),
    # a bore from 0 mm: a hole where there was none is what the slider is for (no W0510)
    "generator/spur_gear": ("bore", {"teeth", "module", "bore", "backlash"}),
}


@pytest.mark.parametrize("how", [DESKTOP, PHONE], ids=["desktop", "phone"])
def test_every_generator_s_sizes_are_sliders(server, chromium, how):
    """The joint demonstrations and the logo plate open with a slider for each size; the
    slider named first in SIZES at its top end draws with no warning (a count's new holes are
    no "change": the tab and slot's 4 tabs cut 7 openings where 2 cut 3)."""
    # a phone: two of them (the page's layout is the same for all; cheaper for the suite)
    ids = list(SIZES) if how is DESKTOP else ["generator/tab_and_slot", "generator/spur_gear"]
    page = opened(chromium, server, how, ids[0])
    try:
        for i, eid in enumerate(ids):
            moved, sizes = SIZES[eid]
            if i:
                n = views(page)
                page.click("#open-gallery")
                page.click(f'#cards .card[data-id="{eid}"]')
                settled(page, n)
            names = set(page.eval_on_selector_all("#params input[type=range]",
                                                  "els => els.map(e => e.name)"))
            assert sizes <= names, (eid, names)
            slider = page.locator(f'input[type=range][name="{moved}"]')
            top = slider.get_attribute("max")
            n = views(page)
            slider.fill(top)                                    # the slider at its end
            settled(page, n)
            assert drawn(page, moved) == pytest.approx(float(top)), eid
            assert note(page, moved) == "", eid          # its own end: nothing moved
            said = [d["message"] for d in page.evaluate("window.studio.view.diagnostics")]
            assert said == [], (eid, said)
        shot(page, f"sizes-{'phone' if how is PHONE else 'desktop'}")
    finally:
        page.context.close()
