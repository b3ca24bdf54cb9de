# Request: a 4-hole pendant ocarina cut as a glued stack of five layers. The outline: a 64 mm
# round body that tapers on tangent lines to an 18 mm round mouthpiece end centred 48 mm from
# the body's centre, and on the other side to a 12 mm round lug centred 34 mm out with a 4 mm
# lanyard hole 35 mm from the centre through every layer. From the bottom:
# - back, 3 mm plywood, solid, its outside face engraved "OCARINA" (7 mm serif, filled) and
#   "IN C" (5 mm) under it;
# - two chamber layers, 6 mm plywood: a 52 mm round cavity (a 6 mm wall round it);
# - windway layer, 1.5 mm acrylic: the same cavity and an 8 mm wide windway channel from the
#   mouthpiece end into the cavity;
# - top, 3 mm plywood: a window 5 mm long and 8 mm wide, starting 1 mm before the cavity's edge
#   over the windway (its far edge the labium); four finger holes of 10, 8, 7 and 5 mm at
#   (-5, 14), (12, 12), (-5, -14) and (12, -12) mm from the centre, each at least 2 mm inside
#   the cavity's edge.

thickness 3 mm

BODY_R = 32 mm
CAVITY_R = 26 mm
HOLE_X = [-5 mm, 12 mm, -5 mm, 12 mm]
HOLE_Y = [14 mm, 12 mm, -14 mm, -12 mm]
HOLE_D = [10 mm, 8 mm, 7 mm, 5 mm]

def outline() -> solid {
    shape = Hull(Circle(center=(0, 0), radius=BODY_R), Circle(center=(-48 mm, 0), radius=9 mm),
                 Circle(center=(34 mm, 0), radius=6 mm))
    centre = Point(0, 0, construction=true)     # the body's (and the cavity's) centre
    hole lanyard {
        c = Circle(center=(35 mm, 0), diameter=4 mm)
    }
}

assembly ocarina {
    solid back {
        o = outline()
        drawing name {
            word = Text("OCARINA", position=(0, 6 mm), size=7 mm, font="serif", valign="middle",
                        fill=true)
            key = Text("IN C", position=(0, -8 mm), size=5 mm, valign="middle")
        }
    }
    solid chamber_1 {
        thickness 6 mm
        o = outline()
        hole cavity {
            c = Circle(center=(0, 0), radius=CAVITY_R)
        }
    }
    solid chamber_2 {
        thickness 6 mm
        o = outline()
        hole cavity {
            c = Circle(center=(0, 0), radius=CAVITY_R)
        }
    }
    solid windway {
        thickness 1.5 mm
        o = outline()
        hole cavity {
            c = Circle(center=(0, 0), radius=CAVITY_R)
            channel = Rectangle(corner=(-60 mm, -4 mm), opposite=(-24 mm, 4 mm))
        }
    }
    solid top {
        o = outline()
        hole window {
            w = Rectangle(center=(-CAVITY_R - 1 mm + 2.5 mm, 0), width=5 mm, height=8 mm)
        }
        hole fingers {
            for i in range(4) {
                h = Circle(center=(HOLE_X[i], HOLE_Y[i]), diameter=HOLE_D[i])
            }
        }
    }

    # flat on the sheet: a row
    RightOf(chamber_1, back, gap=6 mm)
    AlignTop(chamber_1, back)
    RightOf(chamber_2, chamber_1, gap=6 mm)
    AlignTop(chamber_2, chamber_1)
    Below(windway, back, gap=6 mm)
    AlignLeft(windway, back)
    RightOf(top, windway, gap=6 mm)
    AlignTop(top, windway)

    # in 3D: the back's engraved face down (outside), then the layers upward
    Place(back, position=(0, 0, 3 mm), face="down", up="front")
    Place(chamber_1, position=(0, 0, 3 mm))
    Place(chamber_2, position=(0, 0, 9 mm))
    Place(windway, position=(0, 0, 15 mm))
    Place(top, position=(0, 0, 16.5 mm))

    assert back.o.shape.bb.height == 64 mm, "64 mm body"
    assert back.o.shape.bb.width == 9 mm + 48 mm + 34 mm + 6 mm, "mouth end to lug end"
    assert back.o.lanyard.c.diameter == 4 mm, "4 mm lanyard hole"
    assert back.o.lanyard.c.center.x - back.o.shape.bb.left == 48 mm + 9 mm + 35 mm,
        "lanyard hole 35 from the centre"
    assert chamber_1.cavity.c.diameter == 52 mm and chamber_2.cavity.c.diameter == 52 mm,
        "52 mm cavity"
    assert windway.cavity.channel.bb.height == 8 mm, "8 mm windway"
    assert top.window.w.bb.width == 5 mm and top.window.w.bb.height == 8 mm, "window 5 x 8"
    assert (top.o.shape.bb.left + 48 mm + 9 mm) - top.window.w.bb.left == 26 mm + 1 mm,
        "window starts 1 mm before the cavity"
    assert len(top.fingers.h) == 4, "four finger holes"
    assert top.fingers.h[0].diameter == 10 mm and top.fingers.h[1].diameter == 8 mm and
        top.fingers.h[2].diameter == 7 mm and top.fingers.h[3].diameter == 5 mm, "hole sizes"
    for i in range(4) {
        assert distance(top.fingers.h[i].center, top.o.centre) + top.fingers.h[i].radius
            <= 26 mm - 2 mm, "finger holes 2 mm inside the cavity"
    }
    assert distance(top.window, top.fingers) >= 3 mm, "window clear of the finger holes"
    assert distance(back.name, back.o.lanyard) >= 2 mm, "name clear of the lanyard hole"
    assert back.name.bb.width <= 2 * 26 mm, "name within the body"
}
