# Request (pets): a breeder box that hangs inside an aquarium to keep guppy fry safe, in
# 3 mm clear acrylic. An open-top finger-jointed box 150 long x 100 deep x 100 tall
# outside, 10 mm fingers. Water flows through 2 mm slots: two rows of thirteen 25 mm slots
# (10 mm pitch) in the bottom, and a row of thirteen 30 mm slots in the front and in the
# back, their bottoms 15 mm above the box's bottom edge. GUPPY FRY engraved filled in bold
# sans, 10 mm capitals, centred on the front 20 mm below its top. Two hanging clips hook
# over the tank's glass (up to 6 mm thick, 2 mm play): each clip is glued into the back
# wall by one 20 mm tenon through a mortise, the mortises 50 mm either side of the middle,
# 25 mm below the rim; the clip's inner leg is 8 mm wide, it rises 15 mm above the rim
# and its outer leg comes 30 mm down outside the glass. Three kinds of part, seven parts.

import "std/joints.aidl"

thickness 3 mm

glass = 6 mm
play = 2 mm

# a clip seen from the side: x out from the back wall's outer face (0) toward the glass,
# y up from the box's bottom edge (the rim at 100); its tenon's tip 3 mm inside the wall
def clip() -> solid {
    gap_in = 8 mm
    gap_out = gap_in + glass + play
    body = Polygon([(-3, 50), (gap_in, 50), (gap_in, 107), (gap_out, 107), (gap_out, 85),
                    (gap_out + 8, 85), (gap_out + 8, 115), (0, 115), (0, 100), (-3, 100)])
    tenon = tab_and_slot(part="tab", length=50 mm, thickness=3 mm, tabs=1, tab=20 mm,
                         screw=0, rotation=90 deg, cx=-3 mm, cy=75 mm)
}

assembly breeder {
    box = finger_box(length=150 mm, depth=100 mm, height=100 mm, thickness=3 mm,
                     finger=10 mm, closed=false)

    hole bottom_vents {
        for r in range(2) {
            for i in range(13) {
                s = Slot(center=(i * 10 - 60, r * 36 - 18), length=25, width=2, rotation=90)
            }
        }
    }
    CenterInside(bottom_vents, box.bottom)
    CutInto(bottom_vents, box.bottom)

    hole front_vents {
        for i in range(13) {
            s = Slot(center=(i * 10 - 60, 0), length=30, width=2, rotation=90)
        }
    }
    AlignCenterX(front_vents, box.front)
    front_vents.bb.bottom == box.front.bb.bottom + 15 mm
    CutInto(front_vents, box.front)

    hole back_vents {
        for i in range(13) {
            s = Slot(center=(i * 10 - 60, 0), length=30, width=2, rotation=90)
        }
    }
    AlignCenterX(back_vents, box.back)
    back_vents.bb.bottom == box.back.bb.bottom + 15 mm
    CutInto(back_vents, box.back)

    hole mortises {
        left = Rectangle(center=(-50, 0), width=3, height=20)
        right = Rectangle(center=(50, 0), width=3, height=20)
    }
    AlignCenterX(mortises, box.back)
    box.back.bb.top - mortises.left.center.y == 25 mm
    CutInto(mortises, box.back)

    drawing label {
        t = Text("GUPPY FRY", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                 fill=true)
    }
    AlignCenterX(label, box.front)
    box.front.bb.top - label.t.position.y == 20 mm
    CutInto(label, box.front)

    left_clip = clip()
    right_clip = clip()
    RightOf(left_clip, box, gap=10)
    AlignTop(left_clip, box)
    RightOf(right_clip, left_clip, gap=5)
    AlignTop(right_clip, left_clip)
    Place(left_clip, position=(-51.5, 50, 0), face="right", up="up")
    Place(right_clip, position=(48.5, 50, 0), face="right", up="up")

    assert box.front.bb.width == 150 mm, "150 long"
    assert box.left.bb.height == 100 mm, "100 deep"
    assert box.front.bb.height == 100 mm, "100 tall"
    assert len(bottom_vents.s) == 2 and len(bottom_vents.s[0]) == 13, "2 rows of 13 slots"
    assert bottom_vents.s[0][1].center.x - bottom_vents.s[0][0].center.x == 10 mm, "10 pitch"
    assert bottom_vents.s[0][0].width == 2 mm and bottom_vents.s[0][0].length == 25 mm,
        "2 x 25 slots"
    assert front_vents.s[0].length == 30 mm, "30 mm wall slots"
    assert mortises.right.center.x - mortises.left.center.x == 2 * 50 mm, "clips 50 either side"
    assert left_clip.body.points[3].x - left_clip.body.points[2].x == 6 mm + 2 mm,
        "glass 6 + 2 play"
    assert left_clip.body.points[6].y - 100 mm == 15 mm, "clip rises 15 above the rim"
    assert left_clip.body.points[6].y - left_clip.body.points[4].y == 30 mm, "outer leg 30"
}
