# Request: "A rack for the office's six rubber stamps, 4 mm ply. The stamps hang by the neck
# under their knob in six notches along the front of a shelf: each notch a 10 mm wide
# entry from the front edge to a 14 mm round seat whose centre is 20 mm in, 35 mm apart;
# each stamp's name engraved (4 mm) 12 mm behind its seat: PAID, COPY, RECEIVED, URGENT,
# FILED, DRAFT. The shelf is 220 x 60 mm between the sides, its underside 70 mm above the
# desk, flush with the back, tabbed into the sides (two 15 mm tabs). Two sides 100 mm tall
# and 90 mm deep, the front sloping down to 60 mm, top corners r5, finger-jointed (15 mm
# fingers) to a 90 mm deep base the stamps stand over."

import "std/joints.aidl"

thickness 4 mm

t = 4 mm
inner = 220 mm        # between the sides
depth = 90 mm
shelf_d = 60 mm
shelf_z = 70 mm
side_h = 100 mm
front_h = 60 mm
pitch = 35 mm
names = ["PAID", "COPY", "RECEIVED", "URGENT", "FILED", "DRAFT"]

def side() -> solid {
    prof = Polygon([(-depth / 2, 0), (depth / 2, 0), (depth / 2, side_h), (0, side_h),
                    (-depth / 2, front_h)])
    feet = finger_edge(length=depth, thickness=t, finger=15 mm, start="gap", rotation=180 deg,
                       cx=0, cy=0)
    shelf_slots = tab_and_slot(part="slot", length=shelf_d, thickness=t, tabs=2, tab=15 mm,
                               screw=0, cx=depth / 2 - shelf_d / 2, cy=shelf_z + t / 2)
    Fillet([prof.points[2], prof.points[3], prof.points[4]], 5)
}

assembly rack {
    solid base {
        board = Rectangle(center=(0, 0), width=inner + 2 * t, height=depth)
        lf = finger_edge(length=depth, thickness=t, finger=15 mm, start="tab", rotation=90 deg,
                         cx=-inner / 2 - t, cy=0)
        rf = finger_edge(length=depth, thickness=t, finger=15 mm, start="tab", rotation=-90 deg,
                         cx=inner / 2 + t, cy=0)
    }
    solid shelf {
        board = Rectangle(center=(0, 0), width=inner + 2 * t, height=shelf_d)
        for i in range(6) {
            hole notch {
                entry = Rectangle(center=((i - 2.5) * pitch, -shelf_d / 2 + 10 mm - 0.5 mm),
                                  width=10, height=21)
                seat = Circle(center=((i - 2.5) * pitch, -shelf_d / 2 + 20 mm), diameter=14)
            }
        }
        drawing labels {
            for i in range(6) {
                n = Text(names[i], position=((i - 2.5) * pitch, -shelf_d / 2 + 32 mm), size=4,
                         valign="middle")
            }
        }
        lt = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=90 deg, cx=-inner / 2 - t, cy=0)
        rt = tab_and_slot(part="tab", length=shelf_d, thickness=t, tabs=2, tab=15 mm, screw=0,
                          rotation=-90 deg, cx=inner / 2 + t, cy=0)
    }
    left = side()
    right = side()

    # on the sheet
    Below(shelf, base, gap=5)
    AlignLeft(shelf, base)
    RightOf(left, base, gap=5)
    AlignTop(left, base)
    Below(right, left, gap=5)
    AlignLeft(right, left)

    # in 3D: x across, y front to back, z up
    Place(base, position=(0, 0, 0))
    Place(shelf, position=(0, depth / 2 - shelf_d / 2, shelf_z))
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-inner / 2 - t, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(inner / 2, 0, 0))

    assert len(shelf.notch) == 6, "six stamps"
    assert shelf.notch[1].seat.center.x - shelf.notch[0].seat.center.x == 35 mm, "35 mm apart"
    assert shelf.notch[0].seat.diameter == 14 mm and shelf.notch[0].entry.bb.width == 10 mm,
        "10 mm entry, 14 mm seat"
    assert shelf.notch[0].seat.center.y - shelf.board.bb.bottom == 20 mm, "seat 20 mm in"
    assert shelf.labels.n[0].position.y - shelf.notch[0].seat.center.y == 12 mm,
        "names 12 mm behind the seats"
    assert shelf.board.bb.width - 2 * t == 220 mm and shelf.board.bb.height == 60 mm,
        "220 x 60 between the sides"
    assert left.prof.bb.height == 100 mm and left.prof.bb.width == 90 mm, "sides 100 x 90"
    assert left.prof.points[4].y - left.prof.points[0].y == 60 mm, "front slopes to 60 mm"
    assert base.board.bb.height == 90 mm, "90 mm deep base"
}
