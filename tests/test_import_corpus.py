"""``aidl import`` never writes a program its own compiler refuses (issue 58).

Every sample DXF of the ezdxf project (tests/data/ezdxf/, gzip-compressed, MIT: see its
README.md) is imported as ``aidl import FILE`` imports it and the program is compiled by the
real compiler: no error diagnostic.  A file that cannot be imported is a clean
:class:`~aidl_lang.drawing.model.DrawingError` (the files of :data:`REFUSED`, each with its
code), never another exception.

Before issue 58: ``integration_tests/data/no_layouts.dxf`` imported to
``Bezier(points=[p, q, q, q])`` whose segment is one point (E0108 "remove it"); with the
zero-length spans dropped, its polyline drawn as a cubic spline (a handle of zero length at
every corner) made a closed ``Bezier`` the compiler took for crossing itself (E0108). The
regression tests below rebuild both cases, the first from a Boxes.py-style SVG written here.
"""
from __future__ import annotations

import gzip
import pathlib
import re

import pytest

from aidl_lang import api
from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.drawing import DrawingError
from aidl_lang.drawing.write.program import import_drawing
from aidl_lang.base.limits import Budget
from aidl_lang.pipeline import _compile, compile_source, run_deep

DATA = pathlib.Path(__file__).resolve().parent / "data" / "ezdxf"
FILES = sorted(p.name for p in DATA.iterdir() if p.name.lower().endswith(".dxf.gz"))
SEGMENT = re.compile(r"= (?:Line|Arc|Circle|Spline|Bezier|Ellipse|Text)\(")

# Files with nothing to import (3D solids and faces, images, tables, entities in a tilted
# UCS, empty model spaces): each is E0132 "nothing to import" naming what
# the file holds and why each kind was left out (a change here is a change of what the importer
# reads, to be looked at).
REFUSED = {
    "docs_source_tutorials_src_geo_Graz_10km_3m.dxf": "E0132",  # IMAGE only
    "examples_acistools_3dsolids.dxf": "E0132",  # 3DSOLID
    "examples_dxf_Minimal_DXF_AC1006.dxf": "E0132",  # 3DFACE, a LINE off the plane
    "examples_dxf_Minimal_DXF_AC1009.dxf": "E0132",  # empty
    "examples_dxf_Minimal_DXF_AC1021.dxf": "E0132",  # empty
    "examples_dxf_acad_table_simple.dxf": "E0132",  # ACAD_TABLE
    "examples_dxf_acad_table_with_blk_ref.dxf": "E0132",  # ACAD_TABLE
    "examples_dxf_circle_radius_le_0.dxf": "E0132",  # two circles of radius <= 0
    "examples_xref_sphere.dxf": "E0132",  # 3DSOLID
    "exploration_acis_torus_r2000.dxf": "E0132",  # 3DSOLID
    "exploration_acis_torus_r2004.dxf": "E0132",  # 3DSOLID
    "exploration_acis_torus_r2007.dxf": "E0132",  # 3DSOLID
    "exploration_acis_torus_r2010.dxf": "E0132",  # 3DSOLID
    "integration_tests_data_MODEL.dxf": "E0132",  # empty
    "integration_tests_data_POLI-ALL210_12.DXF": "E0132",  # 3DFACE, POLYLINE in a tilted UCS
    "integration_tests_data_acad_table_with_blk_ref.dxf": "E0132",  # ACAD_TABLE
    "integration_tests_data_cc_dxflib.dxf": "E0132",  # POLYLINE in a tilted UCS
    "integration_tests_data_dxf_unicode.dxf": "E0132",  # empty
    "integration_tests_data_layout_broken_links.dxf": "E0132",  # empty
    "integration_tests_data_layout_broken_links_2.dxf": "E0132",  # empty
    "integration_tests_data_layout_missing_block_definition.dxf": "E0132",  # empty
    "integration_tests_data_layout_missing_block_record.dxf": "E0132",  # empty
    "integration_tests_data_r12_blocks_with_no_names.dxf": "E0132",  # empty
    "integration_tests_data_r2000_blocks_with_no_name_and_no_block_record.dxf": "E0132",  # empty
    "integration_tests_data_r2000_blocks_with_no_names.dxf": "E0132",  # empty
    "integration_tests_data_small_r14.dxf": "E0132",  # empty
}

# More segments than this: the final-part geometry checks (warnings only, W05xx) are left
# out of the compile (``shape_checks=False``), which still parses, type-checks, interprets,
# solves and runs the booleans.  Those checks are quadratic in the segments until issue 58's
# O(n log n) checks land (the USA map, examples_addons_drawing_data_usa.dxf, grew past 17 GB);
# the lead lifts this then.
FULL_CHECKS_BELOW = 2000
# Under that size but slow in the same checks (text engravings: thousands of strokes); the
# same reason.
NO_CHECKS = {"examples_dxf_text_fonts.dxf"}
# What these tests check is the import's result, not its speed (the budget's own tests are
# test_import_limits.py's): the largest samples (edgeminer, 10 s on a quiet machine) ran past
# the default 15 s of wall time when the machine was busy
ROOMY = Budget(seconds=120)
# h24-suite: the suite imports a fixed sample (every file of 103: 29 s of CPU; this, 52 files:
# about 11 s): every file of REFUSED (each kind of refusal, 0.6 s in all), every third of the
# others in name order from the first, and the compiles of the two other kinds, without the
# final-part checks (NO_CHECKS; the USA map, above FULL_CHECKS_BELOW segments).  Every file:
# `python benchmarks/imports/import_corpus.py tests/data/ezdxf --full-checks-below 2000`.
KINDS = ("examples_dxf_text_fonts.dxf", "examples_addons_drawing_data_usa.dxf")
SAMPLE = sorted({*(f for f in FILES if f[:-3] in REFUSED),
                 *[f for f in FILES if f[:-3] not in REFUSED][::3], *(f"{n}.gz" for n in KINDS)})


def compiled(text: str, name: str):
    n = len(SEGMENT.findall(text))
    if n < FULL_CHECKS_BELOW and name not in NO_CHECKS:
        return compile_source(text, name.replace(".dxf", ".aidl"), budget=ROOMY)
    sink = DiagnosticSink()
    return run_deep(lambda: _compile(sink, text, name.replace(".dxf", ".aidl"), None, True,
                                     budget=ROOMY, shape_checks=False))


def errors(c) -> list[str]:
    return [f"{d.code} {d.message[:200]}" for d in c.sink.items if d.is_error]


@pytest.mark.parametrize("gz", SAMPLE)
def test_every_ezdxf_sample_imports_to_a_program_that_compiles(gz):
    name = gz[:-3]
    data = gzip.decompress((DATA / gz).read_bytes())
    if name in REFUSED:
        with pytest.raises(DrawingError) as ex:
            import_drawing(data, name, budget=ROOMY)
        assert ex.value.code == REFUSED[name], ex.value.message
        return
    text, notes = import_drawing(data, name, budget=ROOMY)
    assert all(n.code == "W0130" for n in notes)
    c = compiled(text, name)
    assert errors(c) == [], (name, errors(c)[:3])
    assert c.model is not None and c.solve is not None and c.solve.converged
    assert c.drawing is not None                     # the booleans ran


def test_the_corpus_is_whole():
    """103 DXF files (README.md lists what was left out: nothing) and the licence."""
    assert len(FILES) == 103
    assert (DATA / "LICENSE").read_text().startswith("MIT License")
    assert set(REFUSED) <= {f[:-3] for f in FILES}
    assert set(NO_CHECKS) <= set(KINDS) and set(SAMPLE) <= set(FILES) and len(SAMPLE) == 52


# ------------------------------------------------------------------ regressions
# A Boxes.py-style sheet: a gore outline whose path holds a cubic of zero length
# (``C x,y x,y x,y``, as Boxes.py's Sphere writes between its lines) and a line of zero
# length, and a hole drawn with one more zero cubic.  viewBox in mm.
SVG = b"""<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="80mm" viewBox="0 0 100 80">
<path stroke="#000000" fill="none" d="M 10 70 C 10 70 10 70 10 70 L 30 10 C 40 5 60 5 70 10
 C 70 10 70 10 70 10 L 90 70 L 90 70 L 10 70 Z"/>
<path stroke="#0000ff" fill="none" d="M 40 40 L 60 40 C 60 40 60 40 60 40 L 60 50 L 40 50 Z"/>
</svg>"""


def test_zero_length_pieces_of_an_svg_are_dropped_counted_and_the_program_compiles():
    """Before: ``Bezier(points=[p, p, p, p, ...])`` whose segment 0 is one point: E0108
    "remove it", then E0101 for the names after it."""
    text, notes = import_drawing(SVG, "gores.svg", roles="laser")
    dropped = [n.message for n in notes if "dropped" in n.message]
    assert len(dropped) == 1, [n.message for n in notes]
    assert "4 pieces of `gores.svg` dropped" in dropped[0]
    assert "(3 Bézier pieces, 1 line)" in dropped[0]
    assert "60, 40), (60, 40), (60, 40)" not in text
    c = compile_source(text, "gores.aidl")
    assert errors(c) == []
    # what is kept: the gore (two lines, the curve, the base) and the hole (four lines)
    assert len(re.findall(r"= Line\(", text)) == 7
    assert len(re.findall(r"= Bezier\(", text)) == 1
    res = api.compile(source=text, path="gores.aidl")
    assert res.ok
    (part,) = res.parts
    assert part.holes == 1
    # the gore: the trapezoid (10,70)-(30,10)-(70,10)-(90,70), 0.5 * (80 + 40) * 60 = 3600 mm²
    # (y down in the SVG), plus the cubic's bulge beyond its chord y = 10, minus the 20 x 10
    # hole; the compiler's area is of its tessellation (chords within 0.01 mm)
    want = 3600 + _bulge(((30, 10), (40, 5), (60, 5), (70, 10))) - 200
    assert part.area == pytest.approx(want, abs=0.5)
    assert _bulge(((30, 10), (40, 5), (60, 5), (70, 10))) == pytest.approx(105, abs=1e-9)   # 15 * (30/20 + 120/30 + 30/20), by hand


def _bulge(b) -> float:
    """The area between the cubic Bézier ``b`` and its chord: 1/2 of the integral of
    (x dy - y dx) along the cubic and back along the chord (Gauss-Legendre, exact for this
    polynomial of degree 5)."""
    import numpy as np
    t, w = np.polynomial.legendre.leggauss(8)
    t, w = (t + 1) / 2, w / 2
    P = np.asarray(b, dtype=float)
    u = 1 - t
    B = (u ** 3)[:, None] * P[0] + (3 * u * u * t)[:, None] * P[1] + \
        (3 * u * t * t)[:, None] * P[2] + (t ** 3)[:, None] * P[3]
    D = (3 * u * u)[:, None] * (P[1] - P[0]) + (6 * u * t)[:, None] * (P[2] - P[1]) + \
        (3 * t * t)[:, None] * (P[3] - P[2])
    curve = 0.5 * float(np.sum(w * (B[:, 0] * D[:, 1] - B[:, 1] * D[:, 0])))
    chord = 0.5 * (P[3, 0] * P[0, 1] - P[0, 0] * P[3, 1])
    return abs(curve + chord)


def test_no_layouts_dxf_drops_its_zero_spans_and_compiles():
    """ezdxf's integration_tests/data/no_layouts.dxf: two closed cubic splines through
    repeated control points (the letter outline and its hole).  Before: E0108 "a Bezier's
    segment 2 (points[6] to points[9]) is one point", twice; then, with those dropped, E0108
    "crosses itself" at the corners, where a handle of zero length stops the curve (the
    compiler now tells a cusp from a crossing: tests/test_spline.py)."""
    name = "integration_tests_data_no_layouts.dxf"
    data = gzip.decompress((DATA / (name + ".gz")).read_bytes())
    text, notes = import_drawing(data, name)
    dropped = [n.message for n in notes if "dropped" in n.message]
    assert len(dropped) == 1
    assert dropped[0].startswith(f"9 pieces of `{name}` dropped")
    assert "(9 Bézier pieces)" in dropped[0]
    c = compile_source(text, "no_layouts.aidl")
    assert errors(c) == []
    # the outline and its one hole, each one closed Bezier through its cusps, as drawn
    assert text.count("closed=true") == 2
    assert text.count("hole ") == 1


def test_the_bound_grows_with_the_drawing_so_a_kept_piece_is_never_refused():
    """Far from the origin (a georeferenced sheet, 400 m out) the compiler's "one point" is
    1e-9 x 400 000 mm = 4e-4 mm: a cubic 2e-4 mm long is refused there (E0108), though it is
    longer than the 1e-6 mm the chaining calls one point.  The bound, 1e-8 x the largest
    coordinate (4e-3 mm here), drops it; a 0.01 mm cubic beside it is kept."""
    svg = b"""<svg xmlns="http://www.w3.org/2000/svg" width="1000000mm" height="100mm"
 viewBox="0 0 1000000 100"><path stroke="#000000" fill="none" d="M 400000 10 L 400010 10
 C 400010 10.0002 400010.0001 10.0002 400010.0002 10 L 400010.0002 20
 C 400010.0002 20.01 400010.01 20.01 400010 20.01 L 400000 20 Z"/></svg>"""
    text, notes = import_drawing(svg, "far.svg")
    dropped = [n.message for n in notes if "dropped" in n.message]
    assert len(dropped) == 1 and "1 piece of `far.svg` dropped" in dropped[0], dropped
    assert "within 0.004 mm" in dropped[0]
    assert len(re.findall(r"= Bezier\(", text)) == 1           # the 0.01 mm one
    assert errors(compile_source(text, "far.aidl")) == []
