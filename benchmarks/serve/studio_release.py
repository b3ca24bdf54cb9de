"""Slider to picture in Chromium (issue 104, "Speed where the user waits"):

    .venv/bin/python benchmarks/serve/studio_release.py                       # this tree
    .venv/bin/python benchmarks/serve/studio_release.py --busy 2 --runs 5     # two busy loops
    .venv/bin/python benchmarks/serve/studio_release.py --tree /tmp/before    # another tree

Starts `aidl studio --port 0` (two compile workers, the default rate; `--tree DIR`: that
checkout's `aidl_lang`, by PYTHONPATH), opens each design in Debian's Chromium (1280 x 800), and
releases one of its sliders ``--runs`` times (the range input's value set and its `input`
event, as a drag's last move), alternating between its value and one a few steps up, each
after the last has settled (picture, 3D and the page idle).  For each release: ms from the
move to the flat picture shown (`window.studio.shownAt`) and to its 3D model on screen
(`builtAt`); with this tree's page, where the time went (`window.studio.timeline`: waited in
the page's debounce and pacing, compile in the worker, transfer and queue, drawing).  Prints
the median of each per design.  ``--busy N``: N processes spinning beside it (a loaded
machine).
"""
from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

DESIGNS = {                 # design: the slider released, and by how many of its steps
    "example/mounting_plate": ("width", 4),
    "generator/board_enclosure": ("width", 10),
    "generator/gear_train": ("module", 2),
    "generator/planetary": ("planet", 2),
}

RELEASE = """([name, value]) => {
  const r = document.querySelector(`input[type=range][name="${name}"]`);
  window.__released = performance.now();
  r.value = value;
  r.dispatchEvent(new Event("input", { bubbles: true }));
}"""


def settle(page, n: int) -> None:
    try:
        page.wait_for_function(
            f"() => window.studio.views > {n} && window.studio.idle && window.studio.view "
            "&& window.studio.view.ok && window.studio.glbView === window.studio.views",
            timeout=120_000)
    except Exception:
        state = page.evaluate("""() => ({ views: window.studio.views, idle: window.studio.idle,
            glbView: window.studio.glbView, ok: !!(window.studio.view && window.studio.view.ok),
            status: document.getElementById('status').textContent,
            b3d: document.getElementById('building3d').textContent, errors: window.studio.errors })""")
        raise RuntimeError(f"the page never settled after view {n}: {state}")


def run(url: str, runs: int, designs: dict) -> dict:
    from playwright.sync_api import sync_playwright

    from benchmarks.serve.serve_latency import CHROMIUM, CHROMIUM_ARGS
    out = {}
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        for eid, (name, steps) in designs.items():
            ctx = browser.new_context(viewport={"width": 1280, "height": 800})
            ctx.route("**/api/thumb/**", lambda r: r.abort())
            page = ctx.new_page()
            page.asked = []             # the compile requests the page sent (for a stuck page)
            page.on("request", lambda r, page=page: page.asked.append(r.url.rsplit("/", 1)[1])
                    if "/api/" in r.url else None)
            page.goto(url)
            page.wait_for_function("() => window.studio && window.studio.ready && window.studio.view"
                                   " && window.studio.view.ok", timeout=300_000)
            page.keyboard.press("Escape")
            n = page.evaluate("window.studio.views")
            page.click("#open-gallery")
            page.click(f'#cards .card[data-id="{eid}"]')
            settle(page, n)
            p = page.evaluate(f"window.studio.view.params.find((p) => p.name === {name!r})")
            values = [p["value"], min(p["max"], p["value"] + steps * (p.get("step") or 1))]
            rows = []
            print(f"{eid}: {name} {values}", file=sys.stderr, flush=True)
            for i in range(runs):
                n = page.evaluate("window.studio.views")
                page.asked.clear()
                page.evaluate(RELEASE, [name, values[(i + 1) % 2]])
                try:
                    settle(page, n)
                except RuntimeError as e:       # said, and the design's other runs left
                    print(f"{eid}: {e}; asked since the release: {page.asked[:40]}; "
                          f"values {page.evaluate('JSON.stringify(window.studio.state.values)')}",
                          file=sys.stderr, flush=True)
                    rows.append({"flat": None, "built": None, "split": None})
                    break
                rows.append(page.evaluate("""() => {
                  const s = window.studio, k = s.views, t0 = window.__released;
                  const t = (s.timeline || {})[k];
                  return { flat: s.shownAt[k] - t0, built: s.builtAt[k] - t0,
                           split: t ? { waited: t.sent - t0, compile: t.compile_ms, cpu: t.cpu_ms,
                                        transfer: t.answered - t.sent - (t.compile_ms || 0),
                                        drawing: t.drawn === null ? null : t.drawn - t.answered } : null };
                }"""))
            ctx.close()
            out[eid] = rows
        browser.close()
    return out


def med(xs):
    xs = [x for x in xs if x is not None]
    return round(statistics.median(xs)) if xs else None


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--busy", type=int, default=0, help="processes spinning beside the run")
    ap.add_argument("--tree", default=None, help="another checkout's aidl_lang (PYTHONPATH)")
    ap.add_argument("--only", default=None, help="one design id (generator/planetary)")
    ap.add_argument("--each", action="store_true", help="print every release's figures too")
    args = ap.parse_args(argv)
    from benchmarks.serve.studio_server import studio
    env = {"AIDL_STUDIO_MODEL_URL": ""}
    if args.tree:
        env["PYTHONPATH"] = str(Path(args.tree).resolve())
    designs = {k: v for k, v in DESIGNS.items() if not args.only or k == args.only}
    busy = [subprocess.Popen([sys.executable, "-c", "while True: pass"])
            for _ in range(args.busy)]
    try:
        with studio("--compilers", "2", env=env) as (url, _proc):
            got = run(url, args.runs, designs)
    finally:
        for b in busy:
            b.kill()
            b.wait()
    print(f"{'design':28} {'flat ms':>8} {'3D ms':>8} | {'waited':>7} {'compile':>8} "
          f"{'transfer':>9} {'drawing':>8}   (median of {args.runs}, {args.busy} busy loops)")
    for eid, rows in got.items():
        if args.each:
            for i, r in enumerate(rows):
                print(f"  {eid} release {i + 1}: {r}")
        split = [r["split"] for r in rows if r["split"]]
        cells = [med([s[k] for s in split]) for k in ("waited", "compile", "transfer", "drawing")] \
            if split else ["-"] * 4
        print(f"{eid:28} {str(med([r['flat'] for r in rows])):>8} {str(med([r['built'] for r in rows])):>8} | "
              + " ".join(f"{str(c):>8}" for c in cells))
    return 0


if __name__ == "__main__":
    sys.exit(main())
