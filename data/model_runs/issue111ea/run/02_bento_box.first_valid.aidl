# Request (kitchen): a bento lunch box in 3 mm ply, 180 x 110 x 60 mm outside with a
# lift-off lid (finger joints at least 12 mm, lid clearance 0.3 mm). Inside it two loose
# dividers 45 mm high, cross-halved (0.2 mm clearance in the slots): a long one down the
# middle, 1 mm shorter than the inside length, and a short one across it 70 mm from the
# inside of the left wall, 1 mm shorter than the inside width. That makes four
# compartments. The lid carries "BENTO" engraved filled (bold sans, 14 mm capitals) and a
# five-petal flower 24 mm across engraved filled to its left.

import "std/boxes.aidl"
import "std/joints.aidl"

thickness 3 mm

ply = 3 mm
box_l = 180 mm
box_w = 110 mm
box_h = 60 mm
div_h = 45 mm
cross_at = 70 mm
in_l = box_l - 2 * ply
in_w = box_w - 2 * ply
long_l = in_l - 1 mm
short_l = in_w - 1 mm
# where the short divider crosses, in the long divider's own x (centred on the box)
cross_x = -in_l / 2 + cross_at

assembly bento {
    box = lid_box(length=box_l, width=box_w, height=box_h, thickness=ply, finger=12 mm,
                  clearance=0.3 mm)

    solid long_div {
        body = Rectangle(center=(0, div_h / 2), width=long_l, height=div_h)
        slot = cross_halving(depth=div_h / 2, thickness=ply, clearance=0.2 mm, cx=cross_x,
                             cy=div_h)
    }
    solid short_div {
        body = Rectangle(center=(0, div_h / 2), width=short_l, height=div_h)
        slot = cross_halving(depth=div_h / 2, thickness=ply, clearance=0.2 mm,
                             rotation=180 deg, cx=0 mm, cy=0 mm)
    }

    drawing lid_art {
        word = Text("BENTO", position=(12, 0), size=14, font="sans:Bold", valign="middle",
                    fill=true)
        for k in range(5) {
            petal = Ellipse(center=(-40 + 6 * cos(90 deg + k * 72 deg),
                                    6 * sin(90 deg + k * 72 deg)),
                            rx=6, ry=3.5, rotation=90 deg + k * 72 deg, fill=true)
        }
    }
    CenterInside(lid_art, box.lid)
    CutInto(lid_art, box.lid)

    # flat: the dividers beside the box's parts
    RightOf(long_div, box, gap=10)
    AlignTop(long_div, box)
    Below(short_div, long_div, gap=10)
    AlignLeft(short_div, long_div)

    # 3D: both stand on the floor; the long one along x on the box's centre line, the
    # short one across it
    Place(long_div, position=(0, ply / 2, ply), face="front", up="up")
    Place(short_div, position=(cross_x - ply / 2, 0, ply), face="right", up="up")

    assert long_div.body.bb.width == 180 mm - 6 mm - 1 mm, "long divider 1 short of inside"
    assert short_div.body.bb.width == 110 mm - 6 mm - 1 mm, "short divider 1 short of inside"
    assert long_div.body.bb.height == 45 mm, "dividers 45 high"
    assert short_div.body.bb.height == 45 mm, "dividers 45 high"
    assert long_div.slot.cut.bb.height + short_div.slot.cut.bb.height == 45 mm, "halvings meet"
    assert long_div.slot.cut.bb.width == 3.2 mm, "0.2 clearance in the slot"
    assert cross_x - (-in_l / 2) == 70 mm, "crossing 70 from the left wall"
    assert lid_art.word.size == 14 mm, "14 mm capitals"
    assert len(lid_art.petal) == 5, "five petals"
    assert distance(lid_art.word, lid_art.petal[4]) >= 3 mm, "flower clear of the word"
}
