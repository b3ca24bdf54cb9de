# Request: a raised cat bed ("cat cot") in 9 mm birch ply. A 420 x 420 mm top with 30 mm
# rounded corners and a 300 mm round opening; a round fabric sling is laced under it through
# 16 holes of 5 mm on a 168 mm radius (the first 11.25 degrees off the x axis, so none meets
# the legs or the name). The cat's name "MISO" engraved filled, 20 mm bold, centred 185 mm in
# front of the middle. Two 500 mm legs along the diagonals, crossing under the middle in a
# cross halving (0.2 mm clearance), 200 mm from the floor to the top's underside, each with a
# 40 mm high, 420 mm wide foot notch (20 mm rounded) so it stands on its ends; each leg has
# two 40 mm tenons, centred 200 mm from the middle, through mortises in the top (0.1 mm over).

import "std/joints.aidl"

thickness 9 mm

t = 9 mm
top_w = 420 mm
opening = 300 mm
leg_len = 500 mm
leg_h = 200 mm
notch_h = 40 mm
notch_w = 420 mm
tenon_at = 200 mm         # tenon centres from the middle
halving = 100 mm          # where the two halvings meet, above the floor

def leg(from_top=true) -> solid {
    body = Rectangle(bottom_left=(-leg_len / 2, 0), width=leg_len, height=leg_h)
    pad_l = Rectangle(center=(-tenon_at, leg_h + t / 2), width=100, height=t)
    pad_r = Rectangle(center=(tenon_at, leg_h + t / 2), width=100, height=t)
    ten_l = tab_and_slot(part="tab", length=100, thickness=t, tabs=1, tab=40 mm, screw=0,
                         cx=-tenon_at, cy=leg_h + t)
    ten_r = tab_and_slot(part="tab", length=100, thickness=t, tabs=1, tab=40 mm, screw=0,
                         cx=tenon_at, cy=leg_h + t)
    hole feet {
        n = RoundedRectangle(center=(0, notch_h / 2), width=notch_w, height=notch_h,
                             corner_radii=[20, 20, 0, 0])
    }
    if from_top {
        x = cross_halving(depth=leg_h - halving, thickness=t, clearance=0.2 mm, cx=0, cy=leg_h)
    } else {
        x = cross_halving(depth=halving - notch_h, thickness=t, clearance=0.2 mm,
                          rotation=180 deg, cx=0, cy=notch_h)
    }
}

assembly cot {
    solid top {
        plate = RoundedRectangle(center=(0, 0), width=top_w, height=top_w, corner_radius=30)
        hole bed { c = Circle(center=(0, 0), diameter=opening) }
        hole lace { c = Circle(center=(168 * cos(11.25 deg), 168 * sin(11.25 deg)), diameter=5) }
        laces = CircularPattern(lace, 16, plate.center)
        for k in range(4) {
            m = tab_and_slot(part="slot", length=100, thickness=t, tabs=1, tab=40 mm, screw=0,
                             clearance=0.1 mm, rotation=45 deg + k * 90 deg,
                             cx=tenon_at * cos(45 deg + k * 90 deg),
                             cy=tenon_at * sin(45 deg + k * 90 deg))
        }
        drawing name {
            word = Text("MISO", position=(0, -185), size=20, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }
    leg_a = leg(from_top=true)
    leg_b = leg(from_top=false)

    # flat on the sheet
    RightOf(leg_a, top, gap=10)
    Above(leg_b, leg_a, gap=10)
    AlignBottom(leg_a, top)

    # in 3D: legs along the diagonals, each centred on its own plane
    Place(leg_a, position=(-t / 2 * cos(45 deg), t / 2 * sin(45 deg), 0),
          rotation=(90 deg, 0, 45 deg))
    Place(leg_b, position=(-t / 2 * cos(45 deg), -t / 2 * sin(45 deg), 0),
          rotation=(90 deg, 0, 135 deg))
    Place(top, position=(0, 0, leg_h))

    assert top.plate.bb.width == 420 mm and top.plate.bb.height == 420 mm, "top 420 x 420"
    assert top.bed.c.diameter == 300 mm, "300 mm opening"
    assert len(top.laces) == 16, "16 lacing holes"
    assert distance(top.lace.c.center, top.plate.center) == 168 mm, "lacing on a 168 mm radius"
    assert leg_a.body.bb.width == 500 mm, "legs 500 mm long"
    assert leg_a.body.bb.height == 200 mm, "200 mm to the top's underside"
    assert leg_a.x.depth + leg_b.x.depth == leg_h - notch_h, "the halvings meet"
}
