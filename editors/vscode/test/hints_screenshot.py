"""A picture of the solved values in the code: the inlay hints and code lenses that `aidl lsp`
sends for a file (computed by the server's own functions, ``hints.solved_facts``,
``hints.inlay_hints`` and ``hints.code_lenses``, from ``aidl_lang.compile``), drawn the way VS
Code draws them (a hint is a grey label after its statement; a lens is a small grey line above
its structure), in Chromium.

    .venv/bin/python editors/vscode/test/hints_screenshot.py examples/bracket.aidl FIRST OUT.png

(FIRST: the first 1-based line shown; 44 lines are shown). Needs Playwright and Debian's
/usr/bin/chromium. Used for docs/images/vscode-inlay-hints.png.
"""
import html
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE))

import aidl_lang  # noqa: E402
from aidl_lang.diagnostics import DiagnosticSink  # noqa: E402
from aidl_lang.editor.lsp import hints  # noqa: E402
from aidl_lang.parser import parse  # noqa: E402
from preview_screenshot import chromium_page, colour  # noqa: E402

PAGE = """<!DOCTYPE html><html><head><meta charset="utf-8"><style>
body {{ margin: 0; font: 13px sans-serif; background: #fff; }}
.tab {{ background: #ececec; padding: 6px 12px; border-bottom: 1px solid #ddd; }}
pre {{ margin: 0; padding: 6px 0; font: 12px/18px "DejaVu Sans Mono", monospace; }}
.ln {{ display: inline-block; width: 3.5em; color: #999; text-align: right; margin-right: 1em; }}
.kw {{ color: #0000ff; }} .cm {{ color: #008000; }} .fn {{ color: #795e26; }}
.hint {{ color: #6e6e6e; background: #f0f0f0; border-radius: 3px; padding: 0 4px;
        margin-left: 6px; font-size: 11px; }}
.lens {{ color: #8a8a8a; font: 11px/16px sans-serif; }}
</style></head><body><div class="tab">{name}</div><pre>{code}</pre></body></html>"""


def main(src: str, first: int, out: str) -> None:
    text = Path(src).read_text()
    lines = text.split("\n")
    path = str(Path(src).resolve())
    facts = hints.solved_facts(aidl_lang.compile(source=text, path=path))
    prog = parse(text, path, DiagnosticSink())
    at: dict[int, list] = {}
    for h in hints.inlay_hints(text, prog, facts):
        at.setdefault(h["position"]["line"], []).append(h)
    lens = {L["range"]["start"]["line"]: L["command"]["title"]
            for L in hints.code_lenses(text, prog, facts)}
    rows = []
    for i in range(first - 1, min(len(lines), first - 1 + 44)):
        ln = lines[i]
        if i in lens:
            indent = len(ln) - len(ln.lstrip())
            rows.append(f'<span class="ln"></span><span class="lens">{" " * indent}'
                        f'{html.escape(lens[i])}</span>')
        row, done = "", 0
        for h in sorted(at.get(i, []), key=lambda h: h["position"]["character"]):
            c = h["position"]["character"]
            row += colour(ln[done:c]) + f'<span class="hint">{html.escape(h["label"])}</span>'
            done = c
        rows.append(f'<span class="ln">{i + 1}</span>{row + colour(ln[done:])}')
    doc = PAGE.format(name=html.escape(Path(src).name), code="\n".join(rows))
    with chromium_page(doc, 1100, 860) as page:
        page.screenshot(path=out)
    n = sum(len(v) for v in at.values())
    print(f"{out}: {n} inlay hints, {len(lens)} code lenses in the file")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]), sys.argv[3])
