"""Issue 91: W0515's fix was a `Fixed` polygon hole of typed coordinates: it changed nothing
in the output (as it should: the opening is cut either way), but it did not follow the
params, left `--dof` calling the new hole free, and the message ("the shapes merge around
it") was read as "filled".  Now the message says the opening is cut through the part, and
the fix names the shapes around it (`AllowOverlap(base, post, brace)`), which holds whatever
the params make of them.  Tested through `aidl check` and `aidl render` on real files, the
SVG re-read by svgelements: the fix applied, the part comes out exactly as before (the
opening there, as promised), a `--set` of other sizes stays silent, `--dof` says the same
before and after; the other way the hint offers (the shapes made to overlap across it)
leaves no opening.  Cost: 8 small compiles and 4 renders, about 1.6 s."""
from __future__ import annotations

import contextlib
import io
import json

from exact_geometry import L, read_svg_loops

BRACKET = """param t = 6
param h = 60
solid bracket {
    base = Rectangle(center=(0, 0), width=h, height=t)
    post = Rectangle(center=(-h / 2 + t / 2, h / 2 - t / 2), width=t, height=h)
    brace = Polygon([(h / 2, 0), (h / 2, t), (-h / 2 + t, h), (-h / 2, h), (-h / 2, h - t)])
}
"""


def _run(*args) -> tuple:
    from aidl_lang.cli.main import main
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(list(args))
    return rc, out.getvalue(), err.getvalue()


def _diagnostics(path, *extra) -> list:
    rc, out, _ = _run("check", str(path), "--json", *extra)
    assert rc == 0, out
    return json.loads(out)["diagnostics"]


def _loops(path, tmp, *extra) -> list:
    svg = tmp / (path.stem + "".join(extra).replace("=", "_") + ".svg")
    rc, _, err = _run("render", str(path), "-o", str(svg), *extra)
    assert rc == 0, err
    return read_svg_loops(svg)


def _area(loop) -> float:
    assert all(isinstance(s, L) for s in loop)          # the bracket is all straight lines
    return 0.5 * sum(s.start[0] * s.end[1] - s.end[0] * s.start[1] for s in loop)


def test_W0515_says_the_opening_is_cut_and_its_fix_keeps_it_and_follows_the_params(tmp_path):
    src = tmp_path / "bracket.aidl"
    src.write_text(BRACKET)
    (w,) = [d for d in _diagnostics(src) if d["code"] == "W0515"]
    assert "is cut through `bracket`" in w["message"]
    assert "the part comes out with a window there" in w["message"]
    assert "the part stays as it is" in w["hint"] and "the opening is gone" in w["hint"]
    fix = w["fix"]
    assert fix["replacement"].strip() == "AllowOverlap(base, post, brace)"
    text = BRACKET[:fix["span"]["start"]] + fix["replacement"] + BRACKET[fix["span"]["end"]:]
    fixed = tmp_path / "fixed.aidl"
    fixed.write_text(text)
    assert _diagnostics(fixed) == []
    # the output is as the fix promised: the same outline and the same opening
    before, after = _loops(src, tmp_path), _loops(fixed, tmp_path)
    areas = sorted(_area(lp) for lp in before)
    assert len(before) == len(after) == 2 and areas[0] < -1000      # the opening (clockwise)
    assert sorted(_area(lp) for lp in after) == areas
    # it follows the params: other sizes, still said meant; the file without it still warned
    sizes = ("--set", "t=10", "--set", "h=80")
    assert [d["code"] for d in _diagnostics(src, *sizes)] == ["W0515"]
    assert _diagnostics(fixed, *sizes) == []
    assert len(_loops(fixed, tmp_path, *sizes)) == 2
    # and adds nothing for --dof to call free (the old fix's Fixed hole did)
    dof = [_run("check", str(p), "--dof")[1].split(": ", 1)[1] for p in (src, fixed)]
    assert dof[0] == dof[1] and "floating" in dof[0]
    # naming only some of the shapes around it does not say it: still W0515, and W0523
    part = tmp_path / "part.aidl"
    part.write_text(BRACKET.replace("\n}\n", "\n    AllowOverlap(base, post)\n}\n"))
    assert [d["code"] for d in _diagnostics(part)] == ["W0515", "W0523"]


def test_W0515_the_other_way_the_hint_offers_leaves_no_opening(tmp_path):
    """"make the shapes around it overlap across it": the brace drawn as a web down to the
    base and the post, the window is gone from the SVG and nothing is said."""
    closed = tmp_path / "closed.aidl"
    closed.write_text(BRACKET.replace("(-h / 2, h - t)", "(-h / 2, 0)"))
    assert _diagnostics(closed) == []
    assert len(_loops(closed, tmp_path)) == 1
