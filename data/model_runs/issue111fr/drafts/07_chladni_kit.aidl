# Request: a Chladni-figure kit for a school science club, all 3 mm (plates in acrylic).
# A loudspeaker driver under a sand tray shakes a plate through an M4 stud.
# - Three plates, each with a 4.2 mm centre hole for the stud and an engraved centring
#   cross (four 6 mm dashes from 4 to 10 mm off the centre, clear of the hole), and its
#   name engraved 5 mm tall 20 mm in from its bottom edge:
#   a square 200 x 200 ("SQUARE 200"), a disc 200 across ("ROUND 200"), and a violin
#   shape 240 long, 142 across the lower bout, with pointed C-bout corners ("VIOLIN"),
#   its stud hole at its middle (the waist).
# - A hub: a 40 mm disc with the 4.2 mm stud hole and six 3.2 mm holes on a 30 mm circle
#   to bolt to the driver's cone adapter.
# - A sand tray: an open finger-jointed box 260 x 260 x 40 outside, 10 mm fingers, a 30 mm
#   hole in the middle of its bottom for the stud to come up from the driver.
# - Assembled: the square plate 80 above the bench on the hub, over the tray.

import "std/joints.aidl"
import "std/shapes.aidl"

thickness 3 mm

STUD = 4.2 mm
RIGHT = [(0, -120), (40, -114), (64, -96), (71, -68), (66, -46), (46, -30), (42, -6),
         (46, 14), (58, 24), (58, 50), (50, 88), (30, 112), (0, 120)]
LEFT = [(-RIGHT[11 - k][0], RIGHT[11 - k][1]) for k in range(11)]
VIOLIN = RIGHT + LEFT

def centre_marks() -> drawing {
    n = Line((0, 4), (0, 10))
    s = Line((0, -4), (0, -10))
    e = Line((4, 0), (10, 0))
    w = Line((-4, 0), (-10, 0))
}

assembly chladni {
    solid square {
        body = Rectangle(center=(0, 0), width=200, height=200)
        hole stud { c = Circle(center=(0, 0), diameter=STUD) }
        marks = centre_marks()
        drawing name { t = Text("SQUARE 200", position=(0, -80), size=5) }
    }
    solid round {
        body = Circle(center=(0, 0), diameter=200)
        hole stud { c = Circle(center=(0, 0), diameter=STUD) }
        marks = centre_marks()
        drawing name { t = Text("ROUND 200", position=(0, -80), size=5) }
    }
    solid violin {
        body = Spline(VIOLIN, closed=true, corners=[4, 8, 16, 20])
        hole stud { c = Circle(center=(0, 0), diameter=STUD) }
        marks = centre_marks()
        drawing name { t = Text("VIOLIN", position=(0, -100), size=5) }
    }
    solid hub {
        disc = Circle(center=(0, 0), diameter=40)
        hole stud { c = Circle(center=(0, 0), diameter=STUD) }
        bolts = bolt_circle(count=6, pcd=30 mm, hole_d=3.2 mm)
    }

    tray = finger_box(length=260 mm, depth=260 mm, height=40 mm, thickness=3 mm, finger=10 mm,
                      closed=false)
    hole feed { c = Circle(center=(0, 0), diameter=30) }
    Coincident(feed.c.center, tray.bottom.outline.center)
    CutInto(feed, tray.bottom)

    # flat: the plates and the hub in a row right of the tray's net
    RightOf(square, tray, gap=10)
    AlignBottom(square, tray)
    RightOf(round, square, gap=10)
    AlignBottom(round, tray)
    RightOf(violin, round, gap=10)
    AlignBottom(violin, tray)
    RightOf(hub, violin, gap=10)
    AlignBottom(hub, tray)

    # assembled: hub and square plate on the stud, 80 above the bench
    Place(hub, position=(0, 0, 77))
    Place(square, position=(0, 0, 80))

    assert square.body.bb.width == 200 mm and square.body.bb.height == 200 mm, "square 200"
    assert round.body.diameter == 200 mm, "round 200"
    assert violin.body.points[12].y - violin.body.points[0].y == 240 mm, "violin 240 long"
    assert violin.body.points[3].x - violin.body.points[21].x == 142 mm, "lower bout 142"
    assert violin.stud.c.center.y == (violin.body.points[12].y + violin.body.points[0].y) / 2,
        "stud at the violin's middle"
    assert square.stud.c.diameter == 4.2 mm, "M4 stud hole"
    assert distance(square.marks, square.stud) >= 1 mm, "cross clear of the hole"
    assert square.marks.n.length == 6 mm, "6 mm dashes"
    assert square.name.t.position.y - square.body.bb.bottom == 20 mm, "square name 20 in"
    assert round.name.t.position.y - round.body.bb.bottom == 20 mm, "round name 20 in"
    assert violin.name.t.position.y - violin.body.points[0].y == 20 mm, "violin name 20 in"
    assert hub.disc.diameter == 40 mm and len(hub.bolts.bolt) == 6, "hub 40, six bolts"
    assert hub.bolts.pitch.diameter == 30 mm and hub.bolts.bolt[0].diameter == 3.2 mm,
        "30 mm PCD, 3.2 mm holes"
    assert tray.bottom.outline.bb.width == 260 mm, "tray 260"
    assert feed.c.diameter == 30 mm, "30 mm feed hole"
}
