# PROBE (not counted): attempt 1 without the saddle, to see which mark W0513 measured
# Request: a "bike parking" sign for the office bike shed, 3 mm two-colour laminate (blue face,
# white core), 200 x 300 mm portrait, R10 corners. Everything white is engraved filled:
# - a border band 4 mm wide, 4 mm in from the edge (corners R6 on its outer line);
# - a bold "P" 90 mm high, centred 80 mm above the middle;
# - a bicycle pictogram facing right, its wheels' centres 25 mm below the middle and 104 mm
#   apart: wheels are rings 60 mm outside, 5 mm wide, with 6 mm hub dots; the frame, fork,
#   seat post, saddle and handlebar are 4 mm bands;
# - "BIKE PARKING" in bold, 16 mm high, centred 90 mm below the middle.
# Four M5 screw holes (medium fit), 14 mm in from each edge, clear of the border band.

import "std/fasteners.aidl"

thickness 3 mm

bx = 0 mm
by = -25 mm
def pt(x, y) = (bx + x, by + y)

solid sign {
    body = RoundedRectangle(center=(0, 0), width=200, height=300, corner_radius=10)
    Fixed(body)

    screw = clearance_hole(size=5)
    screws = CornerPattern(screw, body, inset=14)

    drawing face {
        border = Shell(RoundedRectangle(center=(0, 0), width=192, height=292, corner_radius=6), -4, fill=true)
        p = Text("P", position=(0, 80), size=90, valign="middle", font="sans:Bold", fill=true)
        words = Text("BIKE PARKING", position=(0, -90), size=16, valign="middle", font="sans:Bold", fill=true)
    }
    drawing bike {
        rear = Shell(Circle(center=pt(-52, 0), radius=25), 5, fill=true)
        front = Shell(Circle(center=pt(52, 0), radius=25), 5, fill=true)
        rear_hub = Circle(center=pt(-52, 0), diameter=6, fill=true)
        front_hub = Circle(center=pt(52, 0), diameter=6, fill=true)
        chain_side = Stroke(Polyline([pt(-52, 0), pt(-5, 0), pt(40, 40), pt(52, 0)]), width=4, fill=true)
        seat_side = Stroke(Polyline([pt(-52, 0), pt(-20, 45), pt(-5, 0)]), width=4, fill=true)
        top_tube = Stroke(Line(pt(-20, 45), pt(40, 40)), width=4, fill=true)
        post = Stroke(Line(pt(-20, 45), pt(-23, 54)), width=4, fill=true)
        bars = Stroke(Polyline([pt(40, 40), pt(35, 56), pt(46, 58)]), width=4, fill=true)
    }

    assert body.bb.width == 200 mm and body.bb.height == 300 mm, "sign 200 x 300"
    assert len(screws) == 4, "four screws"
    assert screws[0].c.center.x - body.bb.left == 14 mm and screws[0].c.center.y - body.bb.bottom == 14 mm, "screws 14 in"
    assert distance(screws[0], face.border) >= 2 mm, "screws clear of the border"
    assert face.p.position.y - body.center.y == 80 mm, "P 80 above the middle"
    assert face.words.position.y - body.center.y == -90 mm, "words 90 below the middle"
    assert distance(bike.rear_hub.center, bike.front_hub.center) == 104 mm, "wheelbase 104"
    assert bike.rear.bb.width == 60 mm, "wheels 60 outside"
    assert distance(face.p, bike) >= 0 mm, "probe: report the distance"
    assert distance(face.words, bike) >= 8 mm, "words clear of the bike"
    assert distance(face.words, face.border) >= 3 mm, "words clear of the border"
    assert distance(bike, face.border) >= 3 mm, "bike clear of the border"
}
