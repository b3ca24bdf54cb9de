# Request (kitchen): "A taco holder for taco night, 4 mm birch ply: it holds three hard-shell
# tacos upright side by side. A base 240 x 110 mm with 8 mm rounded corners, and two wavy
# uprights 220 mm long standing 60 mm above the base, 60 mm apart centre to centre. Each
# upright has three U-shaped valleys 55 mm wide and 40 mm deep, 70 mm apart, the peaks' top
# corners rounded 3 mm. The uprights are glued in with three 20 mm tabs each into mortises
# (0.1 mm play). 'TACO TUESDAY' engraved filled, bold, 7 mm high, centred in the strip in
# front of the front upright."

import "std/joints.aidl"

thickness 4 mm

def upright() -> solid {
    # y = 0 is the base's top face; the tabs' tips reach the base's underside at y = -4
    body = Rectangle(bottom_left=(-110, -4), width=220, height=64)
    hole valleys {
        for i in range(3) {
            v = Slot(start=(-70 + 70 * i, 47.5), end=(-70 + 70 * i, 90), width=55)
        }
    }
    j = tab_and_slot(part="tab", length=220 mm, thickness=4 mm, tabs=3, tab=20 mm, screw=0,
                     rotation=180 deg, cx=0 mm, cy=-4 mm)
    Fillet([[body.top, valleys.v[0]], [body.top, valleys.v[1]], [body.top, valleys.v[2]],
            body.top_left, body.top_right], 3)
}

assembly taco_holder {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=240, height=110, corner_radius=8)
        front_slots = tab_and_slot(part="slot", length=220 mm, thickness=4 mm, tabs=3,
                                   tab=20 mm, screw=0, clearance=0.1 mm, cx=0 mm, cy=-30 mm)
        back_slots = tab_and_slot(part="slot", length=220 mm, thickness=4 mm, tabs=3,
                                  tab=20 mm, screw=0, clearance=0.1 mm, cx=0 mm, cy=30 mm)
        drawing label {
            t = Text("TACO TUESDAY", position=(0, -44), size=7, font="sans:Bold",
                     valign="middle", fill=true)
        }
        # centred in the strip between the plate's front edge and the front mortises
        label.t.position.y == (plate.bb.bottom + front_slots.slot[0].bb.bottom) / 2
        AlignCenterX(label.t.position, plate)
    }
    front_up = upright()
    back_up = upright()

    # laid out flat above the base
    Above(front_up, base, gap=6)
    Above(back_up, front_up, gap=6)
    AlignCenterX(front_up, base)
    AlignCenterX(back_up, base)

    # assembled: base on z = 0, each upright stood up on its row of mortises
    Place(base, position=(0, 0, 0))
    Place(front_up, position=(0, -28, 4), rotation=(90 deg, 0, 0))
    Place(back_up, position=(0, 32, 4), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert base.plate.bb.width == 240 mm and base.plate.bb.height == 110 mm, "base 240 x 110"
    assert front_up.body.bb.width == 220 mm, "uprights 220 long"
    assert front_up.body.bb.top - front_up.body.bb.bottom - 4 mm == 60 mm, "60 mm above the base"
    assert back_up.valleys.v[1].start.x - back_up.valleys.v[0].start.x == 70 mm, "valleys 70 apart"
    assert front_up.valleys.v[0].width == 55 mm, "valleys 55 wide"
    assert (front_up.body.bb.top - (front_up.valleys.v[2].start.y - front_up.valleys.v[2].radius)
            == 40 mm), "valleys 40 deep"
    assert len(front_up.valleys.v) == 3, "three tacos"
    assert len(base.front_slots.slot) == 3 and len(base.back_slots.slot) == 3, "three tabs each"
    assert base.back_slots.slot[0].bb.center_y - base.front_slots.slot[0].bb.center_y == 60 mm,
        "uprights 60 apart"
    assert abs(base.label.t.position.y - (base.plate.bb.bottom + base.front_slots.slot[0].bb.bottom) / 2) < 0.01 mm,
        "label centred in the front strip"
}
