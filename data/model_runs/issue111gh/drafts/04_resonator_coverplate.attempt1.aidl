# Request: a cover plate for the 6-inch biscuit resonator cone in my cigar-box resonator guitar.
# 3 mm walnut ply, 180 mm round. Six M3 countersunk screws (3.5 mm holes, 7 mm heads) on a
# 168 mm circle, the first at 0 deg. A central slot 70 x 20 mm (round ends) across the plate for
# the biscuit's saddle. Eight petal sound holes, ellipses 24 x 8 mm pointing out radially, centred
# 55 mm from the centre at 22.5 deg and every 45 deg after. "HOUND DOG" engraved along the rim over
# the top (5 mm letters, their middle on a 148 mm circle) and "No. 7" under the bottom, the right
# way up. Underneath, a 3 mm spacer ring 180 OD / 150 ID with the same six screw holes, plain.

import "std/shapes.aidl"

thickness 3 mm

assembly resonator {
    solid plate {
        body = Circle(center=(0, 0), diameter=180)
        hole saddle { s = Slot(center=(0, 0), length=70, width=20) }
        hole petal { e = Ellipse(center=(55, 0), rx=12, ry=4) }
        petals = CircularPattern(petal, 8, body.center, start_angle=22.5)
        screws = bolt_circle(count=6, pcd=168, hole_d=3.5, start=0)
        Countersink(screws, diameter=7)
        drawing name {
            ring = Circle(center=(0, 0), diameter=148, construction=true)
            top = Text("HOUND DOG", along=ring, size=5, valign="middle")
            bottom = Text("No. 7", along=ring, size=5, valign="middle", flip=true)
        }
    }
    solid spacer {
        rim = Circle(center=(0, 0), diameter=180)
        hole well { c = Circle(center=(0, 0), diameter=150) }
        screws = bolt_circle(count=6, pcd=168, hole_d=3.5, start=0)
    }
    RightOf(spacer, plate, gap=5)
    AlignTop(spacer, plate)

    Place(spacer, position=(0, 0, 0))
    Place(plate, position=(0, 0, 3))

    assert plate.body.diameter == 180 mm, "180 round"
    assert plate.screws.pitch.diameter == 168 mm, "screws on 168"
    assert len(plate.screws.bolt) == 6, "six screws"
    assert plate.screws.bolt[0].diameter == 3.5 mm, "3.5 mm holes"
    assert plate.saddle.s.length == 70 mm and plate.saddle.s.width == 20 mm, "saddle slot 70 x 20"
    assert len(plate.petals) == 8, "eight petals"
    assert distance(plate.petals[1].e.center, plate.body.center) == 55 mm, "petals at 55"
    assert distance(plate.petal, plate.saddle) >= 5 mm, "petals clear of the slot"
    assert distance(plate.name, plate.screws) >= 1 mm, "lettering clear of the screws"
    assert distance(plate.name, plate.petal) >= 1 mm, "lettering clear of the petals"
    assert spacer.rim.diameter == 180 mm and spacer.well.c.diameter == 150 mm, "ring 180 / 150"
}
