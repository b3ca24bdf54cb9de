# Request (sport): a bicycle bottle cage from 3 mm plywood for a standard 74 mm bottle.
# A 40 x 160 mm back plate with the two standard cage bolt holes 64 mm apart (5.5 mm wide
# slots, 9 mm long so they take up frame tolerance). A flat cradle the bottle stands on: an
# 86 mm disc with a 50 mm drain hole, and a hoop 127 mm above it (inner 77 mm, 6 mm band)
# that the bottle slides through. The bottle's axis is 44 mm in front of the back plate's
# front face (leaves 4 mm behind the bottle for the bolt heads). Cradle and hoop join the
# back plate with two 8 mm glued tabs each on a 40 mm tongue. Show it assembled.

import "std/joints.aidl"

thickness 3 mm

param bottle_d = 74 mm, min = 60 mm, max = 80 mm
param standoff = 44 mm, min = 40 mm, max = 50 mm

def tongue_joint() -> hole {
    j = tab_and_slot(part="tab", length=40 mm, thickness=3 mm, tabs=2, tab=8 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=0 mm)
}

assembly cage {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=40, height=160, corner_radius=6)
        hole bolts {
            lower = Slot(center=(0, -35), length=9, width=5.5, rotation=90 deg)
            upper = Slot(center=(0, 29), length=9, width=5.5, rotation=90 deg)
        }
        s_cradle = tab_and_slot(part="slot", length=40 mm, thickness=3 mm, tabs=2, tab=8 mm,
                                screw=0, cx=0 mm, cy=-72 mm)
        s_hoop = tab_and_slot(part="slot", length=40 mm, thickness=3 mm, tabs=2, tab=8 mm,
                              screw=0, cx=0 mm, cy=55 mm)
    }

    solid cradle {
        tongue = Rectangle(center=(0, 8), width=40, height=16)
        disc = Circle(center=(0, 3 + standoff), diameter=86)
        hole drain { c = Circle(center=(0, 3 + standoff), diameter=50) }
        joint = tongue_joint()
    }

    solid hoop {
        tongue = Rectangle(center=(0, 8), width=40, height=16)
        band = Shell(Circle(center=(0, 3 + standoff), diameter=bottle_d + 3), 6)
        hole opening { c = Circle(center=(0, 3 + standoff), diameter=bottle_d + 3) }
        joint = tongue_joint()
    }

    RightOf(cradle, back, gap=8)
    RightOf(hoop, cradle, gap=8)
    AlignBottom(cradle, back)
    AlignBottom(hoop, back)

    Place(back, position=(0, 0, 80), face="front", up="up")
    Place(cradle, position=(0, 0, 80 - 72 - 1.5), rotation=(0, 0, 180 deg))
    Place(hoop, position=(0, 0, 80 + 55 - 1.5), rotation=(0, 0, 180 deg))

    assert back.plate.width == 40 mm and back.plate.height == 160 mm
    assert back.bolts.upper.center.y - back.bolts.lower.center.y == 64 mm, "bolts 64 apart"
    assert back.bolts.lower.width == 5.5 mm and back.bolts.lower.length == 9 mm
    assert back.s_hoop.slot[0].bb.center_y - back.s_cradle.slot[0].bb.center_y == 127 mm, "hoop 127 above cradle"
    assert cradle.disc.diameter == 86 mm and cradle.drain.c.diameter == 50 mm
    assert hoop.opening.c.diameter == 77 mm and hoop.band.bb.width == 77 mm + 12 mm
    assert cradle.disc.center.y - 3 mm == 44 mm, "bottle axis 44 in front of the plate"
}
