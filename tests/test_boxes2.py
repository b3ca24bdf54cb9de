"""std/boxes.aidl (issue 52, "Boxes"), the second three: hinged_box, drawer, flex_box.

As tests/test_boxes.py: each generator goes through the real pipeline; its stated sizes
(outside and inside, for `outside=true` and `false`) are re-read from the DXF `aidl render -o
x.dxf` writes, with ezdxf (an independent reader), to 1e-9 mm; assembled, the fit check finds no
collision (W0517) and no loose part (W0518) at kerf 0 and 0.15 mm, and material thicker than
`thickness` collides (W0517). Beyond: the hinged lid swings open past 90 degrees without
touching a wall (the lid and cheeks turned about the pin in Manifold), the drawer's clearance
all round is measured on the assembled solids, and the flex box's wall is as long as the base's
perimeter at the wall's middle line, from the base's outline and corner arcs in the DXF, and
assembled it wraps the base's outline.
"""
import io
import math
from pathlib import Path

import ezdxf
import ezdxf.bbox
import numpy as np
import pytest

import aidl_lang
from aidl_lang.output.fabrication import assembly

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


def read_dxf(r):
    """The cut DXF re-read by ezdxf: layer (the part's path after `kit.b.`) -> its
    LWPOLYLINE and LINE entities (a through-cut), and -> its CIRCLE entities."""
    doc = ezdxf.read(io.StringIO(r.to_dxf()))
    polys: dict[str, list] = {}
    circles: dict[str, list] = {}
    for e in doc.modelspace():
        name = e.dxf.layer.removeprefix("CUT-kit.b.")
        if e.dxftype() in ("LWPOLYLINE", "LINE"):
            polys.setdefault(name, []).append(e)
        elif e.dxftype() == "CIRCLE":
            circles.setdefault(name, []).append(e)
    return polys, circles


def box(e):
    """An entity's bounding box, its arcs (bulges) included (ezdxf.bbox)."""
    b = ezdxf.bbox.extents([e], fast=False)
    return b.extmin.x, b.extmin.y, b.extmax.x, b.extmax.y


def size(entities):
    """Width and height of a part's outline (its widest polyline)."""
    x0, y0, x1, y1 = max((box(e) for e in entities), key=lambda b: b[2] - b[0])
    return x1 - x0, y1 - y0


def fit_codes(r):
    return [d.code for d in r.sink.items if d.code in CODES]


HINGED = ("hinged_box(length={L} mm, width={W} mm, height={H} mm, thickness=3 mm, clearance=0.3 mm, "
          "outside={o})")
DRAWER = ("drawer(length={L} mm, depth={W} mm, height={H} mm, thickness=3 mm, clearance=0.3 mm, "
          "outside={o})")
FLEX = ("flex_box(length={L} mm, width={W} mm, height={H} mm, radius=15 mm, thickness=3 mm, "
        "clearance=0.3 mm, outside={o})")
GENERATORS = {"hinged_box": HINGED, "drawer": DRAWER, "flex_box": FLEX}


def hinge(p=T, t=T, c=C):
    """The hinge's figures, computed here from the construction the template's comment states:
    the cheek's hole (the square pin's diagonal plus the clearance), its lobe (a third of a
    thickness more), the pivot twice the lobe under the lid and the lobe in from the back, and
    the walls lowered behind it by the lid's swing there plus the clearance."""
    rh = (math.hypot(p, t) + c) / 2
    r = rh + t / 3
    b = 2 * r
    return rh, r, b, b - math.sqrt(b * b - r * r) + c


# ------------------------------------------------------------------------------ hinged_box

@pytest.mark.parametrize("outside", ["true", "false"])
def test_hinged_box_sizes_and_the_hinge(tmp_path, outside):
    L, W, H = 120.0, 80.0, 50.0
    r = compile_src(tmp_path, program(HINGED.format(L=L, W=W, H=H, o=outside)))
    polys, circles = read_dxf(r)
    assert set(polys) == {"bottom", "front", "back", "left", "right", "lid", "cheek[0]", "cheek[1]",
                          "pin[0]", "pin[1]"}
    if outside == "true":
        lo, wo, hb = L - 2 * T - 2 * C, W, H - T
    else:
        lo, wo, hb = L + 2 * T, W + 2 * T, H + T
    rh, rr, b, g = hinge()
    lid_l, lid_w = size(polys["lid"])
    assert (lid_l, lid_w) == pytest.approx((lo + 2 * T + 2 * C, wo), abs=1e-9)
    assert size(polys["bottom"]) == pytest.approx((lo, wo), abs=1e-9)
    assert size(polys["front"]) == pytest.approx((lo, hb), abs=1e-9)
    # the back wall lowered by the swing; the side walls full height
    assert size(polys["back"]) == pytest.approx((lo, hb - g), abs=1e-9)
    for side in ("left", "right"):
        assert size(polys[side]) == pytest.approx((hb, wo), abs=1e-9)
    # outside: the lid's length, the lid on the walls; inside: between the walls, floor to lid
    if outside == "true":
        assert (lid_l, lid_w, hb + T) == pytest.approx((L, W, H), abs=1e-9)
    else:
        assert (lo - 2 * T, wo - 2 * T, hb - T) == pytest.approx((L, W, H), abs=1e-9)
    # the pin: a strip of the sheet, thickness wide, through a wall and a cheek with the clearance
    for k in range(2):
        assert size(polys[f"pin[{k}]"]) == pytest.approx((2 * T + C, T), abs=1e-9)
        (hole,) = circles[f"cheek[{k}]"]
        assert 2 * hole.dxf.radius == pytest.approx(math.hypot(T, T) + C, abs=1e-9)
        # the cheek: the lobe's width, from the pivot to the lid
        assert size(polys[f"cheek[{k}]"]) == pytest.approx((b + rr, 2 * rr), abs=1e-9)
    # each side wall's hole for the pin: the pin's section, `b` under the top (the wall's top
    # edge is the net's x = min for the left wall), `r` in from the back edge
    for side in ("left", "right"):
        outline, *holes = sorted(polys[side], key=lambda e: -(box(e)[2] - box(e)[0]))
        (x0, y0, x1, y1) = box(outline)
        (hx0, hy0, hx1, hy1), = [box(e) for e in holes]
        assert (hx1 - hx0, hy1 - hy0) == pytest.approx((T, T), abs=1e-9)
        top = x0 if side == "left" else x1
        assert abs((hx0 + hx1) / 2 - top) == pytest.approx(b, abs=1e-9)
        assert y1 - (hy0 + hy1) / 2 == pytest.approx(rr, abs=1e-9)


def test_hinged_box_pin_width(tmp_path):
    r = compile_src(tmp_path, program("hinged_box(pin=4 mm)"))
    polys, circles = read_dxf(r)
    assert size(polys["pin[0]"]) == pytest.approx((2 * T + C, 4.0), abs=1e-9)
    assert 2 * circles["cheek[0]"][0].dxf.radius == pytest.approx(math.hypot(4, T) + C, abs=1e-9)
    assert fit_codes(r) == []


def turned(bodies, names, deg, yp, zp):
    """The named bodies turned by `deg` about the line along x through (yp, zp), the front
    going up."""
    th = math.radians(deg)
    c, s = math.cos(th), math.sin(th)
    R = np.array([[1, 0, 0], [0, c, s], [0, -s, c]])
    off = np.array([0, yp, zp]) - R @ np.array([0, yp, zp])
    M = np.hstack([R, off[:, None]])
    return {n: bodies[n].transform(M) for n in names}


def test_hinged_lid_opens_past_a_right_angle_without_touching_a_wall(tmp_path):
    """The lid and its cheeks turned about the pin, 0 to 120 degrees in steps of 5: they meet
    neither a wall nor a pin (the check at the closed position alone is the fit check's);
    with the back wall not lowered they would."""
    L, W, H = 120.0, 80.0, 50.0
    r = compile_src(tmp_path, program(HINGED.format(L=L, W=W, H=H, o="true")))
    bodies = dict(assembly.solids(r.output))
    moving = ["kit.b.lid", "kit.b.cheek[0]", "kit.b.cheek[1]"]
    fixed = [n for n in bodies if n not in moving]
    rh, rr, b, g = hinge()
    yp, zp = W / 2 - rr, H - T - b
    for deg in range(0, 121, 5):
        moved = turned(bodies, moving, deg, yp, zp)
        for m in moving:
            for f in fixed:
                assert (moved[m] ^ bodies[f]).volume() < 1e-6, (deg, m, f)
    # the test can fail: the back wall raised to the lid's underside is hit on the way
    import manifold3d as mf
    wall = mf.Manifold.cube([L, T, g]).translate([-L / 2, W / 2 - T, H - T - g])
    hit = [deg for deg in range(5, 121, 5)
           if (turned(bodies, ["kit.b.lid"], deg, yp, zp)["kit.b.lid"] ^ wall).volume() > 1e-3]
    assert hit


# ------------------------------------------------------------------------------ drawer

@pytest.mark.parametrize("outside", ["true", "false"])
def test_drawer_sizes_and_the_pull(tmp_path, outside):
    L, D, H = 120.0, 100.0, 60.0
    r = compile_src(tmp_path, program(DRAWER.format(L=L, W=D, H=H, o=outside)))
    polys, circles = read_dxf(r)
    assert set(polys) == {f"{a}.{p}" for a, ps in [("carcass", ["bottom", "top", "back", "left", "right"]),
                                                   ("box", ["bottom", "front", "back", "left", "right"])]
                          for p in ps}
    lo, do, ho = (L, D, H) if outside == "true" else (L + 2 * T, D + T, H + 2 * T)
    assert size(polys["carcass.bottom"]) == pytest.approx((lo, do), abs=1e-9)
    assert size(polys["carcass.top"]) == pytest.approx((lo, do), abs=1e-9)
    assert size(polys["carcass.back"]) == pytest.approx((lo, ho), abs=1e-9)
    assert size(polys["carcass.left"]) == pytest.approx((ho, do), abs=1e-9)
    # inside the carcass: between the sides, the front to the back, the floor to the top
    inner = (lo - 2 * T, do - T, ho - 2 * T)
    assert inner == pytest.approx((L, D, H) if outside == "false" else (L - 2 * T, D - T, H - 2 * T),
                                  abs=1e-9)
    # the drawer: the inside less the clearance at the sides, the back and the top
    ld, hd = size(polys["box.front"])
    assert (ld, hd) == pytest.approx((inner[0] - 2 * C, inner[2] - C), abs=1e-9)
    assert size(polys["box.bottom"]) == pytest.approx((ld, inner[1] - C), abs=1e-9)
    assert size(polys["box.left"]) == pytest.approx((hd, inner[1] - C), abs=1e-9)
    # the finger pull: a round hole in the middle of the front
    (pull,) = circles["box.front"]
    x0, y0, x1, y1 = box(polys["box.front"][0])
    assert 2 * pull.dxf.radius == pytest.approx(min(20.0, hd / 2), abs=1e-9)
    assert (pull.dxf.center.x, pull.dxf.center.y) == pytest.approx(((x0 + x1) / 2, (y0 + y1) / 2), abs=1e-9)


def test_drawer_clearance_all_round_assembled(tmp_path):
    """On the assembled solids: the drawer stands on the carcass floor, flush with its front,
    `clearance` from the side walls, the top and the back wall."""
    L, D, H = 120.0, 100.0, 60.0
    r = compile_src(tmp_path, program(DRAWER.format(L=L, W=D, H=H, o="true")))
    bodies = dict(assembly.solids(r.output))
    lo = np.min([b.bounding_box()[:3] for n, b in bodies.items() if ".box." in n], axis=0)
    hi = np.max([b.bounding_box()[3:] for n, b in bodies.items() if ".box." in n], axis=0)
    assert lo == pytest.approx([-L / 2 + T + C, -D / 2, T], abs=1e-6)
    assert hi == pytest.approx([L / 2 - T - C, D / 2 - T - C, H - T - C], abs=1e-6)


# ------------------------------------------------------------------------------ flex_box

def arcs(e):
    """The radii of a polyline's arcs (its bulges), as ezdxf reads them."""
    return [a.dxf.radius for a in e.virtual_entities() if a.dxftype() == "ARC"]


@pytest.mark.parametrize("outside", ["true", "false"])
@pytest.mark.parametrize("dims", [(120.0, 80.0, 50.0, 15.0), (90.0, 90.0, 40.0, 30.0)])
def test_flex_box_wall_is_as_long_as_the_base_perimeter(tmp_path, outside, dims):
    L, W, H, R = dims
    call = (f"flex_box(length={L} mm, width={W} mm, height={H} mm, radius={R} mm, thickness=3 mm, "
            f"clearance=0.3 mm, outside={outside})")
    r = compile_src(tmp_path, program(call))
    polys, _ = read_dxf(r)
    assert set(polys) == {"base", "lid", "lip[0]", "lip[1]", "wall"}
    # the base's outline re-read: its size and its four corner arcs
    (base,) = polys["base"]
    bl, bw = size(polys["base"])
    radii = arcs(base)
    assert len(radii) == 4 and max(radii) - min(radii) < 1e-9
    ro = radii[0]
    lo, wo, ho, r_out = (L, W, H, R) if outside == "true" else (L + 2 * T, W + 2 * T, H + 4 * T, R + T)
    assert (bl, bw, ro) == pytest.approx((lo, wo, r_out), abs=1e-9)
    assert size(polys["lid"]) == pytest.approx((lo, wo), abs=1e-9)
    # the wall: as long as the base's perimeter at the wall's middle line (the straight sides
    # and four quarter arcs of the outer radius less half a thickness), between base and lid
    perimeter = 2 * (bl - 2 * ro) + 2 * (bw - 2 * ro) + 2 * math.pi * (ro - T / 2)
    wl, wh = size(polys["wall"])
    assert wl == pytest.approx(perimeter, abs=1e-9)
    assert wh + 2 * T == pytest.approx(ho, abs=1e-9)
    # the lips: inside the wall with the clearance all round, corners concentric with the base's
    for k in range(2):
        (lip,) = polys[f"lip[{k}]"]
        assert size([lip]) == pytest.approx((lo - 2 * T - 2 * C, wo - 2 * T - 2 * C), abs=1e-9)
        assert arcs(lip) == pytest.approx([ro - T - C] * 4, abs=1e-9)
    # the living hinges: one over each corner's arc, centred on it along the strip (the strip
    # starts mid-front: half the front, a quarter arc, the side, ...)
    outline = max(polys["wall"], key=lambda e: box(e)[2] - box(e)[0])
    x0 = box(outline)[0]
    cuts = sorted((box(e)[0] + box(e)[2]) / 2 - x0 for e in polys["wall"] if e is not outline)
    # each slit one LINE on the wall's cut layer (a through-cut, cut once), not a rectangle
    assert {e.dxftype() for e in polys["wall"] if e is not outline} == {"LINE"}
    groups = [[cuts[0]]]
    for x in cuts[1:]:
        if x - groups[-1][-1] < 5:
            groups[-1].append(x)
        else:
            groups.append([x])
    arc = math.pi * (ro - T / 2) / 2
    ls, ws = bl - 2 * ro, bw - 2 * ro
    want = [ls / 2 + arc / 2, ls / 2 + arc + ws + arc / 2, ls / 2 + 2 * arc + ws + ls + arc / 2,
            perimeter - ls / 2 - arc / 2]
    assert len(groups) == 4
    for g, w in zip(groups, want):
        assert (min(g) + max(g)) / 2 == pytest.approx(w, abs=1e-9)
        assert max(g) - min(g) < arc


def test_flex_box_wall_wraps_the_base_outline(tmp_path):
    """Assembled, the wall stands on the base bent round its corners (`Bend`, tests/test_bend.py):
    its outer face on the base's outline, between the base and the lid (it stood unbent along
    the back, its ends running on past the corners)."""
    L, W, H = 120.0, 80.0, 50.0
    r = compile_src(tmp_path, program(FLEX.format(L=L, W=W, H=H, o="true")))
    bodies = dict(assembly.solids(r.output))
    x0, y0, z0, x1, y1, z1 = bodies["kit.b.wall"].bounding_box()
    assert (x0, x1, y0, y1, z0, z1) == pytest.approx((-L / 2, L / 2, -W / 2, W / 2, T, H - T), abs=1e-6)


# ------------------------------------------------------------------------------ the fit check

@pytest.mark.parametrize("name", list(GENERATORS))
@pytest.mark.parametrize("kerf", [0.0, 0.15])
@pytest.mark.parametrize("outside", ["true", "false"])
def test_assembles_without_a_collision_or_a_gap(tmp_path, name, kerf, outside):
    call = GENERATORS[name].format(L=110, W=80, H=50, o=outside)
    r = compile_src(tmp_path, program(call, kerf=kerf))
    assert fit_codes(r) == []
    assert [d.code for d in r.sink.items if d.code.startswith("W05")] == []


@pytest.mark.parametrize("name", list(GENERATORS))
def test_material_thicker_than_the_thickness_collides(tmp_path, name):
    r = compile_src(tmp_path, program(GENERATORS[name].format(L=110, W=80, H=50, o="true"), material=4))
    ws = [d for d in r.sink.items if d.code == "W0517"]
    assert ws and any(", 1 mm deep," in w.message for w in ws)


@pytest.mark.parametrize("name", list(GENERATORS))
def test_defaults_compile_clean(tmp_path, name):
    r = compile_src(tmp_path, program(f"{name}()"))
    assert [d.code for d in r.sink.items] == [], [d.message for d in r.sink.items]
