# Request (camping): a flat-pack dish-drying rack for the camp kitchen, 6 mm ply, 4 parts that
# slot together with cross halvings (no glue, no screws):
# - two long notched sides 360 x 90 mm: 9 plate notches 10 mm wide and 45 mm deep (round
#   bottoms) from the top edge, 35 mm apart, centred; a shallow arch 240 mm wide and 25 mm high
#   cut from the bottom edge to leave feet; a halving slot 30 mm deep up from the bottom edge
#   160 mm either side of the middle; "CAMP KITCHEN" engraved between the notches and the arch;
# - two end pieces 160 x 60 mm with halving slots 30 mm deep down from the top edge 60 mm either
#   side of the middle (the sides stand 120 mm apart) and a 70 x 20 mm carrying slot in the
#   middle.

units mm
thickness 6 mm
import "std/joints.aidl"

t = 6 mm
side_l = 360 mm
side_h = 90 mm
notches = 9
notch_w = 10 mm
notch_d = 45 mm
pitch = 35 mm
end_w = 160 mm
end_h = 60 mm
spread = 120 mm            # the sides' middles apart

def side(label="") -> solid {
    body = Rectangle(center=(0, side_h / 2), width=side_l, height=side_h)
    hole plates {
        for i in range(notches) {
            n = Slot(center=(-(notches - 1) / 2 * pitch + i * pitch, side_h - notch_d + (notch_d + 10 mm) / 2),
                     length=notch_d + 10 mm, width=notch_w, rotation=90 deg, overrun=true)
        }
    }
    hole arch { e = Ellipse(center=(0, 0), rx=120, ry=25) }
    lh = cross_halving(depth=end_h / 2, thickness=t, rotation=180 deg, cx=-160 mm, cy=0 mm)
    rh = cross_halving(depth=end_h / 2, thickness=t, rotation=180 deg, cx=160 mm, cy=0 mm)
    drawing name { w = Text(label, position=(0, 35), size=8, valign="middle") }
    Fixed(body)
}

def end_piece() -> solid {
    body = Rectangle(center=(0, end_h / 2), width=end_w, height=end_h)
    lh = cross_halving(depth=end_h / 2, thickness=t, cx=-spread / 2, cy=end_h)
    rh = cross_halving(depth=end_h / 2, thickness=t, cx=spread / 2, cy=end_h)
    hole handle { s = Slot(center=(0, end_h / 2), length=70, width=20) }
    Fixed(body)
}

assembly dish_rack {
    front = side(label="CAMP KITCHEN")
    back = side()
    left = end_piece()
    right = end_piece()
    Below(back, front, gap=10)
    AlignLeft(back, front)
    Below(left, back, gap=10)
    AlignLeft(left, back)
    RightOf(right, left, gap=10)
    AlignBottom(right, left)

    assert front.body.width == 360 mm and front.body.height == 90 mm, "sides 360 x 90"
    assert len(front.plates.n) == 9, "9 notches"
    assert front.body.bb.top - front.plates.n[0].bb.bottom == 45 mm, "notches 45 deep"
    assert front.plates.n[1].center.x - front.plates.n[0].center.x == 35 mm, "35 apart"
    assert front.arch.e.rx * 2 == 240 mm and front.arch.e.ry == 25 mm, "arch 240 x 25"
    assert left.body.width == 160 mm and left.body.height == 60 mm, "ends 160 x 60"
    assert front.lh.depth + left.lh.depth == left.body.height, "halvings add up to the end's height"
    assert left.rh.cut.bb.center_x - left.lh.cut.bb.center_x == 120 mm, "sides 120 apart"
    assert front.rh.cut.bb.center_x - front.lh.cut.bb.center_x == 320 mm, "ends 160 either side"
}
