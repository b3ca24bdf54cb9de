# Request: a 15-string lap harp (C4 to C6, C major), built as a stack. Strings 14 mm apart,
# running up from a straight row of 2 mm hitch-pin holes to a slanted row of zither tuning
# pins: the longest string (left) 330 mm, the shortest (right) 150 mm. Outline 22 mm outside
# the outer strings and below the hitch pins, 25 mm above the tuning pins, corners r10.
# Top (soundboard): 3 mm plywood with 5.2 mm clearance holes for the tuning pins, the 2 mm
# hitch-pin holes, a 60 mm sound hole ringed by twelve 5 mm holes on a 40 mm radius, and each
# string's note engraved 5 mm tall under its hitch pin. Four 6 mm plywood frame rings below it
# (24 mm deep), solid as pin blocks 20 mm below the tuning pins and 20 mm above the hitch
# pins, 15 mm wide at the sides, with 4.7 mm pilot holes for the tuning pins and 2 mm ones for
# the hitch pins. A 3 mm plywood back, the outline alone.

units mm
thickness 3 mm

N = 15
PITCH = 14 mm
L_LONG = 330 mm
L_SHORT = 150 mm
NOTES = ["C", "D", "E", "F", "G", "A", "B", "C", "D", "E", "F", "G", "A", "B", "C"]

def sx(i) = i * PITCH
def pin_y(i) = L_LONG - i * (L_LONG - L_SHORT) / (N - 1)
# the tuning-pin line at any x
def pin_line(x) = L_LONG - x * (L_LONG - L_SHORT) / sx(N - 1)

X0 = -22 mm
X1 = (N - 1) * PITCH + 22 mm
Y0 = -22 mm

def harp_outline() -> solid {
    body = Polygon([(X0, Y0), (X1, Y0), (X1, pin_line(X1) + 25 mm), (X0, pin_line(X0) + 25 mm)])
    Fillet(10)
}

def frame_ring() -> solid {
    thickness 6 mm
    body = Polygon([(X0, Y0), (X1, Y0), (X1, pin_line(X1) + 25 mm), (X0, pin_line(X0) + 25 mm)])
    hole well {
        w = Polygon([(X0 + 15 mm, 20), (X1 - 15 mm, 20), (X1 - 15 mm, pin_line(X1 - 15 mm) - 20 mm),
                     (X0 + 15 mm, pin_line(X0 + 15 mm) - 20 mm)])
    }
    hole pins {
        for i in range(N) {
            tune = Circle(center=(sx(i), pin_y(i)), diameter=4.7)
            hitch = Circle(center=(sx(i), 0), diameter=2)
        }
    }
    Fillet(10)
}

assembly lap_harp {
    solid top {
        body = Polygon([(X0, Y0), (X1, Y0), (X1, pin_line(X1) + 25 mm), (X0, pin_line(X0) + 25 mm)])
        hole pins {
            for i in range(N) {
                tune = Circle(center=(sx(i), pin_y(i)), diameter=5.2)
                hitch = Circle(center=(sx(i), 0), diameter=2)
            }
        }
        hole sound { c = Circle(center=(70, 130), diameter=60) }
        hole rosette {
            for k in range(12) {
                r = Circle(center=(70 + 40 * cos(k * 30 deg), 130 + 40 * sin(k * 30 deg)),
                           diameter=5)
            }
        }
        drawing notes {
            for i in range(N) {
                t = Text(NOTES[i], position=(sx(i), -10), size=5, valign="top")
            }
        }
        Fillet(10)
    }
    ring1 = frame_ring()
    ring2 = frame_ring()
    ring3 = frame_ring()
    ring4 = frame_ring()
    back = harp_outline()

    # 3D: back at the bottom, four rings, the soundboard on top
    Place(back, position=(0, 0, 0))
    Place(ring4, position=(0, 0, 3))
    Place(ring3, position=(0, 0, 9))
    Place(ring2, position=(0, 0, 15))
    Place(ring1, position=(0, 0, 21))
    Place(top, position=(0, 0, 27))

    # the sheet
    RightOf(ring1, top, gap=5)
    RightOf(ring2, ring1, gap=5)
    Below(ring3, top, gap=5)
    RightOf(ring4, ring3, gap=5)
    RightOf(back, ring4, gap=5)
    AlignTop(ring1, top)
    AlignTop(ring2, top)
    AlignTop(ring4, ring3)
    AlignTop(back, ring3)

    # the request's numbers
    assert len(top.pins.tune) == 15 and len(NOTES) == 15, "15 strings"
    assert top.pins.tune[1].center.x - top.pins.tune[0].center.x == 14 mm, "14 mm apart"
    assert top.pins.tune[0].center.y - top.pins.hitch[0].center.y == 330 mm, "longest 330"
    assert top.pins.tune[14].center.y - top.pins.hitch[14].center.y == 150 mm, "shortest 150"
    assert top.sound.c.diameter == 60 mm, "60 mm sound hole"
    assert top.pins.hitch[0].center.y - ring1.well.w.bb.bottom == -20 mm,
        "pin block 20 above the hitch pins"
    assert ring1.pins.tune[0].center.y - ring1.well.w.points[3].y >= 20 mm,
        "pin block 20 below the tuning pins"
    # the sound hole and its rosette stay off the pin blocks
    assert top.rosette.bb.bottom >= ring1.well.w.bb.bottom + 3 mm, "rosette over the well"
}
