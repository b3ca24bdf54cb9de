# Request: a two-layer "RECYCLE" sign for the office's recycling corner, 3 mm acrylic: a green
# back plate and a white front plate, both 200 x 250 mm portrait with r8 corners, screwed to
# the wall through four 5 mm holes 12 mm in from each corner (countersunk 10 mm on the front
# plate). Cut through the front plate so the green shows: the recycling symbol, three chasing
# arrows round a centre 40 mm above the plate's centre, each a band 14 mm wide on a 50 mm
# radius running 80 deg counter-clockwise and ending in an arrowhead 28 mm wide and 22 deg
# long; under it "RECYCLE" in 28 mm bold stencil letters (counters held) centred 50 mm below
# the plate's centre; "PAPER  CANS  PLASTIC" engraved 8 mm under that, 90 mm below the centre.

thickness 3 mm

param plate_w = 200 mm, min = 160 mm, max = 300 mm
param plate_h = 250 mm, min = 200 mm, max = 360 mm
hub = (0 mm, 40 mm)
r_arrow = 50 mm
band = 14 mm

def screw_hole() -> hole {
    c = Circle(center=(0, 0), diameter=5)
}

assembly sign {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=8)
        screw = screw_hole()
        holes = CornerPattern(screw, body, inset=12)
    }

    solid front {
        body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=8)
        screw = screw_hole()
        holes = CornerPattern(screw, body, inset=12)
        Countersink(screw, diameter=10 mm)

        hole symbol {
            for k in range(3) {
                arc = ArcSlot(center=hub, radius=r_arrow, start_angle=k * 120 deg + 20 deg,
                              end_angle=k * 120 deg + 100 deg, width=band)
                head = Triangle(a=polar(hub, r_arrow - band, k * 120 deg + 100 deg),
                                b=polar(hub, r_arrow + band, k * 120 deg + 100 deg),
                                c=polar(hub, r_arrow, k * 120 deg + 122 deg))
            }
        }
        hole word {
            w = Text("RECYCLE", position=(0, -50), size=28, font="sans:Bold", stencil=true,
                     valign="middle")
        }
        drawing kinds {
            k = Text("PAPER  CANS  PLASTIC", position=(0, -90), size=8, valign="middle")
        }
    }

    RightOf(front, back, gap=10)
    AlignBottom(front, back)
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3 mm))

    assert front.body.bb.width == 200 mm and front.body.bb.height == 250 mm, "200 x 250"
    assert back.body.bb.width == 200 mm and back.body.bb.height == 250 mm, "200 x 250"
    assert len(front.holes) == 4 and len(back.holes) == 4, "four screws"
    assert front.screw.c.center.x - front.body.bb.left == 12 mm, "12 in"
    assert front.screw.c.center.y - front.body.bb.bottom == 12 mm, "12 in"
    assert front.screw.c.diameter == 5 mm, "5 mm holes"
    assert len(front.symbol.arc) == 3, "three arrows"
    assert front.symbol.arc[0].width == 14 mm and front.symbol.arc[0].radius == 50 mm, "bands"
    assert front.symbol.arc[0].center.y - front.body.bb.center_y == 40 mm, "symbol 40 up"
    assert front.word.w.position.y - front.body.bb.center_y == -50 mm, "RECYCLE 50 down"
    assert front.kinds.k.position.y - front.body.bb.center_y == -90 mm, "kinds 90 down"
    assert front.word.bb.width < front.body.bb.width - 30 mm, "RECYCLE fits"
    assert front.symbol.bb.bottom > front.word.bb.top + 5 mm, "symbol clear of the word"
    assert front.word.bb.bottom > front.kinds.bb.top + 5 mm, "word clear of the kinds"
    assert front.symbol.bb.top < front.body.bb.top - 20 mm, "symbol clear of the top screws"
}
