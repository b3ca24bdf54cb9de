"""Whole jobs through `aidl mcp` and the official SDK's stdio client
(benchmarks/agents/mcp_tokens.py), each job's files re-read (ezdxf, trimesh, the G-code's own header)
and what the server returned counted (characters / 4).

Issue 86's four (a plate's M4 holes made M5 and the plate 150 mm wide, a finger-jointed box
to a cutting sheet with its assembled fit, a DXF turned into a design with its pitch
changed, a gear pair with its centre distance read): before, 3,813 / 19,238 / 1,619 /
21,398 tokens, `tools/list` 13,663; after, about 500 / 1,000 / 400 / 400 and 3,400.
Issue 73's four (a switch plate to DXF with every size checked, a living-hinge cover to SVG
and G-code, a finger-joint box on a sheet with kerf and a 3D fit check, the plate's DXF
imported, patched with `write_program` and re-rendered): before issue 73, 3921 / 35451 /
2103 / 924 tokens; after, about 1200 / 1400 / 1000 / 550.
One server for the module; its further calls check the error shape, the patch tool, the
symlink refusal and the limits in the descriptions."""
import asyncio

import pytest

pytest.importorskip("mcp")
ezdxf = pytest.importorskip("ezdxf")
from benchmarks.agents import mcp_tokens as M  # noqa: E402

BUDGET = {"plate": 3000, "box": 3000, "drawing": 3000, "gears": 3000,     # issue 86
          "switch": 2500, "hinge": 2500, "sheet": 2500, "import": 1500}    # tokens (chars/4)
LISTED = 5000       # tokens of tools/list, with two more tools of the average size
EXTRA: dict = {}
NEW = "solid s { c = Circle(center=(0, 0), radius=4) }\n"


async def _more(session):
    """Further calls after the jobs, their results kept in EXTRA."""
    tools = {t.name: t for t in (await session.list_tools()).tools}
    EXTRA["tools"] = tools
    calls = {
        "no_match": ("values", {"path": "plate.aidl", "names": ["nothing.here"]}),
        "many_names": ("values", {"path": "plate.aidl", "names": ["x"] * 100_000}),
        "wide": ("render", {"path": "plate.aidl", "width": 5000}),
        "unknown": ("check", {"path": "plate.aidl", "budgt": 3}),
        "escape": ("check", {"path": "escape.aidl"}),
        "write_link": ("write_program", {"path": "link.aidl", "text": "units mm\n"}),
        "write_new": ("write_program", {"path": "sub/new.aidl", "text": NEW}),
        "patch_missing": ("write_program", {"path": "sub/new.aidl", "old": "radius=9",
                                            "new": "radius=5"}),
        "patch_span": ("write_program", {"path": "sub/new.aidl", "start": NEW.index("radius"),
                                         "end": NEW.index("radius") + 8, "new": "radius=6"}),
        "broken": ("check", {"source": "solid s { c = Circel(center=(0, 0), radius=4) }\n"}),
        "hinge_detail": ("describe", {"path": "hinge.aidl", "detail": True}),
        "plate_values": ("values", {"path": "plate.aidl", "names": ["plate.body", "screws"]}),
    }
    for key, (tool, args) in calls.items():
        EXTRA[key] = await session.call_tool(tool, args)
    for topic in ("finger_box", "kerf", "param", "outputs"):
        EXTRA[f"docs_{topic}"] = await session.call_tool("docs", {"name": topic})
    EXTRA["topic_resource"] = await session.read_resource("aidl://docs/topic/finger_box")


@pytest.fixture(scope="module")
def jobs(tmp_path_factory):
    root = tmp_path_factory.mktemp("jobs")
    outside = root.parent / (root.name + "-secret.aidl")
    outside.write_text(M.PLATE)
    (root / "escape.aidl").symlink_to(outside)
    (root / "link.aidl").symlink_to(root / "plate.aidl")
    figures, results = asyncio.run(M.run_jobs(root, _more))
    print("\nMCP tokens per job:", {k: v for k, v in figures.items()})
    return root, figures, results, outside


def _sc(results, job, k):
    return results[job][k][2].structured_content


def test_every_job_is_done_in_few_tokens_and_one_text_block(jobs):
    """Each result is one text block: a first line of figures, then (issue 95) a line per
    diagnostic, value, feature, ... of its structured content, so a host that shows the
    model the text only hides nothing; the tokens count both, within the jobs' budgets."""
    root, figures, results, _ = jobs
    assert figures["_counter"] in ("characters/4", "tiktoken cl100k_base")
    for job, most in BUDGET.items():
        assert figures[job]["tokens"] <= most, (job, figures[job])
    for job in (*M.JOBS, *M.EARLIER):
        for tool, args, r in results[job]:
            assert not r.is_error, (tool, args, r.content)
            texts = [c.text for c in r.content if c.type == "text"]
            assert len(texts) == 1 and "ok" in texts[0].split("\n")[0].split("; "), \
                (tool, texts)
            assert "structured content" not in texts[0], (tool, texts)
            assert r.structured_content["ok"] is True, (tool, r.structured_content)


def test_the_switch_plate_dxf_has_every_size(jobs):
    root, _, results, _ = jobs
    doc = ezdxf.readfile(root / "plate.dxf")
    circles = sorted((round(c.dxf.center.y, 9), round(c.dxf.radius, 9))
                     for c in doc.modelspace().query("CIRCLE"))
    assert circles == [(-30.15, 1.75), (30.15, 1.75)]
    vals = {v["name"]: v["value"] for v in _sc(results, "switch", 2)["values"]}
    assert vals["plate.screws.top.diameter"] == pytest.approx(3.5)
    assert vals["plate.screws.top.radius"] == pytest.approx(1.75)
    assert vals["plate.body.corner_radius"] == pytest.approx(4)
    assert "circle d=3.5 at (0, 30.15)" in _sc(results, "switch", 1)["text"]


def test_the_hinge_is_summarised_and_its_gcode_figures_are_the_programs(jobs):
    root, _, results, _ = jobs
    described = _sc(results, "hinge", 1)
    cuts = described["describe"]["parts"][0]["through_cuts"]
    assert [(c["count"], c["alike"]["length"]) for c in cuts] == [(74, 15.0), (20, 11.5)]
    assert "74 alike, within x -20..20" in described["text"]
    full = EXTRA["hinge_detail"].structured_content
    assert len(full["describe"]["parts"][0]["through_cuts"]) == 94
    groups = [v for v in _sc(results, "hinge", 2)["values"] if v["kind"] == "group"]
    assert {v["name"]: v["count"] for v in groups}["cover.flex.cut_a[*].start"] == 74
    job = _sc(results, "hinge", 4)["job"]
    gcode = (root / "hinge.gcode").read_text()
    header = next(ln for ln in gcode.splitlines() if ln.startswith("; cut "))
    # the built-in laser cuts twice: the header says the path and its passes (issue 86)
    assert job["passes"] == 2 and job["cut_mm"] == pytest.approx(2 * job["path_mm"], abs=2e-3)
    assert header.startswith(f"; cut {job['path_mm']:.1f} mm path x 2 passes = "
                             f"{job['cut_mm']:.1f} mm, travel {job['travel_mm']:.1f} mm")
    # every slit and the outline are cut: at least their lengths (74 x 15 + 20 x 11.5)
    assert job["cut_mm"] >= 74 * 15 + 20 * 11.5 and job["seconds"] > 0
    assert _sc(results, "hinge", 3)["job"]["cut_mm"] == job["cut_mm"]


def test_the_box_fits_and_its_sheet_layout_is_given(jobs):
    root, _, results, _ = jobs
    fit = _sc(results, "sheet", 0)["fit"]
    assert fit == {"checked": True, "collisions": [], "floating": []}
    assert _sc(results, "sheet", 1)["fit"]["checked"] is True
    lay = _sc(results, "sheet", 2)["layout"]
    placed = {p["part"]: p for p in lay["placements"]}
    assert set(placed) == {f"kit.box.{n}" for n in ("bottom", "front", "back", "left",
                                                   "right", "lid")}
    for p in placed.values():
        x0, y0, x1, y1 = p["bbox"]
        assert 0 <= x0 < x1 <= 600 and 0 <= y0 < y1 <= 400
    parts = _sc(results, "sheet", 0)["parts"]
    assert lay["use"][0] == pytest.approx(sum(p["area"] for p in parts) / 240000, abs=1e-3)
    assert ezdxf.readfile(root / "box.dxf").modelspace().query("LWPOLYLINE LINE ARC")


def test_the_imported_program_is_patched_in_the_workspace_and_rerendered(jobs):
    root, _, results, _ = jobs
    written = _sc(results, "import", 1)
    assert written["written"] == "plate2.aidl" and written["ok"]
    assert "param holes_d = 4 mm" in (root / "plate2.aidl").read_text()
    circles = [round(c.dxf.radius, 9) for c in
               ezdxf.readfile(root / "plate2.dxf").modelspace().query("CIRCLE")]
    assert circles == [2.0, 2.0]


def _error(r):
    assert r.is_error
    e = r.structured_content["error"]
    text = r.content[0].text
    assert r.structured_content["ok"] is False and "\n" not in text
    assert "pydantic" not in text and "https://" not in text
    return e, text


def test_errors_have_one_shape_with_codes(jobs):
    e, text = _error(EXTRA["no_match"])
    assert e["code"] == "no_match" and e["argument"] == "names" and "nothing.here" in text
    e, text = _error(EXTRA["many_names"])
    assert e["code"] == "bad_argument" and e["argument"] == "names" and len(text) < 400
    e, text = _error(EXTRA["wide"])
    assert e["code"] == "bad_argument" and e["argument"] == "width" and "4096" in text
    e, text = _error(EXTRA["unknown"])
    assert e["code"] == "unknown_argument" and e["argument"] == "budgt" and "`budget`" in text
    broken = EXTRA["broken"]
    assert not broken.is_error and broken.structured_content["error"]["code"] == "E0103"


def test_the_symlink_refusal_names_the_link_and_its_target(jobs):
    _, _, _, outside = jobs
    e, text = _error(EXTRA["escape"])
    assert e["code"] == "outside_root"
    assert "symbolic link `escape.aidl`" in text and str(outside) in text
    e, text = _error(EXTRA["write_link"])
    assert e["code"] == "symlink" and "`link.aidl` is the symbolic link" in text


def test_write_program_writes_and_patches_inside_the_root(jobs):
    root = jobs[0]
    assert EXTRA["write_new"].structured_content["written"] == "sub/new.aidl"
    e, text = _error(EXTRA["patch_missing"])
    assert e["code"] == "no_match" and e["argument"] == "old"
    span = EXTRA["patch_span"].structured_content
    assert span["ok"] and (root / "sub" / "new.aidl").read_text() == \
        "solid s { c = Circle(center=(0, 0), radius=6) }\n"
    assert span["parts"][0]["area"] == pytest.approx(3.141592653589793 * 36, rel=1e-3)


def test_limits_are_stated_once_in_the_descriptions(jobs):
    from aidl_lang.base.limits import MAX_ITER
    from aidl_lang.parser import MAX_NESTING
    said = [name for name, t in EXTRA["tools"].items()
            if f"{MAX_ITER:,} items in one loop" in t.description]
    assert said == ["check"]
    d = EXTRA["tools"]["check"].description
    assert f"{MAX_NESTING} deep" in d and "20 MB" in d


def test_the_docs_served_name_tool_arguments_not_cli_flags(jobs):
    from aidl_lang.library.reference import find
    for topic, flag, said in (("finger_box", "--assembled", "`render` with assembled=true"),
                              ("kerf", "--kerf", '`render` with kerf="0.2mm"'),
                              ("param", "--set", "`overrides`"),
                              ("outputs", "--page", 'page="A4-landscape"')):
        assert flag in find(topic).render()
        text = EXTRA[f"docs_{topic}"].content[0].text
        prose = "\n".join(ln for ln in text.splitlines() if not ln.lstrip().startswith("#"))
        assert flag not in prose and said in text, (topic, prose)
    assert "`render` with assembled=true" in EXTRA["topic_resource"].contents[0].text


# ---------------------------------------------------------------- issue 86's jobs
def test_tools_list_leaves_room_for_two_more_tools_under_5000_tokens(jobs):
    """`tools/list` through the SDK's stdio client (13,663 tokens before issue 86): with two
    more tools of its average size it stays within 5,000 tokens; the served prompt is
    counted too."""
    _, figures, _, _ = jobs
    listed = figures["tools/list"]
    n = listed["tools"]
    assert n >= 8 and listed["tokens"] * (n + 2) / n <= LISTED, listed
    # issue 95 (round six): 4,166 tokens, exactly at the bound; the descriptions unindented,
    # the limits said tighter, alike outputs "as `check`: all its fields": 3,968 (chars / 4),
    # 5 % under it, room for a field or two; issue 101's `work` ({spent, budget}) in every
    # compiling tool's and import_drawing's result: 3,990; issue 111's `machine` as a
    # profile's keys (an object in render's schema): 4,006
    assert listed["tokens"] <= 4010 or figures["_counter"] != "characters/4", listed
    # 7,365 before; 6,801 with the line of `set_params` and `measure`, 6,828 with who moves,
    # 6,845 with `check` with sweep=true; issue 95's transforms, ring_gear, stencil and inside
    # sizes and issue 91's crossing Fillet: 7,046; issue 92's "declare each param's range": 7,069;
    # issue 95's hole in a drawing (engraving minus engraving): 7,078; issue 92's gears
    # (spur_gear's addendum= and mate=, ring_gear's pinion=, h18-gears): 7,083; issue 102's
    # Countersink and Counterbore, issue 105's who moves between shapes, Scale in place and
    # the constructs models reached for (max_width=, tip_radius=, incenter): 7,203; issue
    # 105's "assert the request's own numbers and counts": 7,252; issue 111's anchors of the
    # 38 stdlib templates (`@ POINT`), a param reading constants, line breaks: 7,548; issue
    # 112's Text(..., font=): 7,632; issue 111's reached-for constructs (a bar's start/end,
    # Fillet for a Polygon's corners, a solid's hole hides no drawing's lines): 7,672; issue
    # 111's `overrun=true` and issue 112's filled letters (Text's fill=): 7,716; issue 111's
    # numbers asserted as copied from the request, never the program: 7,732; a hole's
    # geometry never reading its parent's (E0201, issue 111's second run): 7,773; a pattern's
    # copies following their sunk original (issue 111's third run): 7,784; an engraving run
    # off its part on purpose (W0505's `AllowOverlap(lines, self)`): 7,800; a drawing engraved
    # on a template's part by `CutInto` (one word fewer, four tokens more): 7,804; a name set
    # in nested loops, `dia[i][j]`: 7,810; an f-string's format spec: 7,817; a Point
    # in a Hull (a sharp corner): 7,823; `Fixed` carried by its structure: 7,849; `sum`: 7,850; CutInto's pattern
    # copies: 7,857; asin, acos, atan, atan2 giving angles: 7,866; issue 111's round nine
    # (start_angle, "on its part", functions, Fillet at an oval and in a sharp tip): 8,175;
    # round eleven's Star and RegularPolygon centres, a drawing's hole drawing no line: 8,318;
    # a feature placed whole (one Text moves its drawing): 8,339; a closed shape's fill: 8,351;
    # asserts on differences (a layout moves coordinates): 8,369; round twelve's `def` at the
    # top or in a structure: 8,376; an assert across placed parts holding where they are
    # written: 8,397; a heart placed by a relation held by Rigid(self): 8,405; Fillet takes
    # no Hull's or Arc's crossing (runs bk, ce): 8,421; `part = NAME` of an outer solid makes
    # no part (runs by, ch x2): 8,446; the single-stroke font is ASCII (run ce): 8,456;
    # round thirteen's `Place` by where the top face looks, face= and up= (five faces turned
    # to the wall in round twelve): 8,512; a RegularPolygon's sizes as members (run ck): 8,542;
    # lists join with `+` (run cy): 8,548; round fourteen: a box template's `thickness=` is
    # the material (run dc): 8,559; an ArcSlot's angles at its caps' centres (run dj): 8,573;
    # a Text's width per letter, max_width= for little room (run dk): 8,595; RightOf sets x
    # only, Below y only (runs dg, dj): 8,616; a rail is a bar under each letter (run dn), the
    # Text width line shortened: 8,620; distance of shapes in an assert (runs dd, dh, dr): 8,636;
    # a bar Rectangle's height is its length (run dy): 8,643; Hull of a Line or an Arc (run ed): 8,650;
    # RoundedRectangle by two corners (run ek): 8,672; Fixed of a list (run er): 8,676;
    # CutInto of a cut (run es): 8,678; Place on= another part (run ep) and a bare number
    # passed to a def (run ew): 8,714; AllowOverlap of an engraving and a hole it crosses
    # (run fj): 8,720; a one-line def returns a shape too (run fz): 8,722; E0202 or E0108
    # (runs fw, fy): 8,725
    assert figures["prompt"]["tokens"] <= 8790, figures["prompt"]     # round eighteen: a Spline's box, a template's arguments; round seventeen: a mortise never at an edge, Offset of a list, W0532 accepted, Spline mirror=


def test_each_of_issue_86s_jobs_is_at_most_3000_tokens_and_renders_no_picture(jobs):
    _, figures, results, _ = jobs
    for job in M.JOBS:
        assert figures[job]["tokens"] <= 3000, (job, figures[job])
        for tool, args, r in results[job]:
            assert [c.type for c in r.content] == ["text"], (job, tool)


def test_the_plate_has_four_m5_holes_and_is_150_mm_wide(jobs):
    root, _, results, _ = jobs
    msp = ezdxf.readfile(root / "mount.dxf").modelspace()
    holes = sorted((round(c.dxf.center.x, 9), round(c.dxf.center.y, 9), round(c.dxf.radius, 9))
                   for c in msp.query("CIRCLE"))
    assert holes == [(-67.0, -32.0, 2.75), (-67.0, 32.0, 2.75), (67.0, -32.0, 2.75),
                     (67.0, 32.0, 2.75)]
    done = _sc(results, "plate", -1)
    assert done["size"] == [150.0, 80.0] and done["written"] == "mount.dxf"
    job = done["job"]
    # the outline (150 x 80, corners of radius 4) and four circles of 5.5 mm, cut twice
    path = 2 * (150 + 80) - 8 * 4 + 2 * 3.141592653589793 * 4 + 4 * 3.141592653589793 * 5.5
    assert job["path_mm"] == pytest.approx(path, abs=1e-2) and job["passes"] == 2
    assert job["cut_mm"] == pytest.approx(2 * path, abs=2e-2)
    line = results["plate"][-1][2].content[0].text
    assert f"cut {path:.1f} mm path x 2 passes = {2 * path:.1f} mm" in line


def test_the_finger_box_is_on_one_sheet_and_fits_assembled(jobs):
    import trimesh
    root, _, results, _ = jobs
    written = _sc(results, "box", 0)
    assert written["fit"] == {"checked": True, "collisions": [], "floating": []}
    sheet = _sc(results, "box", 1)
    assert sheet["layout"]["sheets"] == 1 and len(sheet["layout"]["placements"]) == 6
    assert ezdxf.readfile(root / "fbox.dxf").modelspace().query("LWPOLYLINE LINE ARC")
    assembled = _sc(results, "box", 2)
    assert assembled["fit"]["checked"] and not assembled["fit"]["collisions"]
    mesh = trimesh.load(root / "fbox.stl")
    # the assembled box's outer size: 100 x 70 x 40 mm (the panels' 3 mm inside it)
    assert sorted(mesh.extents) == pytest.approx(sorted([100, 70, 40]), abs=1e-6)


def test_the_drawing_becomes_a_design_whose_pitch_is_changed(jobs):
    root, _, _, _ = jobs
    assert "param holes_pitch = 22 mm" in (root / "rail.aidl").read_text()
    xs = sorted(round(c.dxf.center.x, 9) for c in
                ezdxf.readfile(root / "rail2.dxf").modelspace().query("CIRCLE"))
    assert len(xs) == 6 and [round(b - a, 9) for a, b in zip(xs, xs[1:])] == [22.0] * 5
    assert xs[0] + xs[-1] == pytest.approx(160)          # still about the middle


def test_the_gear_centres_are_60_mm_apart(jobs):
    root, _, results, _ = jobs
    read = _sc(results, "gears", 1)
    if "values" in read:
        (x0, y0), (x1, y1) = [v["value"] for v in read["values"]]
        assert ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5 == pytest.approx(60, abs=1e-9)
    circles = ezdxf.readfile(root / "gears.dxf").modelspace().query("CIRCLE")
    bores = sorted((round(c.dxf.radius, 9), round(c.dxf.center.x, 9)) for c in circles)
    assert bores == [(2.5, 0.0), (4.0, 60.0)]
