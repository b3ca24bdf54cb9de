# Request: a cachepot (plant pot cover) for a 12 cm herb pot on the kitchen windowsill, 3 mm
# birch ply: outside 150 x 150 x 140 mm tall, open top, finger-jointed (10 mm fingers).
# On all four walls a band of 17 diamond windows (16 mm across the corners) in three staggered
# rows of 6, 5 and 6, 20 mm apart along a row and 14 mm from row to row, centred across the
# wall, the band's top tips 20 mm below the rim. On the front "BASIL" engraved filled, bold
# sans, 20 mm high, centred, its baseline 35 mm above the bottom edge.

import "std/joints.aidl"

thickness 3 mm

param plant = "BASIL"

# the window band, its top row's tips at y = 8, drawn for a wall whose "up" is turned by `turn`
def band(turn=0 deg) -> hole {
    for r in range(3) {
        for c in range(6 - r % 2) {
            u = (c - (5 - r % 2) / 2) * 20 mm
            v = -r * 14 mm
            d = RegularPolygon(center=(u * cos(turn) - v * sin(turn), u * sin(turn) + v * cos(turn)),
                               radius=8 mm, sides=4)
        }
    }
}

assembly cachepot {
    box = finger_box(length=150 mm, depth=150 mm, height=140 mm, thickness=3 mm, finger=10 mm,
                     closed=false, outside=true)

    front_band = band(turn=0 deg)
    back_band = band(turn=0 deg)
    left_band = band(turn=90 deg)
    right_band = band(turn=-90 deg)
    CutInto(front_band, box.front)
    CutInto(back_band, box.back)
    CutInto(left_band, box.left)
    CutInto(right_band, box.right)
    # centred across each wall, 20 mm below the rim (the front's and back's top edge is +y,
    # the left's -x, the right's +x)
    AlignCenterX(front_band, box.front)
    front_band.bb.top == box.front.bb.top - 20 mm
    AlignCenterX(back_band, box.back)
    back_band.bb.top == box.back.bb.top - 20 mm
    AlignCenterY(left_band, box.left)
    left_band.bb.left == box.left.bb.left + 20 mm
    AlignCenterY(right_band, box.right)
    right_band.bb.right == box.right.bb.right - 20 mm

    drawing name {
        w = Text(plant, position=(0, 0), size=20 mm, font="sans:Bold", fill=true)
    }
    CutInto(name, box.front)
    AlignCenterX(name.w.position, box.front)
    name.w.position.y == box.front.bb.bottom + 35 mm

    assert box.front.bb.width == 150 mm and box.front.bb.height == 140 mm, "150 wide, 140 tall"
    assert len(front_band.d[0]) + len(front_band.d[1]) + len(front_band.d[2]) == 17, "17 windows"
    assert len(front_band.d[0]) == 6 and len(front_band.d[1]) == 5, "rows of 6, 5, 6"
    assert front_band.d[0][0].bb.width == 16 mm, "16 mm across the corners"
    assert front_band.d[0][1].center.x - front_band.d[0][0].center.x == 20 mm, "20 apart"
    assert front_band.d[0][0].center.y - front_band.d[1][0].center.y == 14 mm, "14 row to row"
    assert box.front.bb.top - front_band.bb.top == 20 mm, "20 below the rim"
    assert box.left.bb.right - left_band.bb.right == box.left.bb.right - box.left.bb.left - 20 mm - 44 mm,
        "side band 20 below its rim"
    assert name.w.size == 20 mm, "20 mm letters"
    assert name.w.position.y - box.front.bb.bottom == 35 mm, "baseline 35 up"
}
