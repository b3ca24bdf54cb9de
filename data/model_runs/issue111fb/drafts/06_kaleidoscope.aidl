# Request: a kaleidoscope, all parts 3 mm thick. A square tube 50 x 50 mm outside and 200 mm
# long from four 3 mm ply walls finger-jointed along their long edges (10 mm fingers), holding
# three 30 mm wide mirror strips (bought) as an equilateral triangle. The front wall has
# "KALEIDOSCOPE" engraved filled (bold, 8 mm) along it; the back wall a row of six filled
# five-point stars (12 mm across the tips) 28 mm apart. At the eye end: a 50 x 50 cap with a
# 9 mm eye hole ringed by an engraved 16 mm circle, and inside the tube under it a spacer
# plate (the tube's 44 mm inside less 0.4 mm) with a 30 mm equilateral triangular window
# whose centroid is on the eye hole, which the mirrors butt against. At the object end:
# a clear acrylic window 50 x 50, two 3 mm ply frames 50 x 50 with a 36 mm round opening
# (a 6 mm deep chamber for beads), and a frosted acrylic end plate 50 x 50 with eight 4 mm
# filled dots engraved on a 24 mm circle.

import "std/joints.aidl"

thickness 3 mm
t = 3 mm

tube = 50 mm
tube_len = 200 mm
inside = tube - 2 * t
mirror = 30 mm

def wall(edges="fingers") -> solid {
    p = finger_panel(width=tube, height=tube_len, thickness=t, finger=10, bottom="flat", top="flat",
                     left=edges, right=edges, cx=0, cy=tube_len / 2)
}

def square_plate() -> solid {
    plate = Rectangle(center=(0, 0), width=tube, height=tube)
}

def frame() -> solid {
    plate = Rectangle(center=(0, 0), width=tube, height=tube)
    hole chamber { c = Circle(center=(0, 0), diameter=36) }
}

assembly kaleidoscope {
    front = wall(edges="fingers")
    back = wall(edges="fingers")
    left = wall(edges="slots")
    right = wall(edges="slots")

    drawing name {
        word = Text("KALEIDOSCOPE", position=(0, 0), size=8, font="sans:Bold", fill=true,
                    valign="middle", rotation=90)
    }
    At(name.word.position, front.p.outline.center)
    CutInto(name, front)

    drawing stars {
        s = Star(center=(0, 0), points=5, outer_radius=6, inner_radius=2.5, fill=true)
        row = LinearPattern(s, 6, (0, 28))
    }
    At(stars.s.center, back.p.outline.center, dy=-70)
    CutInto(stars, back)

    solid eye_cap {
        plate = Rectangle(center=(0, 0), width=tube, height=tube)
        hole eye { c = Circle(center=(0, 0), diameter=9) }
        drawing ring { r = Circle(center=(0, 0), diameter=16) }
    }

    solid spacer {
        plate = Rectangle(center=(0, 0), width=inside - 0.4, height=inside - 0.4)
        hole window {
            tri = Triangle(center=(0, 0), base=mirror, height=mirror * sqrt(3) / 2)
        }
        Coincident(window.tri.centroid, plate.center)
    }

    window = square_plate()
    frame_1 = frame()
    frame_2 = frame()

    solid end_plate {
        plate = Rectangle(center=(0, 0), width=tube, height=tube)
        drawing dots {
            d = Circle(center=(12, 0), diameter=4, fill=true)
        }
        ring = CircularPattern(dots.d, 8, plate.center)
    }

    # on the sheet: the walls in a row, the end pieces in two columns beside them
    RightOf(left, front, gap=4)
    AlignBottom(left, front)
    RightOf(back, left, gap=4)
    AlignBottom(back, left)
    RightOf(right, back, gap=4)
    AlignBottom(right, back)
    RightOf(eye_cap, right, gap=6)
    AlignTop(eye_cap, right)
    Below(spacer, eye_cap, gap=4)
    AlignCenterX(spacer, eye_cap)
    Below(window, spacer, gap=4)
    AlignLeft(window, eye_cap)
    RightOf(frame_1, eye_cap, gap=4)
    AlignTop(frame_1, eye_cap)
    Below(frame_2, frame_1, gap=4)
    AlignLeft(frame_2, frame_1)
    Below(end_plate, frame_2, gap=4)
    AlignLeft(end_plate, frame_2)

    # in 3D the tube stands on z = 0, the eye end up
    Place(front, position=(0, -tube / 2 + t, 0), face="front", up="up")
    Place(back, position=(0, tube / 2 - t, 0), face="back", up="up")
    Place(left, position=(-tube / 2 + t, 0, 0), face="left", up="up")
    Place(right, position=(tube / 2 - t, 0, 0), face="right", up="up")
    Place(eye_cap, position=(0, 0, tube_len), face="up")
    Place(spacer, position=(0, 0, tube_len - t), face="up")
    Place(window, position=(0, 0, 0), face="down")
    Place(frame_1, position=(0, 0, -t), face="down")
    Place(frame_2, position=(0, 0, -2 * t), face="down")
    Place(end_plate, position=(0, 0, -3 * t), face="down")

    # the request's numbers
    assert front.p.outline.width == 50 mm and front.p.outline.height == 200 mm, "tube 50 x 200"
    assert eye_cap.eye.c.diameter == 9 mm and eye_cap.ring.r.diameter == 16 mm, "eye 9, ring 16"
    assert spacer.plate.width == 44 mm - 0.4 mm, "spacer fits the 44 mm inside"
    assert spacer.window.tri.base == 30 mm, "30 mm mirror triangle"
    assert distance(spacer.window.tri.centroid, spacer.plate.center) < 0.001 mm,
        "the triangle's centroid on the axis"
    assert frame_1.chamber.c.diameter == 36 mm, "36 mm chamber"
    assert len(stars.row) == 6, "six stars"
    assert stars.row[1].center.y - stars.row[0].center.y == 28 mm, "stars 28 apart"
    assert stars.s.bb.height <= 12 mm, "stars 12 across the tips"
    assert len(end_plate.ring) == 8, "eight dots"
    assert distance(end_plate.dots.d.center, end_plate.plate.center) == 12 mm, "on a 24 circle"
    assert name.word.bb.height <= tube_len - 20 mm and name.word.bb.width <= inside - 10 mm,
        "the name fits along the wall"
}
