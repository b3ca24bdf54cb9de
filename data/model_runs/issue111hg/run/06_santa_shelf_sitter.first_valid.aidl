# Request (holidays): a Santa shelf sitter for the mantelpiece, from 6 mm ply, to paint.
# The figure stands on the shelf at its front edge: a coat 110 mm wide at the bottom and
# 80 mm at the shoulders, 80 mm tall; a round face (56 mm across) whose centre is 105 mm up;
# a pointed beard hanging to 52 mm up; a hat on a 70 x 14 mm brim, its tip flopping to the
# left with a 20 mm bobble; round mittens (24 mm) at both sides. The whole figure is at
# most 175 mm tall. Engraved: eyes and nose (filled), a moustache, the beard's outline, a
# belt 10 mm deep with a buckle. A separate legs piece is glued to the front of the coat's
# bottom: a lap 100 x 40 mm and two 28 mm legs hanging 80 mm below the shelf into boots
# 44 x 20 mm, boot cuffs and "HO HO HO" (7 mm) engraved. A triangular gusset, 60 mm deep
# and 40 mm tall, holds it upright from behind by one 25 mm glued tab in a mortise in the
# coat, hidden behind the lap.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
lap_h = 40 mm

assembly santa {
    solid figure {
        coat = Trapezoid(center=(0, 40), bottom_width=110, top_width=80, height=80)
        face = Circle(center=(0, 105), radius=28)
        beard = Hull(Circle(center=(0, 92), radius=24), Point(0, 52))
        brim = RoundedRectangle(center=(0, 128), width=70, height=14, corner_radius=7)
        hat = Polygon([(-30, 128), (30, 128), (6, 160), (-36, 158)])
        bobble = Circle(center=(-40, 156), radius=10)
        left_mitt = Circle(center=(-52, 48), radius=12)
        right_mitt = Circle(center=(52, 48), radius=12)
        mortise = tab_and_slot(part="slot", length=lap_h, thickness=t, tabs=1, tab=25 mm,
                               screw=0, clearance=0.1 mm, rotation=90 deg,
                               cx=0 mm, cy=lap_h / 2)
        drawing details {
            eye_l = Circle(center=(-10, 112), radius=3, fill=true)
            eye_r = Circle(center=(10, 112), radius=3, fill=true)
            nose = Circle(center=(0, 103), radius=4, fill=true)
            tache_l = Ellipse(center=(-9, 95), rx=9, ry=3.5)
            tache_r = Ellipse(center=(9, 95), rx=9, ry=3.5)
            beard_line = Hull(Circle(center=(0, 92), radius=24), Point(0, 52))
            belt_top = Line((-51, 60), (51, 60))
            belt_bottom = Line((-52, 50), (52, 50))
            buckle = Rectangle(center=(0, 55), width=16, height=12)
        }
    }

    solid legs {
        lap = RoundedRectangle(center=(0, lap_h / 2), width=100, height=lap_h,
                               corner_radius=8)
        leg_l = Rectangle(center=(-22, -40), width=28, height=80)
        leg_r = Rectangle(center=(22, -40), width=28, height=80)
        boot_l = RoundedRectangle(center=(-30, -80), width=44, height=20,
                                  corner_radii=[4 mm, 4 mm, 4 mm, 10 mm])
        boot_r = RoundedRectangle(center=(30, -80), width=44, height=20,
                                  corner_radii=[4 mm, 4 mm, 10 mm, 4 mm])
        drawing trim {
            cuff_l = Line((-36, -64), (-8, -64))
            cuff_r = Line((8, -64), (36, -64))
            ho = Text("HO HO HO", (0, lap_h / 2), size=7, valign="middle")
        }
    }

    solid gusset {
        body = Triangle((0, 0), (60, 0), (0, lap_h))
        tab = tab_and_slot(part="tab", length=lap_h, thickness=t, tabs=1, tab=25 mm,
                           screw=0, rotation=90 deg, cx=0 mm, cy=lap_h / 2)
    }

    RightOf(legs, figure, gap=15)
    AlignBottom(legs, figure)
    RightOf(gusset, legs, gap=15)
    AlignBottom(gusset, legs)

    # in 3D: the shelf top is z = 0, its front edge y = 0; the legs hang in front of it
    Place(figure, position=(0, t, 0), face="front", up="up")
    Place(legs, position=(0, 0, 0), face="front", up="up")
    Place(gusset, position=(-t / 2, 0, 0), face="right", up="up")

    assert figure.coat.bb.width == 110 mm and figure.coat.bb.height == 80 mm, "coat"
    assert figure.bb.height <= 175 mm, "at most 175 tall"
    assert legs.lap.bb.bottom - legs.boot_l.bb.bottom == 90 mm, "legs hang 80 + boots"
    assert figure.mortise.slot[0].bb.top <= figure.coat.bb.bottom + lap_h - 5 mm,
        "mortise hidden behind the lap"
    assert gusset.body.bb.width == 60 mm and gusset.body.bb.height == 40 mm, "gusset"
}
