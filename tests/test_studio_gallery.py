"""The gallery of ``aidl studio`` (aidl_lang/studio/gallery.py): every example and every
renderable stdlib generator is an entry with a unique URL-safe id, a readable one-line purpose,
a self-contained program that compiles in an empty folder, its params as form rows, and a
thumbnail.  The programs the gallery writes (synthesized generators) or rewrites (examples
whose generator arguments are lifted into params) are checked to be wired: a param override
changes the render, and a lifted program draws exactly what its file draws.

Measured on two shared cores: building the gallery takes about 1.5 s, compiling all 47
entries about 3 s, the whole module about 35 s (most of it the param-wiring checks, which
compile each written program once per param)."""
import json
import re
from pathlib import Path

import pytest

from aidl_lang import api
from aidl_lang.library.reference import stdlib_templates
from aidl_lang.studio import gallery as g
from aidl_lang.studio.wording import page_program

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE_FILES = sorted((ROOT / "examples").glob("*.aidl"))
GENERATOR_FILES = sorted((ROOT / "examples" / "generators").glob("*.aidl"))
ENTRIES = g.entries()
IDS = [e.id for e in ENTRIES]
# the entries whose params the gallery wrote: synthesized programs and lifted examples
WRITTEN = [e for e in ENTRIES if e.synthesized or "# the arguments of " in e.source]


@pytest.fixture(scope="module")
def at_defaults():
    """Each entry compiled at its written values in a fresh empty folder
    (:func:`aidl_lang.studio.gallery.compile_entry`), once for the module: the empty-folder
    test, the param-wiring test's base and the lifted examples' own render read the same
    result (they compiled it three times: 72 compiles, now 48)."""
    done: dict = {}

    def compiled(e):
        if e.id not in done:
            done[e.id] = g.compile_entry(e)
        return done[e.id]
    return compiled


def test_the_examples_folder_is_the_repository_s():
    """One examples folder for the gallery, `aidl prompt` and the MCP server: the package's
    aidl_lang/examples, a link to the repository's examples/ (the wheel holds the files)."""
    from aidl_lang.llm.prompt import EXAMPLES_DIR
    from aidl_lang.mcp.server import _EXAMPLES
    assert g.EXAMPLES.resolve() == (ROOT / "examples").resolve()
    assert g.EXAMPLES == EXAMPLES_DIR == _EXAMPLES == ROOT / "aidl_lang" / "examples"
    assert (ROOT / "aidl_lang" / "examples").is_symlink()
    assert not (ROOT / "aidl_lang" / "studio" / "examples").exists()


def test_every_example_and_generator_example_file_appears_once():
    origins = [e.origin for e in ENTRIES if e.origin.startswith("examples/")]
    want = [f"examples/{p.name}" for p in EXAMPLE_FILES] + \
        [f"examples/generators/{p.name}" for p in GENERATOR_FILES]
    assert sorted(origins) == sorted(want)
    assert len(EXAMPLE_FILES) >= 20 and len(GENERATOR_FILES) >= 18
    for e in ENTRIES:
        assert e.kind in g.KINDS
        if e.origin.startswith("examples/generators/"):
            assert e.kind == "generator" and e.id == f"generator/{Path(e.origin).stem}"
        elif e.origin.startswith("examples/"):
            assert e.kind == "example" and e.id == f"example/{Path(e.origin).stem}"
        else:
            assert e.synthesized and e.kind == "generator" and e.origin.startswith("std/")


def test_ids_are_unique_and_url_safe():
    assert len(IDS) == len(set(IDS))
    for i in IDS:
        assert re.fullmatch(r"(example|generator)/[a-z0-9_-]+", i), i
    assert g.entry("generator/divider_tray").title == "Divider tray"
    assert g.entry("example/telephone").kind == "example"
    assert g.entry("example/pcb_enclosure").title == "PCB enclosure"
    assert g.entry("generator/nope") is None


@pytest.mark.parametrize("e", ENTRIES, ids=IDS)
def test_every_purpose_is_one_readable_line(e):
    p = e.purpose
    assert p and len(p) <= g.PURPOSE_MAX, p
    assert "\n" not in p and "`" not in p and "  " not in p, p
    assert p[0].isupper() and p[-1] in ".…", p
    # more than the file name: not "A name tag." for name_tag.aidl
    words = re.sub(r"\b(a|an|the)\b|[^a-z0-9 ]", " ", p.lower()).split()
    assert words != e.id.split("/")[1].split("_"), p
    assert len(words) >= 3, p
    assert e.title and e.title[0].isupper()


def test_purposes_come_from_the_leading_comment():
    assert g.entry("generator/divider_tray").purpose.startswith("A parts tray of 3 x 4")
    assert g.entry("generator/washer").purpose == ("A flat washer: a ring with a concentric "
                                                   "bore, outer and inner their diameters.")
    # a long first sentence keeps what fits of its list
    key = g.entry("example/key").purpose
    assert key.startswith("A house key: a round bow with a key-ring hole") and key.endswith("…")
    assert g.purpose_of("A `width` x `height` plate. Member: `body`.") == "A width x height plate."
    assert g.purpose_of('A plate from the library (import "std/plates.aidl").') == \
        "A plate from the library."


def test_every_documented_renderable_generator_is_in_the_gallery():
    gens = g.renderable_generators()
    shown = {e.generator for e in ENTRIES if e.generator}
    assert set(gens) <= shown, set(gens) - shown
    assert {"divider_tray", "spur_gear", "text_on_arc", "finger_box", "gear_pair"} <= shown
    # the rest of the library is left out for a reason: holes and through-cuts only cut into
    # a solid
    assert set(gens) | set(g.skipped()) == set(stdlib_templates())
    for name, why in g.skipped().items():
        assert stdlib_templates()[name].node.kind in ("hole", "cut"), (name, why)
    # an example file of its own takes precedence over a synthesized program
    assert not g.entry("generator/divider_tray").synthesized
    assert g.entry("generator/gear_pair") is None            # examples/gear_pair.aidl shows it
    assert g.entry("example/gear_pair").generator == "gear_pair"
    synth = {e.generator for e in ENTRIES if e.synthesized}
    assert "washer" in synth and "spur_gear" in synth


@pytest.mark.parametrize("e", ENTRIES, ids=IDS)
def test_every_entry_compiles_alone_in_an_empty_folder(e, at_defaults):
    r = at_defaults(e)                  # compile_entry: main.aidl in a new empty folder
    assert r.ok, [f"{d.code} {d.message}" for d in r.errors]
    assert r.parts or e.generator == "text_on_arc"           # a drawing has no solid part


def test_programs_are_self_contained():
    gear = g.entry("example/gear").source
    assert not re.search(r'^import "parts/', gear, re.M) and "def spoked_gear(" in gear
    assert '"std/drawings/logo.svg"' in g.entry("example/logo_plate").source
    assert '"std/drawings/pcb_board.dxf"' in g.entry("example/pcb_enclosure").source
    for e in ENTRIES:
        for m in re.finditer(r'^\s*import\s+"([^"]+)"', e.source, re.M):
            assert m.group(1).startswith("std/"), (e.id, m.group(1))


def test_the_divider_tray_has_its_form():
    rows = {p["name"]: p for p in g.entry("generator/divider_tray").params}
    for n in ("rows", "cols"):
        assert rows[n]["kind"] == "integer" and rows[n]["step"] == 1
        assert rows[n]["min"] >= 1 and rows[n]["max"] >= 6
        assert isinstance(rows[n]["default"], int)
    assert (rows["rows"]["default"], rows["cols"]["default"]) == (3, 4)   # the example's
    t = rows["thickness"]
    assert (t["kind"], t["unit"], t["default"], t["min"], t["max"]) == ("length", "mm", 3, 1, 12)
    assert rows["length"]["default"] == 160 and rows["length"]["unit"] == "mm"
    assert rows["outside"]["kind"] == "bool" and rows["outside"]["min"] is None
    for p in rows.values():
        assert set(p) == {"name", "kind", "unit", "default", "min", "max", "step", "declared",
                          "help"}


def test_example_params_keep_their_own_ranges_and_comments():
    rows = {p["name"]: p for p in g.entry("example/laser_box").params}
    assert (rows["length"]["min"], rows["length"]["max"], rows["length"]["step"]) == (60, 200, 5)
    assert rows["length"]["declared"]
    opener = {p["name"]: p for p in g.entry("example/bottle_opener").params}
    assert opener["length"]["help"] == "from the head's center to the end of the handle"
    assert opener["grips"]["kind"] == "integer"


@pytest.mark.parametrize("e", WRITTEN, ids=[e.id for e in WRITTEN])
def test_written_params_have_ranges_that_hold_their_defaults(e):
    assert e.params
    for p in e.params:
        if p["kind"] in ("length", "angle", "number", "integer"):
            assert p["declared"], p
            assert p["min"] <= p["default"] <= p["max"] and p["step"] > 0, p
    t = next((p for p in e.params if p["name"] == "thickness"), None)
    if t is not None:
        assert (t["min"], t["max"]) == (1, 12)


def test_ranges_follow_the_generators_asserts():
    rows = {p["name"]: p for p in g.entry("generator/tablet_stand").params}
    assert 30 < rows["angle"]["min"] < rows["angle"]["default"] < rows["angle"]["max"] < 85
    assert rows["width"]["min"] >= 60
    shelf = {p["name"]: p for p in g.entry("generator/wall_shelf").params}
    assert shelf["length"]["min"] >= 150 and shelf["depth"]["min"] >= 60


def _changed(value, p):
    """A value a little away from the default, inside the slider's range, as --set text."""
    if p["kind"] == "bool":
        return "false" if value else "true"
    step = p["step"]
    if p["kind"] == "integer":
        new = value + 1 if value + 1 <= p["max"] else value - 1
    else:
        new = round((value * 1.25 if value else value + 10 * step) / step) * step
        new = new if abs(new - value) >= step / 2 else value + step
        if new > p["max"]:
            new = max(value - 10 * step, p["min"])
    return f"{new:g} {p['unit']}".strip()


@pytest.mark.parametrize("e", WRITTEN, ids=[e.id for e in WRITTEN])
def test_every_written_param_is_wired(e, at_defaults):
    """Overriding any one param of a program the gallery wrote changes the render: the flat
    SVG, else the assembled STL (a gear set's `thickness` only lifts its parts in 3D); or it
    trips the generator's own assertion (E0405: the value reached it)."""
    base = at_defaults(e)
    assert base.ok
    svg, stl = base.to_svg(kerf=0), None
    for p in e.params:
        if p["kind"] == "string":
            continue
        text = _changed(p["default"], p)
        r = g.compile_entry(e, {p["name"]: text})
        if r.ok:
            if r.to_svg(kerf=0) == svg:
                stl = stl or base.encode("stl", assembled=True)
                assert r.encode("stl", assembled=True) != stl, \
                    f"--set {p['name']}={text} changed nothing"
        else:
            assert {d.code for d in r.errors} == {"E0405"}, \
                (p["name"], text, [d.message for d in r.errors])


def test_a_synthesized_program_follows_its_params(at_defaults):
    e = g.entry("generator/rounded_plate")
    assert e.synthesized and e.source.startswith("# A plate")
    base = at_defaults(e)
    wide = g.compile_entry(e, {"width": "120 mm"})
    assert base.ok and wide.ok
    (b,), (w,) = base.parts, wide.parts
    assert b.bbox[2] - b.bbox[0] == pytest.approx(80)
    assert w.bbox[2] - w.bbox[0] == pytest.approx(120)
    assert w.area > b.area * 1.4
    washer = g.entry("generator/washer")
    small, big = at_defaults(washer), g.compile_entry(washer, {"outer": "20 mm"})
    assert big.parts[0].area - small.parts[0].area == pytest.approx(
        3.141592653589793 * (10 ** 2 - 5 ** 2), rel=1e-3)


def test_a_synthesized_program_reads_well():
    src = g.entry("generator/spur_gear").source
    assert 'import "std/gears.aidl"' in src and "units mm" in src
    assert "param teeth = 20, min=8, max=80, step=1" in src
    assert "param module = 2 mm, min=0.5 mm, max=6 mm, step=0.25 mm" in src
    assert "part = spur_gear(teeth=teeth, module=module," in src
    assert "cx" not in src.split("units mm")[1]                  # placement is not a param
    assert all(len(line) <= 100 for line in src.splitlines())


@pytest.mark.parametrize("e", [e for e in WRITTEN if not e.synthesized],
                         ids=[e.id for e in WRITTEN if not e.synthesized])
def test_a_lifted_example_draws_what_its_file_draws(e, at_defaults):
    mine = at_defaults(e)
    file = api.compile(path=str(ROOT / e.origin))
    assert mine.ok and file.ok
    assert [(p.name, p.bbox, round(p.area, 6)) for p in mine.parts] == \
        [(p.name, p.bbox, round(p.area, 6)) for p in file.parts]
    assert mine.to_svg() == file.to_svg()


def test_the_joint_demonstrations_have_their_sizes_as_sliders():
    """Files that call a generator twice are shown as their forms (studio/forms/, issue 94:
    they had no slider): every size a param with a declared range."""
    for name, n in (("cross_halving", 4), ("dovetail", 5), ("finger_edge", 5),
                    ("tab_and_slot", 6)):
        e = g.entry(f"generator/{name}")
        assert e.source == page_program((g.FORMS / f"{name}.aidl").read_text())
        assert len(e.params) == n and all(p["declared"] for p in e.params), name


@pytest.mark.parametrize("id", ["generator/divider_tray", "generator/text_on_arc",
                                "generator/washer", "example/telephone"])
def test_thumbnail_is_a_small_svg(id):
    svg = g.thumbnail(g.entry(id))
    assert svg.startswith("<svg") and "<path" in svg
    w, h = (float(re.search(rf'<svg\b[^>]*\b{a}="([\d.]+)px"', svg).group(1))
            for a in ("width", "height"))
    assert max(w, h) == 240 and min(w, h) >= 1
    assert "viewBox=" in svg
    assert not re.search(r"\d\.\d{3}", svg)             # coordinates rounded to 0.01 mm


def test_thumbnail_of_a_broken_program_raises():
    e = g.Entry("example/broken", "Broken", "A broken program.", "example",
                "solid s { c = Circle(center=(0, 0), radius=-1) }")
    with pytest.raises(ValueError, match="example/broken does not compile"):
        g.thumbnail(e)


def test_to_json():
    e = g.entry("generator/divider_tray")
    d = g.to_json(e)
    assert json.loads(json.dumps(d)) == d
    assert d["id"] == e.id and d["source"] == e.source and d["params"] == e.params
    assert set(d) == {"id", "title", "purpose", "kind", "source", "params", "tags", "origin",
                      "generator", "synthesized"}
    listing = g.to_json(e, with_source=False)
    assert "source" not in listing and listing["tags"] == ["box"]


def test_tags():
    assert "gear" in g.entry("generator/spur_gear").tags
    assert "stand" in g.entry("generator/laptop_stand").tags
    assert "joint" in g.entry("generator/dovetail").tags
    assert "enclosure" in g.entry("generator/board_enclosure").tags
    assert "box" not in g.entry("example/wrench").tags       # "(box) end" is not a box
    for e in ENTRIES:
        assert all(re.fullmatch(r"[a-z0-9]+", t) for t in e.tags), e.tags


def test_entries_is_cached_and_returns_a_new_list():
    a, b = g.entries(), g.entries()
    assert a == b and a is not b and a[0] is b[0]
