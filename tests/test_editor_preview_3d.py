"""The VS Code preview's 3D view in a real browser: the webview page that
editors/vscode/preview.js writes (``html(cspSource, threeUrl)``, made by node with the test
shim), served with the extension's bundled three.js (``dist/webview/three.js``, made by ``npm run
bundle``) over a local HTTP server as a webview serves its resources, in Debian's Chromium (SwiftShader WebGL).  The page gets the
``aidl/preview`` result the language server sends with ``assembled: true`` (the phone stand's
GLB) after its 3D button is pressed; it draws both parts in their colours, a drag orbits, and
it asks the extension for the assembled product.  Screenshot: out/vscode-preview-3d.png."""
from __future__ import annotations

import base64
import functools
import http.server
import io
import json
import os
import re
import shutil
import subprocess
import threading
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXT = ROOT / "editors" / "vscode"
from conftest import skip_without_chromium  # noqa: E402

skip_without_chromium()
if shutil.which("node") is None \
        or not (EXT / "dist" / "webview" / "three.js").exists():
    pytest.skip("needs Debian's chromium, node and `npm ci && npm run bundle` in editors/vscode",
                allow_module_level=True)

MAKE = """
require('./test/helpers');
const { html } = require('./preview');
process.stdout.write(html(process.argv[1], process.argv[2]));
"""


# seconds: only a hang guard (a page that never answers), never a claim on this machine's
# speed; each wait ends on the page's own outcome (ready, drawn, or its error) long before
HANG_GUARD = 300


def _poll(page, expression: str, what: str, errors: list) -> None:
    """Wait until ``expression`` holds in the page; a script error in the page ends the wait
    at once with that error (the outcome the page promises is one or the other)."""
    end = time.monotonic() + HANG_GUARD
    while not page.evaluate(expression):
        assert not errors, f"the page failed while waiting for {what}: {errors}"
        if time.monotonic() > end:
            pytest.fail(f"the page never reached {what} (hung: {HANG_GUARD} s hang guard)")
        time.sleep(0.1)


def test_vscode_preview_shows_the_assembled_product_in_3d(tmp_path):
    import aidl_lang
    import numpy as np
    from PIL import Image
    from playwright.sync_api import sync_playwright

    # the files a webview would serve: the page and the extension's bundled three.js
    site = tmp_path / "site"
    site.mkdir()
    (site / "three.js").symlink_to(EXT / "dist" / "webview" / "three.js")
    srv = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(
        http.server.SimpleHTTPRequestHandler, directory=str(site)))
    base = f"http://127.0.0.1:{srv.server_address[1]}"
    threading.Thread(target=srv.serve_forever, daemon=True).start()
    page_html = subprocess.run(["node", "-e", MAKE, base, base + "/three.js"], cwd=EXT,
                               capture_output=True, text=True, timeout=60, check=True).stdout
    nonce = re.search(r"'nonce-([^']+)'", page_html)[1]
    stub = (f'<script nonce="{nonce}">window.sent = []; window.acquireVsCodeApi = () => '
            '({postMessage: (m) => window.sent.push(m)});</script>')
    (site / "index.html").write_text(page_html.replace("<title>", stub + "<title>", 1))

    stand = (ROOT / "examples" / "phone_stand.aidl").read_text()
    r = aidl_lang.compile(stand, str(ROOT / "examples" / "phone_stand.aidl"))
    result = {"uri": "file:///stand.aidl", "version": 1, "ok": True, "stale": False,
              "svg": r.to_svg(kerf=0), "shapes": [], "values": {}, "params": [],
              "diagnostics": {"errors": 0, "warnings": 0, "first": None}, "ms": 1,
              "glb": base64.b64encode(r.encode("glb", assembled=True)).decode()}
    shot = Path(os.environ.get("AIDL_SCREENSHOT_VSCODE_3D", ROOT / "out" / "vscode-preview-3d.png"))
    shot.parent.mkdir(parents=True, exist_ok=True)
    args = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
            "--no-first-run", "--disable-background-networking"]
    try:
        import tempfile
        with tempfile.TemporaryDirectory() as prof, sync_playwright() as pw:
            ctx = pw.chromium.launch_persistent_context(
                prof, executable_path="/usr/bin/chromium", headless=True, args=args,
                viewport={"width": 900, "height": 700})
            try:
                page = ctx.pages[0]
                errors = []
                page.on("pageerror", lambda e: errors.append(str(e)))
                page.goto(base + "/index.html")
                # polled from here: the page's nonce-only script policy refuses the eval of
                # wait_for_function's polling once its first try finds the page not ready
                _poll(page, "!!window.aidl3d && window.sent.length > 0", "the page ready", errors)
                page.click("#mode3d")
                assert {"type": "assembled", "on": True} in page.evaluate("window.sent")
                page.evaluate("(r) => window.postMessage({type: 'update', result: r}, '*')", result)
                _poll(page, "document.body.dataset.loaded3d === '1' "
                      "|| !!document.body.dataset.error3d", "the product in 3D", errors)
                assert page.evaluate("document.body.dataset.error3d") is None and errors == []
                assert page.locator("#view").is_hidden()
                page.wait_for_timeout(400)

                def view():
                    return np.asarray(Image.open(io.BytesIO(
                        page.locator("#view3d").screenshot())).convert("RGB")).astype(int)
                before = view()
                r_, g_, b_ = before[:, :, 0], before[:, :, 1], before[:, :, 2]
                assert ((b_ > r_ + 60) & (b_ > g_ + 20)).mean() > 0.03       # the support, blue
                assert ((r_ > b_ + 80) & (r_ > g_ + 30)).mean() > 0.01       # the foot, orange
                page.screenshot(path=str(shot))
                box = page.locator("#view3d").bounding_box()
                cx, cy = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
                page.mouse.move(cx, cy)
                page.mouse.down()
                page.mouse.move(cx + 150, cy + 20, steps=8)
                page.mouse.up()
                page.wait_for_timeout(300)
                assert np.abs(view() - before).sum(axis=2).astype(bool).mean() > 0.02
                # the flat sheet again
                page.click("#mode3d")
                assert page.locator("#view").is_visible()
                assert {"type": "assembled", "on": False} in page.evaluate("window.sent")
            finally:
                ctx.close()
    finally:
        srv.shutdown()
