"""Every text the studio's page shows at every slider end of every gallery entry, before and
after the page's wording (issue 94; aidl_lang/studio/wording.py): the view's messages and hints
and the cutting sheet's error (nested on the page's default 600 x 400 mm sheet), each param
alone at its min and max, the others at their defaults.  Prints how many texts hold a
command-line option (``--sheet``) or backticked code as the compiler writes them, how many as
the page shows them (0), and the first of each.

    python benchmarks/serve/studio_wording.py          # ~100 CPU-s
"""
from __future__ import annotations

import re
import sys
import tempfile
import time
from collections import OrderedDict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from aidl_lang.studio import compiler, gallery  # noqa: E402
from aidl_lang.studio.wording import page_answer  # noqa: E402

FLAG = re.compile(r"(?<![\w-])--[a-z]")
CODE = re.compile(r"`[^`]*[(=][^`]*`")
TEXTS = ("message", "hint", "error", "text", "summary", "notes", "import_error")
KEEP = ("svg", "source", "program", "code", "rendered", "values", "clamped", "dropped", "span")


def texts(obj, key=None):
    """The strings a visitor reads in an answer; an error's own code is the visitor's program."""
    if isinstance(obj, dict):
        for k, v in obj.items():
            if k not in KEEP and not (obj.get("severity") == "error" and k in ("message", "hint")):
                yield from texts(v, k)
    elif isinstance(obj, list):
        for x in obj:
            yield from texts(x, key)
    elif isinstance(obj, str) and key in TEXTS:
        yield obj


def bad(text: str) -> bool:
    return bool(FLAG.search(text) or CODE.search(text) or "`" in text)


def kinds(text: str) -> set:
    """What a text holds that a visitor cannot use: an option, code, a name in backticks."""
    return {k for k, hit in (("option", FLAG.search(text)), ("code", CODE.search(text)),
                             ("backticks", "`" in text)) if hit}


def main() -> int:
    folder = tempfile.mkdtemp(prefix="aidl-wording-")
    sessions: OrderedDict = OrderedDict()
    ends = before = after = 0
    first_before, first_after = [], []
    counts: dict = {}
    said: dict = {}
    t0 = time.process_time()
    for e in gallery.entries():
        for p in e.params:
            if p.get("kind") not in ("length", "angle", "number"):
                continue
            for end in ("min", "max"):
                ends += 1
                values = {p["name"]: f"{p[end]:.12g} {p.get('unit') or ''}".strip()}
                got = [compiler.view(sessions, e.id, folder, e.source, values, {})]
                sheet = compiler.download(folder, e.source, values, "svg",
                                          {"layout": True, "sheet": [600, 400]})
                if isinstance(sheet, dict):
                    got.append(sheet)
                for answer in got:
                    raw = compiler.hide_paths(answer, folder)
                    for t in texts(raw):
                        for k in kinds(t):
                            counts[k] = counts.get(k, 0) + 1
                        if bad(t):
                            before += 1
                            first_before.append((e.id, p["name"], end, t))
                            if FLAG.search(t) or CODE.search(t):
                                said.setdefault(re.sub(r"[\d.]+", "N", t)[:60], t)
                    for t in texts(page_answer(raw)):
                        if bad(t):
                            after += 1
                            first_after.append((e.id, p["name"], end, t))
    print(f"{ends} slider ends, {time.process_time() - t0:.1f} CPU-s")
    print(f"texts with an option or code: {before} as the compiler writes them, "
          f"{after} as the page shows them")
    print("  as the compiler writes them:", counts)
    from aidl_lang.studio.wording import for_page
    for t in list(said.values())[:40]:
        print("  before:", t)
        print("  page:  ", for_page(t))
    for row in first_after[:20]:
        print("  after: ", row)
    return 1 if after else 0


if __name__ == "__main__":
    sys.exit(main())
