"""The picture follows a drag (issue 113), in Debian's Chromium through Playwright against the
test process's `aidl studio` (tests/conftest.py).

Board enclosure's `width` is dragged for 10 s, a move every 250 ms (40 moves, each 2 mm up:
the range input's value and its `input` event, as a drag's moves), beside one busy core (this
test's own `python3 -c 'while True: pass'`, killed after).  Before, the page threw away every
answer whose values the slider had left meanwhile: 0 pictures until the mouse was released at
a move every 110 or 280 ms, 3 beside one busy core at 250 ms.  Now every picture answered
during the drag is on the flat view as it comes (counted by the <img>'s own `load` events, not
by the page's counters), marked with the value it is of, and the last is the slider's own.

What the shares allow is asserted with margin (marked `timing`): every picture answered
during the drag is shown (a law at any load), and at least 4 are (a board enclosure's move
is about 0.1 s of CPU in the worker; on the shared 2-core machine at load 9-10, beside the
busy loop, 5 and 8 came; the issue's 8 is for one busy core on an otherwise quiet machine).
"""
from __future__ import annotations

import subprocess
import sys

import pytest

HANG = 120_000          # ms: a guard against a hung page, not a speed limit
pytestmark = pytest.mark.timing

# 40 moves, one every 250 ms (the page's own timer: no round trip to Python between moves);
# each load of the flat view's <img> during the drag is recorded with the mark it carries
DRAG = """async ([name, start, step, moves, every]) => {
  const r = document.querySelector(`input[type=range][name="${name}"]`);
  const img = document.getElementById("flat-img");
  const loads = [];
  const onload = () => {
    const mark = document.getElementById("flat-for");
    loads.push({ mark: mark && !mark.hidden ? mark.textContent : "", views: window.studio.views });
  };
  img.addEventListener("load", onload);
  const views = window.studio.views, passing = window.studio.passing;
  for (let i = 1; i <= moves; i++) {
    r.value = start + i * step;
    r.dispatchEvent(new Event("input", { bubbles: true }));
    await new Promise((ok) => setTimeout(ok, every));
  }
  // the loads that land after the last move stay counted until the page settles (LATE)
  window.__dragLoads = loads;
  window.__dragOff = () => img.removeEventListener("load", onload);
  return { loads: loads.slice(), views: window.studio.views - views,
           passing: window.studio.passing - passing };
}"""

LATE = """() => { window.__dragOff(); return window.__dragLoads; }"""


def settle(page, after: int) -> None:
    page.wait_for_function(
        f"() => window.studio.views > {after} && window.studio.idle"
        " && !document.getElementById('flat').classList.contains('building')", timeout=HANG)


def test_a_drag_shows_the_pictures_answered_while_it_goes_on(studio_page):
    page = studio_page
    n = page.evaluate("window.studio.views")
    page.click("#open-gallery")
    page.click('#cards .card[data-id="generator/board_enclosure"]')
    settle(page, n)
    start = page.evaluate("window.studio.view.params.find((p) => p.name === 'width').value")
    assert start == 85
    answers = []            # the previews answered during the drag: each a picture or not

    def answered(r):
        if r.url.endswith("/api/view") and answers is not None:
            doc = r.json()
            answers.append(bool(doc.get("ok") and doc.get("svg")))
    page.on("response", answered)
    busy = subprocess.Popen([sys.executable, "-c", "while True: pass"])
    try:
        n = page.evaluate("window.studio.views")
        got = page.evaluate(DRAG, ["width", start, 2, 40, 250])
        pictures, answers = sum(answers), None
    finally:
        busy.kill()
        busy.wait()
        page.remove_listener("response", answered)
    settle(page, n)
    late = page.evaluate(LATE)[len(got["loads"]):]
    # every picture answered while the slider moves is taken up by the page (each a passing
    # picture, or the sliders' own); the page's own counters, beside the <img>'s loads below
    # (an answer that reached the test in the drag's last instant may reach the page after it)
    assert got["passing"] + got["views"] >= pictures - 1 and pictures >= 1, (pictures, got)
    # and is on the flat view: an <img> load for each, marked with the width it is of, a
    # width the slider passed (85 + 2k mm), never the sliders' own while they move on.  Loads
    # that land after the last move (its answer came in its last instant, or the image was
    # decoded after it) are counted with a mark until the page settles; one image may be
    # overtaken by the next answer before it is decoded (the browser then loads only the
    # newer: CI's run at load 2 lost one so, 23 loads of 25 answers, once)
    loads = got["loads"] + [x for x in late if x["mark"]]
    assert len(loads) >= pictures - 2, (pictures, got, late)
    passed = [x for x in loads if x["mark"]]
    assert len(loads) >= 4, got
    assert len(passed) >= 3, got
    for x in passed:
        assert x["mark"].startswith("showing width "), x
        w = float(x["mark"].removeprefix("showing width ").removesuffix(" mm"))
        assert 85 < w < 165 and (w - 85) % 2 == 0, x
    # the widths shown go up with the drag (an answer is never shown after a later one)
    widths = [float(x["mark"].split()[2]) for x in passed]
    assert widths == sorted(widths), widths
    # once the slider rests, its own picture: the mark gone, the picture drawn at 165 mm
    assert page.evaluate("window.studio.view.values.width") == "165mm"
    assert page.evaluate("document.getElementById('flat-for').hidden")
    assert page.evaluate("window.studio.errors") == []
