# Request (pets): a corner ledge for a rat cage, bolted to the wire bars.
# 6 mm ply. A quarter-round platform of radius 160 mm (measured from the inside corner)
# with a 60 mm climb-through hole whose centre is 95 mm out on the diagonal, and
# "NIBBLES & SQUEAK" engraved along the rim, 8 mm letters standing on a 140 mm radius.
# Two back plates 60 mm tall stand against the two cage walls; the platform's straight
# edges have three 20 mm tenons each, glued through mortises in the back plates, the
# platform's underside 30 mm up. One M6 bolt hole per back plate, 80 mm along from the
# inside corner, 15 mm up, for a bolt, washer and wing nut through the bars.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 9 mm
param r = 160 mm, min = 120 mm, max = 220 mm
param hatch_d = 60 mm, min = 45 mm, max = 80 mm
param hatch_out = 95 mm, min = 70 mm, max = 130 mm
param plate_h = 60 mm, min = 45 mm, max = 90 mm
param shelf_up = 30 mm, min = 22 mm, max = 45 mm
param bolt_along = 80 mm, min = 40 mm, max = 120 mm
param bolt_up = 15 mm, min = 10 mm, max = 20 mm

def back_plate(start=0 mm) -> solid {
    # frame: x along the wall from the inside corner, y up from the bottom edge
    body = Rectangle(bottom_left=(start, 0), width=r - start, height=plate_h)
    mortises = tab_and_slot(part="slot", length=r, thickness=t, tabs=3, tab=20 mm, screw=0,
                            cx=r / 2, cy=shelf_up + t / 2)
    bolt = clearance_hole(size=6, cx=bolt_along, cy=bolt_up)
}

assembly cage_ledge {
    solid platform {
        # the inside corner at (0, 0); tenons run t past both straight edges
        top = Sector(center=(0, 0), radius=r, start_angle=0, end_angle=90)
        strip_x = Rectangle(bottom_left=(0, -t), width=r, height=t)
        strip_y = Rectangle(bottom_left=(-t, 0), width=t, height=r)
        tenons_x = tab_and_slot(part="tab", length=r, thickness=t, tabs=3, tab=20 mm, screw=0,
                                rotation=180 deg, cx=r / 2, cy=-t)
        tenons_y = tab_and_slot(part="tab", length=r, thickness=t, tabs=3, tab=20 mm, screw=0,
                                rotation=90 deg, cx=-t, cy=r / 2)
        hole hatch {
            c = Circle(center=(hatch_out * cos(45 deg), hatch_out * sin(45 deg)),
                       diameter=hatch_d)
        }
        drawing names {
            ring = Circle(center=(0, 0), radius=140, construction=true)
            word = Text("NIBBLES & SQUEAK", along=ring, angle=45 deg, size=8,
                        font="sans:Bold", fill=true)
        }
    }
    wall_x = back_plate(start=-t)
    wall_y = back_plate()

    # on the sheet
    RightOf(wall_x, platform, gap=6)
    AlignBottom(wall_x, platform)
    Above(wall_y, wall_x, gap=6)
    AlignLeft(wall_y, wall_x)

    # assembled: the cage's inside corner on the z axis, its walls' inner faces at x = 0, y = 0
    Place(platform, position=(0, 0, shelf_up), face="up", up="back")
    Place(wall_x, position=(0, 0, 0), face="front", up="up")
    Place(wall_y, position=(-t, 0, 0), face="right", up="up")

    # the request's numbers
    assert platform.top.radius == 160 mm, "radius 160"
    assert platform.hatch.c.diameter == 60 mm, "60 mm hatch"
    assert distance(platform.hatch.c.center, platform.top.center) == 95 mm, "95 mm out"
    assert wall_x.body.bb.height == 60 mm, "back plates 60 tall"
    assert wall_x.mortises.slot[0].bb.bottom - wall_x.body.bb.bottom == 30 mm,
        "underside 30 mm up"
    assert wall_y.bolt.c.center.x - wall_y.body.bb.left == 80 mm, "bolt 80 along"
    assert wall_y.bolt.c.center.y - wall_y.body.bb.bottom == 15 mm, "bolt 15 up"
    assert wall_x.bolt.c.center.y + wall_x.bolt.c.radius + 8 mm <
        wall_x.mortises.slot[0].bb.bottom, "washer clear of the platform"
    assert len(wall_x.mortises.slot) == 3, "three tenons"
}
