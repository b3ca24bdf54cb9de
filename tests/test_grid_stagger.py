"""GridPattern(..., stagger=true) (issue 111: a honeycomb of vent holes was reached for and
written by hand): every odd row moved half the column spacing, `cols` copies in every row, the
index r * cols + c as without it.  The docs' program, written to DXF and re-read by ezdxf."""
from __future__ import annotations

import pytest

import aidl_lang

SRC = """solid panel {
    body = Rectangle(center=(0, 0), width=120, height=90)
    hole vents {
        c = Circle(center=(0, 0), diameter=8)
        holes = GridPattern(c, 5, 8, (10 mm, 9 mm)STAGGER)
    }
    CenterInside(vents, body)
}
"""


def _centres(tmp_path, stagger: str) -> list:
    import ezdxf
    r = aidl_lang.compile(source=SRC.replace("STAGGER", stagger))
    assert r.ok and not [d for d in r.diagnostics if d.severity == "warning"], r.diagnostics
    out = tmp_path / "panel.dxf"
    r.write(out)
    return sorted((round(e.dxf.center.x, 9), round(e.dxf.center.y, 9))
                  for e in ezdxf.readfile(out).modelspace() if e.dxftype() == "CIRCLE")


def test_odd_rows_move_half_a_pitch_and_the_field_is_centred(tmp_path):
    got = _centres(tmp_path, ", stagger=true")
    # 8 per row, 5 rows 9 mm apart; the field 7.5 pitches wide, centred: x from -37.5
    want = sorted((round(-37.5 + 10 * c + (5 if r % 2 else 0), 9), round(-18 + 9 * r, 9))
                  for r in range(5) for c in range(8))
    assert [c for p in got for c in p] == pytest.approx([c for p in want for c in p], abs=1e-9)


def test_without_stagger_the_grid_is_as_before(tmp_path):
    got = _centres(tmp_path, "")
    want = sorted((-35 + 10 * c, -18 + 9 * r) for r in range(5) for c in range(8))
    assert [c for p in got for c in p] == pytest.approx([c for p in want for c in p], abs=1e-9)


def test_the_copy_index_is_row_major_with_stagger():
    r = aidl_lang.compile(source=SRC.replace("STAGGER", ", stagger=true").replace(
        "    CenterInside(vents, body)\n",
        "    CenterInside(vents, body)\n    assert vents.holes[9].center.x - vents.holes[0]"
        ".center.x == 15 mm\n    assert vents.holes[16].center.x == vents.holes[0].center.x\n"))
    assert r.ok, [d.message for d in r.errors]


def test_a_grid_indexed_as_rows_says_its_list_is_flat():
    """Issue 111 (run s): `cells[1][2]` of a GridPattern (rows of lists guessed) was E0111 "a
    hole structure cannot be indexed" with the generic hint; the hint says the list is flat,
    and `aidl docs GridPattern` (and the prompt) say so."""
    from aidl_lang.library.reference import lookup_text
    r = aidl_lang.compile(source="""solid p {
    body = Rectangle(center=(0, 0), width=100, height=100)
    hole h { c = Circle(center=(-35, -35), diameter=5) }
    grid = GridPattern(h, 8, 8, 10)
    assert grid[1][2].c.center.x == -15 mm
    assert grid[1 * 8 + 2].c.center.x == -15 mm
}
""")
    (e,) = [d for d in r.diagnostics if d.is_error]
    assert (e.code, e.span.line) == ("E0111", 5)
    assert e.hint == ("a pattern's list is flat, one copy an item: a GridPattern's is row by row, "
                      "copy (r, c) is `grid[r * cols + c]`")
    assert "gives one flat list, row by row: copy (r, c) is `g[r * cols + c]`" in \
        " ".join(lookup_text("GridPattern")[0].split())
