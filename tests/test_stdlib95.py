"""Issue 95's standard-library additions, through the real pipeline and read back.

`ring_gear` (the internal gear that was only inside `planetary`): a pinion set at the centre
distance module * (ring - pinion) / 2 meshes in it without a word, and turned half a pitch or
set 0.5 mm deeper the parts interpenetrate (W0511); its tips (cut back for a given pinion) and
roots (1.25 modules deep) re-read from the DXF (ezdxf).  `finger_box(outside=false)`: the sizes are the space inside, the panels two
thicknesses larger, re-read from the DXF; assembled, the fit check finds nothing.  (~4 s CPU.)"""
import math

import pytest

from test_mechanisms import by_layer, bbox, circles, dxf_render, part, run

RING = """import "std/gears.aidl"
assembly set {{
    ring = ring_gear(teeth={z}, module={m} mm{given})
    pinion = spur_gear(teeth={p}, module={m} mm, phase={phase} deg, cx={cx} mm)
}}
"""


def _overlaps(c) -> list:
    return [d.message for d in c.sink.items if d.code == "W0511"]


@pytest.mark.parametrize("z,p,m", [(40, 14, 2), (48, 18, 1.5)])
def test_a_pinion_meshes_in_the_ring_gear_and_only_in_mesh(tmp_path, z, p, m):
    a = m * (z - p) / 2
    c = run(tmp_path, RING.format(z=z, p=p, m=m, phase=0, cx=a, given=f', pinion={p}'))
    assert c.ok and _overlaps(c) == [], [(d.code, d.message) for d in c.sink.items]
    # half a pinion pitch turned: tooth on tooth
    c = run(tmp_path, RING.format(z=z, p=p, m=m, phase=180 / p, cx=a, given=f', pinion={p}'))
    assert c.ok and len(_overlaps(c)) == 1
    # 0.5 mm deeper: the pinion's tips in the ring's teeth
    c = run(tmp_path, RING.format(z=z, p=p, m=m, phase=0, cx=a + 0.5, given=f', pinion={p}'))
    assert c.ok and len(_overlaps(c)) == 1


@pytest.mark.parametrize("given", ["", ", pinion=14"])
def test_the_ring_gear_s_tips_roots_and_rim_from_the_dxf(tmp_path, given):
    z, m = 40, 2
    layers = by_layer(dxf_render(tmp_path, RING.format(z=z, p=14, m=m, phase=0, cx=26, given=given)))
    ring = part(layers, "ring")
    (bx, by, br), = circles(ring)
    assert (bx, by) == pytest.approx((0, 0), abs=1e-9)
    assert br == pytest.approx(m * z / 2 + 1.25 * m + 6, abs=1e-9)        # the rim: 6 mm
    inner = min((e for e in ring if e.dxftype() == "LWPOLYLINE"),
                key=lambda e: bbox([e])[2] - bbox([e])[0])
    radii = [math.hypot(x, y) for x, y in inner.get_points("xy")]
    # the teeth's tips: the addendum circle m (z - 2) / 2 = 38 mm; for a 14-tooth pinion, cut
    # back to where the line of action meets its base circle, sqrt(rb^2 + (a sin 20)^2) =
    # 38.63 mm (rb = 40 cos 20 deg, a = 26 mm)
    a20 = math.radians(20)
    tips = math.hypot(m * z / 2 * math.cos(a20), 26 * math.sin(a20)) if given else m * (z - 2) / 2
    assert min(radii) == pytest.approx(tips, abs=1e-9)
    assert (round(tips, 2) == 38.63) if given else tips == 38
    # the spaces' roots: 1.25 m past the pitch circle (ISO 53's dedendum; they were m)
    assert max(radii) == pytest.approx(m * (z + 2.5) / 2, abs=1e-6)
    # a space along +x: the outline reaches the roots there
    far = max(inner.get_points("xy"), key=lambda q: q[0])
    assert math.atan2(far[1], far[0]) == pytest.approx(0, abs=0.05)


BOX = """import "std/joints.aidl"
thickness 3 mm
assembly kit {{ box = finger_box(length=100 mm, depth=60 mm, height=40 mm, closed={closed},
                                 outside=false) }}
"""


@pytest.mark.parametrize("closed,tall", [("true", 46), ("false", 43)])
def test_finger_box_by_its_inside_sizes(tmp_path, closed, tall):
    """100 x 60 x 40 mm inside from 3 mm: the bottom 106 x 66, the front and back 106 wide
    and 46 tall (a lid and a bottom) or 43 (open), the sides 66 deep; assembled, every finger
    in its slot (no W0517, W0518)."""
    src = BOX.format(closed=closed)
    c = run(tmp_path, src)
    assert c.ok and c.drawing.placement
    assert [d.code for d in c.sink.items if d.code in ("W0517", "W0518")] == []
    layers = by_layer(dxf_render(tmp_path, src))

    def size(name):
        x0, y0, x1, y1 = bbox(part(layers, name))
        return round(x1 - x0, 9), round(y1 - y0, 9)
    assert size("bottom") == (106, 66)
    assert size("front") == size("back") == (106, tall)
    assert size("left") == size("right") == (tall, 66)
    assert (size("lid") == (106, 66)) if closed == "true" else not part(layers, "lid")
