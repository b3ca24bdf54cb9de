# Request (bathroom): an eyeshadow-palette organiser for the bathroom counter, 3 mm clear
# acrylic. A 200 x 110 mm base with 5 mm rounded corners carries six upright dividers 36 mm
# apart (centre to centre), so five palettes up to 32 mm thick stand on edge between them.
# Each divider is 110 mm deep, 100 mm tall at the back and 45 mm at the front, its sloping
# top's two corners rounded r8, glued into the base by two 20 mm tabs through two slots. The
# leftmost divider has "ZOE" engraved filled, 12 mm high, in bold sans.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
pitch = 36 mm
n_div = 6
depth = 110 mm
back_h = 100 mm
front_h = 45 mm

def divider(name="") -> solid {
    # the tabs' tips on y = -3 (they pass through the 3 mm base); the base's top at y = 0
    body = Polygon([(-depth / 2, -T), (depth / 2, -T), (depth / 2, front_h), (-depth / 2, back_h)])
    tabs = tab_and_slot(part="tab", length=depth, thickness=T, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-T)
    Fillet(body.points[2], 8)
    Fillet(body.points[3], 8)
    if name != "" {
        drawing label {
            t = Text(name, position=(-12, 35), size=12, font="sans:Bold", valign="middle",
                     fill=true)
        }
    }
}

assembly organiser {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=200, height=110, corner_radius=5)
        for i in range(n_div) {
            slot = tab_and_slot(part="slot", length=depth, thickness=T, tabs=2, tab=20 mm,
                                screw=0, rotation=90 deg, cx=(i - (n_div - 1) / 2) * pitch,
                                cy=0 mm)
        }
    }
    for i in range(n_div) {
        d = divider(name="ZOE" if i == 0 else "")
        Above(d, base, gap=10)
        d.bb.left == base.bb.left + i * (depth + 10 mm)
        # 3D: standing across the base, its x along the base's depth, its y up
        Place(d, rotation=(90 deg, 0, 90 deg),
              position=((i - (n_div - 1) / 2) * pitch - T / 2, 0, T))
    }

    assert base.body.bb.width == 200 mm and base.body.bb.height == 110 mm, "base 200 x 110"
    assert len(d) == 6, "six dividers"
    assert base.slot[1].bb.center_x - base.slot[0].bb.center_x == 36 mm, "dividers 36 apart"
    assert d[0].body.bb.height - T == 100 mm, "100 tall at the back"
    assert d[0].body.points[2].y - d[0].body.points[1].y - T == 45 mm, "45 tall at the front"
    assert d[0].body.bb.width == 110 mm, "110 deep"
}
