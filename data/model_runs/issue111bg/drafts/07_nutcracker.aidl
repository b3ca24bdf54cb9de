# Request (holidays): a flat nutcracker soldier to stand on the mantelpiece at Christmas, cut
# from 6 mm ply. The figure is a symmetric silhouette 240 mm tall from the boot soles to the
# top of the hat: a hat 48 mm wide with a 56 mm brim at 190-196 mm, a face 40 mm wide, a jacket
# 76 mm wide across the arms, legs with an 8 mm gap between them up to 60 mm. Engraved: two
# filled eyes, a nose, a filled moustache, a filled star badge on the hat and the hat band,
# four filled buttons down the jacket, a belt with a buckle, the arms' inner edges and the boot
# tops. It stands in a 120 x 60 mm plinth (R8 corners) with one 14 mm glued tab under each
# boot, its face 2 mm behind the plinth's middle line; "MERRY CHRISTMAS" engraved in front.

units mm
thickness 6 mm
import "std/joints.aidl"

T = 6 mm
HALF = [(0, 240), (22, 240), (24, 238), (24, 196), (28, 196), (28, 190), (20, 190),
        (20, 150), (34, 146), (38, 140), (38, 80), (32, 76), (30, 70), (26, 70), (26, 16),
        (30, 12), (32, 6), (32, -T), (4, -T), (4, 60), (0, 60)]

assembly nutcracker {
    solid figure {
        body = Polygon(HALF, mirror="y")
        tenons = tab_and_slot(part="tab", length=64 mm, thickness=T, tabs=2, tab=14 mm,
                              screw=0, rotation=180 deg, cx=0 mm, cy=-T)
        drawing face {
            eye_l = Circle(center=(-8, 172), radius=2, fill=true)
            eye_r = Circle(center=(8, 172), radius=2, fill=true)
            nose = Circle(center=(0, 166), radius=3)
            tash_l = Ellipse(center=(-6, 160), rx=7, ry=2.5, rotation=-15 deg, fill=true)
            tash_r = Ellipse(center=(6, 160), rx=7, ry=2.5, rotation=15 deg, fill=true)
        }
        drawing hat {
            badge = Star(center=(0, 214), points=5, outer_radius=8, inner_radius=3.5, fill=true)
            band = Line((-24, 200), (24, 200))
        }
        drawing jacket {
            for i in range(4) {
                # (FIX, second step: the taller buckle touched the lowest button (W0513):
                # the buttons moved up 2 mm, from 130 - i * 14)
                button = Circle(center=(0, 132 - i * 14), radius=2.5, fill=true)
            }
            belt = Rectangle(center=(0, 80), width=60, height=8)
            # FIX after the first valid program: the buckle, as tall as the belt, burnt the
            # belt's edges twice over 20 mm (W0513). It now stands 2 mm proud of the belt and
            # hides the belt's lines behind it.
            hole behind_buckle { r = Rectangle(center=(0, 80), width=10, height=12) }
            arm_l = Line((-30, 138), (-30, 84))
            arm_r = Line((30, 138), (30, 84))
            boot_l = Line((-25, 22), (-5, 22))
            boot_r = Line((5, 22), (25, 22))
        }
        drawing buckle {
            b = Rectangle(center=(0, 80), width=10, height=12)
        }
    }

    solid plinth {
        body = RoundedRectangle(center=(0, 0), width=120, height=60, corner_radius=8)
        mortises = tab_and_slot(part="slot", length=64 mm, thickness=T, tabs=2, tab=14 mm,
                                screw=0, cx=0 mm, cy=5 mm)
        drawing words {
            t = Text("MERRY CHRISTMAS", position=(0, -17), size=7, valign="middle")
        }
    }

    # flat on the sheet
    RightOf(plinth, figure, gap=10)
    AlignBottom(plinth, figure)

    # assembled: the figure stands upright in the plinth's mortises
    Place(plinth, position=(0, 0, 0))
    Place(figure, position=(0, 5 + T / 2, T), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert figure.body.bb.top - figure.tenons.bb.top == 240 mm, "240 tall above the soles"
    assert figure.body.bb.width == 76 mm, "76 across the arms"
    assert len(figure.jacket.button) == 4, "four buttons"
    assert plinth.body.bb.width == 120 mm and plinth.body.bb.height == 60 mm, "plinth 120 x 60"
    assert plinth.mortises.bb.center_y - plinth.body.center.y == 5 mm, "figure 2 mm behind the middle line"
    assert plinth.words.bb.width <= 120 mm - 2 * 8 mm, "words on the plinth"
    assert plinth.mortises.bb.bottom - plinth.words.bb.top >= 5 mm, "words clear of the figure"
}
