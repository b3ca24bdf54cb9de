# Request (workshop): a rack for the shelf above my table saw that keeps 4 circular saw blades
# (up to 254 mm / 10 in) standing upright, one per 30 mm bay. 6 mm birch ply. Base 170 x 220 mm;
# five dividers 200 mm deep x 150 mm tall whose front slopes down to 80 mm over the first 70 mm
# so a blade is easy to grab, top corners rounded r10; each divider glued into the base with two
# 40 mm tabs through slots (0.1 mm clearance). The 20 mm strip at the front of the base is
# engraved under each bay with the blade it holds: 24T RIP, 40T GP, 60T XCUT, 80T FINE.

import "std/joints.aidl"

units mm
thickness 6 mm

ply = 6 mm
bay = 30 mm
pitch = bay + ply
margin = 10 mm
strip = 20 mm
depth = 200 mm
tall = 150 mm
teeth = ["24T", "40T", "60T", "80T"]
kinds = ["RIP", "GP", "XCUT", "FINE"]

def divider() -> solid {
    body = Polygon([(0, 0), (200, 0), (200, 150), (70, 150), (0, 80)])
    feet = tab_and_slot(part="tab", length=200 mm, thickness=6 mm, tabs=2, tab=40 mm, screw=0,
                        rotation=180 deg, cx=100 mm, cy=0 mm)
    Fillet([body.points[2], body.points[3], body.points[4]], 10)
}

assembly rack {
    solid base {
        plate = Rectangle(bottom_left=(0, 0), width=170, height=220)
        for i in range(5) {
            s = tab_and_slot(part="slot", length=200 mm, thickness=6 mm, tabs=2, tab=40 mm,
                             screw=0, clearance=0.1 mm, rotation=90 deg,
                             cx=margin + ply / 2 + i * pitch, cy=strip + depth / 2)
        }
        drawing labels {
            for i in range(4) {
                t = Text(teeth[i], position=(margin + ply + bay / 2 + i * pitch, 11), size=4)
                k = Text(kinds[i], position=(margin + ply + bay / 2 + i * pitch, 4), size=3)
            }
        }
    }

    for i in range(5) {
        d = divider()
        # stood on edge: its x runs front to back (world y), its y up (world z), its thickness along world x
        Place(d, rotation=(90 deg, 0, 90 deg), position=(margin + i * pitch, strip, 0))
    }

    # flat on the sheet: the dividers in a row above the base
    Above(d[0], base, gap=10)
    AlignLeft(d[0], base)
    for i in range(1, 5) {
        RightOf(d[i], d[i - 1], gap=5)
        AlignBottom(d[i], d[0])
    }

    assert len(d) == 5, "five dividers"
    assert len(base.labels.t) == 4, "four bays, one label each"
    assert base.s[1].bb.center_x - base.s[0].bb.center_x - 6 mm == 30 mm, "30 mm bays"
    assert base.plate.bb.width == 170 mm and base.plate.bb.height == 220 mm, "base 170 x 220"
    assert d[0].body.bb.width == 200 mm and d[0].body.bb.height == 150 mm, "dividers 200 deep, 150 tall"
    assert base.s[0].bb.bottom - base.plate.bb.bottom >= 20 mm, "label strip 20 mm clear"
}
