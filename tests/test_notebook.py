"""Issue 75, notebooks: a compiled result shows its drawing in Jupyter (``_repr_svg_``,
``_repr_mimebundle_``: the SVG, the diagnostics under it, the located errors instead of a
drawing), ``aidl_lang.notebook.form`` gives ipywidgets controls for the params that redraw,
and the example notebook docs/notebooks/aidl.ipynb runs in a real kernel (nbclient).

The drawing is read back with an XML parser; its size and loops are checked against numbers
worked out from examples/bracket.aidl by hand: the plate is ``(bolts + 0.5) * pitch`` wide
and 40 mm high, each ear adds its trapezoid's 20 mm less the 1 mm overlap (``gap=-1``), so
the part is 90 + 2 * 19 = 128 mm x 40 mm for 4 bolts and 168 mm for 6 (5 or 7 would put a
bolt hole on the top vent: one loop for two); the SVG page adds 5 %
of the larger side around it; the outline holds 1 outer loop, ``bolts`` bolt holes and 2 eyes
(radius 3) and 8 vents (radius 2)."""
from __future__ import annotations

import asyncio
import base64
import json
import re
import sys
import xml.etree.ElementTree as ET

import pytest

import aidl_lang
from conftest import ROOT

BRACKET = ROOT / "examples" / "bracket.aidl"
NOTEBOOK = ROOT / "docs" / "notebooks" / "aidl.ipynb"
SVG = "{http://www.w3.org/2000/svg}"


def bracket_figures(bolts: int = 4, pitch: float = 20.0) -> dict:
    """What examples/bracket.aidl draws, worked out from its text (module docstring)."""
    w, h = (bolts + 0.5) * pitch + 2 * (20 - 1), 40.0
    m = 0.05 * max(w, h)
    return {"size": (w + 2 * m, h + 2 * m), "loops": 1 + bolts + 2 + 8,
            "r3": bolts + 2, "r2": 8}


def svg_figures(svg: str) -> dict:
    """The page size (viewBox, mm) and the loops of the drawing's paths, by radius of the
    arcs each loop is made of (a circle hole is two half arcs ``A r,r``)."""
    root = ET.fromstring(svg)
    vb = [float(v) for v in root.get("viewBox").replace(",", " ").split()]
    loops = []
    for p in root.iter(SVG + "path"):
        loops += [s for s in re.split(r"(?=M)", p.get("d")) if s.strip()]
    radius = {}
    for lp in loops:
        radii = set(re.findall(r"A([\d.]+),\1 ", lp))
        if len(radii) == 1 and "L" not in lp:
            r = float(radii.pop())
            radius[r] = radius.get(r, 0) + 1
    return {"size": (round(vb[2], 6), round(vb[3], 6)), "loops": len(loops),
            "r3": radius.get(3.0, 0), "r2": radius.get(2.0, 0),
            "circles": len(list(root.iter(SVG + "circle")))}


def assert_bracket(svg: str, bolts: int = 4, pitch: float = 20.0) -> None:
    got, want = svg_figures(svg), bracket_figures(bolts, pitch)
    assert got["size"] == pytest.approx(want["size"], abs=1e-6)
    assert (got["loops"], got["r3"], got["r2"]) == (want["loops"], want["r3"], want["r2"])


def img_svg(html: str) -> str | None:
    """The SVG of the ``<img src="data:image/svg+xml;base64,...">`` in an HTML display."""
    m = re.search(r'src="data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)"', html)
    return base64.b64decode(m.group(1)).decode() if m else None


# ------------------------------------------------------------------ the result's display
def test_a_result_shows_its_drawing_as_svg_html_and_a_short_summary():
    r = aidl_lang.compile(path=str(BRACKET))
    bundle = r._repr_mimebundle_()
    assert set(bundle) == {"image/svg+xml", "text/html", "text/plain"}
    assert_bracket(bundle["image/svg+xml"])
    assert r._repr_svg_() == bundle["image/svg+xml"]
    # the SVG the CLI writes for `aidl render -o x.svg` (the preview style)
    assert bundle["image/svg+xml"] == r.to_svg()
    assert img_svg(bundle["text/html"]) == bundle["image/svg+xml"]
    plain = bundle["text/plain"]
    assert plain == f"aidl {BRACKET}: ok, 1 part, 128 x 40 mm" and "\n" not in plain


def test_the_drawing_is_made_once_and_only_when_shown():
    r = aidl_lang.compile(path=str(BRACKET))
    calls = []
    real = r.encode
    r.encode = lambda *a, **k: calls.append(a) or real(*a, **k)
    assert repr(r).startswith("<aidl Result") and calls == []      # compile, repr: no SVG
    r._repr_mimebundle_()
    r._repr_svg_()
    r._repr_mimebundle_(include=["image/svg+xml"])
    assert calls == [("svg", None)]


def test_a_result_with_errors_shows_its_located_errors_instead_of_a_drawing():
    src = ("param width = 40 mm\n"
           "solid plate {\n"
           "    body = Rectangle(center=(0, 0), width=width, height=20)\n"
           "    hole bore { c = Circle(center=(0, 0), radius=wdth / 8) }\n"
           "}\n")
    r = aidl_lang.compile(source=src, path="plate.aidl")
    bundle = r._repr_mimebundle_()
    assert r._repr_svg_() is None and "image/svg+xml" not in bundle
    html = bundle["text/html"]
    assert "<img" not in html
    col = src.splitlines()[3].index("wdth") + 1
    assert f"plate.aidl:4:{col}: error[E0101]: unknown name `wdth`" in html
    # the source line and the caret under the name, the hint and the fix
    assert "\n4 |     hole bore { c = Circle(center=(0, 0), radius=wdth / 8) }\n" in html
    assert "\n  | " + " " * (col - 1) + "^^^^\n" in html
    assert "did you mean `width`?" in html
    assert bundle["text/plain"] == \
        f"aidl plate.aidl: 1 error; first: 4:{col} E0101 unknown name `wdth`"


def test_warnings_are_listed_under_the_drawing_with_code_line_and_column():
    src = ("solid plate {\n"
           "    body = Rectangle(center=(0, 0), width=40, height=20)\n"
           "    hole far { c = Circle(center=(100, 0), radius=3) }\n"
           "}\n")
    r = aidl_lang.compile(source=src, path="plate.aidl")
    assert r.ok and r.diagnostics
    html = r._repr_mimebundle_()["text/html"]
    assert img_svg(html) is not None
    items = re.findall(r"<li>(.*?)</li>", html)
    assert len(items) == len(r.diagnostics)
    for d, item in zip(r.diagnostics, items):
        assert f"{d.severity}[{d.code}]" in item and f"{d.span.line}:{d.span.col}" in item
    assert r._repr_mimebundle_()["text/plain"].endswith(
        f", {len(r.diagnostics)} warning" + ("s" if len(r.diagnostics) > 1 else ""))


def test_every_text_in_the_html_is_escaped():
    name = '<img src=x onerror="alert(1)">.aidl'
    r = aidl_lang.compile(source="solid p { c = Circle(center=(0, 0), radius=r) }", path=name)
    html = r._repr_mimebundle_()["text/html"]
    assert "<img" not in html and "&lt;img src=x onerror=&quot;alert(1)&quot;&gt;.aidl" in html
    ok = aidl_lang.compile(source="solid p { c = Circle(center=(0, 0), radius=3) }", path=name)
    html = ok._repr_mimebundle_()["text/html"]
    assert html.count("<img") == 1 and 'onerror="' not in html


def test_a_drawing_past_its_bounded_work_shows_the_located_e0304(cpu_clock):
    """600 circles stacked at one place: the program compiles, but its exact outlines are
    refused past 10,000,000 (edge, chord) pairs (an OutputError, whatever the budget): the
    display says so where the drawing would be, located, as `aidl render` does."""
    src = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, "
           "height=20)\n    for i in range(600) { hole h { c = Circle(center=(i * 0.001, "
           "0), radius=1) } }\n}\n")
    r = aidl_lang.compile(source=src, path="stacked.aidl", budget=0.3)
    assert r.ok
    bundle = r._repr_mimebundle_()
    assert "image/svg+xml" not in bundle and r._repr_svg_() is None
    html = bundle["text/html"]
    assert "<img" not in html
    assert "stacked.aidl:2:1: error[E0304]: the program ran out of its evaluation budget in " \
           "the exact outlines of `plate`" in html
    assert "more than 10,000,000 (edge, chord) pairs" in html
    assert "\n2 | solid plate {\n  | ^^^^^^^^^^^^^\n" in html
    assert bundle["text/plain"].startswith("aidl stacked.aidl: not drawn: 2:1 E0304 ")


# ------------------------------------------------------------------ the form
PROGRAM = """param width = 40 mm, min=20 mm, max=80 mm, step=1 mm
param teeth = 12, min=6, max=60
param tilt = 15 deg, min=-30 deg, max=30 deg
param ratio = 0.5
param holes = true
param title = "AB"
solid plate {
    body = Rectangle(center=(0, 0), width=width, height=20)
    if holes {
        hole h { c = Circle(center=(0, 0), radius=3) }
    }
}
assert plate.bb.width <= 70 mm, "fits the bed"
"""


def test_the_form_has_the_customizers_control_for_each_param():
    from aidl_lang.notebook import form
    from aidl_lang.serve.params import declared_params
    from aidl_lang.studio.gallery import param_rows
    f = form(PROGRAM, path="plate.aidl")
    c = f.controls
    assert list(c) == ["width", "teeth", "tilt", "ratio", "holes", "title"]
    kinds = {n: type(w).__name__ for n, w in c.items()}
    assert kinds == {"width": "FloatSlider", "teeth": "IntSlider", "tilt": "FloatSlider",
                     "ratio": "FloatSlider", "holes": "Checkbox", "title": "Text"}
    assert (c["width"].min, c["width"].max, c["width"].step, c["width"].value) == (20, 80, 1, 40)
    assert (c["teeth"].min, c["teeth"].max, c["teeth"].step) == (6, 60, 1)
    assert (c["tilt"].min, c["tilt"].max, c["tilt"].value) == (-30, 30, 15)
    assert "(mm)" in c["width"].description and "(deg)" in c["tilt"].description
    # the same ranges and steps as `aidl serve`'s sliders and the studio's form rows
    for p, row in zip(declared_params(PROGRAM, "plate.aidl"), param_rows(PROGRAM, "plate.aidl")):
        if p.kind in ("length", "angle", "number"):
            w = c[p.name]
            assert (w.min, w.max, w.step) == pytest.approx((p.min, p.max, p.step))
            assert (type(w).__name__ == "IntSlider") == (row["kind"] == "integer")
    assert c["ratio"].readout_format == ".3f"             # default span: step 0.002
    assert (c["holes"].value, c["title"].value) == (True, "AB")
    assert f.overrides() == {} and f.redraws == 1


def test_moving_a_control_redraws_the_drawing():
    from aidl_lang.notebook import form
    f = form(BRACKET)                            # a path
    assert f.path == str(BRACKET) and list(f.controls) == ["bolts", "pitch", "fillet"]
    assert_bracket(img_svg(f.output.value), 4)
    f.controls["bolts"].value = 6                # no event loop running: at once
    assert f.redraws == 2 and f.overrides() == {"bolts": "6"}
    assert_bracket(img_svg(f.output.value), 6)
    r = f.set(bolts=4, pitch=22.5)
    assert f.redraws == 3 and f.overrides() == {"pitch": "22.5mm"}
    assert r.ok and r.value("pitch").value == pytest.approx(22.5)
    w, _ = svg_figures(img_svg(f.output.value))["size"]
    assert w == pytest.approx(((4 + 0.5) * 22.5 + 38) * 1.1)
    with pytest.raises(KeyError, match="no param 'boltz'; the form has bolts, pitch, fillet"):
        f.set(boltz=3)


def test_changes_are_debounced_on_the_running_event_loop():
    from aidl_lang.notebook import form
    f = form(BRACKET, debounce=0.2)

    async def drag():
        for v in (5, 8, 6):
            f.controls["bolts"].value = v       # a slider dragged: three changes
        assert f.redraws == 1                  # none compiled yet
        for _ in range(600):
            await asyncio.sleep(0.05)
            if f.redraws > 1:
                break
        await asyncio.sleep(0.3)
    asyncio.run(drag())
    assert f.redraws == 2                      # one compile, with the last value
    assert_bracket(img_svg(f.output.value), 6)


def test_errors_in_the_form_are_shown_located():
    from aidl_lang.notebook import form
    f = form(PROGRAM, path="plate.aidl")
    assert img_svg(f.output.value) is not None
    f.set(width=75)
    html = f.output.value
    assert img_svg(html) is None
    line = PROGRAM.splitlines().index('assert plate.bb.width <= 70 mm, "fits the bed"') + 1
    assert re.search(rf"plate\.aidl:{line}:\d+: error\[E\d+\]", html), html
    f.set(width=60, holes=False, title="C<D")
    assert f.overrides() == {"width": "60mm", "holes": "false", "title": '"C<D"'}
    assert img_svg(f.output.value) is not None
    assert svg_figures(img_svg(f.output.value))["loops"] == 1   # no hole


PLATE = ("units mm\nparam width = 120 mm\nparam teeth = 12, min=6, max=60\nparam holes = true\n"
         "solid p { body = Rectangle(center=(0, 0), width=width, height=20) }\n")


def drawn_width(f) -> float:
    """The width of the form's drawing (mm, wider than its 20 mm height): its SVG page less
    the margin of 5 % of the larger side on each side."""
    return svg_figures(img_svg(f.output.value))["size"][0] / 1.1


@pytest.mark.parametrize("values, said", [
    ({"width": -5}, "`width` = -5 mm is outside its control's range 30 .. 240 mm; nothing "
                    "changed (`param width` declares no range: its `min=` and `max=` give it one)"),
    ({"width": 1e9}, "`width` = 1000000000 mm is outside its control's range 30 .. 240 mm"),
    ({"teeth": 61}, "`teeth` = 61 is outside its control's range 6 .. 60; nothing changed"),
    ({"width": "abc"}, "`width` takes a number in mm, not 'abc'; nothing changed"),
    ({"width": float("nan")}, "`width` takes a number in mm, not nan"),
    ({"teeth": 7.5}, "`teeth` takes a whole number, not 7.5"),
    ({"width": 150, "holes": "yes"}, "`holes` takes True or False, not 'yes'"),
])
def test_a_refused_set_says_why_in_one_line_and_changes_nothing(values, said):
    """Issue 83: `set(width=-5)` was clamped to 30 mm (and 1e9 to 240 mm) and drawn without a
    word; a wrong type was traitlets' TraitError; `set(width=150, holes="yes")` left the
    width control at 150 under a drawing 120 mm wide.  Now each is a FormError (a
    ValueError) saying what and why, and the controls, the result and the drawing are as
    before it."""
    from aidl_lang.notebook import FormError, form
    f = form(PLATE, path="plate.aidl")
    assert drawn_width(f) == pytest.approx(120)
    before = (f.values, f.result, f.output.value, f.redraws)
    with pytest.raises(FormError) as e:
        f.set(**values)
    assert isinstance(e.value, ValueError) and said in str(e.value) and "\n" not in str(e.value)
    assert (f.values, f.result, f.output.value, f.redraws) == before
    assert f.values == {"width": 120, "teeth": 12, "holes": True}
    r = f.set(width=150, teeth=60)                # the ends of the ranges are in them
    assert r.ok and drawn_width(f) == pytest.approx(150) and f.values["teeth"] == 60


def test_a_refused_set_is_one_line_in_ipython(capsys):
    """IPython shows a FormError as its one line (`_render_traceback_`), not a traceback."""
    from IPython.core.interactiveshell import InteractiveShell
    shell = InteractiveShell()
    shell.run_cell("from aidl_lang.notebook import form\n"
                   f"f = form({PLATE!r})\n"
                   "f.set(width='abc')\n")
    out = capsys.readouterr().out
    assert out == "FormError: `width` takes a number in mm, not 'abc'; nothing changed\n"


def test_a_program_that_does_not_compile_gives_a_form_without_controls():
    from aidl_lang.notebook import form
    f = form("solid p { c = Circle(center=(0, 0), radius=r) }")
    assert f.controls == {} and "E0101" in f.output.value
    assert "does not compile far enough" in f.widget.children[0].children[0].value
    missing = form(ROOT / "no such file.aidl")
    assert missing.controls == {} and "E0004" in missing.output.value
    plain = form("solid p { c = Circle(center=(0, 0), radius=3) }")
    assert "declares no `param`" in plain.widget.children[0].children[0].value


def test_without_ipywidgets_the_error_names_the_extra(monkeypatch):
    from aidl_lang.notebook import form
    monkeypatch.setitem(sys.modules, "ipywidgets", None)
    with pytest.raises(ImportError, match=re.escape("pip install 'aidl-lang[notebook]'")):
        form(BRACKET)


# ------------------------------------------------------------------ the example notebook
def test_the_example_notebook_runs_and_shows_the_drawing_and_the_form(tmp_path, monkeypatch):
    """docs/notebooks/aidl.ipynb run by a real kernel (this venv's python, through a
    kernelspec in the test's folder), its outputs read back: the bracket's SVG, the located
    error, the form's widget and its model (the sliders and the redrawn drawing)."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    kernels = tmp_path / "jupyter" / "kernels" / "python3"
    kernels.mkdir(parents=True)
    (kernels / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python 3 (aidl test venv)", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "jupyter"))
    monkeypatch.setenv("JUPYTER_RUNTIME_DIR", str(tmp_path / "runtime"))
    monkeypatch.setenv("JUPYTER_PLATFORM_DIRS", "1")
    monkeypatch.setenv("IPYTHONDIR", str(tmp_path / "ipython"))
    nb = nbformat.read(NOTEBOOK, as_version=4)
    assert all(not c.get("outputs") for c in nb.cells if c.cell_type == "code"), \
        "the notebook is committed without outputs"
    # not in the example: a slider dragged in the kernel redraws once, after the debounce, on
    # the kernel's own event loop (the cell awaits, so the loop runs)
    nb.cells.append(nbformat.v4.new_code_cell(
        "import asyncio\n"
        "for v in (21, 23, 25):\n"
        "    f.controls['pitch'].value = v\n"
        "before = f.redraws\n"
        "for _ in range(600):\n"
        "    await asyncio.sleep(0.05)\n"
        "    if f.redraws > before:\n"
        "        break\n"
        "await asyncio.sleep(0.5)\n"
        "print(before, f.redraws, f.overrides())"))
    client = nbclient.NotebookClient(nb, kernel_name="python3", timeout=120,
                                     startup_timeout=120, store_widget_state=True,
                                     resources={"metadata": {"path": str(NOTEBOOK.parent)}})
    client.execute()
    code = [c for c in nb.cells if c.cell_type == "code"]
    for c in code:
        assert not [o for o in c.outputs if o.output_type == "error"], c.outputs
    shown = code[0].outputs[0].data
    assert_bracket(shown["image/svg+xml"])
    assert img_svg(shown["text/html"]) == shown["image/svg+xml"]
    assert shown["text/plain"] == "aidl ../../examples/bracket.aidl: ok, 1 part, 128 x 40 mm"
    error = code[2].outputs[0].data
    assert "image/svg+xml" not in error
    assert "error[E0101]: unknown name `wdth`" in error["text/html"]
    view = code[3].outputs[0].data["application/vnd.jupyter.widget-view+json"]
    state = nb.metadata["widgets"]["application/vnd.jupyter.widget-state+json"]["state"]
    models = {k: m["model_name"] for k, m in state.items()}
    assert models[view["model_id"]] == "VBoxModel"
    sliders = {m["state"]["description"]: m["state"] for m in state.values()
               if m["model_name"] in ("IntSliderModel", "FloatSliderModel")}
    assert sliders["bolts"]["value"] == 6 and sliders["pitch (mm)"]["value"] == 25
    bolts = sliders["bolts"]
    assert (bolts["min"], bolts["max"], bolts["step"]) == (1, 10, 1)   # a count from 1 (issue 92)
    html = [m["state"]["value"] for m in state.values() if m["model_name"] == "HTMLModel"
            and "aidl-result" in m["state"]["value"]]
    assert len(html) == 1
    assert_bracket(img_svg(html[0]), 6, 25)    # the form's drawing after the last cell's drag
    assert code[5].outputs[0].text.strip() == "2 3 {'bolts': '6', 'pitch': '25mm'}"
    last = code[4].outputs
    assert "{'bolts': '6'}" in last[0].text
    assert_bracket(last[1].data["image/svg+xml"], 6)


def test_a_form_made_from_a_swept_result_offers_only_the_clean_range():
    """Issue 84: after `Result.sweep()` the form's sliders span the clean range the sweep
    found (a hole that leaves its 50 mm plate past offset = 21.5 mm: the slider stops there),
    not the declared 0..30 mm; a result never swept keeps the declared range."""
    from aidl_lang.notebook import form
    src = ("param offset = 10 mm, min = 0 mm, max = 30 mm, step = 0.5 mm\n"
           "solid plate {\n    body = Rectangle(center=(0, 0), width=50, height=30)\n"
           "    hole h { c = Circle(center=(offset, 0), radius=3) }\n}\n")
    r = aidl_lang.compile(source=src, path="plate.aidl")
    assert (form(r).controls["offset"].min, form(r).controls["offset"].max) == (0, 30)
    [f] = r.sweep(points=0).findings
    c = form(r).controls["offset"]
    assert c.min == 0 and c.max == f.clean["offset"][1] and 21 <= c.max <= 21.5
    assert c.value == 10
