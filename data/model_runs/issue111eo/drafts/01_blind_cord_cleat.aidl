# Request: a child-safety cleat for a roller-blind pull cord, screwed high up in the window
# reveal. 6 mm birch ply, two parts glued and screwed together. Front plate: a dog-bone 110 mm
# long overall, two round lobes 34 mm in diameter joined by a waist 16 mm high, the inside
# corners where waist meets lobe rounded R4. Behind it a spacer 40 x 14 mm with R4 corners,
# centred under the waist, so the lobes stand 6 mm off the wall and the cord is wound in a
# figure of eight behind them. Two M4 countersunk wood screws 24 mm apart through the middle
# of both parts (countersinks 9 mm on the front plate only).

import "std/fasteners.aidl"

t = 6 mm
thickness t

param length = 110 mm, min = 90 mm, max = 160 mm
param lobe_d = 34 mm, min = 26 mm, max = 50 mm
param waist_h = 16 mm, min = 12 mm, max = 22 mm
pitch = 24 mm

assembly cleat {
    solid front {
        waist = Rectangle(center=(0, 0), width=length - lobe_d, height=waist_h)
        left_lobe = Circle(center=(-(length - lobe_d) / 2, 0), diameter=lobe_d)
        right_lobe = Circle(center=((length - lobe_d) / 2, 0), diameter=lobe_d)
        Fixed(waist)
        Concentric(left_lobe, waist.left.midpoint)
        Concentric(right_lobe, waist.right.midpoint)
        Fillet([waist, left_lobe], 4)
        Fillet([waist, right_lobe], 4)

        screw = clearance_hole(size=4)
        screws = LinearPattern(screw, 2, (pitch, 0))
        At(screw.c.center, waist.center, dx=-pitch / 2)
        Countersink(screws, diameter=9)
    }

    solid spacer {
        # FIX after the first valid program: drawn at (0, -40) in its own frame, the spacer
        # stood 40 mm below the front plate in 3D (note W0518); drawn at (0, 0), `Below` lays
        # it out on the sheet and `Place` puts it behind the waist
        block = RoundedRectangle(center=(0, 0), width=40, height=14, corner_radius=4)
        screw = clearance_hole(size=4)
        screws = LinearPattern(screw, 2, (pitch, 0))
        At(screw.c.center, block.center, dx=-pitch / 2)
    }

    # on the sheet: the spacer below the front plate
    Below(spacer, front, gap=8)
    AlignCenterX(spacer, front)

    # in 3D: the spacer against the wall (y = 0), the front plate on it, both facing the room
    Place(spacer, position=(0, 0, 0), face="front", up="up")
    Place(front, position=(0, -t, 0), face="front", up="up")

    # the request's numbers
    assert front.bb.width == 110 mm, "110 mm overall"
    assert front.left_lobe.diameter == 34 mm and front.right_lobe.diameter == 34 mm
    assert front.waist.height == 16 mm, "waist 16 mm"
    assert spacer.block.width == 40 mm and spacer.block.height == 14 mm
    assert spacer.block.height < front.waist.height, "spacer hidden behind the waist"
    assert front.screws[1].c.center.x - front.screws[0].c.center.x == 24 mm
    assert spacer.screws[1].c.center.x - spacer.screws[0].c.center.x == 24 mm
    assert len(front.screws) == 2 and len(spacer.screws) == 2
    assert front.screw.c.diameter >= 4.3 mm, "M4 clearance"
}
