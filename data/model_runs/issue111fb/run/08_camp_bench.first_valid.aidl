# Request: a knock-down camp bench from 9 mm birch ply, no glue or screws. Seat 450 x 240 mm
# (R20 corners), 300 mm from the ground, with a 120 x 30 mm hand-hold slot in the middle,
# a mountain-range line and a sun (16 mm circle) engraved behind it and "BASECAMP"
# (18 mm bold, filled) engraved in front of it. Two legs 220 mm wide, 170 mm either side of
# the middle, each with two 50 mm tenons up through the seat (flush; mortises 0.2 mm
# over) and an arch of radius 70 at the bottom leaving two feet. A stretcher 60 mm high
# (bottom 80 mm off the ground) runs between the legs; its 40 mm high tusk tenons pass
# through the legs (mortises 0.5 mm over) and stand 45 mm out, each with a 20 x 9.5 mm wedge
# hole starting 1 mm inside the leg's outer face. Two wedges, 90 mm long, tapering 22 to 14
# mm, lock it.

import "std/joints.aidl"

thickness 9 mm
t = 9 mm

seat_w = 450 mm
seat_d = 240 mm
seat_z = 300 mm
leg_x = 170 mm
leg_w = 220 mm
str_z = 80 mm
str_h = 60 mm
ten_h = 40 mm
ten_out = 45 mm
inner = leg_x - t / 2      # the legs' inner faces
outer = leg_x + t / 2      # and outer faces

def leg() -> solid {
    body = Rectangle(bottom_left=(-leg_w / 2, 0), width=leg_w, height=seat_z)
    tenons = tab_and_slot(part="tab", length=leg_w, thickness=t, tabs=2, tab=50, screw=0,
                          cx=0, cy=seat_z)
    hole arch { a = Circle(center=(0, 0), radius=70) }
    hole through {
        m = Rectangle(center=(0, str_z + str_h / 2), width=t + 0.5, height=ten_h + 0.5)
    }
}

def wedge() -> solid {
    w = Trapezoid(center=(0, 0), bottom_width=22, top_width=14, height=90)
}

assembly bench {
    solid seat {
        board = RoundedRectangle(center=(0, 0), width=seat_w, height=seat_d, corner_radius=20)
        hole grip { s = Slot(center=(0, 0), length=120, width=30) }
        m_left = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=2, tab=50, screw=0,
                              clearance=0.2, rotation=90, cx=-leg_x, cy=0)
        m_right = tab_and_slot(part="slot", length=leg_w, thickness=t, tabs=2, tab=50, screw=0,
                               clearance=0.2, rotation=90, cx=leg_x, cy=0)
        drawing art {
            ridge = Polyline([(-90, 40), (-62, 72), (-44, 58), (-12, 92), (18, 60), (42, 76),
                              (66, 56), (90, 40)])
            sun = Circle(center=(70, 92), diameter=16)
            name = Text("BASECAMP", position=(0, -72), size=18, font="sans:Bold", fill=true,
                        valign="middle")
        }
    }

    leg_l = leg()
    leg_r = leg()

    solid stretcher {
        body = Polygon([(-inner, 0), (inner, 0), (inner, (str_h - ten_h) / 2),
                        (outer + ten_out, (str_h - ten_h) / 2),
                        (outer + ten_out, (str_h + ten_h) / 2), (inner, (str_h + ten_h) / 2),
                        (inner, str_h), (-inner, str_h), (-inner, (str_h + ten_h) / 2),
                        (-outer - ten_out, (str_h + ten_h) / 2),
                        (-outer - ten_out, (str_h - ten_h) / 2), (-inner, (str_h - ten_h) / 2)])
        hole wedge_holes {
            r = Rectangle(bottom_left=(outer - 1, str_h / 2 - 4.75), width=20, height=9.5)
            l = Rectangle(bottom_left=(-outer + 1 - 20, str_h / 2 - 4.75), width=20, height=9.5)
        }
    }

    w_left = wedge()
    w_right = wedge()

    # on the sheet
    Below(leg_l, seat, gap=8)
    AlignLeft(leg_l, seat)
    RightOf(leg_r, leg_l, gap=8)
    AlignTop(leg_r, leg_l)
    Below(stretcher, leg_l, gap=8)
    AlignLeft(stretcher, seat)
    RightOf(w_left, seat, gap=8)
    AlignTop(w_left, seat)
    RightOf(w_right, w_left, gap=8)
    AlignTop(w_right, w_left)

    # in 3D: z up from the ground
    Place(seat, position=(0, 0, seat_z - t), face="up")
    Place(leg_l, position=(-leg_x + t / 2, 0, 0), face="left", up="up")
    Place(leg_r, position=(leg_x + t / 2, 0, 0), face="left", up="up")
    Place(stretcher, position=(0, t / 2, str_z), face="front", up="up")
    Place(w_left, position=(-outer - 9.5, 0, str_z + str_h / 2 - t / 2), face="up")
    Place(w_right, position=(outer + 9.5, 0, str_z + str_h / 2 - t / 2), face="up")

    # the request's numbers
    assert seat.board.width == 450 mm and seat.board.height == 240 mm, "seat 450 x 240"
    assert leg_l.body.height == 300 mm, "seat top 300 off the ground (tenons flush)"
    assert leg_l.body.width == 220 mm, "legs 220 wide"
    assert seat.m_right.slot[0].bb.center_x - seat.board.center.x == 170 mm, "legs 170 out"
    assert seat.grip.s.length == 120 mm and seat.grip.s.width == 30 mm, "hand hold 120 x 30"
    assert leg_l.arch.a.radius == 70 mm, "arch R70"
    assert leg_l.through.m.bb.bottom + 0.25 mm - (str_z + (str_h - ten_h) / 2) == 0 mm,
        "the leg's mortise meets the tenon"
    assert stretcher.body.bb.width == 2 * (170 mm + 4.5 mm + 45 mm), "tenons 45 out"
    assert stretcher.wedge_holes.r.bb.left == outer - 1 mm, "wedge hole 1 inside the face"
    assert stretcher.wedge_holes.r.width == 20 mm and stretcher.wedge_holes.r.height == 9.5 mm,
        "wedge hole 20 x 9.5"
    assert w_left.w.bottom_width == 22 mm and w_left.w.top_width == 14 mm and w_left.w.height == 90 mm,
        "wedges 90 long, 22 to 14"
    assert w_left.w.top_width < 20 mm - 1 mm and w_left.w.bottom_width > 20 mm - 1 mm,
        "the wedge binds in its hole"
    assert stretcher.wedge_holes.r.bb.right < stretcher.body.bb.right - 10 mm,
        "wood beyond the wedge hole"
    assert distance(seat.art.name, seat.grip) >= 5 mm and distance(seat.art.ridge, seat.grip) >= 5 mm,
        "art clear of the hand hold"
    assert distance(seat.art.name, seat.m_left) >= 5 mm, "name clear of the mortises"
}
