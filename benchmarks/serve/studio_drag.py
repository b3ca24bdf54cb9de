"""A 20 s drag after browsing four designs, in Chromium (issue 104: "after browsing four designs,
a 20 s drag had 8 of 30 requests refused once"):

    .venv/bin/python benchmarks/serve/studio_drag.py                      # the default rate
    .venv/bin/python benchmarks/serve/studio_drag.py --rate "30/5 seconds" --seconds 20

Starts `aidl studio --port 0` (two compile workers; ``--rate``: the studio's rate, default
its own, 300/minute), opens the page in Debian's Chromium (1280 x 800) and browses as a
visitor does: the gallery opened four times and scrolled through (its thumbnails loaded, not
stopped), a design
opened from it each time and left when its picture has come.  Then one slider of the fourth
design is dragged for ``--seconds``: its value moved one step every 50 ms, up and down its
range (the range input's value and its `input` event, as a drag's moves), and the page is
let settle.  Every answer the page got from /api/ is counted by route and status, apart for
the browsing and for the drag; a refused request is a 429 (the rate) or a 503 (busy).
Prints the counts, the pictures the drag showed and whether the last is the slider's value.
"""
from __future__ import annotations

import argparse
import collections
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

BROWSE = ("generator/board_enclosure", "generator/gear_train", "example/mounting_plate",
          "generator/tool_holder")

MOVE = """([name, value]) => {
  const r = document.querySelector(`input[type=range][name="${name}"]`);
  r.value = value;
  r.dispatchEvent(new Event("input", { bubbles: true }));
}"""


def route(url: str) -> str:
    path = url.split("/api/", 1)[1].split("?", 1)[0]
    return "thumb" if path.startswith("thumb/") else "gallery" if path.startswith("gallery") \
        else path.split("/", 1)[0]


def run(url: str, seconds: float) -> dict:
    from playwright.sync_api import sync_playwright

    from benchmarks.serve.serve_latency import CHROMIUM, CHROMIUM_ARGS
    got = {"browse": collections.Counter(), "drag": collections.Counter()}
    phase = ["browse"]
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        ctx = browser.new_context(viewport={"width": 1280, "height": 800})
        page = ctx.new_page()
        page.on("response", lambda r: got[phase[0]].update([(route(r.url), r.status)])
                if "/api/" in r.url else None)
        page.goto(url)
        page.wait_for_function("() => window.studio && window.studio.ready && window.studio.view"
                               " && window.studio.view.ok", timeout=300_000)
        page.keyboard.press("Escape")
        for eid in BROWSE:
            n = page.evaluate("window.studio.views")
            page.click("#open-gallery")
            # the gallery's thumbnails as a visitor sees them come: scrolled through
            page.mouse.move(640, 400)
            for _ in range(4):
                page.mouse.wheel(0, 1200)
                page.wait_for_timeout(400)
            page.click(f'#cards .card[data-id="{eid}"]')
            page.wait_for_function(f"() => window.studio.views > {n} && window.studio.idle",
                                   timeout=300_000)
        p = page.evaluate("window.studio.view.params.find((p) => p.min != null && p.max != null"
                          " && p.max > p.min)")
        name, lo, hi = p["name"], p["min"], p["max"]
        step = p.get("step") or (hi - lo) / 100
        phase[0] = "drag"
        views = page.evaluate("window.studio.views")
        v, d, moves = p["value"], 1, 0
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            if not lo <= v + d * step <= hi:
                d = -d
            v = round(v + d * step, 9)
            page.evaluate(MOVE, [name, v])
            moves += 1
            page.wait_for_timeout(50)
        page.wait_for_function("() => window.studio.idle", timeout=300_000)
        last = page.evaluate("window.studio.view.values")
        shown = page.evaluate("window.studio.views") - views
        ctx.close()
        browser.close()
    return {"counts": got, "slider": (name, v), "moves": moves, "shown": shown, "last": last}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seconds", type=float, default=20.0)
    ap.add_argument("--rate", default=None, help="the studio's --rate (default: its own)")
    args = ap.parse_args(argv)
    from benchmarks.serve.studio_server import studio
    extra = ("--rate", args.rate) if args.rate else ()
    with studio("--compilers", "2", *extra, env={"AIDL_STUDIO_MODEL_URL": ""}) as (url, _proc):
        out = run(url, args.seconds)
    for phase in ("browse", "drag"):
        c = out["counts"][phase]
        refused = sum(n for (_, status), n in c.items() if status in (429, 503))
        print(f"{phase}: {sum(c.values())} requests, {refused} refused (429/503); by route and "
              f"status: {dict(sorted(c.items()))}")
    name, v = out["slider"]
    print(f"drag: {out['moves']} moves of `{name}` over {args.seconds:g} s, {out['shown']} "
          f"pictures shown; the last drawn with {out['last']} (the slider at {v:g})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
