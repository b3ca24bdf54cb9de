"""The four whole jobs of issue 73 through `aidl mcp` and the official SDK's stdio client
(benchmarks/mcp_tokens.py): a switch plate to DXF with every size checked, a living-hinge
cover to SVG and G-code, a finger-joint box on a sheet with kerf and a 3D fit check, and the
plate's DXF imported, patched with `write_program` and re-rendered; each job's files re-read
(ezdxf, the G-code's own header), and what the server returned counted (characters / 4:
before issue 73, 3921 / 35451 / 2103 / 924 tokens; after, about 1400 / 1700 / 1400 / 760).
One server for the module; its further calls check the error shape, the patch tool, the
symlink refusal and the limits in the descriptions."""
import asyncio

import pytest

pytest.importorskip("mcp")
ezdxf = pytest.importorskip("ezdxf")
from benchmarks import mcp_tokens as M  # noqa: E402

BUDGET = {"plate": 2500, "hinge": 2500, "box": 2500, "import": 1500}   # tokens (chars/4)
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


def test_every_job_is_done_in_few_tokens_and_one_line_of_text(jobs):
    root, figures, results, _ = jobs
    assert figures["_counter"] in ("characters/4", "tiktoken cl100k_base")
    for job, most in BUDGET.items():
        assert figures[job]["tokens"] <= most, (job, figures[job])
    for job in M.JOBS:
        for tool, args, r in results[job]:
            assert not r.is_error, (tool, args, r.content)
            texts = [c.text for c in r.content if c.type == "text"]
            assert len(texts) == 1 and "\n" not in texts[0], (tool, texts)
            assert r.structured_content["ok"] is True, (tool, r.structured_content)


def test_the_switch_plate_dxf_has_every_size(jobs):
    root, _, results, _ = jobs
    doc = ezdxf.readfile(root / "plate.dxf")
    circles = sorted((round(c.dxf.center.y, 9), round(c.dxf.radius, 9))
                     for c in doc.modelspace().query("CIRCLE"))
    assert circles == [(-30.15, 1.75), (30.15, 1.75)]
    vals = {v["name"]: v["value"] for v in _sc(results, "plate", 2)["values"]}
    assert vals["plate.screws.top.diameter"] == pytest.approx(3.5)
    assert vals["plate.screws.top.radius"] == pytest.approx(1.75)
    assert vals["plate.body.corner_radius"] == pytest.approx(4)
    assert "circle d=3.5 at (0, 30.15)" in _sc(results, "plate", 1)["text"]


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
    assert header.startswith(f"; cut {job['cut_mm']:.1f} mm, travel {job['travel_mm']:.1f} mm")
    # every slit and the outline are cut: at least their lengths (74 x 15 + 20 x 11.5)
    assert job["cut_mm"] >= 74 * 15 + 20 * 11.5 and job["seconds"] > 0
    assert _sc(results, "hinge", 3)["job"]["cut_mm"] == job["cut_mm"]


def test_the_box_fits_and_its_sheet_layout_is_given(jobs):
    root, _, results, _ = jobs
    fit = _sc(results, "box", 0)["fit"]
    assert fit == {"checked": True, "collisions": [], "floating": []}
    assert _sc(results, "box", 1)["fit"]["checked"] is True
    lay = _sc(results, "box", 2)["layout"]
    placed = {p["part"]: p for p in lay["placements"]}
    assert set(placed) == {f"kit.box.{n}" for n in ("bottom", "front", "back", "left",
                                                   "right", "lid")}
    for p in placed.values():
        x0, y0, x1, y1 = p["bbox"]
        assert 0 <= x0 < x1 <= 600 and 0 <= y0 < y1 <= 400
    parts = _sc(results, "box", 0)["parts"]
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


def test_limits_are_in_the_descriptions(jobs):
    from aidl_lang.limits import MAX_ITER
    from aidl_lang.parser import MAX_NESTING
    for name in ("check", "render", "values", "describe", "write_program", "import_drawing"):
        d = EXTRA["tools"][name].description
        assert f"{MAX_ITER:,} items in one loop" in d and f"{MAX_NESTING} deep" in d, name
        assert "20 MB" in d


def test_the_docs_served_name_tool_arguments_not_cli_flags(jobs):
    from aidl_lang.reference import find
    for topic, flag, said in (("finger_box", "--assembled", "`render` with assembled=true"),
                              ("kerf", "--kerf", '`render` with kerf="0.2mm"'),
                              ("param", "--set", "`overrides`"),
                              ("outputs", "--page", 'page="A4-landscape"')):
        assert flag in find(topic).render()
        text = EXTRA[f"docs_{topic}"].content[0].text
        prose = "\n".join(ln for ln in text.splitlines() if not ln.lstrip().startswith("#"))
        assert flag not in prose and said in text, (topic, prose)
    assert "`render` with assembled=true" in EXTRA["topic_resource"].contents[0].text
