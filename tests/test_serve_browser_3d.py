"""`aidl serve`'s 3D view in a real browser: Debian's Chromium on SwiftShader (no GPU), driven
by Playwright for Python, its own Playwright and browser (tests/test_serve_browser.py shares
one Chromium between its tests; a second sync Playwright cannot start inside it)."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
pytest.importorskip("starlette")
from conftest import skip_without_chromium  # noqa: E402

skip_without_chromium()

from benchmarks.serve.serve_latency import move_slider, open_page, served  # noqa: E402


def test_assembled_3d_view_orbits_and_follows_a_slider(tmp_path):
    """The 3D view (three.js, vendored): the phone stand's two parts in the flat view's
    colours, loaded from /download/glb; a drag orbits the camera (the picture changes), a
    slider reloads the product (live) without moving the camera, the toggle goes back to the
    sheet.  WebGL runs on SwiftShader (no GPU); the screenshot is out/serve-assembled.png."""
    import tempfile

    import numpy as np
    from PIL import Image
    from playwright.sync_api import sync_playwright
    f = tmp_path / "stand.aidl"
    f.write_text((ROOT / "examples" / "phone_stand.aidl").read_text())
    shot = Path(os.environ.get("AIDL_SCREENSHOT_3D", ROOT / "out" / "serve-assembled.png"))
    shot.parent.mkdir(parents=True, exist_ok=True)
    args = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
            "--disable-quic", "--no-first-run", "--disable-background-networking"]

    def view(page) -> np.ndarray:
        return np.asarray(Image.open(__import__("io").BytesIO(
            page.locator("#viewer3d").screenshot())).convert("RGB")).astype(int)

    def blue(im) -> float:            # the support's #0072b2, however lit
        r, g, b = im[:, :, 0], im[:, :, 1], im[:, :, 2]
        return float(((b > r + 60) & (b > g + 20)).mean())

    def orange(im) -> float:          # the foot's #d55e00
        r, g, b = im[:, :, 0], im[:, :, 1], im[:, :, 2]
        return float(((r > b + 80) & (r > g + 30)).mean())
    with served(f) as url, tempfile.TemporaryDirectory() as prof, sync_playwright() as pw:
        ctx = pw.chromium.launch_persistent_context(
            prof, executable_path="/usr/bin/chromium", headless=True, args=args,
            viewport={"width": 1200, "height": 800})
        try:
            page = open_page(ctx, url)
            page.click("#mode3d")
            page.wait_for_function("window.aidl3d && (window.aidl3d.loaded > 0 || window.aidl3d.error)",
                                   timeout=30_000)
            got = page.evaluate("({parts: window.aidl3d.parts, colours: window.aidl3d.colours,"
                                " error: window.aidl3d.error})")
            assert got["error"] is None and sorted(got["parts"]) == ["stand.foot", "stand.support"]
            assert got["colours"] == {"stand.support": "#0072b2", "stand.foot": "#d55e00"}
            assert page.locator("#viewer").is_hidden() and page.locator("#viewer3d canvas").count() == 1
            page.wait_for_timeout(500)
            before = view(page)
            # both parts drawn, shaded, in their colours (blue support, orange foot)
            assert blue(before) > 0.03 and orange(before) > 0.01
            page.screenshot(path=str(shot))
            # a drag orbits: the picture changes
            box = page.locator("#viewer3d").bounding_box()
            cx, cy = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
            page.mouse.move(cx, cy)
            page.mouse.down()
            page.mouse.move(cx + 150, cy + 20, steps=8)
            page.mouse.up()
            page.wait_for_timeout(300)
            turned = view(page)
            assert np.abs(turned - before).sum(axis=2).astype(bool).mean() > 0.02
            # a slider: the product is loaded again (live), with the new values
            n = page.evaluate("window.aidl3d.loaded")
            move_slider(page, "angle", 55)
            page.wait_for_function(f"window.aidl3d.loaded > {n}", timeout=30_000)
            assert page.evaluate("window.aidl3d.error") is None
            # back to the flat sheet
            page.click("#mode3d")
            assert page.locator("#viewer").is_visible() and page.locator("#viewer3d").is_hidden()
        finally:
            ctx.close()
