# Request (camping): a knock-down buck saw frame for a 21 in (533 mm) bow-saw blade, for
# the canoe trip, from 12 mm birch ply, packing flat.
# - Two arms 300 mm tall: the outline is the hull of a 30 mm circle at the bottom (its
#   centre 15 mm up), a 44 mm circle at the stretcher (170 mm up) and a 24 mm circle at the
#   top (288 mm up). The blade goes through a 1.2 x 26 mm slot in each arm 22 mm up (pinned
#   outside); a 6 mm cord hole 285 mm up; a mortise for the stretcher at 170 mm up
#   (its tenon + 0.2 mm).
# - The arms' outer faces 512 mm apart (the blade's 5 mm pins are 517 mm apart and bear on
#   them), so 488 mm between the arms.
# - A stretcher 40 mm tall, 488 mm between the arms, with a 30 mm tenon at each end going
#   through the arm and 6 mm proud (18 mm long); "BUCK SAW 21 in" filled-engraved on it.
# - A toggle stick 150 mm long, 14 mm wide, round ends, a 5 mm hole in its middle for
#   the cord.

units mm
thickness 12 mm
import "std/joints.aidl"

t = 12 mm
between = 488 mm       # between the arms' inner faces
stretch_h = 170 mm     # the stretcher's middle, up the arm
tenon = 30 mm
tenon_l = 18 mm        # through the 12 mm arm and 6 mm proud

def arm() -> solid {
    # x across the arm (world y), y up the arm from its foot
    outline = Hull(Circle(center=(0, 15), diameter=30), Circle(center=(0, stretch_h), diameter=44),
                   Circle(center=(0, 288), diameter=24))
    hole blade { s = Rectangle(center=(0, 22), width=1.2, height=26) }
    hole cord { c = Circle(center=(0, 285), diameter=6) }
    mortise = tab_and_slot(part="slot", length=40, thickness=t, tabs=1, tab=tenon, screw=0,
                           clearance=0.2, rotation=90, cx=0, cy=stretch_h)
}

assembly buck_saw {
    left = arm()
    right = arm()

    solid stretcher {
        bar = Rectangle(center=(0, 0), width=between + 2 * tenon_l, height=40)
        end_l = tab_and_slot(part="tab", length=40, thickness=tenon_l, tabs=1, tab=tenon,
                             screw=0, rotation=90, cx=-(between / 2 + tenon_l), cy=0)
        end_r = tab_and_slot(part="tab", length=40, thickness=tenon_l, tabs=1, tab=tenon,
                             screw=0, rotation=-90, cx=between / 2 + tenon_l, cy=0)
        drawing label {
            word = Text("BUCK SAW 21 in", position=(0, 0), size=14, valign="middle",
                        font="sans:Bold", fill=true)
        }
    }

    solid toggle {
        stick = Slot(center=(0, 0), length=150, width=14)
        hole cord { c = Circle(center=(0, 0), diameter=5) }
    }

    # flat on the sheet: the stretcher and the toggle above the two arms lying down
    RightOf(right, left, gap=6)
    AlignBottom(right, left)
    Above(stretcher, left, gap=6)
    AlignLeft(stretcher, left)
    Above(toggle, stretcher, gap=6)
    AlignLeft(toggle, stretcher)

    # standing up: the arms' faces across x, the stretcher and toggle in the plane y = 0
    Place(left, position=(-between / 2, 0, 0), face="left", up="up")
    Place(right, position=(between / 2, 0, 0), face="right", up="up")
    Place(stretcher, position=(0, t / 2, stretch_h), face="front", up="up")
    Place(toggle, position=(0, t / 2, stretch_h + 40), face="front", up="up")

    # the request's numbers
    assert left.outline.bb.height == 300 mm, "arms 300 tall"
    assert between + 2 * t == 512 mm and 517 mm - 5 mm == 512 mm, "outer faces 512 apart"
    assert stretcher.bar.width - 2 * tenon_l == 488 mm, "488 between the arms"
    assert tenon_l - t == 6 mm, "6 mm proud"
    assert left.mortise.slot[0].bb.height == 30.2 mm and left.mortise.slot[0].bb.width ==
        12.2 mm, "mortise = tenon + 0.2"
    assert left.blade.s.center.y - left.outline.bb.bottom == 22 mm, "blade slot 22 up"
    assert left.cord.c.center.y - left.outline.bb.bottom == 285 mm, "cord hole 285 up"
    assert toggle.stick.length == 150 mm, "toggle 150"
}
