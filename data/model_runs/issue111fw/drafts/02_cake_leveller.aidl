# REQUEST (kitchen): a wire cake leveller, 6 mm birch ply, three parts. A base board 360 x
# 90 mm with R8 corners and "CAKE LEVELLER" engraved filled (sans bold, 10 mm) in its
# middle. Two uprights 70 mm wide standing 100 mm above the base, top corners R10, each
# glued into the base on two 15 mm tenons (mortises through the base); their inner faces
# 300 mm apart, so a 28 cm cake fits between. Each upright has 11 wire notches, 2 mm wide
# slits 15 mm deep with round inner ends, at 10 to 60 mm above the base in 5 mm steps, all
# opening to the back edge so a cake wire hooks in level from behind; each notch has its
# height engraved beside it ("10" ... "60", 3.5 mm). Shown assembled.

units mm
import "std/joints.aidl"

t = 6 mm
thickness t

# an upright drawn with its tenons' tips on y = 0 (the base's underside), its shoulder on
# y = t (the base's top); back = 1: the notches open to +x, back = -1: to -x
def upright(back=1) -> solid {
    body = RoundedRectangle(bottom_left=(-35, 0), width=70, height=t + 100,
                            corner_radii=[10, 10, 0, 0])
    tenons = tab_and_slot(part="tab", length=70 mm, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=180 deg, cx=0 mm, cy=0 mm)
    hole notches {
        for i in range(11) {
            s = Slot(start=(back * 21, t + 10 + 5 * i), end=(back * 40, t + 10 + 5 * i), width=2)
        }
    }
    drawing heights {
        for i in range(11) {
            n = Text(str(10 + 5 * i), position=(back * 16, t + 10 + 5 * i), size=3.5,
                     anchor="end" if back == 1 else "start", valign="middle")
        }
    }
}

assembly leveller {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=360, height=90, corner_radius=8)
        left_mortise = tab_and_slot(part="slot", length=70 mm, thickness=t, tabs=2, tab=15 mm,
                                    screw=0, rotation=90 deg, cx=-153 mm, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=70 mm, thickness=t, tabs=2, tab=15 mm,
                                     screw=0, rotation=90 deg, cx=153 mm, cy=0 mm)
        drawing name {
            w = Text("CAKE LEVELLER", position=(0, 0), size=10, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    left = upright(back=1)
    right = upright(back=-1)
    Above(left, base, gap=10)
    AlignLeft(left, base)
    Above(right, base, gap=10)
    AlignRight(right, base)

    Place(base, position=(0, 0, 0))
    # inner faces at x = -150 and x = 150; each upright's top face looks into the cake
    Place(left, position=(-156, 0, 0), face="right", up="up")
    Place(right, position=(156, 0, 0), face="left", up="up")
}

# the request's numbers
assert leveller.base.board.width == 360 mm and leveller.base.board.height == 90 mm, "base 360 x 90"
assert leveller.left.body.width == 70 mm, "uprights 70 mm wide"
assert leveller.left.body.height - t == 100 mm, "uprights stand 100 mm above the base"
assert len(leveller.left.notches.s) == 11 and len(leveller.right.notches.s) == 11, "11 notches each"
assert leveller.left.notches.s[0].center.y - t == 10 mm, "lowest notch 10 mm above the base"
assert leveller.left.notches.s[10].center.y - t == 60 mm, "highest notch 60 mm above the base"
assert leveller.left.notches.s[0].bb.right - leveller.left.body.bb.right >= 0 mm, "notches open at the edge"
assert leveller.left.body.bb.right - leveller.left.notches.s[0].bb.left == 15 mm, "notches 15 mm deep"
assert leveller.left.notches.s[0].width == 2 mm, "notches 2 mm wide"
