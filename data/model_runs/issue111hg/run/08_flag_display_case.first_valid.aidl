# Request (gifts): a memorial display case for a folded 3 x 5 ft flag (a right-angled
# triangle about 394 mm along its long edge and 197 mm high, up to 36 mm thick), made as
# a stack of layers. Outside: a right isosceles triangle 500 mm along the bottom and 250 mm
# high, right angle at the top. From the front: a 6 mm ply frame 25 mm wide with
# "SGT JAMES R. MILLER  1948 - 2023" engraved (8 mm, centred) on its bottom band; a 3 mm ply
# rebate layer 11.5 mm wide holding a 3 mm clear acrylic pane 12 mm in from the outside
# (0.5 mm play); four 6 mm ply spacer frames 20 mm wide (the flag's pocket, at least
# 400 mm along the bottom); a 6 mm ply back. The back is screwed to the spacers with three
# wood screws, one in each corner 10 mm in from both edges: 4 mm holes countersunk 8 mm in
# the back, 2.5 mm pilot holes in the spacers. Two keyholes (8 mm head, 4 mm slot, 10 mm
# long, upward) in the back, 60 mm either side of the centre and 110 mm up.

import "std/plates.aidl"

units mm
thickness 6 mm

base = 500 mm
height = 250 mm
apex_y = height
# the inradius of a right isosceles triangle whose long side is `base`
r_in = base * (sqrt(2) - 1) / 2
# corner points 10 mm in from both edges: the triangle shrunk about its incentre (0, r_in)
k = (r_in - 10 mm) / r_in
screw_pts = [(-base / 2 * k, r_in * (1 - k)), (base / 2 * k, r_in * (1 - k)),
             (0, r_in + (apex_y - r_in) * k)]

def ring(band=20 mm, pilots=false) -> solid {
    outer = Triangle(center=(0, height / 2), base=base, height=height)
    hole window {
        w = Inset(Triangle(center=(0, height / 2), base=base, height=height), band,
                  join="miter")
    }
    if pilots {
        hole pilot {
            c = Circle(center=screw_pts[0], diameter=2.5)
        }
        pilots_all = CornerPattern(pilot, at=screw_pts)
    }
}

assembly case {
    front = ring(band=25 mm)
    drawing name {
        t = Text("SGT JAMES R. MILLER  1948 - 2023", (0, 25 mm / 2), size=8,
                 valign="middle")
    }
    CutInto(name, front)
    AlignCenterX(name, front)
    name.bb.center_y == front.outer.bb.bottom + 12.5 mm

    solid rebate {
        thickness 3 mm
        outer = Triangle(center=(0, height / 2), base=base, height=height)
        hole window {
            w = Inset(Triangle(center=(0, height / 2), base=base, height=height), 11.5 mm,
                      join="miter")
        }
    }

    solid pane {
        thickness 3 mm
        glass = Inset(Triangle(center=(0, height / 2), base=base, height=height), 12 mm,
                      join="miter")
    }

    for i in range(4) {
        spacer = ring(band=20 mm, pilots=true)
    }

    solid back {
        panel = Triangle(center=(0, height / 2), base=base, height=height)
        hole screw {
            c = Circle(center=screw_pts[0], diameter=4)
        }
        screws = CornerPattern(screw, at=screw_pts)
        Countersink(screw, diameter=8 mm)
        left_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                           cx=-60 mm, cy=110 mm)
        right_key = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg,
                            cx=60 mm, cy=110 mm)
    }

    # flat on the sheet: one below the other
    Below(rebate, front, gap=10)
    AlignLeft(rebate, front)
    Below(pane, rebate, gap=10)
    AlignCenterX(pane, rebate)
    Below(spacer[0], pane, gap=10)
    AlignLeft(spacer[0], rebate)
    for i in range(1, 4) {
        Below(spacer[i], spacer[i - 1], gap=10)
        AlignLeft(spacer[i], spacer[0])
    }
    Below(back, spacer[3], gap=10)
    AlignLeft(back, spacer[0])

    # assembled: the front at y = -3..3, the back's countersinks looking back
    Place(front, position=(0, 3, 0), face="front", up="up")
    Place(rebate, position=(0, 6, 0), face="front", up="up")
    Place(pane, position=(0, 6, 0), face="front", up="up")
    for i in range(4) {
        Place(spacer[i], position=(0, 12 + 6 * i, 0), face="front", up="up")
    }
    Place(back, position=(0, 30, 0), face="back", up="up")

    assert front.outer.bb.width == 500 mm and front.outer.bb.height == 250 mm, "outside"
    assert spacer[0].window.w.bb.width >= 400 mm, "the flag's pocket at least 400 long"
    assert len(spacer) == 4, "four spacers"
    assert front.window.w.bb.bottom - front.outer.bb.bottom == 25 mm, "front band 25"
    assert pane.glass.bb.width + 1 mm <= rebate.window.w.bb.width, "pane fits the rebate"
    assert distance(back.screw, back.panel) >= 0 mm, "screws on the back"
    assert distance(name, front.window) >= 4 mm, "name on the band"
}
