"""`aidl prompt`, `aidl generate` and `aidl eval` against a stub chat-completions server on
127.0.0.1 that replies first with a broken program and, once it has seen feedback, a fixed one."""
import contextlib
import io
import json
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import pytest

from aidl_lang.cli import main
from aidl_lang.llm.generate import extract_code
from aidl_lang.llm.prompt import EXAMPLES_DIR, code_blocks, example_programs, system_prompt, word_count
from aidl_lang.registry import ENTRIES

BROKEN = """Here is the plate:

```aidl
solid plate {
    body = Rectangle(center=(0, 0), width=60, height=30)
    hole bore {
        c = Circle(center=(0, 0), radius=6)
    }
    Rotate(body, 30 deg)
    CenterInside(bore, self)
}
```
"""

FIXED = """Fixed: rotation is an argument.

```aidl
solid plate {
    body = Rectangle(center=(0, 0), width=60, height=30, rotation=30 deg)
    hole bore {
        c = Circle(center=(0, 0), radius=6)
    }
    CenterInside(bore, self)
}
```
"""


class Stub:
    """Replies BROKEN to a fresh conversation and FIXED once the model has replied before."""

    def __init__(self):
        self.requests = []
        stub = self

        class H(BaseHTTPRequestHandler):
            def do_POST(self):
                n = int(self.headers.get("Content-Length", 0))
                body = json.loads(self.rfile.read(n))
                stub.requests.append({"body": body, "auth": self.headers.get("Authorization"),
                                      "path": self.path})
                seen = any(m["role"] == "assistant" for m in body["messages"])
                reply = FIXED if seen else BROKEN
                data = json.dumps({"choices": [{"message": {"role": "assistant",
                                                            "content": reply}}]}).encode()
                self.send_response(200)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

            def log_message(self, *a):
                pass

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), H)
        self.url = f"http://127.0.0.1:{self.server.server_address[1]}/v1"
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.server.shutdown()
        self.server.server_close()


@pytest.fixture
def stub():
    with Stub() as s:
        yield s


def run_cli(*args, env=None, monkeypatch=None):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main([str(a) for a in args])
    return rc, out.getvalue(), err.getvalue()


# ------------------------------------------------------------------ prompt
def test_every_example_in_the_prompt_compiles(compile_text):
    from aidl_lang.llm.prompt import PROMPT_EXAMPLES
    text = system_prompt(examples=len(PROMPT_EXAMPLES))
    blocks = code_blocks(text)
    # the booleans' example in the description, then every example program
    assert len(blocks) == 1 + len(example_programs()) and len(PROMPT_EXAMPLES) >= 4
    # as `aidl check` runs them (W0401, W0404 included): no warning either (issue 61)
    from aidl_lang.api import compile as aidl_compile
    for name, code in [("booleans.aidl", blocks[0])] + [
            (str(EXAMPLES_DIR / n), code) for (n, _), code in zip(example_programs(), blocks[1:])]:
        c = aidl_compile(code, path=name)
        c.find_redundant(seconds=None, max_rows=None)
        assert c.ok and not c.sink.items, (name, [d.message for d in c.sink.items])


def test_prompt_examples_option():
    from aidl_lang.llm.prompt import DEFAULT_EXAMPLES, PROMPT_EXAMPLES
    assert len(code_blocks(system_prompt())) == 1 + DEFAULT_EXAMPLES
    for n in range(len(PROMPT_EXAMPLES) + 1):
        rc, out, _ = run_cli("prompt", "--examples", str(n))
        assert rc == 0 and len(code_blocks(out)) == 1 + n
        assert out == system_prompt(examples=n)
    rc, out, _ = run_cli("prompt", "--examples", "9")
    assert rc == 0 and len(code_blocks(out)) == 1 + len(PROMPT_EXAMPLES)
    rc, _, err = run_cli("prompt", "--examples", "-1")
    assert rc == 2 and "--examples" in err


def test_prompt_lists_the_whole_registry_and_stays_compact():
    text = system_prompt()
    for name in ENTRIES:
        assert f"- {name}(" in text, name
    # synonyms are accepted silently (tests/test_vocabulary.py); the prompt names only the
    # ones whose arguments are swapped, and teaches one canonical spelling otherwise
    assert "Orthogonal" not in text and "ConvexHull" not in text
    assert "construction" in text and "Contains(a, b) means Inside(b, a)" in text
    # measured 2,200 words before issue 14; it may grow by at most 25% (docs/llm.md); issue
    # 23 allows 25% over its 2,596 words (3,245) for new constructs and the members-by-kind
    # table; issue 35 allows 15% over its 2,992 words (3,440) for the standard library,
    # statements and the booleans' example, and moved two of the four examples behind
    # `--examples N`; issues 36, 39 and 40 (Polyline, Sector, Stroke, mirror, Drawing2D, Place:
    # about 110 words) stay within the 3,440 and move the rules without examples to 3,000;
    # issue 52's 15 generators (boxes, joints, stands, an enclosure, gear mechanisms) add one
    # signature line each, 471 words (+13.7%): 3,950 and 3,480 without examples; hinged_box,
    # drawer and flex_box (std/boxes) 96 more: 4,046 and 3,576; issue 61's findings (settings
    # without `=`, Mirrored of a list, a point on an ellipse, one font, CornerPattern, centroid, mirror=, CutInto, lift=, ...) 102 more (2.5%): 4,148 and 3,680
    # issue 65's answers (min_wall, params from params, what stays put, polar(), RegularPolygon
    # side=, CornerPattern inset=(dx, dy), --describe's thickness and notches, how a warning on a
    # design as meant is accepted) 164 more (4.0%):
    # 4,312 and 3,844; issue 73's (flexible=true on every literal shape, W0524, AllowOverlap
    # and W0512) 22 more: 4,335 and 3,867; issue 72's Bend (living hinges in 3D) 14 more:
    # 4,349 and 3,881; issue 73's Intersect (its signature and line) 27 more: 4,376 and 3,908;
    # issue 71's sheet-level cut (a `cut` in an assembly) 8 more: 4,384 and 3,916; issue 84's
    # `pi`, `tau` count radians (`a + pi / 2` is `a + 90 deg`: tau read as 6.28 deg turned a
    # door sign's moon round) 14 more: 4,398 and 3,930; issue 86's `aidl set` line (10 words)
    # and the list defaults of gear_train and board_enclosure shown, not `...` (18): 4,426 and
    # 3,958; issue 84's who moves between two parts (the first-named to the second) 15 more:
    # 4,441 and 3,973; issue 84's `aidl check --sweep` (one line) 8 more: 4,449 and 3,981;
    # issue 84's Text width (a door sign's label ran over its screw holes) 4 more: 4,453, 3,985;
    # issue 95's constructs (Scale, Scaled, Translate, Translated, Flip: a line each; ring_gear;
    # Text's stencil=; finger_box's outside=) 120 more: 4,573 and 4,105; issue 91's Fillet of two
    # edges "where they meet or cross" (a model wrote the crossing one for a headphone hook) 2
    # more: 4,575 and 4,107; issue 92's `min = LO, max = HI` on every param (models declared no
    # range) 21 more: 4,596 and 4,128; issue 95's hole in a drawing (engraving minus
    # engraving: a compass rose's back points) 7 more: 4,603 and 4,135
    # issue 92's gears (spur_gear's addendum= and mate=, ring_gear's pinion=) 3 more: 4,606, 4,138
    # issue 102's Countersink and Counterbore (two signature lines and a line saying screw
    # heads are sunk, not an engraved ring) 48 more: 4,654 and 4,186; issue 105's who moves
    # between two shapes too, and Scale about its own centre (20 words): 4,674 and 4,206
    # issue 105's asserts of the request's own numbers and counts (a lip 2 mm low, a
    # CornerPattern's four holes where two were asked: slips no check could name) 34 more:
    # 4,708 and 4,240; issue 111's param reading constants, a statement ending at the line
    # break, a rounded star's outer_radius (30 more): 4,738 and 4,270; issue 111's anchors
    # (each stdlib template's line says the point `cx, cy` is, `@ X`, and which way its
    # rotation 0 points: two models guessed a cross_halving's mouth was its middle) 196 more
    # (4.1%): 4,934 and 4,466; issue 112's letters as a font's outlines (a cake topper's word,
    # `font=` in the Text line: 50 more): 4,984 and 4,516; issue 111's constructs models
    # reached for (a bar's start/end members, no radius= on Polygon/Polyline: Fillet, a
    # solid's hole hides no drawing's lines: 25 more): 5,009 and 4,541; `overrun=true` (a joint's run past the edge
    # counts in no box) and the joints' member `overrun`: 8 more, 5,017 and 4,549; issue 112's filled letters (Text's `fill=` and
    # "engraved in a drawing (`fill=true`: their area)", 16 more): 5,033 and 4,565; issue 111's
    # "each number copied from the request, never from the program" (a pick 33 mm wide where 27
    # was asked passed its own assert `width == 33 mm, "27 mm wide"`): 10 more, 5,043 and 4,575;
    # issue 111's second run: a hole's Circle cannot read its parent's geometry (E0201, with the
    # fix: numbers and a constraint in the parent; a first try failed on it), 27 more: 5,070, 4,602
    # issue 111's third run: a pattern's copies follow their sunk original (+7): 5,077, 4,609;
    # an engraving run off its part on purpose, `AllowOverlap(lines, self)` (W0505, +6): 5,083, 4,615;
    # a drawing engraved by CutInto (-1) and a name set in nested loops, `dia[i][j]` (+3): 5,085, 4,617;
    # an f-string's format, `f"{d:.1f} mm"` (a model wanted "1.0", str gives "1"; +3): 5,088, 4,620;
    # a Point in a Hull is a sharp corner (a heart's tip drawn as an R1 circle; +5): 5,093, 4,625;
    # `Fixed` holds in its structure, which carries it (run g threaded x0 through 16 coordinates
    # of its own template for want of it; +17): 5,110, 4,642; `sum` among the functions: 5,111, 4,643;
    # CutInto's "a pattern's copies follow" (run l cut 1 of 15 air holes; +4): 5,115, 4,647;
    # "asin, acos, atan, atan2 give angles" (runs i and m wrote `acos(x) * 1 rad`; +6): 5,121, 4,653
    # round nine (issue 111, runs x-z): start_angle turns from where the original is drawn (+28),
    # "stays where written on its part (it moves with its part)" (+8), functions `def f(v) = ...`
    # (+12), Fillet at [edge, circle or ellipse] (+9), washer's diameters (+9): 5,314; a fillet's
    # arc in a sharp tip (W0411, +30), two shapes meeting (+3), `AllowOverlap(labels)` (+2), a Spline's box bulges past its points (+14): 5,363
    assert word_count(text) <= 5772          # round eighteen: a Spline's box swells past its points, the box the cut part (runs gr, gs, hb) +19, a template's arguments known before solving (run gw) +7; round seventeen: W0516 accepted (runs gj, go) +1, Spline mirror= (runs gc, gj) +6, AllowOverlap(labels, part) for W0532 (run gc) +3, Offset of a list, their union (run gb) +4, a mortise never at an edge (W0530 in runs fh, fl, fn, fs, fj) +4; round sixteen: E0202 or E0108 (runs fw, fy) +2, a one-line def returns a shape (run fz) +3; Place on= (run ep), a bare number passed to a def (run ew) +28, AllowOverlap of a hole an engraving crosses (run fj) +5; round fifteen: Hull of a Line or an Arc +7 (run ed), RoundedRectangle by two corners +6 (run ek), Fixed of a list +3 (run er), CutInto of a cut +2 (run es); round fourteen: a bar's height +5, distance of shapes in an assert +10, a rail is a bar under each letter, the Text width line shortened: 5,657; RightOf x only +12, a box template's thickness= +7, ArcSlot's caps +12, a Text's width per letter +18; round thirteen: Place by face= and up= +35, a RegularPolygon's sizes as members +17, lists join with + +5; round twelve: the stroke font's ASCII +6, a def in a structure +7, asserts read placed parts where written +9, a heart's Rigid(self) +10, Fillet not at a Hull's or Arc's crossing +13, an outer solid named in an assembly makes no part +19; round eleven: a Star's, RegularPolygon's own centre +19, a drawing's hole draws no line +4, a feature placed whole +16, a closed shape's fill=true +7, asserts on differences +12; round ten: an Align relation reads a point +24, divider_height +2, kerf +2, after a comma or an operator +16, Triangle base, height +10, exp, log +2, Stroke ends +6
    assert word_count(system_prompt(examples=False)) <= 5304          # round eighteen +26, round seventeen +18, round nine +115, round ten +62, round eleven +59, round twelve +64, round thirteen +57, round fourteen +67, round fifteen +18


def test_the_agents_prompt_is_shorter_and_keeps_the_vocabulary(compile_text):
    """`aidl mcp`'s prompt (aidl://prompt, issue 86) says what the tools' `docs` does not
    repeat: the whole registry and every standard-library template (their defaults are in
    `docs`), one example program that compiles clean (the others are resources)."""
    from aidl_lang.api import compile as aidl_compile
    from aidl_lang.llm.prompt import agent_prompt
    from aidl_lang.library.reference import stdlib_templates
    text = agent_prompt()
    for name in ENTRIES:
        assert f"- {name}(" in text, name
    for name in stdlib_templates():
        assert f"- {name}(" in text, name
    assert "- lid_box(length, width, height, thickness, finger, clearance, outside) -> " \
        "assembly" in text
    blocks = code_blocks(text)
    assert len(blocks) == 2 and "aidl://examples/NAME.aidl" in text
    for code in blocks:
        c = aidl_compile(code, path=str(EXAMPLES_DIR / "x.aidl"))
        assert c.ok and not c.sink.items, [d.message for d in c.sink.items]
    # 4,399 words (29,460 characters as served) in the prompt of `aidl prompt`; + 3 words
    # for `set_params` and `measure` (issue 86), 4,083; + 15 for who moves (issue 84), 4,098;
    # + 8 for `check` with sweep=true, 4,106; + 4 for Text's width (issue 84), 4,110; + 115 for
    # issue 95's constructs (five transforms, ring_gear, stencil=, outside=), 4,225; issue 91's
    # crossing Fillet, 4,227; + 21 for declaring each param's range (issue 92), 4,248; + 7 for
    # a hole in a drawing (issue 95's engraving minus engraving), 4,255; + 3 for the
    # gears' addendum=, mate= and pinion= (issue 92), 4,258; + 48 for Countersink and
    # Counterbore (issue 102), 4,306; + 20 for who moves between shapes and Scale about its
    # own centre (issue 105), 4,326; + 34 for asserting the request's own numbers and counts
    # (issue 105: three of five defects in a model run were slips an assert would have named),
    # 4,360; + 196 for each template's anchor, `@ X` (issue 111), 4,586; + 50 for the letters
    # as a font's outlines (issue 112: the prompt's line and Text's font= in the registry),
    # 4,636; + 25 for issue 111's reached-for constructs (a bar's start/end, Fillet for a
    # Polygon's corners, a solid's hole and a drawing's lines), 4,661; + 8 for `overrun=true`
    # and the joints' member `overrun` (issue 111), 4,669; + 16 for filled letters (issue 112), 4,685;
    # + 10 for asserting numbers copied from the request, never the program (issue 111), 4,695;
    # + 27 for a hole's geometry never reading its parent's (E0201, issue 111's second run), 4,722
    # + 7 for a pattern's copies following their sunk original (issue 111's third run), 4,729
    # + 6 for an engraving run off its part on purpose (W0505's `AllowOverlap(lines, self)`), 4,735
    # + 2 for CutInto's drawing (-1) and a nested loop's `dia[i][j]` (+3), 4,737
    # + 3 for an f-string's format (`f"{d:.1f} mm"`), 4,740; + 5 for a Point in a Hull, 4,745;
    # + 17 for `Fixed` holding in its structure, which carries it, 4,762; + 1 for `sum`, 4,763;
    # + 4 for CutInto's pattern copies, 4,767; + 6 for the inverse functions giving angles, 4,773
    # + 96 for round nine (start_angle, "on its part", functions, Fillet at an oval, washer,
    # a fillet's arc in a sharp tip), 4,996
    # + 19 for round eleven (a Star's, RegularPolygon's own centre in the centring relations; a drawing's hole draws no line, +4; a feature placed whole, +16; a closed shape's fill=true, +7; asserts on differences, +12), 5,135; + 58 for round twelve (a def in a structure, asserts read placed parts where written, a heart's Rigid(self), Fillet's shapes, an outer solid named in an assembly, the stroke font's ASCII), 5,199; + 35 for Place by face= and up= (round thirteen), 5,234; + 17 for a RegularPolygon's sizes as members (run ck), 5,251; + 5 for lists joining with + (run cy), 5,256; + 7 for a box template's thickness= (run dc), 5,263; + 12 for an ArcSlot's angles at its caps' centres (run dj), 5,275; + 18 for a Text's width per letter (run dk), 5,293; + 12 for RightOf setting x only (runs dg, dj), 5,305; a rail as a bar under each letter (run dn), the Text width line shortened, 5,308; + 10 for distance of shapes in an assert (runs dd, dh, dr), 5,318; + 5 for a bar Rectangle's height (run dy), 5,323; + 7 for Hull of a Line or an Arc (run ed), 5,330; + 6 for RoundedRectangle by two corners (run ek), 5,336; + 3 for Fixed of a list (run er), 5,339; + 2 for CutInto of a cut (run es), 5,341; + 28 for Place on= (run ep) and a bare number passed to a def (run ew), 5,369; + 5 for AllowOverlap of a hole an engraving crosses (run fj), 5,374; + 3 for a one-line def returning a shape (run fz), 5,377; + 2 for E0202 or E0108 (runs fw, fy), 5,379
    # (the ratio: 0.93 until round fourteen, whose words the two prompts share grew it)
    # + 26 for round eighteen (a Spline's box, a template's arguments), 5,423
    assert word_count(text) <= 5423 and len(text) < 0.935 * len(system_prompt())


def test_prompt_members_table_gives_each_member_its_kind():
    text = system_prompt(examples=False)
    row = next(ln for ln in text.splitlines() if ln.startswith("- Rectangle, RoundedRectangle |"))
    assert "points: top_left top_right bottom_left bottom_right center" in row
    assert "lines: top bottom left right" in row and "numbers: width height" in row
    assert "fully constrained" in text and "degrees of freedom left" in text
    assert "assembly" in text and "--layout sheet" in text


def test_aidl_prompt_command():
    rc, out, err = run_cli("prompt", "--words")
    assert rc == 0 and out == system_prompt()
    assert f"{word_count(out)} words" in err
    rc, out, _ = run_cli("prompt", "--no-examples")
    assert rc == 0 and len(code_blocks(out)) == 1 and "Examples:" not in out


def test_extract_code():
    assert extract_code(BROKEN).startswith("solid plate {")
    assert extract_code("```\nsolid a {\n}\n```") == "solid a {\n}\n"
    assert extract_code("no code here") is None
    assert extract_code("```aidl\nsolid a {\n") == "solid a {\n"      # cut-off reply


# ------------------------------------------------------------------ generate
def test_generate_ends_valid_in_round_two(stub, tmp_path, monkeypatch):
    monkeypatch.setenv("OPENAI_API_KEY", "sk-test")
    monkeypatch.delenv("AIDL_BASE_URL", raising=False)
    out = tmp_path / "plate.aidl"
    rc, stdout, err = run_cli("generate", "a plate with a bore, turned 30 degrees", "-o", out,
                              "--base-url", stub.url, "--model", "stub-model")
    assert rc == 0, err
    assert "round 1/5" in err and "round 2: valid" in err and "E0103" in err
    assert out.read_text() == extract_code(FIXED)
    tr = json.loads((tmp_path / "plate.transcript.json").read_text())
    assert tr["ok"] and tr["rounds_used"] == 2 and not tr["first_try"]
    r1, r2 = tr["rounds"]
    assert r1["error_codes"] == ["E0103"] and r2["ok"] and r2["error_codes"] == []
    assert "Rotate" in r1["code"] and "rotation=30 deg" in r2["code"]
    # the feedback carries the diagnostic and asks to fix, not delete
    fb = r1["feedback"]
    assert "error[E0103]: unknown function `Rotate`" in fb and "rotation=" in fb
    assert "rather than deleting it" in fb
    assert [m["role"] for m in tr["messages"]] == ["system", "user", "assistant", "user", "assistant"]
    md = (tmp_path / "plate.transcript.md").read_text()
    assert "## Round 1" in md and "## Round 2: valid" in md
    # what the server saw: the system prompt, the model name, the key, the path
    req = stub.requests
    assert len(req) == 2 and req[0]["path"] == "/v1/chat/completions"
    assert req[0]["body"]["model"] == "stub-model" and req[0]["auth"] == "Bearer sk-test"
    assert req[0]["body"]["messages"][0]["content"] == system_prompt()
    assert req[1]["body"]["messages"][3]["content"] == fb


def test_generate_writes_nothing_when_rounds_run_out(stub, tmp_path, monkeypatch):
    monkeypatch.setenv("AIDL_BASE_URL", stub.url)
    out = tmp_path / "plate.aidl"
    rc, _, err = run_cli("generate", "a plate", "-o", out, "--rounds", "1")
    assert rc == 1 and "not written" in err
    assert not out.exists()
    tr = json.loads((tmp_path / "plate.transcript.json").read_text())
    assert not tr["ok"] and tr["rounds_used"] == 1


def test_generate_reports_an_unreachable_endpoint(tmp_path):
    rc, _, err = run_cli("generate", "x", "-o", tmp_path / "a.aidl",
                         "--base-url", "http://127.0.0.1:9/v1")
    assert rc == 1 and "cannot reach http://127.0.0.1:9/v1/chat/completions" in err
    assert "Traceback" not in err


# ------------------------------------------------------------------ eval
def test_eval_writes_report_and_contact_sheet(stub, tmp_path):
    prompts = tmp_path / "prompts.txt"
    prompts.write_text("# three prompts\na plate with a bore\n\na turned plate\na bracket\n")
    out = tmp_path / "report"
    rc, stdout, err = run_cli("eval", prompts, "--runs", "1", "-o", out, "--base-url", stub.url,
                              "--model", "stub-model")
    assert rc == 0, err
    assert "3 runs: 0 valid on first try, 3 within 5 rounds" in stdout
    rep = json.loads((out / "report.json").read_text())
    s = rep["summary"]
    assert rep["runs"] == 3 and s["valid_first_try"] == 0 and s["valid_within_rounds"] == 3
    assert s["mean_rounds_valid"] == 2 and s["error_codes"] == {"E0103": 3}
    assert [r["rounds_used"] for r in rep["results"]] == [2, 2, 2]
    assert [r["prompt"] for r in rep["results"]] == ["a plate with a bore", "a turned plate",
                                                     "a bracket"]
    page = (out / "index.html").read_text()
    assert page.count("<svg") == 3 and page.count("<section>") == 3
    assert "a turned plate" in page and "valid in 2 rounds" in page
    for r in rep["results"]:
        assert (out / r["program"]).exists() and (out / r["svg"]).exists()
    md = (out / "report.md").read_text()
    assert "valid within 5 rounds: 3 (100%)" in md


# ------------------------------------------------------------------ warnings fed back
WARNED = "```aidl\nsolid plate {\n    body = Rectangle(center=(0, 0), width=60, height=30)\n    1 + 1\n}\n```"
CLEAN = "```aidl\nsolid plate {\n    body = Rectangle(center=(0, 0), width=60, height=30)\n}\n```"


class Scripted:
    """A chat client that replies from a list and records what it was sent."""

    model = "scripted"

    def __init__(self, replies):
        self.replies, self.sent = list(replies), []

    def complete(self, messages):
        self.sent.append([dict(m) for m in messages])
        return self.replies.pop(0)


def test_generate_feeds_warnings_back_for_extra_rounds():
    from aidl_lang.llm.generate import generate
    c = Scripted([WARNED, CLEAN])
    res = generate("a plate", c, max_rounds=1, warning_rounds=1)
    assert res.ok and res.clean and len(res.rounds) == 2          # one round past max_rounds
    fb = c.sent[1][-1]["content"]
    assert "compiles, but with warnings" in fb and "W0101" in fb and "1 + 1" in fb
    assert res.rounds[0].warning_codes == ["W0101"] and res.code.strip() == CLEAN[8:-3].strip()
    # no warning rounds: the first valid program is taken, its warnings counted
    res = generate("a plate", Scripted([WARNED]), max_rounds=3, warning_rounds=0)
    assert res.ok and not res.clean and res.warnings == ["W0101"] and len(res.rounds) == 1
    # a warning round that breaks the program keeps the earlier valid one
    res = generate("a plate", Scripted([WARNED, BROKEN]), max_rounds=1, warning_rounds=1)
    assert res.ok and res.warnings == ["W0101"] and "1 + 1" in res.code


def test_eval_counts_programs_with_warnings_apart_from_clean_ones(tmp_path):
    from aidl_lang.llm.evaluate import run_eval
    rep = run_eval(["a", "b"], Scripted([WARNED, CLEAN, WARNED, WARNED]), tmp_path, runs=1,
                   max_rounds=2, warning_rounds=1)
    s = rep["summary"]
    # prompt a: warned, then clean; prompt b: warned twice (the one warning round is used)
    assert s["valid_within_rounds"] == 2 and s["valid_clean"] == 1 and s["valid_with_warnings"] == 1
    assert s["warning_codes"] == {"W0101": 1}
    assert "valid with warnings: 1" in (tmp_path / "report.md").read_text()


# ------------------------------------------------------------------ on_round (aidl studio)
def test_generate_calls_on_round_once_per_round_in_order():
    from aidl_lang.llm.generate import generate
    seen = []

    def on_round(r):
        # what the round says when it is handed over: compiled, with its verdict and feedback
        seen.append((r, r.number, r.ok, list(r.error_codes), list(r.warning_codes),
                     r.feedback is not None))

    c = Scripted([BROKEN, WARNED, CLEAN])
    res = generate("a plate", c, max_rounds=3, warning_rounds=1, on_round=on_round)
    assert res.ok and len(res.rounds) == 3
    assert [s[0] for s in seen] == res.rounds                  # the same objects, in order
    assert [s[0] is r for s, r in zip(seen, res.rounds)] == [True] * 3
    assert [s[1:] for s in seen] == [(1, False, ["E0103"], [], True),
                                     (2, True, [], ["W0101"], True),
                                     (3, True, [], [], False)]
    # each call came before the next request: the callback saw round n while n requests
    # had been made
    calls = []
    c = Scripted([BROKEN, FIXED])
    generate("a plate", c, max_rounds=5, on_round=lambda r: calls.append((r.number, len(c.sent))))
    assert calls == [(1, 1), (2, 2)]
    # a reply without code is a round too; rounds that run out still each get one call
    calls = []
    res = generate("a plate", Scripted(["no code", BROKEN]), max_rounds=2,
                   on_round=lambda r: calls.append((r.number, r.ok, r.error_codes)))
    assert not res.ok and calls == [(1, False, ["E0000"]), (2, False, ["E0103"])]
    # without on_round nothing changes
    res = generate("a plate", Scripted([BROKEN, FIXED]), max_rounds=5)
    assert res.ok and len(res.rounds) == 2


def test_on_round_raising_stops_the_loop():
    from aidl_lang.llm.generate import generate

    class Stop(Exception):
        pass

    def stop(r):
        raise Stop

    c = Scripted([BROKEN, FIXED])
    with pytest.raises(Stop):
        generate("a plate", c, max_rounds=5, on_round=stop)
    assert len(c.sent) == 1                                    # no second request was made


def test_on_round_in_visual_rounds_gets_the_round_with_its_picture():
    pytest.importorskip("cairosvg")
    from aidl_lang.llm.generate import generate
    calls = []
    res = generate("a plate", Scripted([CLEAN, "LOOKS RIGHT"]), max_rounds=2, visual_rounds=1,
                   path="plate.aidl",
                   on_round=lambda r: calls.append((r.number, r.kind, r.picture, r.verdict)))
    assert res.ok and res.looks_right and len(res.rounds) == 2
    assert calls == [(1, "program", "plate.round1.png", None), (2, "visual", None, "looks right")]
