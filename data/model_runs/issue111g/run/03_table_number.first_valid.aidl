# Table-number stand for a wedding or a cafe, 3 mm acrylic, two parts that cross-halve.
# Upright: 100 mm wide x 150 mm tall, top corners rounded R10, bottom corners sharp; the number
# "12" cut through in Noto Sans Bold, 60 mm high, centred left-right, its middle 80 mm above the
# bottom edge; "TABLE" engraved in single strokes 8 mm high, centred, its middle 130 mm above
# the bottom edge.
# Foot: 100 mm long x 40 mm tall, top corners R10, bottom corners sharp; it stands on its long
# edge across the upright.
# Joint: cross halving, 3 mm slots with 0.1 mm clearance: the upright slotted 20 mm up from the
# middle of its bottom edge, the foot 20 mm down from the middle of its top edge (20 + 20 = the
# foot's 40 mm height, so both stand on the table). Both parts side by side, 30 mm apart.
import "std/joints.aidl"
units mm
thickness 3 mm

assembly table_number {
    solid upright {
        body = RoundedRectangle(center=(0, 75), width=100, height=150,
                                corner_radii=[10, 10, 0, 0])
        Fixed(body)
        slot = cross_halving(depth=20 mm, thickness=3 mm, clearance=0.1 mm, rotation=180 deg,
                             cx=0 mm, cy=0 mm)
        hole number {
            t = Text("12", position=(0, 80), size=60, font="sans:Bold", valign="middle")
        }
        drawing label {
            t = Text("TABLE", position=(0, 130), size=8, valign="middle")
        }
    }
    solid foot {
        body = RoundedRectangle(center=(130, 20), width=100, height=40,
                                corner_radii=[10, 10, 0, 0])
        Fixed(body)
        slot = cross_halving(depth=20 mm, thickness=3 mm, clearance=0.1 mm, cx=130 mm, cy=40 mm)
    }

    # the request's numbers
    assert upright.body.width == 100 mm and upright.body.height == 150 mm, "upright size"
    assert foot.body.width == 100 mm and foot.body.height == 40 mm, "foot size"
    assert upright.slot.cut.bb.height == 20 mm and foot.slot.cut.bb.height == 20 mm, "slot depths"
    assert upright.slot.cut.bb.height + foot.slot.cut.bb.height == 40 mm, "depths add to 40"
    assert upright.slot.cut.bb.width == 3.1 mm, "3 mm + 0.1 mm clearance"
    assert upright.slot.cut.bb.bottom == upright.body.bb.bottom, "slot from the bottom edge"
    assert foot.slot.cut.bb.top == foot.body.bb.top, "slot from the top edge"
    assert upright.slot.cut.bb.center_x == upright.body.bb.center_x, "upright slot in the middle"
    assert foot.slot.cut.bb.center_x == foot.body.bb.center_x, "foot slot in the middle"
    assert abs(upright.number.bb.height - 60 mm) < 1 mm, "number 60 mm high"
    assert abs(upright.number.bb.center_x - upright.body.bb.center_x) < 0.01 mm, "number centred"
    assert abs(upright.number.bb.center_y - upright.body.bb.bottom - 80 mm) < 0.5 mm, "number 80 mm up"
    assert upright.label.t.position.y - upright.body.bb.bottom == 130 mm, "TABLE 130 mm up"
    assert foot.body.bb.left - upright.body.bb.right == 30 mm, "30 mm apart"
}
