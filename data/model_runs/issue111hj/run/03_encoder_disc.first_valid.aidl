# Request (electronics): an optical encoder for an N20 gear motor (3 mm D-shaft, flat
# 2.5 mm across), two parts in 3 mm black acrylic.
# - disc 60 mm across: 30 windows 2 x 6 mm, radial, centred on a 24 mm radius, evenly
#   spaced; an index hole 3 mm across at 16 mm radius, in line with the first window;
#   a D-bore for the shaft with 0.05 mm clearance all round (3.1 mm round, flat at 2.6 mm);
#   "30 PPR" engraved 4 mm high under the bore.
# - bracket 100 x 70 mm, 4 mm corner radii, four M3 clearance holes 6 mm in from the
#   edges; the motor: a 4.5 mm hole for the shaft's bushing, 12 mm from the plate's left
#   ... i.e. the shaft 38 mm from the left edge and centred in height, and two 1.8 mm
#   holes for its M1.6 screws 9 mm apart, above and below the shaft; the slotted
#   opto-sensor's board: an M3 slot (3.2 mm wide) along the radius, centre 44 mm right
#   of the shaft, 6 mm of travel, so its beam can be set on the windows' 24 mm radius;
#   the disc's outline engraved round the shaft as a guide. The disc must clear the
#   corner screws by 3 mm.
import "std/plates.aidl"

thickness 3 mm

DISC_D = 60 mm
WIN_R = 24 mm

assembly encoder {
    solid disc {
        rim = Circle(center=(0, 0), diameter=DISC_D)
        hole win {
            w = Rectangle(center=(WIN_R, 0), width=6, height=2)
        }
        windows = CircularPattern(win, 30, rim.center)
        hole index {
            c = Circle(center=(16, 0), diameter=3)
        }
        hole bore {
            d = Intersect(Circle(center=(0, 0), diameter=3.1),
                          Rectangle(center=(-0.275, 0), width=2.65, height=3.4))
        }
        drawing label {
            t = Text("30 PPR", position=(0, -10), size=4, valign="middle")
        }
    }

    solid bracket {
        plate = mounting_plate(width=100 mm, height=70 mm, corner_radius=4 mm, screw=3,
                               inset=6 mm, cx=12 mm, cy=0 mm)
        hole shaft {
            c = Circle(center=(0, 0), diameter=4.5)
        }
        hole motor_screws {
            top = Circle(center=(0, 4.5), diameter=1.8)
            bottom = Circle(center=(0, -4.5), diameter=1.8)
        }
        hole sensor {
            s = Slot(center=(44, 0), length=6 + 3.2, width=3.2, rotation=0)
        }
        drawing guide {
            footprint = Circle(center=(0, 0), diameter=DISC_D)
            track = Circle(center=(0, 0), radius=WIN_R, construction=true)
            t = Text("ENC", position=(44, -8), size=4, valign="middle")
        }
    }

    RightOf(bracket, disc, gap=10)
    AlignCenterY(bracket, disc)

    assert len(windows) == 30, "30 windows"
    assert distance(windows[0].w.center, disc.rim.center) == 24 mm, "windows on a 24 mm radius"
    assert distance(disc.index.c.center, disc.rim.center) == 16 mm, "index at 16 mm radius"
    assert disc.rim.diameter == 60 mm, "disc 60 across"
    assert bracket.plate.body.width == 100 mm and bracket.plate.body.height == 70 mm,
        "bracket 100 x 70"
    assert bracket.shaft.c.center.x - bracket.plate.body.bb.left == 38 mm, "shaft 38 from the left"
    assert bracket.sensor.s.center.x - bracket.shaft.c.center.x == 44 mm, "sensor 44 right of the shaft"
    assert bracket.motor_screws.top.center.y - bracket.motor_screws.bottom.center.y == 9 mm,
        "motor screws 9 apart"
    # the spinning disc clears every corner screw hole by 3 mm
    for k in range(4) {
        assert distance(bracket.plate.corner[k].c.center, bracket.shaft.c.center) -
            bracket.plate.corner[k].c.radius >= DISC_D / 2 + 3 mm, "disc clears the corner screws"
    }
}
