"""The studio's code editor: CodeMirror 6 bundled by editors/codemirror/build.mjs into one ES
module, aidl_lang/studio/static/vendor/codemirror/aidl-editor.js.

The committed bundle is checked without npm: its size, its licence, its words (words.json, which
editors/gen_grammar.py writes from the registry and must be fresh) and the digest of the
sources it was built from.  Then Debian's Chromium, driven by Playwright, runs it: highlighting,
diagnostics, onChange, setText, hover.  The screenshot is saved as out/codemirror.png
(AIDL_SCREENSHOT overrides the path).
"""
from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SRC = ROOT / "editors" / "codemirror"
WORDS = SRC / "src" / "words.json"
VENDOR = ROOT / "aidl_lang" / "studio" / "static" / "vendor" / "codemirror"
BUNDLE = VENDOR / "aidl-editor.js"
# what build.mjs hashes into the bundle's banner, in this order
SOURCES = ["build.mjs", "package-lock.json", "src/aidl-mode.js", "src/index.js", "src/words.json"]


def test_bundle_is_one_small_es_module_with_its_licence():
    text = BUNDLE.read_text(encoding="utf-8")
    assert 50_000 < len(text.encode()) < 1_000_000
    assert "export{" in text and "as createEditor}" in text
    assert "import " not in text.split("*/", 1)[1][:200]        # no imports: one self-contained file
    licence = (VENDOR / "LICENSE").read_text(encoding="utf-8")
    assert "MIT License" in licence and "Marijn Haverbeke" in licence
    readme = (VENDOR / "README.md").read_text(encoding="utf-8")
    assert "npm ci && npm run build" in readme
    # the README and the LICENSE name the exact versions of package.json
    pkg = json.loads((SRC / "package.json").read_text())
    assert pkg["private"] is True and pkg["license"] == "Apache-2.0"
    for name in ("@codemirror/state", "@codemirror/view", "@codemirror/language",
                 "@codemirror/lint"):
        version = pkg["devDependencies"][name]
        assert version[0].isdigit(), f"{name} is not pinned: {version}"
        assert f"{name} {version}" in readme and f"{name} {version}" in licence
    lock = json.loads((SRC / "package-lock.json").read_text())
    assert lock["packages"]["node_modules/@codemirror/view"]["version"] == \
        pkg["devDependencies"]["@codemirror/view"]


def test_words_json_is_fresh():
    code = ("import sys; sys.path.insert(0, 'editors'); import gen_grammar; "
            "sys.stdout.write(gen_grammar.codemirror_words_json())")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       encoding="utf-8")
    assert r.returncode == 0, r.stderr
    assert WORDS.read_text(encoding="utf-8") == r.stdout, \
        "run `python editors/gen_grammar.py`, rebuild the bundle and commit both"
    words = json.loads(r.stdout)
    assert "solid" in words["structure_kinds"] and "Rectangle" in words["primitives"]
    assert {"mm", "deg"} <= set(words["units"]) and "Horizontal" in words["constraints"]
    r = subprocess.run([sys.executable, str(ROOT / "editors" / "gen_grammar.py"), "--check"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout


def test_bundle_was_built_from_the_committed_sources():
    text = BUNDLE.read_text(encoding="utf-8")
    digest = hashlib.sha256()
    for name in SOURCES:
        digest.update(name.encode() + b"\0" + (SRC / name).read_bytes() + b"\0")
    assert f"sources sha256 {digest.hexdigest()} " in text[:400], \
        "the bundle is stale: cd editors/codemirror && npm ci && npm run build, and commit it"
    # every word of words.json is in it (the mode's lists are the generated ones)
    words = json.loads(WORDS.read_text(encoding="utf-8"))
    for key, ws in words.items():
        if isinstance(ws, list):
            for w in ws:
                assert json.dumps(w, ensure_ascii=False) in text, (key, w)


# ---------------------------------------------------------------- in Chromium

PAGE = """<!doctype html>
<html><head><meta charset="utf-8"><title>aidl editor</title>
<style>body { margin: 0; font-family: sans-serif; background: #fff; }
#ed { height: 560px; width: 980px; border: 1px solid #d0d7de; margin: 12px; }
#ro { height: 80px; width: 980px; margin: 12px; }</style></head>
<body><div id="ed"></div><div id="ro"></div>
<script type="module">
import { createEditor } from "/vendor/codemirror/aidl-editor.js";
window.createEditor = createEditor;
window.ready = true;
</script></body></html>
"""

HOVER_TEXT = "Rectangle(center, width, height)\n<b>a shape</b> & more"


@pytest.fixture(scope="module")
def page():
    from conftest import skip_without_chromium
    skip_without_chromium()
    sys.path.insert(0, str(ROOT))
    from benchmarks.serve.serve_latency import chromium

    def serve(route):
        path = route.request.url.split("://", 1)[1].split("/", 1)[1].split("?")[0]
        if path == "":
            route.fulfill(status=200, content_type="text/html", body=PAGE)
        elif path == "vendor/codemirror/aidl-editor.js":
            route.fulfill(status=200, content_type="text/javascript", body=BUNDLE.read_bytes())
        else:
            route.fulfill(status=404, body="")

    with chromium() as ctx:
        pg = ctx.pages[0] if ctx.pages else ctx.new_page()
        errors = []
        pg.on("pageerror", lambda e: errors.append(str(e)))
        pg.on("console", lambda m: m.type == "error" and errors.append(m.text))
        pg.route("http://aidl.studio.test/**", serve)
        pg.goto("http://aidl.studio.test/")
        pg.wait_for_function("window.ready === true", timeout=20_000)
        pg.errors = errors
        yield pg


def spans(page, cls: str) -> list[str]:
    return page.eval_on_selector_all(f"#ed .{cls}", "els => els.map(e => e.textContent)")


def test_editor_in_chromium(page):
    src = (ROOT / "examples" / "bracket.aidl").read_text(encoding="utf-8")
    page.evaluate("""([doc, hoverText]) => {
        window.changes = []; window.hovers = [];
        window.ed = createEditor(document.getElementById("ed"), {
            doc,
            onChange: (text) => window.changes.push(text),
            hover: async (text, pos) => {
                window.hovers.push([text.length, pos]);
                return /\\w/.test(text[pos] || "") ? hoverText : null;
            },
        });
    }""", [src, HOVER_TEXT])
    ed = page.locator("#ed .cm-editor")
    assert ed.count() == 1
    assert page.evaluate("window.ed.getText()") == src
    assert page.evaluate("window.ed.view.state.doc.lines") == src.count("\n") + 1
    box = ed.bounding_box()
    assert box["height"] == pytest.approx(560, abs=2)           # fills its parent

    # highlighting: the classes the mode gives, from the generated word lists
    assert "solid" in spans(page, "cm-aidl-structure") and "hole" in spans(page, "cm-aidl-structure")
    comments = spans(page, "cm-aidl-comment")
    assert comments and comments[0].startswith("# A flat mounting bracket")
    assert "param" in spans(page, "cm-aidl-keyword")
    assert "Rectangle" in spans(page, "cm-aidl-primitive")
    assert "Vertical" in spans(page, "cm-aidl-constraint")
    assert "mm" in spans(page, "cm-aidl-unit") and "deg" in spans(page, "cm-aidl-unit")
    assert "20" in spans(page, "cm-aidl-number")
    assert "bracket" in spans(page, "cm-aidl-defname")
    assert "true" in spans(page, "cm-aidl-constant")
    colours = page.evaluate("""() => ['cm-aidl-structure', 'cm-aidl-comment', 'cm-aidl-variable']
        .map(c => getComputedStyle(document.querySelector('#ed .' + c)).color)""")
    assert len(set(colours[:2])) == 2 and colours[0] != "rgb(36, 41, 47)"   # styled, not default
    assert page.evaluate("getComputedStyle(document.querySelector('#ed .cm-content')).fontSize") \
        == "13px"

    # one error at line 2, col 5 to col 12: the range is those characters
    page.evaluate("""() => window.ed.setDiagnostics([{from: 2, col: 5, to_line: 2, to_col: 12,
        severity: "error", message: "E0101: something is wrong here", code: "E0101"}])""")
    page.wait_for_selector("#ed .cm-lintRange-error")
    line2 = src.splitlines()[1]
    marked = "".join(spans(page, "cm-lintRange-error"))
    assert marked == line2[4:11]
    assert page.locator("#ed .cm-gutter-lint .cm-lint-marker-error").count() == 1

    # typing calls onChange with the whole new text; setText does not
    page.locator("#ed .cm-content").click()
    page.keyboard.press("Control+End")
    page.keyboard.type("# typed")
    page.wait_for_function("window.changes.length > 0 && "
                           "window.changes[window.changes.length - 1].endsWith('# typed')")
    assert page.evaluate("window.changes[window.changes.length - 1]") == src + "# typed"
    assert page.evaluate("window.ed.getText()") == src + "# typed"
    n = page.evaluate("window.changes.length")
    page.evaluate("([t]) => window.ed.setText(t)", [src])
    assert page.evaluate("window.ed.getText()") == src
    assert page.evaluate("window.changes.length") == n
    page.keyboard.press("Escape")

    page.evaluate("""() => window.ed.setDiagnostics([{from: 2, col: 5, to_line: 2, to_col: 12,
        severity: "error", message: "E0101: something is wrong here", code: "E0101"}])""")
    page.wait_for_selector("#ed .cm-lintRange-error")

    # hover over `Rectangle`: the callback gets the text and the offset, the tooltip shows its
    # answer as text (the <b> stays literal)
    at = src.index("Rectangle(")
    page.evaluate("() => window.ed.view.dispatch({selection: {anchor: 0}, scrollIntoView: true})")
    page.wait_for_timeout(100)                  # back at the top: line 2 and `Rectangle` in view
    xy = page.evaluate("""(pos) => { const r = window.ed.view.coordsAtPos(pos);
        return [r.left + 1, (r.top + r.bottom) / 2]; }""", at + 3)
    page.mouse.move(xy[0] - 40, xy[1] + 60)
    page.mouse.move(*xy)
    tip = page.locator("#ed .cm-tooltip .cm-aidl-hover")
    tip.wait_for(timeout=10_000)
    assert tip.text_content() == HOVER_TEXT
    assert page.locator("#ed .cm-tooltip b").count() == 0
    assert [len(src), at + 3] in page.evaluate("window.hovers")

    shot = Path(os.environ.get("AIDL_SCREENSHOT", ROOT / "out" / "codemirror.png"))
    shot.parent.mkdir(parents=True, exist_ok=True)
    page.screenshot(path=str(shot))
    assert page.errors == []


def test_read_only_editor_and_code_point_positions(page):
    # "😀" is one character for Python and two UTF-16 units for CodeMirror
    doc = 'x = "😀" + y  # one\n'
    page.evaluate("""([doc]) => {
        window.roChanges = []; window.roHovers = [];
        window.ro = createEditor(document.getElementById("ro"), {doc, readOnly: true,
            onChange: (t) => window.roChanges.push(t),
            hover: async (text, pos) => { window.roHovers.push(pos); return "y: " + text[pos]; }});
    }""", [doc])
    page.evaluate("""() => window.ro.setDiagnostics([{from: 1, col: 11, to_line: 1, to_col: 12,
        severity: "info", message: "y is unused", code: "I0001"}])""")
    page.wait_for_selector("#ro .cm-lintRange-info")
    assert page.eval_on_selector("#ro .cm-lintRange-info", "e => e.textContent") == "y"
    # bad items and positions are clamped or skipped, never thrown; a list replaces the last
    page.evaluate("""() => window.ro.setDiagnostics([null, 7, {}, {from: 999, col: 999,
        to_line: -4, to_col: "x", severity: "bogus", message: 5},
        {from: 1, col: 1, to_line: 1, to_col: 10000, severity: "warning", message: "w"}])""")
    page.wait_for_selector("#ro .cm-lintRange-warning")
    assert page.locator("#ro .cm-lintRange-info").count() == 0
    # {} is line 1, col 1: its word `x` (shown as the worse of the two); the clamped one is the
    # end, the last (empty) line
    assert page.eval_on_selector_all("#ro .cm-lintRange", "es => es.map(e => "
                                     "e.textContent).join('')") == doc[:-1]
    assert page.eval_on_selector_all("#ro .cm-lintRange-error", "es => es.map(e => "
                                     "e.textContent)") == ["x"]
    assert page.locator("#ro .cm-lint-marker-error").count() == 2
    page.locator("#ro .cm-content").click()
    page.keyboard.press("Control+End")
    page.keyboard.type("zzz")
    page.wait_for_timeout(200)
    assert page.evaluate("window.ro.getText()") == doc
    assert page.evaluate("window.roChanges") == []
    # the hover offset is in code points: `y` is at Python index 10
    xy = page.evaluate("""() => { const r = window.ro.view.coordsAtPos(window.ro.getText()
        .indexOf("y")); return [r.left + 2, (r.top + r.bottom) / 2]; }""")
    page.mouse.move(xy[0] + 100, xy[1] + 100)
    page.mouse.move(*xy)
    page.locator("#ro .cm-tooltip .cm-aidl-hover").wait_for(timeout=10_000)
    assert page.evaluate("window.roHovers")[-1] == doc.index("y") == 10
    page.evaluate("window.ro.destroy()")
    assert page.locator("#ro .cm-editor").count() == 0
    assert page.errors == []
