# Request (parties): a stand that lifts a 5-litre drinks dispenser (a glass jar with a tap)
# off the party table so a cup fits under the tap, from 9 mm birch ply. A 240 mm round top;
# on it a glued lip ring, 240 mm outside and 210 mm inside, that keeps the jar from sliding.
# Under the top two legs, 180 mm deep and 150 mm tall (top's underside 150 mm above the
# table), 160 mm apart centre to centre, each tenoned into the top by two 40 mm tabs and with
# a half-ellipse arch 110 mm wide and 50 mm high cut from its bottom edge to leave two feet.
# A 50 mm tall stretcher between the legs, its centre 85 mm above the table, through-tenoned
# (one 30 mm tenon each end), with "LEMONADE" engraved filled (bold, at most 130 mm wide).

import "std/joints.aidl"

thickness 9 mm

T = 9 mm
top_d = 240 mm
ring_in = 210 mm
leg_depth = 180 mm
leg_h = 150 mm          # table to the top's underside
leg_pitch = 160 mm      # centre to centre
str_h = 50 mm
str_z = 85 mm           # stretcher's centre above the table
str_len = leg_pitch - T + 2 * T   # between the legs' inner faces, plus a tenon each end

def leg() -> solid {
    board = Rectangle(bottom_left=(-leg_depth / 2, 0), width=leg_depth, height=leg_h + T)
    hole arch { e = Ellipse(center=(0, 0), rx=55, ry=50) }
    top_tabs = tab_and_slot(part="tab", length=leg_depth, thickness=T, tabs=2, tab=40 mm,
                            screw=0, cx=0, cy=leg_h + T)
    mortise = tab_and_slot(part="slot", length=str_h, thickness=T, tabs=1, tab=30 mm, screw=0,
                           rotation=90 deg, cx=0, cy=str_z)
}

assembly stand {
    solid top {
        disc = Circle(center=(0, 0), diameter=top_d)
        m_left = tab_and_slot(part="slot", length=leg_depth, thickness=T, tabs=2, tab=40 mm,
                              screw=0, rotation=90 deg, cx=-leg_pitch / 2, cy=0)
        m_right = tab_and_slot(part="slot", length=leg_depth, thickness=T, tabs=2, tab=40 mm,
                               screw=0, rotation=90 deg, cx=leg_pitch / 2, cy=0)
    }
    solid ring {
        outer = Circle(center=(0, 0), diameter=top_d)
        hole inside { c = Circle(center=(0, 0), diameter=ring_in) }
    }
    leg_l = leg()
    leg_r = leg()
    solid stretcher {
        bar = Rectangle(center=(0, 0), width=str_len, height=str_h)
        end_l = tab_and_slot(part="tab", length=str_h, thickness=T, tabs=1, tab=30 mm, screw=0,
                             rotation=90 deg, cx=-str_len / 2, cy=0)
        end_r = tab_and_slot(part="tab", length=str_h, thickness=T, tabs=1, tab=30 mm, screw=0,
                             rotation=-90 deg, cx=str_len / 2, cy=0)
        drawing word {
            t = Text("LEMONADE", position=(0, 0), size=24, font="sans:Bold", valign="middle",
                     max_width=130 mm, fill=true)
        }
    }

    # flat on the sheet
    top.disc.center == (0, 0)
    RightOf(ring, top, gap=6)
    AlignCenterY(ring, top)
    Below(leg_l, top, gap=6)
    AlignLeft(leg_l, top)
    RightOf(leg_r, leg_l, gap=6)
    AlignBottom(leg_r, leg_l)
    RightOf(stretcher, leg_r, gap=6)
    AlignBottom(stretcher, leg_r)

    # in 3D: x across the legs, y front to back, z up from the table
    Place(top, position=(0, 0, leg_h))
    Place(ring, position=(0, 0, leg_h + T))
    Place(leg_l, rotation=(90 deg, 0, 90 deg), position=(-leg_pitch / 2 - T / 2, 0, 0))
    Place(leg_r, rotation=(90 deg, 0, 90 deg), position=(leg_pitch / 2 - T / 2, 0, 0))
    Place(stretcher, rotation=(90 deg, 0, 0), position=(0, T / 2, str_z))

    assert top.disc.diameter == 240 mm, "240 mm top"
    assert ring.inside.c.diameter == 210 mm, "ring 210 inside"
    assert leg_l.board.bb.height - T == 150 mm, "top's underside 150 above the table"
    assert leg_l.arch.bb.width == 110 mm and leg_l.arch.e.ry == 50 mm, "arch 110 x 50"
    assert str_len - 2 * T == 160 mm - T, "stretcher spans between the legs' inner faces"
    assert stretcher.word.t.bb.width <= 130 mm, "LEMONADE at most 130 wide"
    # the stretcher stays above the arch, and the legs stay inside the ring's reach
    assert str_z - str_h / 2 > 50 mm, "stretcher above the arch"
    assert leg_pitch / 2 + T / 2 < ring_in / 2, "legs under the jar's footprint"
}
