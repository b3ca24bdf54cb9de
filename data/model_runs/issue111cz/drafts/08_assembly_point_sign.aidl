# Request (signs): a "fire assembly point" sign for the makerspace car park, two layers of 3 mm
# acrylic glued and screwed to a post: a white back plate and a green front plate, both
# 300 x 400 mm with 15 mm corner radii and four M5 clearance holes 15 mm in from each side at
# the corners (countersunk 10 mm on the front plate only). The front plate has the pictogram
# and the words cut through so the white shows: in a 260 mm square centred 20 mm below the top
# edge, four arrows pointing diagonally in to the centre (tips 75 mm from the centre, heads
# 40 mm wide and 25 mm long, stems 16 mm wide and 25 mm long), and a group of three people in
# the middle (middle figure: 8 mm radius head, 22 x 40 body with 6 mm radii; the two others
# 30 mm either side and 6 mm lower); below it "ASSEMBLY" and "POINT" in bold stencil letters
# 32 mm tall, centred, the first baseline 80 mm and the second 35 mm above the bottom edge.

import "std/fasteners.aidl"

thickness 3 mm

W = 300 mm
H = 400 mm
PICT = 260 mm
PC_Y = H / 2 - 20 mm - PICT / 2      # the pictogram's centre (plate centred at 0, 0)

def plate(sunk=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=15 mm)
    screw = clearance_hole(size=5)
    Fixed(body)
    screws = CornerPattern(screw, body, inset=15 mm)
    if sunk {
        Countersink(screw, diameter=10 mm)
    }
}

def person(dx=0 mm, dy=0 mm) -> hole {
    head = Circle(center=(dx, PC_Y + dy + 20 mm), radius=8 mm)
    body = RoundedRectangle(center=(dx, PC_Y + dy - 12 mm), width=22 mm, height=40 mm,
                            corner_radius=6 mm)
}

assembly sign {
    back = plate(sunk=false)

    solid front {
        base = plate(sunk=true)
        # one arrow on +x pointing left at the centre; the pattern puts four on the diagonals
        hole arrow {
            p = Polygon([(75 mm, PC_Y), (100 mm, PC_Y + 20 mm), (100 mm, PC_Y + 8 mm),
                         (125 mm, PC_Y + 8 mm), (125 mm, PC_Y - 8 mm), (100 mm, PC_Y - 8 mm),
                         (100 mm, PC_Y - 20 mm)])
        }
        arrows = CircularPattern(arrow, 4, (0, PC_Y), start_angle=45 deg)
        mid = person(dx=0 mm, dy=0 mm)
        left = person(dx=-30 mm, dy=-6 mm)
        right = person(dx=30 mm, dy=-6 mm)
        hole words {
            w1 = Text("ASSEMBLY", position=(0, -H / 2 + 80 mm), size=32 mm, font="sans:Bold",
                      stencil=true)
            w2 = Text("POINT", position=(0, -H / 2 + 35 mm), size=32 mm, font="sans:Bold",
                      stencil=true)
        }
    }

    RightOf(front, back, gap=10 mm)

    Place(back, position=(0, 0, 0), face="up")
    Place(front, position=(0, 0, 3 mm), face="up")

    assert back.body.bb.width == 300 mm and back.body.bb.height == 400 mm, "300 x 400"
    assert len(front.arrows) == 4, "four arrows"
    assert front.base.screws[0].c.center.x - front.base.body.bb.left == 15 mm, "holes 15 in"
    assert front.words.w1.size == 32 mm and front.words.w2.size == 32 mm, "32 mm letters"
    assert front.words.w1.position.y - front.base.body.bb.bottom == 80 mm, "ASSEMBLY 80 up"
    assert front.words.w2.position.y - front.base.body.bb.bottom == 35 mm, "POINT 35 up"
    assert front.base.body.bb.top - (PC_Y + PICT / 2) == 20 mm, "pictogram 20 below the top"
    assert front.left.body.center.x - front.mid.body.center.x == -30 mm, "figures 30 apart"
}
