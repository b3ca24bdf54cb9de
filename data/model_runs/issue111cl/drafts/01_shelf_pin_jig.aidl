# Request: a shelf-pin drilling jig for 5 mm shelf pins on the 32 mm cabinet system, cut from
# 6 mm birch ply. The drilling strip is 600 mm long and 60 mm wide, but my laser bed is only
# 400 x 300 mm, so it is cut as two halves (300 mm each along the strip) locked edge to edge
# by a flat sliding dovetail (2 tails, 10 mm deep, over the full 60 mm width). A column of
# 18 guide holes, 5.2 mm diameter, 32 mm apart, the first one 32 mm from the strip's left end
# (which sits against the cabinet floor). Under the strip's front edge a 20 mm deep fence
# (two 280 mm pieces, one per half) is glued into mortises: 3 tabs of 30 mm per fence. The
# holes sit 37 mm from the fence's inner face (the standard 32 mm system setback). Each
# hole's number is engraved beside it, and the left half carries the title "32 mm SYSTEM".

import "std/joints.aidl"

units mm
thickness 6 mm

param ply = 6 mm, min = 3 mm, max = 9 mm
param pitch = 32 mm, min = 25 mm, max = 40 mm
param setback = 37 mm, min = 30 mm, max = 45 mm
param pin_d = 5.2 mm, min = 3 mm, max = 8.5 mm

strip_w = 60 mm
half_len = 300 mm
fence_len = 280 mm
fence_depth = 20 mm
tail_depth = 10 mm
holes_per_half = 9

# FIX after the first valid program: W0530 said the mortises ran out through the front edge
# (notches, not mortises); a 3 mm lip of ply now stands in front of them.
front_lip = 3 mm
# the fence's inner face: the fence is ply thick, its slots start behind the front lip
fence_face_y = front_lip + ply

def fence_piece() -> solid {
    # fence depth below the strip plus the tabs that go through it
    body = Rectangle(bottom_left=(0, 0), width=fence_len, height=fence_depth + ply)
    tabs = tab_and_slot(part="tab", length=fence_len, thickness=ply, tabs=3, tab=30 mm,
                        screw=0, cx=fence_len / 2, cy=fence_depth + ply)
}

assembly jig {
    solid left_half {
        # reaches across the dovetail band: the tails stand in x = 300 .. 310
        body = Rectangle(bottom_left=(0, 0), width=half_len + tail_depth, height=strip_w)
        tails = dovetail(part="tail", length=strip_w, depth=tail_depth, tails=2, angle=10 deg,
                         rotation=-90 deg, cx=half_len, cy=strip_w / 2)
        mortise = tab_and_slot(part="slot", length=fence_len, thickness=ply, tabs=3, tab=30 mm,
                               screw=0, clearance=0.1 mm, cx=half_len / 2, cy=front_lip + ply / 2)
        hole guide {
            for i in range(holes_per_half) {
                c = Circle(center=(pitch * (i + 1), fence_face_y + setback), diameter=pin_d)
            }
        }
        drawing numbers {
            for i in range(holes_per_half) {
                n = Text(str(i + 1), position=(pitch * (i + 1), fence_face_y + setback + 9),
                         size=5, valign="middle")
            }
        }
        drawing title {
            t = Text("32 mm SYSTEM", position=(half_len / 2, 26), size=8, valign="middle")
        }
    }

    solid right_half {
        body = Rectangle(bottom_left=(half_len, 0), width=half_len, height=strip_w)
        sockets = dovetail(part="socket", length=strip_w, depth=tail_depth, tails=2,
                           angle=10 deg, clearance=0.1 mm, rotation=-90 deg,
                           cx=half_len, cy=strip_w / 2)
        mortise = tab_and_slot(part="slot", length=fence_len, thickness=ply, tabs=3, tab=30 mm,
                               screw=0, clearance=0.1 mm, cx=half_len + 15 mm + fence_len / 2,
                               cy=front_lip + ply / 2)
        hole guide {
            for i in range(holes_per_half) {
                c = Circle(center=(pitch * (i + 1 + holes_per_half), fence_face_y + setback),
                           diameter=pin_d)
            }
        }
        drawing numbers {
            for i in range(holes_per_half) {
                n = Text(str(i + 1 + holes_per_half),
                         position=(pitch * (i + 1 + holes_per_half), fence_face_y + setback + 9),
                         size=5, valign="middle")
            }
        }
    }

    left_fence = fence_piece()
    right_fence = fence_piece()

    # on the sheet the fences lie below their halves, centred on their mortises
    Below(left_fence, left_half, gap=10)
    Below(right_fence, right_half, gap=10)
    AlignCenterX(left_fence, left_half.mortise)
    AlignCenterX(right_fence, right_half.mortise)

    # the request's numbers
    assert len(left_half.guide.c) + len(right_half.guide.c) == 18, "18 guide holes"
    assert left_half.guide.c[0].center.x - left_half.body.bb.left == 32 mm, "first hole 32 mm from the end"
    assert left_half.guide.c[1].center.x - left_half.guide.c[0].center.x == 32 mm, "32 mm pitch"
    assert right_half.guide.c[0].center.x - left_half.guide.c[8].center.x == 32 mm, "pitch across the joint"
    assert left_half.guide.c[0].center.y - (left_half.body.bb.bottom + front_lip + ply) == 37 mm, "37 mm setback from the fence face"
    assert right_half.body.bb.right - left_half.body.bb.left == 600 mm, "600 mm strip"
    assert left_half.body.bb.height == 60 mm and right_half.body.bb.height == 60 mm, "60 mm wide"
    assert left_fence.body.bb.width == 280 mm, "280 mm fence"
    assert left_fence.body.bb.height - ply == 20 mm, "20 mm fence depth"
    assert left_half.bb.width <= 400 mm and right_half.bb.width <= 400 mm, "fits the 400 x 300 bed"
}
