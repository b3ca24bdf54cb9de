# Request (kitchen): a magnetic knife strip for the wall above the worktop, two glued
# layers 400 mm x 60 mm with R8 corners. The back layer, 6 mm birch ply, holds 8 disc
# magnets 20 mm x 5 mm in through holes of 20.2 mm, in one row on the strip's centre line,
# 45 mm apart and centred along it. The front skin, 3 mm walnut ply, covers them and has
# a line engraved 4 mm in from its edge all round. Two M4 wall screws through both layers,
# 15 mm from each end on the centre line, countersunk 9 mm in the front skin; at least
# 10 mm of wood between a screw hole and the nearest magnet. In 3D: the back on the wall,
# the front skin on it.

import "std/fasteners.aidl"

units mm

assembly knife_strip {
    solid back {
        thickness 6 mm
        body = RoundedRectangle(center=(0, 0), width=400, height=60, corner_radius=8)
        hole magnet {
            c = Circle(center=(-157.5, 0), diameter=20.2)
        }
        magnets = LinearPattern(magnet, 8, (45, 0))
        screw_l = clearance_hole(size=4, cx=-185, cy=0)
        screw_r = clearance_hole(size=4, cx=185, cy=0)
    }

    solid front {
        thickness 3 mm
        body = RoundedRectangle(center=(0, 0), width=400, height=60, corner_radius=8)
        screw_l = clearance_hole(size=4, cx=-185, cy=0)
        screw_r = clearance_hole(size=4, cx=185, cy=0)
        Countersink([screw_l, screw_r], diameter=9)
        drawing border {
            r = RoundedRectangle(center=(0, 0), width=400, height=60, corner_radius=8,
                                 construction=true)
            line = Inset(r, 4)
        }
    }

    # on the sheet: the skin under the back plate
    Below(front, back, gap=10)
    AlignLeft(front, back)

    # in 3D: back plate against the wall (y = 0), the skin in front of it
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(front, position=(0, -6, 0), face="front", up="up")

    assert back.body.width == 400 mm and back.body.height == 60 mm
    assert front.body.width == back.body.width and front.body.height == back.body.height
    assert len(back.magnets) == 8, "8 magnets"
    assert back.magnets[0].c.diameter == 20.2 mm
    assert distance(back.magnets[0].c.center, back.magnets[1].c.center) == 45 mm
    assert abs((back.magnets[0].c.center.x + back.magnets[7].c.center.x) / 2 -
               back.body.bb.center_x) < 0.01 mm, "row centred along the strip"
    assert abs(back.magnets[3].c.center.y - back.body.bb.center_y) < 0.01 mm, "on the centre line"
    assert back.screw_l.c.center.x - back.body.bb.left == 15 mm
    assert back.body.bb.right - back.screw_r.c.center.x == 15 mm
    assert front.screw_l.c.center.x - front.body.bb.left == 15 mm
    assert front.body.bb.right - front.screw_r.c.center.x == 15 mm
    assert distance(back.screw_l, back.magnets[0]) >= 10 mm, "wood between screw and magnet"
    assert distance(back.screw_r, back.magnets[7]) >= 10 mm, "wood between screw and magnet"
    assert front.border.bb.width == 400 mm - 2 * 4 mm, "border 4 mm in"
}
