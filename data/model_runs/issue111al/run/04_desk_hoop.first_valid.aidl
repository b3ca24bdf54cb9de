# Request (sport): an over-the-door mini basketball hoop for a 70 mm foam ball, 3 mm plywood,
# 3 parts glued. Backboard 180 x 140 mm, corners R8, two keyholes (8 mm head, 4 mm slot,
# 10 mm up) 72 mm either side of the centre, 45 mm above the middle, to hang it on two screws;
# engraved: a 60 x 45 mm shooter's square whose bottom edge is 2 mm above the rim's plane and
# "HOME COURT" in filled bold letters 12 mm high, centred 45 mm above the middle. The rim:
# a ring 90 mm inside, 104 mm outside, its plane 30 mm below the backboard's middle, on a
# 40 mm wide tongue that reaches 20 mm from the ring to the backboard face and ends in two
# 10 mm glued tabs into the backboard; ten net notches (2 mm wide, 2.5 mm deep) round the
# ring's outer edge over 300 deg, none on the tongue. A brace under the tongue: a right
# triangle 23 mm along the tongue and 35 mm down the backboard, one glued tab into each
# (tongue: 10 mm, backboard: 15 mm).

import "std/joints.aidl"
import "std/plates.aidl"

thickness 3 mm

T = 3 mm
rim_in = 90 mm
rim_out = 104 mm
reach = 20 mm          # tongue: ring's outer edge to the backboard face
rim_y = -30 mm         # rim plane on the backboard (its middle)
tongue_w = 40 mm
b_run = 23 mm          # brace along the tongue
b_drop = 35 mm         # brace down the backboard

assembly hoop {
    solid backboard {
        board = RoundedRectangle(center=(0, 0), width=180 mm, height=140 mm, corner_radius=8 mm)
        k1 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=-72 mm, cy=45 mm)
        k2 = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=72 mm, cy=45 mm)
        rim_slots = tab_and_slot(part="slot", length=tongue_w, thickness=T, tabs=2, tab=10 mm,
                                 screw=0, cx=0, cy=rim_y)
        # the brace stands on the centre line under the tongue (tongue underside: rim_y - T / 2)
        brace_slot = tab_and_slot(part="slot", length=b_drop, thickness=T, tabs=1, tab=15 mm,
                                  screw=0, rotation=90 deg, cx=0, cy=rim_y - T / 2 - b_drop / 2)
        drawing art {
            square = Rectangle(corner=(-30 mm, rim_y + 2 mm), opposite=(30 mm, rim_y + 47 mm))
            name = Text("HOME COURT", position=(0, 45 mm), size=12, font="sans:Bold",
                        valign="middle", fill=true)
        }
        assert board.width == 180 mm and board.height == 140 mm, "backboard 180 x 140"
        assert art.square.width == 60 mm and art.square.height == 45 mm, "60 x 45 square"
        assert art.square.bb.bottom - rim_y == 2 mm, "square 2 mm above the rim"
        assert art.name.bb.right < k2.head_hole.center.x - 4 mm - 3 mm, "name clear of the keyholes"
        assert art.square.bb.top < art.name.bb.bottom, "square below the name"
    }

    solid rim {
        ring = Circle(center=(0, 0), diameter=rim_out)
        # the tongue: from inside the ring to the backboard face (at -rim_out / 2 - reach)
        tongue = Rectangle(corner=(-tongue_w / 2, -rim_out / 2 - reach - T),
                           opposite=(tongue_w / 2, -rim_in / 2 - 3 mm))
        tabs = tab_and_slot(part="tab", length=tongue_w, thickness=T, tabs=2, tab=10 mm,
                            screw=0, rotation=180 deg, cx=0, cy=-rim_out / 2 - reach - T)
        brace_slot = tab_and_slot(part="slot", length=b_run, thickness=T, tabs=1, tab=10 mm,
                                  screw=0, rotation=90 deg, cx=0,
                                  cy=-rim_out / 2 - reach + b_run / 2)
        hole opening { c = Circle(center=(0, 0), diameter=rim_in) }
        hole notch {
            n = Rectangle(center=polar((0, 0), rim_out / 2, 300 deg), width=5 mm, height=2 mm,
                          rotation=300 deg, overrun=true)
        }
        net = CircularPattern(notch, 10, ring.center, angle=300 deg)
        assert opening.c.diameter == 90 mm and ring.diameter == 104 mm, "rim 90 / 104"
        assert opening.c.diameter > 70 mm + 15 mm, "the 70 mm ball drops through"
        assert len(net) == 10, "ten net notches"
        assert tongue.width == 40 mm, "40 mm tongue"
    }

    solid brace {
        web = Polygon([(0, 0), (b_run, 0), (0, -b_drop)])
        top = Rectangle(bottom_left=(0, 0), width=b_run, height=T)
        back = Rectangle(bottom_left=(-T, -b_drop), width=T, height=b_drop)
        up = tab_and_slot(part="tab", length=b_run, thickness=T, tabs=1, tab=10 mm, screw=0,
                          cx=b_run / 2, cy=T)
        to_board = tab_and_slot(part="tab", length=b_drop, thickness=T, tabs=1, tab=15 mm,
                                screw=0, rotation=90 deg, cx=-T, cy=-b_drop / 2)
        assert web.points[1].x - web.points[0].x == 23 mm, "23 mm along the tongue"
        assert web.points[0].y - web.points[2].y == 35 mm, "35 mm down the backboard"
    }

    RightOf(rim, backboard, gap=10)
    AlignTop(rim, backboard)
    RightOf(brace, backboard, gap=10)
    Below(brace, rim, gap=10)
}
