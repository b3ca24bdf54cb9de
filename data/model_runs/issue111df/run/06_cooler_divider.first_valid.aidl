# Request (camping): a slot-together divider for a camping cool box whose inside is 400 x 260
# mm, 5 mm acrylic. Two panels 200 mm tall, each 2 mm short of the box wall at both ends
# (396 and 256 long), cross-halved 100 + 100: the long panel slotted from the top 150 mm from
# its left end (a drinks side and a food side), the short panel from the bottom at its
# middle. Bottom corners chamfered 15 mm (the box's inside corners are rounded). Each
# compartment gets a 90 x 25 hand slot 30 mm below the top and a 24 mm half-round drain
# notch in the bottom edge. "DRINKS" and "FOOD" engraved filled 20 mm tall on the long
# panel, centred in their sides; "ICE" on the short panel. Two parts.

import "std/joints.aidl"

units mm
thickness 5 mm

t = 5 mm
box_l = 400 mm
box_w = 260 mm
h = 200 mm
long_l = box_l - 4 mm
short_l = box_w - 4 mm
split = 150 mm
hand_y = h - 30 mm

assembly divider {
    solid long_panel {
        body = Rectangle(bottom_left=(-long_l / 2, 0), width=long_l, height=h)
        Chamfer(body.bottom_left, 15)
        Chamfer(body.bottom_right, 15)
        halving = cross_halving(depth=h / 2, thickness=t, clearance=0.2,
                                cx=-long_l / 2 + split, cy=h)
        left_mid = (-long_l / 2 + (-long_l / 2 + split)) / 2
        right_mid = ((-long_l / 2 + split) + long_l / 2) / 2
        hole hands {
            a = Slot(center=(left_mid, hand_y), length=90, width=25)
            b = Slot(center=(right_mid, hand_y), length=90, width=25)
        }
        hole drains {
            a = Circle(center=(left_mid, 0), diameter=24)
            b = Circle(center=(right_mid, 0), diameter=24)
        }
        drawing words {
            drinks = Text("DRINKS", (left_mid, h / 2), size=20, font="sans:Bold", fill=true,
                          valign="middle", max_width=130)
            food = Text("FOOD", (right_mid, h / 2), size=20, font="sans:Bold", fill=true,
                        valign="middle")
        }
    }

    solid short_panel {
        body = Rectangle(bottom_left=(-short_l / 2, 0), width=short_l, height=h)
        Chamfer(body.bottom_left, 15)
        Chamfer(body.bottom_right, 15)
        halving = cross_halving(depth=h / 2, thickness=t, clearance=0.2, rotation=180 deg,
                                cx=0, cy=0)
        hole hands {
            a = Slot(center=(-short_l / 4, hand_y), length=90, width=25)
            b = Slot(center=(short_l / 4, hand_y), length=90, width=25)
        }
        hole drains {
            a = Circle(center=(-short_l / 4, 0), diameter=24)
            b = Circle(center=(short_l / 4, 0), diameter=24)
        }
        drawing word {
            ice = Text("ICE", (0, 130), size=20, font="sans:Bold", fill=true, valign="middle")
        }
    }

    Place(long_panel, position=(0, t / 2, 0), face="front", up="up")
    Place(short_panel, position=(-long_l / 2 + split - t / 2, 0, 0), face="right", up="up")
    Below(short_panel, long_panel, gap=5)

    assert long_panel.body.bb.width == 396 mm and short_panel.body.bb.width == 256 mm,
        "2 mm short of the walls at each end"
    assert long_panel.body.bb.height == 200 mm, "200 tall"
    assert long_panel.halving.depth + short_panel.halving.depth == 200 mm, "halving 100 + 100"
    assert long_panel.halving.cut.bb.center_x - long_panel.body.bb.left == 150 mm,
        "slot 150 mm from the left end"
    assert long_panel.body.bb.top - long_panel.hands.a.center.y == 30 mm, "hand slots 30 below the top"
}
