# Request (gifts): a two-bottle wine carrier as a wedding present, from 6 mm oak-faced ply.
# Base 210 x 100 mm; two end panels 100 mm wide and 160 mm tall, finger-jointed to the base
# ends (20 mm fingers); a centre divider 80 mm deep and 300 mm tall between the bottles,
# glued into the base with two 20 mm tenons, its top corners rounded 30 mm and a 90 x 28 mm
# hand hole 30 mm below its top; a collar plate at 120 mm (its underside) with two 80 mm
# holes for the bottles, a mortise the divider passes through, and two 20 mm tenons each end
# into mortises in the end panels. Engrave "CHEERS" 16 mm tall in bold on the outside of one
# end panel, and "A & J  12.06.2026" 6 mm tall on the divider under the hand hole.

units mm
thickness 6 mm
kerf 0.15 mm

import "std/joints.aidl"

ply = 6 mm
base_l = 210 mm
depth = 100 mm
end_h = 160 mm
div_d = 80 mm
div_h = 300 mm
collar_z = 120 mm
bottle_hole = 80 mm
tenon = 20 mm
inner_half = base_l / 2 - ply          # 99: inside faces of the end panels
bottle_x = (ply / 2 + inner_half) / 2  # bottle centres between divider and end

def end_panel() -> solid {
    body = Rectangle(bottom_left=(-depth / 2, 0), width=depth, height=end_h)
    Fixed(body)
    fingers = finger_edge(length=depth, thickness=ply, finger=tenon, start="gap",
                          rotation=180 deg, cx=0 mm, cy=0 mm)
    collar_mortise = tab_and_slot(part="slot", length=depth, thickness=ply, tabs=2, tab=tenon,
                                  screw=0, clearance=0.1 mm, cx=0 mm, cy=collar_z + ply / 2)
}

assembly wine_carrier {
    solid base {
        board = Rectangle(center=(0, 0), width=base_l, height=depth)
        Fixed(board)
        left_fingers = finger_edge(length=depth, thickness=ply, finger=tenon, start="tab",
                                   rotation=90 deg, cx=-base_l / 2, cy=0 mm)
        right_fingers = finger_edge(length=depth, thickness=ply, finger=tenon, start="tab",
                                    rotation=-90 deg, cx=base_l / 2, cy=0 mm)
        divider_mortise = tab_and_slot(part="slot", length=div_d, thickness=ply, tabs=2,
                                       tab=tenon, screw=0, clearance=0.1 mm, rotation=90 deg,
                                       cx=0 mm, cy=0 mm)
    }
    end_l = end_panel()
    end_r = end_panel()
    solid divider {
        body = RoundedRectangle(bottom_left=(-div_d / 2, 0), width=div_d, height=div_h,
                                corner_radii=[30 mm, 30 mm, 0, 0])
        Fixed(body)
        hole hand { s = Slot(center=(0, div_h - 30 mm), length=90, width=28) }
        feet = tab_and_slot(part="tab", length=div_d, thickness=ply, tabs=2, tab=tenon,
                            screw=0, rotation=180 deg, cx=0 mm, cy=0 mm)
        drawing names {
            t = Text("A & J  12.06.2026", position=(0, div_h - 70 mm), size=6, valign="middle",
                     max_width=div_d - 10 mm)
        }
    }
    solid collar {
        plate = Rectangle(center=(0, 0), width=base_l, height=depth)
        Fixed(plate)
        left_tenons = tab_and_slot(part="tab", length=depth, thickness=ply, tabs=2, tab=tenon,
                                   screw=0, rotation=90 deg, cx=-base_l / 2, cy=0 mm)
        right_tenons = tab_and_slot(part="tab", length=depth, thickness=ply, tabs=2, tab=tenon,
                                    screw=0, rotation=-90 deg, cx=base_l / 2, cy=0 mm)
        hole bottle_l { c = Circle(center=(-bottle_x, 0), diameter=bottle_hole) }
        hole bottle_r { c = Circle(center=(bottle_x, 0), diameter=bottle_hole) }
        hole pass { r = Rectangle(center=(0, 0), width=ply + 0.2 mm, height=div_d + 0.2 mm) }
    }
    drawing cheers {
        t = Text("CHEERS", position=(0, 0), size=16, font="sans:Bold", valign="middle")
    }
    CutInto(cheers, end_r)
    AlignCenterX(cheers, end_r.body)
    cheers.t.position.y == end_r.body.bb.bottom + 60 mm

    # flat on the sheet
    Above(collar, base, gap=10)
    AlignLeft(collar, base)
    RightOf(end_l, base, gap=10)
    AlignBottom(end_l, base)
    RightOf(end_r, end_l, gap=10)
    AlignBottom(end_r, base)
    RightOf(divider, end_r, gap=10)
    AlignBottom(divider, base)

    # assembled: x along the carrier, y across, z up
    Place(base, position=(0, 0, 0))
    Place(end_l, rotation=(90 deg, 0, 90 deg), position=(-base_l / 2, 0, 0))
    Place(end_r, rotation=(90 deg, 0, 90 deg), position=(base_l / 2 - ply, 0, 0))
    Place(divider, rotation=(90 deg, 0, 90 deg), position=(-ply / 2, 0, 0))
    Place(collar, position=(0, 0, collar_z))

    assert base.board.width == 210 mm and base.board.height == 100 mm, "base 210 x 100"
    assert end_l.body.width == 100 mm and end_l.body.height == 160 mm, "ends 100 x 160"
    assert divider.body.width == 80 mm and divider.body.height == 300 mm, "divider 80 x 300"
    assert divider.body.bb.top - divider.hand.s.center.y == 30 mm, "hand hole 30 below the top"
    assert divider.hand.s.length == 90 mm and divider.hand.s.width == 28 mm, "hand hole 90 x 28"
    assert collar.bottle_l.c.diameter == 80 mm, "80 mm bottle holes"
    assert bottle_x - bottle_hole / 2 - (ply / 2 + 0.1 mm) >= 5 mm, "wood between bottle hole and divider"
    assert inner_half - (bottle_x + bottle_hole / 2) >= 5 mm, "wood between bottle hole and end"
    assert collar_z + ply < end_h, "collar under the end panels' tops"
}
