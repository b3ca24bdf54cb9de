"""The packaged VS Code extension (the esbuild bundle, ``vsce package``'s .vsix) installed into a
real VS Code build, code-server (VS Code in the browser, from npm), driven by Playwright in
Debian's Chromium: examples/phone_stand.aidl is opened, the language server (``aidl lsp`` of
this interpreter's environment, through the ``aidl.serverPath`` setting) runs, a misspelt name
typed into the code shows up as E0101 in the Problems view and goes away with the fix, and
*AIDL: Open Preview* draws the stand in the webview, whose 3D button loads the bundled three.js
(dist/webview/three.js, through the webview's resource URI) and shows the assembled product;
*Developer: Show Running Extensions* lists it with its activation time (printed: ``-s``).

Skipped without code-server (``$AIDL_CODE_SERVER`` or ``code-server`` on ``PATH``), the .vsix
(``$AIDL_VSIX``), Chromium or Playwright; .ci/run step 6 installs code-server from npm
(editors/vscode/test/install_code_server.sh), packages the extension and runs this file with
both set, and fails if it skips."""
from __future__ import annotations

import json
import os
import re
import shutil
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
CODE_SERVER = os.environ.get("AIDL_CODE_SERVER") or shutil.which("code-server")
VSIX = os.environ.get("AIDL_VSIX")
pytest.importorskip("playwright")
if not Path("/usr/bin/chromium").exists() or not CODE_SERVER or not VSIX \
        or not Path(VSIX).is_file():
    pytest.skip("needs code-server ($AIDL_CODE_SERVER or on PATH), the packaged extension "
                "($AIDL_VSIX) and Debian's chromium (.ci/run step 6)", allow_module_level=True)

AIDL = Path(sys.executable).with_name("aidl")
SETTINGS = {
    "security.workspace.trust.enabled": False, "workbench.startupEditor": "none",
    "workbench.tips.enabled": False, "telemetry.telemetryLevel": "off", "update.mode": "none",
    "extensions.autoCheckUpdates": False, "extensions.autoUpdate": False,
    "workbench.enableExperiments": False, "editor.minimap.enabled": False,
    "workbench.welcomePage.walkthroughs.openOnInstall": False, "chat.commandCenter.enabled": False,
    "aidl.serverPath": str(AIDL),
}
# the extension's status item once `aidl lsp` runs: "$(check) AIDL"
STATUS_RUNNING = """[...document.querySelectorAll('.statusbar-item')].some((e) =>
    /\\bAIDL\\b/.test(e.textContent) && e.querySelector('.codicon-check'))"""
LINE = "t = 3 mm        # the material"          # examples/phone_stand.aidl, edited below


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


# seconds: only a hang guard for each wait (code-server or the page never answering), never
# a claim on this machine's speed; every wait ends on its outcome long before (.ci/run bounds
# the whole test too)
HANG_GUARD = 300


def _wait_for_port(port: int, proc: subprocess.Popen) -> None:
    """Until code-server listens on ``port``; its exit ends the wait at once."""
    end = time.monotonic() + HANG_GUARD
    while time.monotonic() < end:
        if proc.poll() is not None:
            raise AssertionError(f"code-server exited with {proc.returncode}")
        with socket.socket() as s:
            if s.connect_ex(("127.0.0.1", port)) == 0:
                return
        time.sleep(0.2)
    pytest.fail(f"code-server never listened on port {port} (hung: {HANG_GUARD} s hang guard)")


def _palette(page, title: str) -> None:
    """Run a command by its title from the command palette."""
    page.keyboard.press("Control+Shift+P")
    page.wait_for_selector(".quick-input-widget input", state="visible",
                           timeout=HANG_GUARD * 1000)
    page.keyboard.type(title)
    page.wait_for_selector(f".quick-input-list .monaco-list-row:has-text('{title}')",
                           timeout=HANG_GUARD * 1000)
    page.keyboard.press("Enter")


def _preview_frame(page):
    """The frame of the preview's webview page (inside the webview's own iframe), or None."""
    for f in page.frames:
        try:
            if f.evaluate("!!document.getElementById('mode3d')"):
                return f
        except Exception:            # a frame that went away or is not ready
            pass
    return None


def _editor_text(page) -> str:
    """The editor's visible lines, top to bottom (Monaco reuses its line elements out of
    order), with plain spaces (it renders them as U+00A0)."""
    return page.evaluate("""[...document.querySelectorAll('.monaco-editor .view-lines .view-line')]
        .sort((a, b) => parseFloat(a.style.top) - parseFloat(b.style.top))
        .map((e) => e.textContent.replace(/\\u00a0/g, ' ')).join('\\n')""")


def _wait(pred, what: str):
    """``pred()``'s first true value."""
    end = time.monotonic() + HANG_GUARD
    while time.monotonic() < end:
        v = pred()
        if v:
            return v
        time.sleep(0.25)
    pytest.fail(f"never saw {what} (hung: {HANG_GUARD} s hang guard)")


def test_packaged_extension_in_code_server(tmp_path):
    from playwright.sync_api import sync_playwright
    work = tmp_path / "work"
    work.mkdir()
    shutil.copy(ROOT / "examples" / "phone_stand.aidl", work / "phone_stand.aidl")
    assert LINE in (work / "phone_stand.aidl").read_text()
    user, exts = tmp_path / "user", tmp_path / "ext"
    (user / "User").mkdir(parents=True)
    (user / "User" / "settings.json").write_text(json.dumps(SETTINGS))
    env = {**os.environ, "XDG_CONFIG_HOME": str(tmp_path / "config"),
           "XDG_DATA_HOME": str(tmp_path / "data"), "HOME": str(tmp_path)}
    dirs = ["--user-data-dir", str(user), "--extensions-dir", str(exts)]
    out = subprocess.run([CODE_SERVER, *dirs, "--install-extension", VSIX], env=env,
                         capture_output=True, text=True, timeout=120)
    assert "successfully installed" in out.stdout, out.stdout + out.stderr
    installed = exts / "aidl-lang.aidl-cad-0.2.0"
    assert (installed / "dist" / "extension.js").is_file()
    # the bundle and nothing beside it: what runs below is dist/extension.js alone
    assert not (installed / "node_modules").exists()

    port = _free_port()
    log = (tmp_path / "code-server.log").open("w")
    server = subprocess.Popen(
        [CODE_SERVER, *dirs, "--bind-addr", f"127.0.0.1:{port}", "--auth", "none",
         "--disable-telemetry", "--disable-update-check", "--disable-workspace-trust",
         "--log", "debug", str(work)],
        env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        _wait_for_port(port, server)
        with sync_playwright() as pw:
            browser = pw.chromium.launch(
                executable_path="/usr/bin/chromium", headless=True,
                args=["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                      "--disable-background-networking", "--disable-component-update",
                      "--no-first-run"])
            page = browser.new_page(viewport={"width": 1400, "height": 900})
            page.set_default_timeout(HANG_GUARD * 1000)
            try:
                page.goto(f"http://127.0.0.1:{port}/?folder={work}")
                page.wait_for_selector(".monaco-workbench")
                # open the example from the Explorer, then wait for the server's status item
                page.click(".explorer-folders-view .monaco-list-row[aria-label*='phone_stand.aidl']")
                page.wait_for_selector(".monaco-editor .view-lines :text('foot_h')")
                # activation (onLanguage) and `aidl lsp` started: the status item "$(check) AIDL"
                page.wait_for_function(STATUS_RUNNING, timeout=HANG_GUARD * 1000)

                # a misspelt name typed at the end of `t = 3 mm`: E0101 in the Problems view
                line = 1 + (work / "phone_stand.aidl").read_text().splitlines().index(LINE)

                def go_to(line: int, column: int) -> None:
                    page.keyboard.press("Control+G")              # Go to Line:Column
                    page.wait_for_selector(".quick-input-widget input", state="visible")
                    page.keyboard.type(f"{line}:{column}")
                    page.keyboard.press("Enter")
                    page.wait_for_selector(".quick-input-widget", state="hidden")
                go_to(line, 1 + len("t = 3 mm"))
                page.keyboard.type(" + wdth")
                page.keyboard.press("Escape")                     # any completion list
                _wait(lambda: "t = 3 mm + wdth  " in _editor_text(page), "the typed text")
                page.wait_for_selector(".monaco-editor .squiggly-error", timeout=HANG_GUARD * 1000)
                page.keyboard.press("Control+Shift+M")            # the Problems view
                page.wait_for_selector(".markers-panel .monaco-list-row :text('wdth')",
                                       timeout=HANG_GUARD * 1000)
                panel = page.inner_text(".markers-panel")
                assert "E0101" in panel and "unknown name" in panel, panel
                # the fix (the typed text selected and deleted) clears it
                page.click(".monaco-editor .view-lines")
                go_to(line, 1 + len("t = 3 mm"))
                for _ in range(len(" + wdth")):
                    page.keyboard.press("Shift+ArrowRight")
                page.keyboard.press("Delete")
                _wait(lambda: LINE in _editor_text(page), "the line as it was")
                page.wait_for_selector(".monaco-editor .squiggly-error", state="detached",
                                       timeout=HANG_GUARD * 1000)

                # AIDL: Open Preview, beside: the drawing, then the bundled three.js in 3D
                _palette(page, "AIDL: Open Preview")
                frame = _wait(lambda: _preview_frame(page), "the preview webview")
                frame.wait_for_selector("#view svg g#aidl-shapes", state="attached",
                                        timeout=HANG_GUARD * 1000)
                assert frame.is_visible("#mode3d")
                frame.click("#mode3d")
                # (polled from here: the webview's script policy forbids wait_for_function's eval)
                _wait(lambda: frame.evaluate("document.body.dataset.loaded3d === '1' "
                                             "|| !!document.body.dataset.error3d"),
                      "the assembled product in 3D")
                assert frame.evaluate("document.body.dataset.error3d") is None
                shot = Path(os.environ.get("AIDL_SCREENSHOT_CODE_SERVER",
                                           ROOT / "out" / "vscode-code-server.png"))
                shot.parent.mkdir(parents=True, exist_ok=True)
                page.screenshot(path=str(shot))

                # VS Code's own account of the activation (Developer: Show Running Extensions:
                # the time to load dist/extension.js and call activate), printed for the log
                _palette(page, "Developer: Show Running Extensions")
                row = page.wait_for_selector(".runtime-extensions-editor .monaco-list-row"
                                             ":has-text('AIDL (CAD language)')",
                                             timeout=HANG_GUARD * 1000)
                activation = re.search(r"Activation: (\d+)\s*ms", row.inner_text())
                assert activation, row.inner_text()
                print(f"code-server: the extension activated in {activation[1]} ms")
            except Exception:
                page.screenshot(path=str(ROOT / "out" / "vscode-code-server-failure.png"))
                raise
            finally:
                browser.close()
    finally:
        os.killpg(server.pid, 15)
        try:
            server.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(server.pid, 9)
            server.wait(timeout=20)
        log.close()
