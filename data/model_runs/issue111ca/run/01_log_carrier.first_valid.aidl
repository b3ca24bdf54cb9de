# Request (home): a firewood log carrier for the hearth, from 9 mm birch ply. Two end panels
# 300 mm wide and 380 mm tall: straight sides up to 230 mm, then a round (semicircular) top;
# a 120 x 35 mm hand hole 320 mm up (its centre) in each; a 200 mm wide, 20 mm high notch in
# the bottom edge leaving two feet. Between the ends: logs up to 400 mm long, so the ends'
# inner faces are 400 mm apart. Two side boards 150 mm tall, 10 mm off the floor, set 12 mm in
# from the ends' edges, their ends through-tenoned into the end panels (2 tabs of 40 mm each
# side, glued). A base board 25 mm off the floor, tenoned into the ends (2 tabs of 60 mm) and
# into the sides (3 tabs of 60 mm). "FIREWOOD" engraved (filled, bold, 50 mm tall) on each side.

import "std/joints.aidl"

thickness 9 mm

T = 9 mm
inner_len = 400 mm      # between the end panels' inner faces
end_w = 300 mm
end_h = 380 mm
shoulder = 230 mm       # straight sides of the end panel
side_h = 150 mm
side_z = 10 mm          # side board's bottom above the floor
inset = 12 mm           # side board's outer face from the end panel's edge
base_z = 25 mm          # base board's underside above the floor

side_len = inner_len + 2 * T          # side board incl. its tenons
side_y = end_w / 2 - inset - T / 2    # side board's mid-plane from the centre line
base_w = 2 * (side_y - T / 2) + 2 * T # base incl. its tenons into the sides
base_len = inner_len + 2 * T

def end_panel() -> solid {
    low = Rectangle(bottom_left=(-end_w / 2, 0), width=end_w, height=shoulder)
    top = Circle(center=(0, shoulder), radius=end_w / 2)
    hole hand { s = Slot(center=(0, 320), length=120, width=35) }
    hole feet { r = Rectangle(center=(0, 7.5), width=200, height=25) }
    # mortises for the side boards (vertical) and the base (horizontal)
    left_m = tab_and_slot(part="slot", length=side_h, thickness=T, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=-side_y, cy=side_z + side_h / 2)
    right_m = tab_and_slot(part="slot", length=side_h, thickness=T, tabs=2, tab=40 mm, screw=0,
                           rotation=90 deg, cx=side_y, cy=side_z + side_h / 2)
    base_m = tab_and_slot(part="slot", length=base_w, thickness=T, tabs=2, tab=60 mm, screw=0,
                          cx=0, cy=base_z + T / 2)
}

def side_board() -> solid {
    board = Rectangle(center=(0, 0), width=side_len, height=side_h)
    left_t = tab_and_slot(part="tab", length=side_h, thickness=T, tabs=2, tab=40 mm, screw=0,
                          rotation=90 deg, cx=-side_len / 2, cy=0)
    right_t = tab_and_slot(part="tab", length=side_h, thickness=T, tabs=2, tab=40 mm, screw=0,
                           rotation=-90 deg, cx=side_len / 2, cy=0)
    base_m = tab_and_slot(part="slot", length=base_len, thickness=T, tabs=3, tab=60 mm, screw=0,
                          cx=0, cy=-side_h / 2 + (base_z - side_z) + T / 2)
    drawing label {
        word = Text("FIREWOOD", position=(0, 15), size=50, font="sans:Bold", valign="middle",
                    fill=true)
    }
}

assembly carrier {
    end_a = end_panel()
    end_b = end_panel()
    side_a = side_board()
    side_b = side_board()
    solid base {
        board = Rectangle(center=(0, 0), width=base_len, height=base_w)
        e1 = tab_and_slot(part="tab", length=base_w, thickness=T, tabs=2, tab=60 mm, screw=0,
                          rotation=90 deg, cx=-base_len / 2, cy=0)
        e2 = tab_and_slot(part="tab", length=base_w, thickness=T, tabs=2, tab=60 mm, screw=0,
                          rotation=-90 deg, cx=base_len / 2, cy=0)
        s1 = tab_and_slot(part="tab", length=base_len, thickness=T, tabs=3, tab=60 mm, screw=0,
                          cx=0, cy=base_w / 2)
        s2 = tab_and_slot(part="tab", length=base_len, thickness=T, tabs=3, tab=60 mm, screw=0,
                          rotation=180 deg, cx=0, cy=-base_w / 2)
    }

    # flat on the sheet: ends side by side, the boards to their right
    end_a.bb.center == (0, 0)
    RightOf(end_b, end_a, gap=10)
    AlignBottom(end_b, end_a)
    RightOf(side_a, end_b, gap=10)
    AlignBottom(side_a, end_b)
    Above(side_b, side_a, gap=10)
    AlignLeft(side_b, side_a)
    Above(base, side_b, gap=10)
    AlignLeft(base, side_b)

    # in 3D: x along the carrier, y across, z up
    Place(end_a, rotation=(90 deg, 0, 90 deg), position=(inner_len / 2, 0, 0))
    Place(end_b, rotation=(90 deg, 0, 90 deg), position=(-inner_len / 2 - T, 0, 0))
    Place(side_a, rotation=(90 deg, 0, 180 deg), position=(0, side_y - T / 2, side_z + side_h / 2))
    Place(side_b, rotation=(90 deg, 0, 0), position=(0, -side_y + T / 2, side_z + side_h / 2))
    Place(base, position=(0, 0, base_z))

    # the request's numbers
    assert end_a.low.bb.width == 300 mm, "ends 300 wide"
    assert end_a.top.bb.top - end_a.low.bb.bottom == 380 mm, "ends 380 tall"
    assert side_a.board.bb.width - 2 * T == 400 mm, "400 mm between the ends"
    assert side_a.board.bb.height == 150 mm, "sides 150 tall"
    assert end_a.hand.s.center.y - end_a.low.bb.bottom == 320 mm, "hand hole 320 up"
    assert end_w / 2 - (side_y + T / 2) == 12 mm, "sides 12 in from the ends' edges"
}
