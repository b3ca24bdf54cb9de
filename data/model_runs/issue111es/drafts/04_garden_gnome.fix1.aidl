# Request: "A garden gnome on a stake for the front flower bed, cut from 6 mm exterior ply
# and painted. The gnome is 240 mm tall from the soles of his boots to the tip of his hat,
# which is tall, curved and bends over to his left (our right); a round nose (R9) under
# the hat brim, a pointed beard down over his coat, a coat 84 mm wide at the hem, two boots.
# Engrave (for the painter) the hat brim line behind the nose, the nose, the beard's outline
# and a belt with a buckle 14 x 10 mm. Below the boots a stake 16 mm wide runs 200 mm down
# to a point. A separate sign 130 x 60 mm (corners R6) with WELCOME cut through as stencil
# letters 16 mm tall is bolted to the front of the stake with two M4 bolts 44 mm apart, its
# middle 40 mm below the boots, so it shows above the soil. 440 mm overall. Kerf 0.2 mm."

import "std/fasteners.aidl"

units mm
thickness 6 mm
kerf 0.2 mm

stake_w = 16 mm
stake_len = 200 mm
sign_drop = 40 mm        # sign's middle below the boots' soles
bolt_gap = 44 mm
brim_y = 118 mm

# FIX after the first valid program: (1) the nose was hidden by the face drawing's own hole:
# it now has its own drawing; (2) brim and beard engraving ran along the cut edge (W0516):
# the brim is clipped to the beard, the beard is only its V over the coat; (3) a window
# between the boots (note W0515): the stake now runs up into the coat; (4) the coat's hem
# corners poked 0.6 mm past the boots as tiny spikes (no message): boots a little wider;
# (5) the coat's top corners stood 2 mm past the beard as ledges: coat top 52 mm, meeting
# the beard's tangent points.
assembly gnome_kit {
    solid gnome {
        stake = Polygon([(-stake_w / 2, 12), (stake_w / 2, 12), (stake_w / 2, -stake_len + 20),
                         (0, -stake_len), (-stake_w / 2, -stake_len + 20)])
        boot_l = Ellipse(center=(-21, 8), rx=22, ry=8)
        boot_r = Ellipse(center=(21, 8), rx=22, ry=8)
        coat = Trapezoid(center=(0, 45), bottom_width=84, top_width=52, height=70)
        beard = Hull(Circle(center=(0, 95), radius=30), Point(0, 35))
        nose = Circle(center=(0, brim_y), radius=9)
        hat = Spline([(-38, brim_y), (-30, 160), (-14, 200), (10, 228), (32, 240), (22, 206),
                      (30, 160), (38, brim_y)], closed=true, corners=[0, 4, 7])

        hole bolts {
            top = clearance_hole(size=4, cx=0 mm, cy=-sign_drop + bolt_gap / 2)
            low = clearance_hole(size=4, cx=0 mm, cy=-sign_drop - bolt_gap / 2)
        }

        drawing brim {
            l = Intersect(Line((-38, brim_y), (38, brim_y)), Circle(center=(0, 95), radius=30))
            hole behind_nose { c = Circle(center=(0, brim_y), radius=9) }
        }
        drawing nose_line {
            n = Circle(center=(0, brim_y), radius=9)
        }
        drawing beard_line {
            # the beard's V over the coat, to its tangent points (60 mm from tip to centre, R30)
            v = Polyline([(-30 * sqrt(3) / 2, 80), (0, 35), (30 * sqrt(3) / 2, 80)])
        }
        drawing belt {
            left = Line((-39, 25), (-7, 25))
            right = Line((7, 25), (39, 25))
            buckle = Rectangle(center=(0, 25), width=14, height=10)
        }
    }

    solid sign {
        plate = RoundedRectangle(center=(0, 0), width=130, height=60, corner_radius=6)
        hole word {
            w = Text("WELCOME", position=(0, 0), size=16, font="sans:Bold", valign="middle",
                     stencil=true)
        }
        top = clearance_hole(size=4, cx=0 mm, cy=bolt_gap / 2)
        low = clearance_hole(size=4, cx=0 mm, cy=-bolt_gap / 2)
    }

    # on the sheet: the sign beside the stake
    RightOf(sign, gnome.stake, gap=10 mm)
    AlignCenterY(sign, gnome.bolts)

    # in 3D: stake point at the ground datum, the sign on the stake's front face
    Place(gnome, position=(0, 0, stake_len), face="front")
    Place(sign, position=(0, -6, stake_len - sign_drop), face="front")

    # the request's numbers
    assert gnome.bb.top - gnome.boot_l.bb.bottom == 240 mm, "240 mm from soles to hat tip"
    assert gnome.bb.height == 440 mm, "440 mm overall"
    assert gnome.boot_l.bb.bottom - gnome.stake.bb.bottom == 200 mm, "stake 200 mm below the boots"
    assert gnome.coat.bottom_width == 84 mm, "coat 84 mm at the hem"
    assert gnome.hat.points[4].x > 0 mm, "hat bends to our right"
    assert gnome.bolts.top.c.center.y - gnome.bolts.low.c.center.y == 44 mm, "bolts 44 mm apart (stake)"
    assert sign.top.c.center.y - sign.low.c.center.y == 44 mm, "bolts 44 mm apart (sign)"
    assert gnome.boot_l.bb.bottom - (gnome.bolts.top.c.center.y + gnome.bolts.low.c.center.y) / 2 == 40 mm,
        "sign's middle 40 mm below the boots"
    assert sign.plate.bb.width == 130 mm and sign.plate.bb.height == 60 mm, "sign 130 x 60"
    assert sign.word.w.bb.width <= 130 mm - 2 * 8 mm, "WELCOME inside the sign with margins"
    assert distance(sign.word.w, sign.top.c) >= 3 mm and distance(sign.word.w, sign.low.c) >= 3 mm,
        "letters clear of the bolt holes"
    assert gnome.bolts.top.c.diameter + 2 * 4 mm <= stake_w, "wood either side of the bolt in the stake"
}
