"""Screenshots of the real extension in a real VS Code: code-server (VS Code in the browser)
with the packaged extension installed, driven by Playwright in Debian's Chromium.

    .venv/bin/python editors/vscode/test/code_server_screenshots.py \\
        --code-server PATH/TO/code-server --vsix aidl-cad-X.vsix --out docs/images

writes ``vscode-inlay-hints.png`` (examples/bracket.aidl: the inlay hints and the
degrees-of-freedom lenses) and ``vscode-preview.png`` (examples/telephone.aidl with *AIDL: Open
Preview* beside it, the cursor on the finger holes' ``Circle`` call, so that the ten holes are
highlighted), both at 1600 x 1000.  The server is started from this checkout's ``.venv`` (the
extension's own discovery); ``aidl_lang`` must be installed there.

CI installs a smaller code-server (``install_code_server.sh``, for
tests/test_vscode_code_server.py) without ripgrep, which this script's Quick Open needs; a full
one was installed for these pictures
with npm 4.100.3 (node 20) where there is no internet but the registries, by hand:
``npm install --ignore-scripts code-server@4.100.3``; then ``node-pre-gyp rebuild
--build-from-source`` in ``node_modules/argon2``; in ``node_modules/code-server/lib/vscode``:
``npm install --omit=dev --ignore-scripts``, ``node-gyp rebuild`` in each of ``@parcel/watcher``,
``@vscode/deviceid``, ``@vscode/spdlog``, ``kerberos``, ``native-watchdog``, ``node-pty`` (Debian's
``libkrb5-dev``, ``libxkbfile-dev``, ``libsecret-1-dev``, ``libx11-dev``), Debian's ``ripgrep``
copied to ``node_modules/@vscode/ripgrep/bin/rg`` (its own postinstall downloads from GitHub),
the links its ``postinstall.sh`` makes (``node_modules.asar``, ``bin/remote-cli/code-server``,
``bin/helpers/browser.sh``), and ``npm install --omit=dev --ignore-scripts`` in ``extensions``.
"""
from __future__ import annotations

import argparse
import json
import socket
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
SETTINGS = {
    "security.workspace.trust.enabled": False, "workbench.startupEditor": "none",
    "workbench.tips.enabled": False, "telemetry.telemetryLevel": "off", "update.mode": "none",
    "extensions.autoCheckUpdates": False, "workbench.colorTheme": "Default Light Modern",
    "window.commandCenter": False, "chat.commandCenter.enabled": False,
    "git.blame.statusBarItem.enabled": False, "editor.minimap.enabled": False,
    "workbench.welcomePage.walkthroughs.openOnInstall": False,
}


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for_port(port: int, seconds: float = 60) -> None:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        with socket.socket() as s:
            if s.connect_ex(("127.0.0.1", port)) == 0:
                return
        time.sleep(0.2)
    raise SystemExit(f"code-server did not listen on port {port} within {seconds:g} s")


def command(page, title: str) -> None:
    """Run a command by its title from the command palette."""
    page.keyboard.press("Control+Shift+P")
    time.sleep(0.8)
    page.keyboard.type(title)
    time.sleep(0.8)
    page.keyboard.press("Enter")


def open_file(page, rel: str, line: int) -> None:
    """Quick Open ``rel``, then go to ``line`` (1-based), cursor at its first character."""
    page.keyboard.press("Control+P")
    time.sleep(0.8)
    page.keyboard.type(rel)
    time.sleep(1.2)
    page.keyboard.press("Enter")
    time.sleep(1.5)
    go_to_line(page, line)


def go_to_line(page, line: int) -> None:
    page.keyboard.press("Control+G")
    time.sleep(0.5)
    page.keyboard.type(str(line))
    page.keyboard.press("Enter")
    time.sleep(0.3)
    page.keyboard.press("Home")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--code-server", default="code-server")
    ap.add_argument("--vsix", required=True)
    ap.add_argument("--out", default=str(ROOT / "docs" / "images"))
    a = ap.parse_args()
    from playwright.sync_api import sync_playwright
    with tempfile.TemporaryDirectory() as tmp:
        user, exts = Path(tmp) / "user", Path(tmp) / "ext"
        (user / "User").mkdir(parents=True)
        (user / "User" / "settings.json").write_text(json.dumps(SETTINGS))
        dirs = ["--user-data-dir", str(user), "--extensions-dir", str(exts)]
        subprocess.run([a.code_server, *dirs, "--install-extension", a.vsix], check=True,
                       stdout=subprocess.DEVNULL)
        port = free_port()
        server = subprocess.Popen(
            [a.code_server, *dirs, "--bind-addr", f"127.0.0.1:{port}", "--auth", "none",
             "--disable-telemetry", "--disable-update-check", str(ROOT)],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        try:
            wait_for_port(port)
            with sync_playwright() as pw:
                browser = pw.chromium.launch(
                    executable_path="/usr/bin/chromium", headless=True,
                    args=["--no-sandbox", "--disable-gpu", "--disable-background-networking",
                          "--disable-component-update", "--disable-sync", "--no-first-run"])
                page = browser.new_page(viewport={"width": 1600, "height": 1000})
                page.goto(f"http://127.0.0.1:{port}/?folder={ROOT}")
                page.wait_for_selector(".monaco-workbench", timeout=60_000)
                time.sleep(4)
                # the inlay hints and lenses come from the last solved version
                open_file(page, "examples/bracket.aidl", 1)
                page.wait_for_selector(".monaco-editor .codelens-decoration", timeout=60_000)
                time.sleep(3)
                page.screenshot(path=str(Path(a.out) / "vscode-inlay-hints.png"))
                open_file(page, "examples/telephone.aidl", 36)
                time.sleep(3)
                command(page, "AIDL: Open Preview")
                time.sleep(6)
                page.keyboard.press("Control+1")            # back to the code, cursor moved
                go_to_line(page, 36)
                page.keyboard.press("Control+ArrowRight")
                time.sleep(3)
                page.screenshot(path=str(Path(a.out) / "vscode-preview.png"))
                browser.close()
        finally:
            server.terminate()
            server.wait(timeout=20)


if __name__ == "__main__":
    main()
