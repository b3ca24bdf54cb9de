# Request: a table teapot warmer for a tealight, 6 mm birch ply. A round top 170 mm across
# that the pot stands on, 70 mm clear above the base: a cluster of seven 16 mm holes in the
# middle (one at the centre, six on a 25 mm radius) lets the heat through, and a ring of
# twelve 6 mm vent holes on a 50 mm radius (kept clear of the legs) lets the air out;
# "WARM TEA" engraved filled in 8 mm bold letters round the rim, over the front.
# A round base 170 mm across with an engraved 40 mm circle where the tealight goes.
# Three legs 35 mm wide (from 40 to 75 mm out from the centre) and 70 mm tall, at 30, 150
# and 270 degrees, each with a 20 mm tenon glued into the top and one into the base, and a
# scoop 10 mm deep out of its outer edge.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
D = 170 mm          # top and base diameter
H = 70 mm           # clear height between base and top
R_IN = 40 mm        # legs' inner edge radius
R_OUT = 75 mm       # legs' outer edge radius
R_MID = (R_IN + R_OUT) / 2
LEG_A = [30 deg, 150 deg, 270 deg]

def leg() -> solid {
    # flat: x = distance from the centre, y = height above the base's top face;
    # the tenons' tips on y = -T (under the base) and y = H + T (over the top)
    body = Rectangle(bottom_left=(40, -6), width=35, height=82)
    hole scoop { c = Circle(center=(100, 35), radius=35) }
    bottom = tab_and_slot(part="tab", length=35 mm, thickness=6 mm, tabs=1, tab=20 mm, screw=0,
                          rotation=180 deg, cx=57.5 mm, cy=-6 mm)
    top = tab_and_slot(part="tab", length=35 mm, thickness=6 mm, tabs=1, tab=20 mm, screw=0,
                       cx=57.5 mm, cy=76 mm)
}

assembly teapot_warmer {
    solid top {
        disc = Circle(center=(0, 0), diameter=D)
        Fixed(disc)
        hole middle { c = Circle(center=(0, 0), diameter=16) }
        hole heat { c = Circle(center=(25, 0), diameter=16) }
        Fixed(middle)
        Fixed(heat)
        cluster = CircularPattern(heat, 6, (0, 0))
        hole vent { c = Circle(center=(50, 0), diameter=6) }
        Fixed(vent)
        vents = CircularPattern(vent, 12, (0, 0), start_angle=15 deg)
        for i in range(3) {
            mortise = tab_and_slot(part="slot", length=35 mm, thickness=6 mm, tabs=1, tab=20 mm,
                                   screw=0, rotation=LEG_A[i], cx=R_MID * cos(LEG_A[i]),
                                   cy=R_MID * sin(LEG_A[i]))
        }
        drawing words {
            rim = Circle(center=(0, 0), radius=66, construction=true)
            t = Text("WARM TEA", along=rim, size=8, font="sans:Bold", fill=true)
        }
    }

    solid base {
        disc = Circle(center=(0, 0), diameter=D)
        Fixed(disc)
        for i in range(3) {
            mortise = tab_and_slot(part="slot", length=35 mm, thickness=6 mm, tabs=1, tab=20 mm,
                                   screw=0, rotation=LEG_A[i], cx=R_MID * cos(LEG_A[i]),
                                   cy=R_MID * sin(LEG_A[i]))
        }
        drawing target { c = Circle(center=(0, 0), diameter=40) }
    }

    leg_a = leg()
    leg_b = leg()
    leg_c = leg()

    # the sheet: base right of the top, the legs in a row under them
    RightOf(base, top, gap=10)
    AlignCenterY(base, top)
    Below(leg_a, top, gap=10)
    AlignLeft(leg_a, top)
    RightOf(leg_b, leg_a, gap=10)
    RightOf(leg_c, leg_b, gap=10)
    AlignTop(leg_b, leg_a)
    AlignTop(leg_c, leg_a)

    # 3D: base on the table, top H above it, legs standing radially (mid-plane through the axis)
    Place(base, position=(0, 0, 0))
    Place(top, position=(0, 0, T + H))
    Place(leg_a, rotation=(90 deg, 0, LEG_A[0]),
          position=(-3 * sin(LEG_A[0]), 3 * cos(LEG_A[0]), T))
    Place(leg_b, rotation=(90 deg, 0, LEG_A[1]),
          position=(-3 * sin(LEG_A[1]), 3 * cos(LEG_A[1]), T))
    Place(leg_c, rotation=(90 deg, 0, LEG_A[2]),
          position=(-3 * sin(LEG_A[2]), 3 * cos(LEG_A[2]), T))

    # the request's numbers
    assert top.disc.diameter == 170 mm and base.disc.diameter == 170 mm, "top and base 170 mm"
    assert len(top.cluster) + 1 == 7, "seven 16 mm holes"
    assert len(top.vents) == 12, "twelve vents"
    assert leg_a.body.bb.height - 2 * 6 mm == 70 mm, "70 mm clear"
    assert leg_a.body.bb.width == 35 mm, "legs 35 mm wide"
    assert leg_a.body.bb.left - leg_a.body.bb.left + 40 mm == R_IN, "legs from 40 mm out"
    assert base.target.c.diameter == 40 mm, "tealight circle 40 mm"
}
