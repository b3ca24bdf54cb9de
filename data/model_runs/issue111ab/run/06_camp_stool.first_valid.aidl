# Request (camping): a flat-pack camp stool from 12 mm birch ply, no glue or screws. Two
# identical-looking legs, each a trapezoid 300 wide at the floor, 260 at the top, 380 tall
# (with the tabs), with an arched cut-out at the floor (a half ellipse 180 wide x 100 high)
# and the two outer feet rounded R10. The legs cross-halve at right angles: one is slotted
# down from the middle of its top to 190 mm above the floor, the other up from the top of
# its arch to 190 mm. Each leg's top has two 30 mm tabs (12 mm long) into mortises in a round
# seat 320 mm across (two rows of mortises at right angles, 0.2 mm clearance). The seat has a
# carrying slot 100 x 30 centred 115 mm from its centre and "BASE CAMP" engraved (14 mm)
# opposite it. Halving slots 12 mm + 0.2 clearance.

units mm
thickness 12 mm
kerf 0.15 mm

import "std/joints.aidl"

ply = 12 mm
leg_h = 380 mm
leg_bottom = 300 mm
leg_top = 260 mm
arch_w = 180 mm
arch_h = 100 mm
meet = 190 mm
seat_d = 320 mm

def leg(top_slot=true) -> solid {
    body = Trapezoid(center=(0, leg_h / 2), bottom_width=leg_bottom, top_width=leg_top,
                     height=leg_h)
    hole arch {
        e = Ellipse(center=(0, 0), rx=arch_w / 2, ry=arch_h)
    }
    tabs = tab_and_slot(part="tab", length=leg_top, thickness=ply, tabs=2, tab=30 mm,
                        screw=0, clearance=0.2 mm, cx=0 mm, cy=leg_h)
    if top_slot {
        halving = cross_halving(depth=leg_h - meet, thickness=ply, clearance=0.2 mm,
                                cx=0 mm, cy=leg_h)
    } else {
        halving = cross_halving(depth=meet - arch_h, thickness=ply, clearance=0.2 mm,
                                rotation=180 deg, cx=0 mm, cy=arch_h)
    }
    Fillet([body.bottom_left, body.bottom_right], 10)
}

assembly stool {
    solid seat {
        disc = Circle(center=(0, 0), diameter=seat_d)
        row_x = tab_and_slot(part="slot", length=leg_top, thickness=ply, tabs=2, tab=30 mm,
                             screw=0, clearance=0.2 mm, cx=0 mm, cy=0 mm)
        row_y = tab_and_slot(part="slot", length=leg_top, thickness=ply, tabs=2, tab=30 mm,
                             screw=0, clearance=0.2 mm, rotation=90 deg, cx=0 mm, cy=0 mm)
        hole carry {
            s = Slot(center=(0, 115), length=100, width=30)
        }
        drawing label {
            t = Text("BASE CAMP", position=(0, -115), size=14, valign="middle")
        }
        assert carry.bb.bottom > row_y.bb.top + 10 mm, "carrying slot clear of the mortises"
        assert label.bb.top < row_y.bb.bottom - 10 mm, "label clear of the mortises"
        assert distance(label.t.bb.bottom_left, disc.center) < seat_d / 2 - 10 mm, "label on the seat"
    }
    leg_a = leg(top_slot=true)
    leg_b = leg(top_slot=false)

    RightOf(leg_a, seat, gap=10)
    RightOf(leg_b, leg_a, gap=10)
    AlignBottom(leg_a, seat)
    AlignBottom(leg_b, seat)

    assert abs(seat.disc.diameter - 320 mm) < 0.01, "seat 320"
    assert abs(leg_a.body.bb.height - 380 mm) < 0.01, "legs 380 tall"
    assert abs(leg_a.body.bottom_width - 300 mm) < 0.01 and abs(leg_a.body.top_width - 260 mm) < 0.01, "300 / 260"
    assert abs(leg_a.halving.cut.bb.bottom - leg_a.body.bb.bottom - 190 mm) < 0.01, "A slotted down to 190"
    assert abs(leg_b.halving.cut.bb.top - leg_b.body.bb.bottom - 190 mm) < 0.01, "B slotted up to 190"
    assert abs(leg_b.halving.cut.bb.bottom - leg_b.body.bb.bottom - 100 mm) < 0.01, "B's slot starts at the arch top"
}
