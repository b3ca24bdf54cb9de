# Request (pets): "A tall enclosure for our Indian stick insects, 250 wide x 200 deep x 400 mm tall
# outside, in 6 mm ply with a 3 mm clear acrylic front. Two sides stand on 20 mm feet; the base
# (its underside 20 mm up) and the back (set 6 mm in from the sides' back edges) are glued into
# the sides with tabs and mortises, the base's back edge into the back, and the sides' and back's
# top edges into a top panel that overhangs 6 mm at the sides and the back. The acrylic front
# lifts out upward: it drops through a 237 x 3.4 mm slot in the top, 10 mm behind the front edge,
# rests on the base, and a 200 mm tongue at its foot sits in a 201 x 3.4 mm slot in the base. A
# handle 80 x 30 mm stands above the top with a 40 x 14 mm finger slot. Ventilation (fly mesh is
# glued behind): in each side two rows of eight 4 x 50 mm slots at 20 mm pitch, one row low
# (centred 80 mm up) and one high (300 mm up), and a 150 x 100 mm R10 opening in the top. The
# species name engraved on the top in front of the opening."

import "std/joints.aidl"

thickness 6 mm
t = 6 mm        # ply
a = 3 mm        # acrylic
fit = 0.1 mm    # glue-joint clearance in mortises
W = 250 mm
D = 200 mm
H = 400 mm
feet = 20 mm
z_base = feet                 # the base's underside
back_y = D - t                # the back's outer face (6 mm in from the sides' back edge)
inner = W - 2 * t             # 238 between the sides
glass_y = 10 mm               # the acrylic's middle, behind the front edge
over = 6 mm                   # the top's overhang

def side() -> solid {
    # drawn as seen from the right: x = depth from the front, y = height from the floor
    board = Rectangle(bottom_left=(0, 0), width=D, height=H)
    top_tabs = tab_and_slot(part="tab", length=D, thickness=t, tabs=2, tab=40 mm, screw=0,
                            cx=D / 2, cy=H)
    base_m = tab_and_slot(part="slot", length=back_y - t, thickness=t, tabs=2, tab=30 mm, screw=0,
                          clearance=fit, cx=(back_y - t) / 2, cy=z_base + t / 2)
    back_m = tab_and_slot(part="slot", length=H - t - z_base, thickness=t, tabs=2, tab=40 mm,
                          screw=0, clearance=fit, rotation=90 deg,
                          cx=back_y - t / 2, cy=(z_base + H - t) / 2)
    hole vents {
        for r in range(2) {
            for c in range(8) {
                v = Slot(center=(30 + 20 * c, [80, 300][r]), length=50, width=4, rotation=90 deg)
            }
        }
    }
}

assembly tank {
    left = side()
    right = side()

    solid base {
        board = Rectangle(bottom_left=(-W / 2, 0), width=W, height=back_y)
        l_tabs = tab_and_slot(part="tab", length=back_y - t, thickness=t, tabs=2, tab=30 mm,
                              screw=0, rotation=90 deg, cx=-W / 2, cy=(back_y - t) / 2)
        r_tabs = tab_and_slot(part="tab", length=back_y - t, thickness=t, tabs=2, tab=30 mm,
                              screw=0, rotation=-90 deg, cx=W / 2, cy=(back_y - t) / 2)
        b_tabs = tab_and_slot(part="tab", length=inner, thickness=t, tabs=2, tab=40 mm, screw=0,
                              cx=0 mm, cy=back_y)
        hole corners {
            cl = Rectangle(center=(-W / 2 + t / 2 - 0.5 mm, back_y - t / 2 + 0.5 mm), width=t + 1 mm,
                           height=t + 1 mm)
            cr = Rectangle(center=(W / 2 - t / 2 + 0.5 mm, back_y - t / 2 + 0.5 mm), width=t + 1 mm,
                           height=t + 1 mm)
        }
        hole tongue_slot {
            s = Rectangle(center=(0, glass_y), width=201, height=3.4)
        }
    }

    solid back {
        # x across, y = height from the floor
        board = Rectangle(bottom_left=(-W / 2, z_base), width=W, height=H - z_base)
        l_tabs = tab_and_slot(part="tab", length=H - t - z_base, thickness=t, tabs=2, tab=40 mm,
                              screw=0, rotation=90 deg, cx=-W / 2, cy=(z_base + H - t) / 2)
        r_tabs = tab_and_slot(part="tab", length=H - t - z_base, thickness=t, tabs=2, tab=40 mm,
                              screw=0, rotation=-90 deg, cx=W / 2, cy=(z_base + H - t) / 2)
        top_tabs = tab_and_slot(part="tab", length=inner, thickness=t, tabs=2, tab=40 mm, screw=0,
                                cx=0 mm, cy=H)
        base_m = tab_and_slot(part="slot", length=inner, thickness=t, tabs=2, tab=40 mm, screw=0,
                              clearance=fit, cx=0 mm, cy=z_base + t / 2)
        hole corners {
            cl = Rectangle(center=(-W / 2 + t / 2 - 0.5 mm, H - t / 2 + 0.5 mm), width=t + 1 mm,
                           height=t + 1 mm)
            cr = Rectangle(center=(W / 2 - t / 2 + 0.5 mm, H - t / 2 + 0.5 mm), width=t + 1 mm,
                           height=t + 1 mm)
        }
    }

    solid top {
        # x across, y = depth from the front
        board = Rectangle(bottom_left=(-W / 2 - over, 0), width=W + 2 * over, height=D + over)
        l_m = tab_and_slot(part="slot", length=D, thickness=t, tabs=2, tab=40 mm, screw=0,
                           clearance=fit, rotation=90 deg, cx=-W / 2 + t / 2, cy=D / 2)
        r_m = tab_and_slot(part="slot", length=D, thickness=t, tabs=2, tab=40 mm, screw=0,
                           clearance=fit, rotation=90 deg, cx=W / 2 - t / 2, cy=D / 2)
        b_m = tab_and_slot(part="slot", length=inner, thickness=t, tabs=2, tab=40 mm, screw=0,
                           clearance=fit, cx=0 mm, cy=back_y - t / 2)
        hole glass_slot {
            s = Rectangle(center=(0, glass_y), width=237, height=3.4)
        }
        hole opening {
            o = RoundedRectangle(center=(0, 110), width=150, height=100, corner_radius=10)
        }
        drawing name {
            n = Text("CARAUSIUS MOROSUS", position=(0, 35), size=7, valign="middle")
        }
    }

    solid glass {
        thickness 3 mm
        # x across, y = height from the floor
        pane = Rectangle(bottom_left=(-(inner - 2 mm) / 2, z_base + t), width=inner - 2 mm,
                         height=H - z_base - t)
        tongue = Rectangle(bottom_left=(-100, z_base), width=200, height=t)
        handle = Rectangle(bottom_left=(-40, H), width=80, height=30)
        hole finger {
            s = Slot(center=(0, H + 16), length=40, width=14)
        }
    }

    # the flat parts side by side on the sheet
    RightOf(right, left, gap=10)
    RightOf(base, right, gap=10)
    RightOf(back, base, gap=10)
    RightOf(top, back, gap=10)
    RightOf(glass, top, gap=10)
    AlignBottom(right, left)
    AlignBottom(base, left)
    AlignBottom(back, left)
    AlignBottom(top, left)
    AlignBottom(glass, left)

    # 3D: x across (+x right), y from the front (0) to the back, z up
    Place(left, position=(-W / 2, 0, 0), face="right", up="up")
    Place(right, position=(W / 2 - t, 0, 0), face="right", up="up")
    Place(base, position=(0, 0, z_base))
    Place(back, position=(0, back_y, 0), face="front", up="up")
    Place(top, position=(0, 0, H - t))
    Place(glass, position=(0, glass_y + a / 2, 0), face="front", up="up")

    # the request's numbers
    assert left.board.width == 200 mm and left.board.height == 400 mm, "sides 200 deep, 400 tall"
    assert base.board.width == 250 mm, "250 wide outside"
    assert z_base == 20 mm, "20 mm feet"
    assert D - back_y == 6 mm, "back 6 mm in from the sides' back edges"
    assert top.board.width - W == 2 * 6 mm and top.board.height - D == 6 mm, "top overhangs 6 mm"
    assert top.glass_slot.s.width == 237 mm and top.glass_slot.s.height == 3.4 mm, "top slot 237 x 3.4"
    assert base.tongue_slot.s.width == 201 mm and base.tongue_slot.s.height == 3.4 mm, "base slot 201 x 3.4"
    assert top.glass_slot.s.center.y == 10 mm, "slot 10 mm behind the front edge"
    assert glass.tongue.width == 200 mm, "200 mm tongue"
    assert glass.pane.width < top.glass_slot.s.width, "the pane lifts out through the top slot"
    assert glass.pane.width > base.tongue_slot.s.width, "the pane rests on the base"
    assert glass.pane.width < inner, "the pane runs between the sides"
    assert glass.handle.width == 80 mm and glass.handle.bb.bottom == H, "handle 80 wide above the top"
    assert glass.handle.height == 30 mm, "handle 30 tall"
    assert glass.finger.s.length == 40 mm and glass.finger.s.width == 14 mm, "finger slot 40 x 14"
    assert len(left.vents.v) == 2 and len(left.vents.v[0]) == 8, "two rows of eight vents"
    assert left.vents.v[0][0].length == 50 mm and left.vents.v[0][0].width == 4 mm, "4 x 50 vents"
    assert left.vents.v[0][1].center.x - left.vents.v[0][0].center.x == 20 mm, "20 mm pitch"
    assert left.vents.v[0][0].center.y == 80 mm and left.vents.v[1][0].center.y == 300 mm, "rows at 80 and 300"
    assert top.opening.o.width == 150 mm and top.opening.o.height == 100 mm, "150 x 100 opening"
    assert distance(left.vents, left.back_m) >= 5 mm, "vents clear of the back's mortises"
    assert distance(top.name, top.glass_slot) >= 5 mm and distance(top.name, top.opening) >= 5 mm, "name clear"
}
