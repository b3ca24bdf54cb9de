# Request (camping): the campsite's fire danger board, 9 mm exterior ply.
# - Board: a half disc 560 mm across standing on a 560 x 90 mm strip (370 mm high in all),
#   10 mm round bottom corners.
# - The dial: five equal sectors (36 degrees each) between radii 90 and 270 mm about the half
#   disc's centre, split by engraved radial lines, closed by engraved arcs at 90 and 270 mm;
#   from the left: LOW, MODERATE, HIGH, VERY HIGH, EXTREME, filled bold 18 mm letters along a
#   215 mm radius, each centred in its sector, at most 115 mm long.
# - "FIRE DANGER TODAY" in filled bold 30 mm letters, centred 50 mm below the dial's centre
#   (36 mm centred on the strip, as first asked, ran into the hub and the screws).
# - An 8.5 mm pivot hole at the dial's centre for an M8 bolt and wing nut; three 6.5 mm
#   screw holes to fix it to the post: in the strip 250 mm each side of the middle, 45 mm
#   below the dial's centre, and one at the top, 255 mm above the centre.
# - A pointer: a 50 mm hub round the pivot (8.5 mm hole), a 16 mm shaft and a 44 mm wide
#   arrowhead 40 mm long, its tip 190 mm from the pivot, short of the labels.

t = 9 mm
thickness t

names = ["LOW", "MODERATE", "HIGH", "VERY HIGH", "EXTREME"]

def mid_angle(i) = 162 deg - i * 36 deg

assembly fire_sign {
    solid board {
        dial = Sector(center=(0, 0), radius=280, start_angle=0 deg, end_angle=180 deg)
        strip = Rectangle(center=(0, -45), width=560, height=90)
        hole pivot { c = Circle(center=(0, 0), diameter=8.5) }
        hole screws {
            for i in range(2) {
                s = Circle(center=((2 * i - 1) * 250, -45), diameter=6.5)
            }
            top = Circle(center=(0, 255), diameter=6.5)
        }
        drawing scale {
            outer = Arc(center=(0, 0), radius=270, start_angle=0 deg, end_angle=180 deg)
            inner = Arc(center=(0, 0), radius=90, start_angle=0 deg, end_angle=180 deg)
            for k in range(6) {
                div = Line((90 * cos(k * 36 deg), 90 * sin(k * 36 deg)),
                           (270 * cos(k * 36 deg), 270 * sin(k * 36 deg)))
            }
            ring = Circle(center=(0, 0), radius=215, construction=true)
            for i in range(5) {
                lab = Text(names[i], along=ring, angle=mid_angle(i), size=18, font="sans:Bold",
                           valign="middle", fill=true, max_width=115 mm)
            }
        }
        drawing title {
            word = Text("FIRE DANGER TODAY", position=(0, -50), size=30, font="sans:Bold",
                        valign="middle", fill=true)
        }
        Fillet([strip.bottom_left, strip.bottom_right], 10)
    }

    solid pointer {
        hub = Circle(center=(0, 0), diameter=50)
        arrow = Polygon([(0, -8), (150, -8), (150, -22), (190, 0), (150, 22), (150, 8), (0, 8)])
        hole pivot { c = Circle(center=(0, 0), diameter=8.5) }
    }

    # 3D: the board stands facing front; the pointer on it, turned to HIGH
    Place(board, position=(0, 0, 90 mm), face="front", up="up")
    Place(pointer, on=board, position=(0, 0), rotation=(0, 0, 90 deg))

    # flat layout for cutting
    Below(pointer, board, gap=6 mm)
    AlignLeft(pointer, board)

    # the request's numbers
    assert board.bb.width == 560 mm and board.bb.height == 370 mm, "560 x 370"
    assert board.dial.radius == 280 mm and board.strip.height == 90 mm, "half disc on a 90 mm strip"
    assert len(board.scale.lab) == 5 and len(board.scale.div) == 6, "five sectors"
    assert board.scale.outer.radius == 270 mm and board.scale.inner.radius == 90 mm, "dial 90 to 270"
    assert board.scale.ring.radius == 215 mm, "labels on 215"
    for i in range(5) {
        assert distance(board.scale.lab[i], board.scale.div) >= 3 mm, "label clear of the lines"
        assert distance(board.scale.lab[i], board.scale.outer) >= 3 mm, "label inside the dial"
    }
    assert distance(board.pivot.c.center, board.dial.center) < 0.01 mm, "pivot at the centre"
    assert board.screws.s[1].center.x - board.screws.s[0].center.x == 2 * 250 mm, "250 each side"
    assert board.dial.center.y - board.screws.s[0].center.y == 45 mm, "45 below the centre"
    assert board.screws.top.center.y - board.dial.center.y == 255 mm, "top screw 255 up"
    assert distance(board.screws, board.scale.lab[2]) >= 3 mm, "top screw clear of HIGH"
    assert distance(board.screws, board.title) >= 5 mm, "screws clear of the title"
    assert board.title.word.bb.top <= board.pivot.c.center.y - 25 mm - 3 mm,
        "title clear of the pointer's hub"
    assert pointer.hub.diameter == 50 mm and pointer.arrow.bb.right - pointer.hub.center.x == 190 mm,
        "50 mm hub, tip 190 from the pivot"
    assert 190 mm < 215 mm - 18 mm / 2, "the tip stops short of the labels"
    assert board.bb.width <= 600 mm and board.bb.height <= 400 mm, "fits the bed"
}
