# Request: the two fretwork end plates for the 20-button Anglo concertina I am building, from
# 3 mm birch ply. Each is a hexagon 152 mm across flats (flats at top and bottom) with:
# - six M2.5 clearance holes for the end bolts, one towards each corner, 77 mm from the
#   centre on the line to the corner;
# - ten 6.5 mm button holes in two rows of five at 14 mm pitch: the outer row centred on
#   x = 0, 30 mm above the centre; the inner row 16 mm above the centre, shifted 7 mm towards
#   the little finger (the right end is the mirror image of the left);
# - on the right end only, an 8 mm air-button hole 30 mm towards the thumb and 15 mm below
#   the centre;
# - fretwork: a ring of twelve 16 x 7 mm elliptical openings on a 56 mm radius, pointing at
#   the centre, midway between the corner directions and the flats (15 deg + k * 30 deg),
#   and a six-pointed star opening (10 / 5 mm radii) 25 mm below the centre;
# - "KOWALSKI 2026" engraved 4.5 mm tall, centred, baseline 71 mm below the centre.
# Fretwork keeps at least 2 mm from the button holes and the engraving.

import "std/fasteners.aidl"

thickness 3 mm

def end_plate(s=1, air=false) -> solid {
    plate = RegularPolygon(center=(0, 0), across_flats=152 mm, sides=6)
    for k in range(6) {
        screw = clearance_hole(size=2.5, cx=77 mm * cos(k * 60 deg), cy=77 mm * sin(k * 60 deg))
    }
    for i in range(5) {
        hole outer { c = Circle(center=(s * (-28 mm + i * 14 mm), 30 mm), diameter=6.5 mm) }
        hole inner { c = Circle(center=(s * (-21 mm + i * 14 mm), 16 mm), diameter=6.5 mm) }
    }
    if air {
        hole air_hole { c = Circle(center=(-s * 30 mm, -15 mm), diameter=8 mm) }
    }
    for k in range(12) {
        hole fret {
            e = Ellipse(center=polar((0, 0), 56 mm, 15 deg + k * 30 deg), rx=8 mm, ry=3.5 mm,
                        rotation=15 deg + k * 30 deg)
        }
    }
    hole rosette { st = Star(center=(0, -25 mm), points=6, outer_radius=10 mm, inner_radius=5 mm) }
    drawing name { t = Text("KOWALSKI 2026", position=(0, -71 mm), size=4.5) }
}

assembly ends {
    left = end_plate(s=1, air=false)
    right = end_plate(s=-1, air=true)
    RightOf(right, left, gap=8)
    AlignBottom(right, left)

    assert left.plate.across_flats == 152 mm and right.plate.across_flats == 152 mm, "152 across flats"
    assert abs(left.plate.points[0].y - left.plate.center.y) < 0.001 mm, "a corner on +x: flats top and bottom"
    assert len(left.screw) == 6 and len(right.screw) == 6, "six end bolts"
    assert distance(left.screw[0].c.center, left.plate.center) == 77 mm, "bolts 77 from the centre"
    assert left.screw[0].c.diameter == 2.9 mm, "M2.5 clearance"
    assert len(left.outer) + len(left.inner) == 10, "ten buttons a side"
    assert left.outer[0].c.diameter == 6.5 mm and right.inner[0].c.diameter == 6.5 mm, "6.5 mm button holes"
    assert left.outer[1].c.center.x - left.outer[0].c.center.x == 14 mm, "14 mm pitch"
    assert left.outer[2].c.center.x - left.plate.center.x == 0 mm, "outer row centred"
    assert left.outer[0].c.center.y - left.plate.center.y == 30 mm, "outer row 30 above"
    assert left.inner[0].c.center.y - left.plate.center.y == 16 mm, "inner row 16 above"
    assert left.inner[0].c.center.x - left.outer[0].c.center.x == 7 mm, "inner row shifted 7"
    assert (right.outer[0].c.center.x - right.plate.center.x) == -(left.outer[0].c.center.x - left.plate.center.x), "right end mirrors the left"
    assert right.air_hole.c.diameter == 8 mm, "8 mm air button"
    assert right.air_hole.c.center.y - right.plate.center.y == -15 mm, "air button 15 below"
    assert len(left.fret) == 12, "twelve fretwork openings"
    assert distance(left.fret[0].e.center, left.plate.center) == 56 mm, "fretwork on 56 mm"
    assert left.rosette.st.center.y - left.plate.center.y == -25 mm, "star 25 below"
    assert left.name.t.size == 4.5 mm, "4.5 mm engraving"
    assert left.name.t.position.y - left.plate.center.y == -71 mm, "baseline 71 below"
    assert distance(left.name, left.fret) >= 2 mm, "engraving clear of the fretwork"
    assert distance(left.fret, left.outer) >= 2 mm and distance(left.fret, left.inner) >= 2 mm, "fretwork clear of the buttons"
    assert distance(right.fret, right.air_hole) >= 2 mm, "fretwork clear of the air button"
    assert distance(left.rosette, left.name) >= 2 mm, "star clear of the engraving"
}
