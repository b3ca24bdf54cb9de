# Request: a crêpe set for my 35 cm crêpe pan, cut from 4 mm beech ply. (1) A spreader (râteau):
# a blade 180 mm long, 20 mm tall at its ends arching to 36 mm in the middle, its straight
# bottom edge drags the batter; a 220 mm handle glued into a mortise in the blade's middle
# with a 10 mm tenon, so the handle's underside stays at least 15 mm above the pan; the handle
# has an 8 mm hanging hole at its round end and "CRÊPES" engraved (filled serif letters).
# (2) A turner: a 320 mm long flat spatula, 34 mm wide at the turning end tapering to 22 mm,
# with an 8 mm hanging hole.

import "std/joints.aidl"

units mm
thickness 4 mm
kerf 0.12 mm

t = 4 mm

assembly crepe_set {
    solid blade {
        bottom = Line((-90, 0), (90, 0))
        right = Line((90, 0), (90, 20))
        top = Arc(start=(90, 20), through=(0, 36), end=(-90, 20))
        left = Line((-90, 20), (-90, 0))
        mortise = tab_and_slot(part="slot", length=18, thickness=t, tabs=1, tab=10, screw=0,
                               clearance=0.1, rotation=90, cx=0, cy=26)
    }

    solid handle {
        body = Hull(Rectangle(center=(10, 0), width=20, height=18), Circle(center=(207, 0), diameter=26))
        tenon = tab_and_slot(part="tab", length=18, thickness=t, tabs=1, tab=10, screw=0,
                             rotation=90, cx=0, cy=0)
        hole hang {
            c = Circle(center=(207, 0), diameter=8)
        }
        drawing label {
            word = Text("CRÊPES", position=(100, 0), size=9, font="serif:Bold", valign="middle",
                        fill=true)
        }
    }

    solid turner {
        body = Hull(Circle(center=(-143, 0), diameter=34), Circle(center=(149, 0), diameter=22))
        hole hang {
            c = Circle(center=(149, 0), diameter=8)
        }
    }

    Below(handle, blade, gap=10)
    AlignLeft(handle, blade)
    Below(turner, handle, gap=10)
    AlignLeft(turner, handle)

    assert blade.bb.width == 180 mm, "blade 180 long"
    assert blade.right.length == 20 mm, "20 tall at the ends"
    assert blade.top.through.y - blade.bottom.start.y == 36 mm, "36 tall in the middle"
    assert handle.bb.width == 220 mm, "handle 220 long"
    assert handle.hang.c.diameter == 8 mm and turner.hang.c.diameter == 8 mm, "8 mm hanging holes"
    assert turner.bb.width == 320 mm, "turner 320 long"
    assert turner.bb.height == 34 mm, "34 wide at the turning end"
    # handle's underside above the pan: mortise centre height minus half the handle's 18 mm
    assert blade.mortise.slot[0].bb.center_y - blade.bottom.start.y - 9 mm >= 15 mm, "handle clears the batter"
}
