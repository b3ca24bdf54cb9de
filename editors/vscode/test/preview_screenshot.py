"""A picture of the VS Code preview: the webview page of preview.js (its real HTML and script)
in Chromium beside the code, fed the `aidl/preview` result of a file with the cursor on a line.

    .venv/bin/python editors/vscode/test/preview_screenshot.py examples/telephone.aidl 36 OUT.png

(line: 1-based; the cursor goes to its first non-blank character). ``--break OLD NEW``: then
replace OLD by NEW in the text (an edit that breaks it) and show that state: the last good
picture, dimmed, and the error. Needs node, Playwright and Debian's /usr/bin/chromium. Used for
docs/images/vscode-preview.png.
"""
import contextlib
import html
import json
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.editor.lsp.preview import Cache, preview  # noqa: E402

PAGE = """<!DOCTYPE html><html><head><meta charset="utf-8"><style>
body {{ margin: 0; display: flex; height: 100vh; font: 13px sans-serif; background: #f3f3f3; }}
.code {{ width: 50%; overflow: hidden; background: #fff; border-right: 1px solid #ccc; }}
.tab {{ background: #ececec; padding: 6px 12px; border-bottom: 1px solid #ddd; }}
pre {{ margin: 0; padding: 6px 0; font: 12px/17px "DejaVu Sans Mono", monospace; }}
.ln {{ display: inline-block; width: 3.5em; color: #999; text-align: right; margin-right: 1em; }}
.cur {{ background: #fff8c5; }}
.kw {{ color: #0000ff; }} .cm {{ color: #008000; }} .fn {{ color: #795e26; }}
iframe {{ width: 50%; border: 0; background: #fff; }}
</style></head><body>
<div class="code"><div class="tab">{name}</div><pre>{code}</pre></div>
<iframe id="wv" srcdoc="{webview}"></iframe>
</body></html>"""


@contextlib.contextmanager
def chromium_page(doc: str, width: int, height: int):
    """A page of Debian's Chromium (Playwright, headless) showing the HTML ``doc`` at
    ``width`` x ``height`` px; the browser is closed on leaving."""
    from playwright.sync_api import sync_playwright
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as pw:
        f = Path(tmp) / "page.html"
        f.write_text(doc)
        b = pw.chromium.launch(executable_path="/usr/bin/chromium", headless=True,
                               args=["--no-sandbox", "--disable-gpu"])
        try:
            page = b.new_page(viewport={"width": width, "height": height})
            page.goto(f.as_uri())
            yield page
        finally:
            b.close()


def colour(line: str) -> str:
    import re
    s = html.escape(line)
    if "#" in line:
        i = s.index("#")
        return colour(line[:line.index("#")]) + f'<span class="cm">{s[i:]}</span>'
    s = re.sub(r"\b(param|solid|hole|drawing|assembly|for|in|def|if|else)\b", r'<span class="kw">\1</span>', s)
    return re.sub(r"\b([A-Z][A-Za-z]+)(?=\()", r'<span class="fn">\1</span>', s)


def main(src: str, line: int, out: str, values: str | None = None, broken=None) -> None:
    text = Path(src).read_text()
    lines = text.split("\n")
    col = len(lines[line - 1]) - len(lines[line - 1].lstrip())
    vals = json.loads(values) if values else {}
    cache = Cache()
    res = preview(text, str(Path(src).resolve()), Path(src).resolve().as_uri(), 1, vals, cache)
    if broken:
        text = text.replace(broken[0], broken[1], 1)
        lines = text.split("\n")
        res = preview(text, str(Path(src).resolve()), Path(src).resolve().as_uri(), 2, vals, cache)
    page_html = _webview_html()
    page_html = page_html.replace("const vscode = acquireVsCodeApi();",
                                  "const vscode = { postMessage() {} };")
    first = max(0, line - 30)
    code = "\n".join(f'<span class="{"cur" if i + 1 == line else ""}"><span class="ln">{i + 1}</span>'
                     f"{colour(lines[i])}</span>" for i in range(first, min(len(lines), first + 60)))
    doc = PAGE.format(name=html.escape(Path(src).name), code=code, webview=html.escape(page_html, quote=True))
    with chromium_page(doc, 1400, 820) as page:
        frame = page.frame_locator("#wv")
        frame.locator("#status").wait_for()
        wv = page.frames[1]
        wv.evaluate("(r) => window.postMessage({type: 'update', result: r}, '*')", res)
        wv.evaluate("(c) => window.postMessage({type: 'cursor', line: c[0], character: c[1]}, '*')",
                    [line - 1, col + 1])
        wv.wait_for_function("document.body.dataset.highlighted !== undefined")
        page.wait_for_timeout(300)
        n = wv.evaluate("document.querySelectorAll('#aidl-shapes .hl').length")
        page.screenshot(path=out)
    print(f"{out}: {res['ms']} ms compile, {len(res['shapes'])} shapes, {n} highlighted")


def _webview_html() -> str:
    js = ("const M=require('node:module');const r=M._resolveFilename;"
          "M._resolveFilename=function(q,...a){return q==='vscode'?require.resolve('./test/shim/vscode.js'):r.call(this,q,...a)};"
          "process.stdout.write(require('./preview.js').html('vscode-resource:'))")
    return subprocess.run(["node", "-e", js], cwd=HERE.parent, capture_output=True, text=True,
                          check=True).stdout


if __name__ == "__main__":
    a = sys.argv[1:]
    brk = None
    if "--break" in a:
        i = a.index("--break")
        brk, a = (a[i + 1], a[i + 2]), a[:i] + a[i + 3:]
    main(a[0], int(a[1]), a[2], a[3] if len(a) > 3 else None, brk)
