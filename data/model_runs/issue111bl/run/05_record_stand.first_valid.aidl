# Request (music): a "Now Playing" stand for a 12-inch LP sleeve (315 x 315 mm, up to 5 mm thick),
# 6 mm ply. A front rail 300 x 50 mm (top corners r6) with NOW PLAYING cut through in bold sans
# stencil letters 22 mm tall (at most 240 mm wide), so the sleeve's art shows through. Two feet,
# 140 mm either side of the centre, each 100 mm deep, 50 mm tall at the front sloping to 12 mm at
# the back (top corners r4), with a 6 mm wide slot that holds the sleeve's bottom edge 8 mm above
# the table, 40 mm behind the foot's front, leaning back 15 degrees from vertical. The rail and
# feet cross-halve (rail slotted 25 mm down from its top, feet 25 mm up from their bottom, 12 mm
# behind their front; 0.2 mm clearance).

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
rail_w = 300 mm
rail_h = 50 mm
foot_x = 140 mm
foot_d = 100 mm
front_h = 50 mm
back_h = 12 mm
sleeve_slot = 6 mm
seat_x = 40 mm
seat_y = 8 mm
lean = 15 deg
slot_len = 50 mm
halving_x = 12 mm

solid foot() {
    body = Polygon([(0, 0), (foot_d, 0), (foot_d, back_h), (0, front_h)])
    Fillet([body.points[2], body.points[3]], 4)
    hole sleeve {
        s = Rectangle(center=(seat_x + slot_len / 2 * sin(lean), seat_y + slot_len / 2 * cos(lean)),
                      width=sleeve_slot, height=slot_len, rotation=-lean)
    }
    h = cross_halving(depth=rail_h / 2, thickness=t, clearance=0.2, rotation=180, cx=halving_x,
                      cy=0)
}

solid rail() {
    body = RoundedRectangle(center=(0, 0), width=rail_w, height=rail_h, corner_radii=[6, 6, 0, 0])
    hole letters {
        word = Text("NOW PLAYING", position=(0, 0), size=22, font="sans:Bold", stencil=true,
                    valign="middle", max_width=240)
    }
    left = cross_halving(depth=rail_h / 2, thickness=t, clearance=0.2, cx=-foot_x, cy=rail_h / 2)
    right = cross_halving(depth=rail_h / 2, thickness=t, clearance=0.2, cx=foot_x, cy=rail_h / 2)
}

assembly stand {
    front = rail()
    foot_l = foot()
    foot_r = foot()

    Above(foot_l, front, gap=5)
    AlignLeft(foot_l, front)
    RightOf(foot_r, foot_l, gap=5)
    AlignBottom(foot_r, foot_l)

    # assembled: the rail across the front, the feet running back from it
    Place(front, rotation=(90 deg, 0, 0), position=(0, t / 2, rail_h / 2))
    Place(foot_l, rotation=(90 deg, 0, 90 deg), position=(-foot_x - t / 2, -halving_x, 0))
    Place(foot_r, rotation=(90 deg, 0, 90 deg), position=(foot_x - t / 2, -halving_x, 0))

    # the request's numbers
    assert front.body.bb.width == 300 mm and front.body.bb.height == 50 mm, "rail size"
    assert front.letters.bb.width <= 240 mm, "letters at most 240 wide"
    assert front.right.cut.bb.center_x - front.body.bb.center_x == 140 mm, "feet 140 out"
    assert foot_l.body.bb.width == 100 mm, "feet 100 deep"
    assert foot_l.body.points[3].y - foot_l.body.points[0].y == 50 mm, "50 tall at the front"
    assert foot_l.body.points[2].y - foot_l.body.points[1].y == 12 mm, "12 at the back"
    assert foot_l.sleeve.s.width == 6 mm, "6 mm slot"
    assert abs(foot_l.sleeve.s.bb.bottom + 6 mm / 2 * sin(15 deg) - foot_l.body.bb.bottom - 8 mm) < 0.001 mm,
        "sleeve edge 8 above the table"
    assert foot_l.h.cut.bb.center_x - foot_l.body.bb.left == 12 mm, "halving 12 behind the front"
    assert front.body.bb.top - front.left.cut.bb.bottom == 25 mm, "rail slot 25 deep"
    assert foot_l.h.cut.bb.top - foot_l.body.bb.bottom == 25 mm, "foot slot 25 deep"
}
