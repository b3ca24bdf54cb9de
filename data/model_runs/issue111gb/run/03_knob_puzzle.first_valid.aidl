# Request (toys): a toddler's inset knob puzzle in 6 mm poplar ply, five parts.
# - Board 300 x 140 mm with 10 mm corner radii, two layers glued: a backing, and a frame
#   layer with three openings whose centres are 95 mm apart along the long centre line:
#   a five-pointed star (outer radius 42 mm, inner 20 mm, tips rounded 5 mm), a heart 82 mm
#   wide and 72 mm tall (two round lobes over a point), and a house (a body 56 mm wide and
#   44 mm tall under a roof 76 mm wide and 32 mm tall).
# - The three pieces are the shapes 0.5 mm smaller all round than their openings, each
#   with an 8 mm hole for a wooden knob (an 8 mm dowel) at its middle (the heart's between
#   the lobes' centres, the house's in the middle of its body).
# - On the backing, under each opening, the shape's name (STAR, HEART, HOUSE) engraved
#   filled, bold, 8 mm tall, centred where the piece's knob is.
# Assembled: backing, the frame glued on top, the pieces in their openings.

units mm
thickness 6 mm

def star_at(x, y) = Star(center=(x, y), points=5, outer_radius=42, inner_radius=20, tip_radius=5)
def lobe(x, y, side) = Hull(Circle(center=(x + side * 19, y + 12), radius=22), Point(x, y - 38))
def house_at(x, y) = Polygon([(x - 28, y - 38), (x + 28, y - 38), (x + 28, y + 6), (x + 38, y + 6),
                              (x, y + 38), (x - 38, y + 6), (x - 28, y + 6)])

assembly puzzle {
    solid backing {
        board = RoundedRectangle(center=(0, 0), width=300, height=140, corner_radius=10)
        drawing names {
            star_name = Text("STAR", position=(-95, 0), size=8, font="sans:Bold", valign="middle", fill=true)
            heart_name = Text("HEART", position=(0, 8), size=8, font="sans:Bold", valign="middle", fill=true)
            house_name = Text("HOUSE", position=(95, -16), size=8, font="sans:Bold", valign="middle", fill=true)
        }
    }

    solid frame {
        board = RoundedRectangle(center=(0, 0), width=300, height=140, corner_radius=10)
        hole star_hole { s = star_at(-95, 0) }
        hole heart_hole {
            l = lobe(0, 0, -1)
            r = lobe(0, 0, 1)
            AllowOverlap(l, r)   # one heart-shaped opening of two lobes
        }
        hole house_hole { h = house_at(95, 0) }
    }

    solid star {
        s = Inset(star_at(0, 0), 0.5)
        hole knob { c = Circle(center=(0, 0), diameter=8) }
    }
    solid heart {
        l = Inset(lobe(0, 0, -1), 0.5)
        r = Inset(lobe(0, 0, 1), 0.5)
        hole knob { c = Circle(center=(0, 8), diameter=8) }
        Fillet(at=[(0.0000, -29.7629)], radius=0.5)   # the nick where the two inset lobes meet (W0519's hint)
    }
    solid house {
        h = Inset(house_at(0, 0), 0.5)
        hole knob { c = Circle(center=(0, -16), diameter=8) }
    }

    # laid out flat for cutting
    Above(frame, backing, gap=10)
    AlignLeft(frame, backing)
    Below(star, backing, gap=10)
    AlignLeft(star, backing)
    RightOf(heart, star, gap=10)
    AlignTop(heart, star)
    RightOf(house, heart, gap=10)
    AlignTop(house, heart)

    # assembled
    Place(backing, position=(0, 0, 0))
    Place(frame, position=(0, 0, 6))
    Place(star, on=frame, position=(-95, 0, 0))
    Place(heart, on=frame, position=(0, 0, 0))
    Place(house, on=frame, position=(95, 0, 0))

    # the request's numbers
    assert backing.board.width == 300 mm and backing.board.height == 140 mm, "board 300 x 140"
    assert frame.board.width == 300 mm and frame.board.height == 140 mm, "frame 300 x 140"
    assert frame.star_hole.s.outer_radius == 42 mm and frame.star_hole.s.inner_radius == 20 mm, "star 42 / 20"
    assert abs(frame.heart_hole.bb.width - 82 mm) < 0.01 mm and abs(frame.heart_hole.bb.height - 72 mm) < 0.01 mm, "heart 82 x 72"
    assert frame.house_hole.bb.width == 76 mm and frame.house_hole.bb.height == 76 mm, "house 76 wide, 44 + 32 tall"
    assert frame.heart_hole.bb.center_x - frame.star_hole.s.center.x == 95 mm, "centres 95 apart"
    assert frame.house_hole.bb.center_x - frame.heart_hole.bb.center_x == 95 mm, "centres 95 apart"
    assert abs(frame.star_hole.bb.width - star.bb.width - 1 mm) < 0.01 mm, "star piece 0.5 smaller all round"
    assert abs(frame.heart_hole.bb.width - heart.bb.width - 1 mm) < 0.01 mm, "heart piece 0.5 smaller all round"
    assert abs(house.knob.c.center.y - house.bb.bottom - 21.5 mm) < 0.01 mm, "house knob mid-body: 22 up the opening, the piece 0.5 in"
    assert star.knob.c.diameter == 8 mm and heart.knob.c.diameter == 8 mm and house.knob.c.diameter == 8 mm, "8 mm knobs"
    assert backing.names.star_name.position.x - backing.board.center.x == frame.star_hole.s.center.x - frame.board.center.x, "STAR under the star"
    assert backing.names.house_name.position.x - backing.board.center.x == frame.house_hole.bb.center_x - frame.board.center.x, "HOUSE under the house"
}
