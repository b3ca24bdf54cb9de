"""A slider released again and again comes to its picture (issue 104), in Debian's Chromium
through Playwright against the test process's `aidl studio` (tests/conftest.py).

The planetary's sun steps by its planets on the counts where 2 x (sun + planet) divides by
them: moving `planet` from 18 to 20 moves the sun (12, the default) to 13, and back to 18
moves it to 12 again.  The second release to 20 left the page asking for that picture for
ever: the sun was then at its default, so not in the values sent, and the page took the sun
the server moved for a change the visitor made meanwhile.  Each release here must bring the
picture drawn with the slider's value (the server's echo of the values it drew with, the
fields on the page), counted by views, never timed.
"""
from __future__ import annotations

HANG = 120_000          # ms: a guard against a hung page, not a speed limit

RELEASE = """([name, value]) => {
  const r = document.querySelector(`input[type=range][name="${name}"]`);
  r.value = value;
  r.dispatchEvent(new Event("input", { bubbles: true }));
}"""

# what the page shows once it has nothing on its way: the picture's values as the server drew
# it (--set texts), the fields, and the views shown so far
SHOWN = """() => {
  const fields = {};
  for (const row of document.querySelectorAll('#params .param')) {
    const n = row.querySelector('input.value');
    if (n) fields[row.dataset.name] = Number(n.value);
  }
  const v = window.studio.view || {};
  return { views: window.studio.views, ok: !!v.ok, values: v.values || {}, fields,
           flat: document.getElementById('flat').className,
           shown: !!v.svg && window.studio.state.lastSvg === v.svg };
}"""


def number(text: str) -> float:
    return float(text.split()[0].removesuffix("mm"))


def settle(page, after: int) -> dict:
    page.wait_for_function(
        f"() => window.studio.views > {after} && window.studio.idle"
        " && !document.getElementById('flat').classList.contains('building')", timeout=HANG)
    return page.evaluate(SHOWN)


def test_a_slider_released_twice_to_a_value_shows_its_picture_both_times(studio_page):
    page = studio_page
    n = page.evaluate("window.studio.views")
    page.click("#open-gallery")
    page.click('#cards .card[data-id="generator/planetary"]')
    first = settle(page, n)
    assert first["ok"] and first["fields"]["planet"] == 18 and first["fields"]["sun"] == 12
    # planet 20, 18, 20: the sun the server moves each time (13, 12, 13) is the page's too
    shown = []
    for planet, sun in ((20, 13), (18, 12), (20, 13)):
        n = page.evaluate("window.studio.views")
        page.evaluate(RELEASE, ["planet", planet])
        now = settle(page, n)
        assert now["ok"] and now["shown"], now
        drawn = {k: number(t) for k, t in now["values"].items()}
        # the picture's values: the planet released, the sun moved onto its step (or at its
        # default, then not sent)
        assert drawn.get("planet", 18) == planet, now
        assert drawn.get("sun", 12) == sun, now
        assert now["fields"]["planet"] == planet and now["fields"]["sun"] == sun, now
        shown.append(now["views"] - n)
    # each release: its picture, and no request past it once the sliders' picture came
    assert all(k >= 1 for k in shown), shown
    assert page.evaluate("window.studio.errors") == []
