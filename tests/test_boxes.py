"""std/boxes.aidl (issue 52, "Boxes"): lid_box, sliding_lid_box, divider_tray.

Each generator goes through the real pipeline; its stated sizes (outside and inside, for
`outside=true` and `false`) are re-read from the DXF `aidl render -o x.dxf` writes, with ezdxf
(an independent reader), to 1e-9 mm; assembled, the fit check finds no collision (W0517) and no
loose part (W0518) at kerf 0 and 0.15 mm, and material thicker than `thickness` collides (W0517).
"""
import io
from pathlib import Path

import ezdxf
import pytest
from hypothesis import example, given, settings, strategies as st

import aidl_lang

ROOT = Path(__file__).resolve().parent.parent
T, C = 3.0, 0.3
CODES = ("W0517", "W0518")


def compile_src(tmp_path, src):
    p = tmp_path / "t.aidl"
    p.write_text(src)
    r = aidl_lang.compile(source=src, path=p)
    assert r.ok, [f"{d.code} {d.message}" for d in r.errors]
    return r


def program(call, material=3, kerf=0.0):
    return (f'import "std/boxes.aidl"\nthickness {material} mm\n'
            + (f"kerf {kerf} mm\n" if kerf else "") + f"assembly kit {{ b = {call} }}\n")


def cut_dxf(r):
    """The cut DXF re-read by ezdxf: layer (the part's path after `kit.b.`) -> its polylines'
    point lists."""
    doc = ezdxf.read(io.StringIO(r.to_dxf()))
    out: dict[str, list] = {}
    for e in doc.modelspace():
        if e.dxftype() == "LWPOLYLINE":
            out.setdefault(e.dxf.layer.removeprefix("CUT-kit.b."), []).append(
                [(x, y) for x, y, *_ in e.get_points("xy")])
    return out


def size(polys):
    """Width and height of a part's outline (its largest polyline)."""
    pts = max(polys, key=lambda p: (max(x for x, _ in p) - min(x for x, _ in p)))
    xs, ys = [x for x, _ in pts], [y for _, y in pts]
    return max(xs) - min(xs), max(ys) - min(ys)


def fit_codes(r):
    return [d.code for d in r.sink.items if d.code in CODES]


LID = "lid_box(length={L} mm, width={W} mm, height={H} mm, thickness=3 mm, clearance=0.3 mm, outside={o})"
SLIDE = ("sliding_lid_box(length={L} mm, width={W} mm, height={H} mm, thickness=3 mm, "
         "clearance=0.3 mm, outside={o})")
TRAY = ("divider_tray(length={L} mm, width={W} mm, height={H} mm, rows=3, cols=4, thickness=3 mm, "
        "clearance=0.3 mm, outside={o})")
GENERATORS = {"lid_box": LID, "sliding_lid_box": SLIDE, "divider_tray": TRAY}


# ------------------------------------------------------------------------------ sizes

@pytest.mark.parametrize("outside", ["true", "false"])
@pytest.mark.parametrize("kerf", [0.0, 0.15])
def test_lid_box_sizes_outside_and_inside(tmp_path, outside, kerf):
    L, W, H = 110.0, 70.0, 45.0
    r = compile_src(tmp_path, program(LID.format(L=L, W=W, H=H, o=outside), kerf=kerf))
    parts = cut_dxf(r)
    assert set(parts) == {"body.bottom", "body.front", "body.back", "body.left", "body.right", "lid", "lip"}
    lo, wo, ho = (L, W, H) if outside == "true" else (L + 2 * T, W + 2 * T, H + 3 * T)
    k = kerf
    assert size(parts["body.bottom"]) == pytest.approx((lo + k, wo + k), abs=1e-9)
    assert size(parts["lid"]) == pytest.approx((lo + k, wo + k), abs=1e-9)
    # the walls plus the lid are the outer height; inside: outer less two walls / two plates
    assert size(parts["body.front"])[1] + T == pytest.approx(ho + k, abs=1e-9)
    bl, bw = size(parts["body.bottom"])
    assert (bl - 2 * T, bw - 2 * T) == pytest.approx((lo - 2 * T + k, wo - 2 * T + k), abs=1e-9)
    if outside == "false":
        # (the height: the floor to the lip under the lid, the space a user fills)
        assert (bl - 2 * T - k, bw - 2 * T - k, size(parts["body.front"])[1] - 2 * T - k) == \
            pytest.approx((L, W, H), abs=1e-9)
    # the lip: the inside less the clearance all round
    assert size(parts["lip"]) == pytest.approx((lo - 2 * T - 2 * C + k, wo - 2 * T - 2 * C + k), abs=1e-9)


@pytest.mark.parametrize("outside", ["true", "false"])
def test_sliding_lid_box_sizes_and_the_groove(tmp_path, outside):
    L, W, H = 120.0, 80.0, 50.0
    r = compile_src(tmp_path, program(SLIDE.format(L=L, W=W, H=H, o=outside)))
    parts = cut_dxf(r)
    assert set(parts) == {"bottom", "front", "back", "left", "right", "lid", "liner[0]", "liner[1]",
                          "rail[0]", "rail[1]"}
    lo, wo, ho = (L, W, H) if outside == "true" else (L + 4 * T, W + 2 * T, H + 4 * T + C)
    assert size(parts["bottom"]) == pytest.approx((lo, wo), abs=1e-9)
    assert size(parts["back"]) == pytest.approx((lo, ho), abs=1e-9)
    assert size(parts["left"]) == pytest.approx((ho, wo), abs=1e-9)
    fl, hf = size(parts["front"])
    assert fl == pytest.approx(lo - 2 * T, abs=1e-9)          # between the side walls
    for k in range(2):
        assert size(parts[f"liner[{k}]"]) == pytest.approx((wo - 2 * T, hf), abs=1e-9)
        assert size(parts[f"rail[{k}]"]) == pytest.approx((wo - T, 2 * T), abs=1e-9)
    # the lid: `clearance` from either side wall and from the back wall; it overlaps each
    # liner and rail by the thickness less the clearance
    lid_l, lid_w = size(parts["lid"])
    assert (lid_l, lid_w) == pytest.approx((lo - 2 * T - 2 * C, wo - T - C), abs=1e-9)
    assert (lid_l - (lo - 4 * T)) / 2 == pytest.approx(T - C, abs=1e-9)
    # the groove: the back wall's height less the floor, the front (the liners), the lid and
    # the rail leaves the clearance over the lid
    assert ho - T - hf - T - 2 * T == pytest.approx(C, abs=1e-9)
    # inside: under the lid, between the liners and between the front and the back
    assert (lo - 4 * T, wo - 2 * T, hf) == pytest.approx(
        (L, W, H) if outside == "false" else (L - 4 * T, W - 2 * T, H - 4 * T - C), abs=1e-9)
    # the lid's pull: one slot hole
    assert len(parts["lid"]) == 2


@pytest.mark.parametrize("outside", ["true", "false"])
def test_divider_tray_sizes_and_halving_slots(tmp_path, outside):
    L, W, H = 130.0, 90.0, 35.0
    r = compile_src(tmp_path, program(TRAY.format(L=L, W=W, H=H, o=outside)))
    parts = cut_dxf(r)
    lo, wo, ho = (L, W, H) if outside == "true" else (L + 2 * T, W + 2 * T, H + T)
    li, wi, hd = lo - 2 * T, wo - 2 * T, ho - T
    assert size(parts["body.bottom"]) == pytest.approx((lo, wo), abs=1e-9)
    assert size(parts["body.front"]) == pytest.approx((lo, ho), abs=1e-9)
    assert (li, wi, hd) == pytest.approx((L, W, H) if outside == "false" else (L - 2 * T, W - 2 * T, H - T),
                                         abs=1e-9)
    rows, cols = 3, 4
    assert sorted(p for p in parts if "divider" in p) == sorted(
        [f"row_divider[{j}]" for j in range(rows - 1)] + [f"col_divider[{i}]" for i in range(cols - 1)])
    cw = (li - (cols - 1) * T) / cols
    rw = (wi - (rows - 1) * T) / rows
    for name, length, n, pitch, top in [("row_divider", li, cols, cw, True),
                                        ("col_divider", wi, rows, rw, False)]:
        for k in range((rows if name == "row_divider" else cols) - 1):
            (pts,) = parts[f"{name}[{k}]"]
            xs, ys = [x for x, _ in pts], [y for _, y in pts]
            x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
            assert (x1 - x0, y1 - y0) == pytest.approx((length - 2 * C, hd), abs=1e-9)
            # the slots' sides: the vertices off the plate's ends, in pairs `t + c` apart,
            # each slot half the height deep from the top (row) or the bottom (col)
            sides = sorted({round(x, 9) for x in xs if abs(x - x0) > 1e-6 and abs(x - x1) > 1e-6})
            assert len(sides) == 2 * (n - 1)
            mid = (x0 + x1) / 2
            for s in range(n - 1):
                a, b = sides[2 * s], sides[2 * s + 1]
                assert b - a == pytest.approx(T + C, abs=1e-9)
                # equal compartments: the slot's center where the divider crossing it stands
                assert (a + b) / 2 - mid == pytest.approx(-length / 2 + (s + 1) * pitch + s * T + T / 2,
                                                          abs=1e-9)
            inner = [y for x, y in pts if abs(x - x0) > 1e-6 and abs(x - x1) > 1e-6
                     and abs(y - (y1 if top else y0)) > 1e-6]
            assert inner and all(y == pytest.approx((y0 + y1) / 2, abs=1e-9) for y in inner)


# ------------------------------------------------------------------------------ the fit check

@pytest.mark.parametrize("name", list(GENERATORS))
@pytest.mark.parametrize("kerf", [0.0, 0.15])
@pytest.mark.parametrize("outside", ["true", "false"])
def test_assembles_without_a_collision_or_a_gap(tmp_path, name, kerf, outside):
    call = GENERATORS[name].format(L=100, W=70, H=40, o=outside)
    r = compile_src(tmp_path, program(call, kerf=kerf))
    assert fit_codes(r) == []
    assert [d.code for d in r.sink.items if d.code.startswith("W05")] == []


@pytest.mark.parametrize("name", list(GENERATORS))
def test_material_thicker_than_the_thickness_collides(tmp_path, name):
    r = compile_src(tmp_path, program(GENERATORS[name].format(L=100, W=70, H=40, o="true"), material=4))
    ws = [d for d in r.sink.items if d.code == "W0517"]
    # the fingers in their slots, 1 mm too thick for them
    assert ws and any(", 1 mm deep," in w.message for w in ws)


def test_open_finger_box_has_its_flat_edge_at_the_top(tmp_path):
    """finger_box(closed=false): the front's flat edge is at the open top, its fingers in the
    bottom's slots (it used to be upside down: a collision with the bottom)."""
    src = ('import "std/joints.aidl"\nthickness 3 mm\n'
           "assembly kit { box = finger_box(length=120 mm, depth=80 mm, height=50 mm, closed=false) }\n")
    assert fit_codes(compile_src(tmp_path, src)) == []


@settings(max_examples=8, deadline=None)
@example(finger=3.1, sheet=6.5, length=120.0, core=36.0)     # the sweep's findings (issue 84)
@example(finger=27.3, sheet=12.0, length=195.0, core=2.4)
@given(sheet=st.sampled_from([1.5, 3.0, 4.5, 6.5, 8.0, 12.0]),
       finger=st.floats(min_value=1.0, max_value=30.0).map(lambda f: round(f, 1)),
       length=st.floats(min_value=60.0, max_value=200.0).map(lambda v: round(v, 1)),
       core=st.floats(min_value=0.5, max_value=40.0).map(lambda v: round(v, 1)))
def test_law_mating_finger_panels_never_overlap(tmp_path_factory, finger, sheet, length, core):
    """Over generated (finger, sheet, length) and the height between the sheets (`core`),
    fingers narrower than the sheet and walls lower than three sheets included, the assembled
    finger_box has no collision and no loose panel (W0517/W0518, Manifold's 3D fit check).
    Before: each kept corner square was 1.5 t square and reached t/2 along the edge, into the
    next slot under fingers narrower than t/2 (0.64 mm^3 at finger 3.1 mm on a 6.5 mm sheet);
    each tab reached t/2 into the core, across a core thinner than t into the far edge's
    slots (3,610 mm^3 in a 26.4 mm high box of 12 mm sheet)."""
    src = ('import "std/joints.aidl"\n'
           f"thickness {sheet} mm\nassembly kit {{ box = finger_box(length={length} mm, "
           f"depth={round(length * 0.7, 1)} mm, height={2 * sheet + core} mm, "
           f"thickness={sheet} mm, finger={finger} mm, closed=false) }}\n")
    r = compile_src(tmp_path_factory.mktemp("law"), src)
    assert fit_codes(r) == [], [d.message for d in r.sink.items if d.code in CODES]


@pytest.mark.parametrize("t, width", [(10, 50), (12, 58), (3, 80)])
def test_sliding_lid_pull_stays_inside_a_short_lid(tmp_path, t, width):
    """The lid's pull hole, re-read from the DXF: inside the lid with a wall of at least 3 t
    (a long lid) or a third of the lid (a short one) before and behind it.  On a thick sheet at the narrowest box (thickness 10 mm, width
    50 mm: a 39.9 mm lid) the pull sat 4 t = 40 mm from its front edge and broke through
    (W0510 in the sweep); at 3 mm it is where it was (6 mm wide, 12 mm from the front)."""
    call = (f"sliding_lid_box(length=130 mm, width={width} mm, height=146 mm, thickness={t} mm, "
            "clearance=0.1 mm)")
    r = compile_src(tmp_path, program(call, material=t))
    loops = cut_dxf(r)["lid"]
    assert len(loops) == 2
    outer, pull = sorted(loops, key=lambda p: -size([p])[1])
    ys, ps = [y for _, y in outer], [y for _, y in pull]
    ll = width - t - 0.1
    wall = min(min(ps) - min(ys), max(ys) - max(ps))
    assert wall >= min(3 * t, ll / 3) - 1e-6
    if t == 3:
        assert size([pull])[1] == pytest.approx(6, abs=1e-6)
        assert (min(ps) + max(ps)) / 2 - min(ys) == pytest.approx(12, abs=1e-6)
