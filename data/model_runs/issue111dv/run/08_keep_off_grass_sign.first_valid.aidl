# Request (signs): a lawn sign "KEEP OFF THE GRASS" on a stake, 6 mm exterior ply.
# - Sign board 300 mm wide: a 130 mm tall body with an arched top rising 30 mm more at
#   the middle; along the bottom edge a fringe of 20 grass blades 15 mm wide, 12 mm or
#   20 mm long (every third one long), leaning a little.
# - "KEEP OFF" bold, filled, 30 mm high, and "THE GRASS" bold, filled, 20 mm high, both at
#   most 190 mm wide, centred 40 mm right of the middle; left of them a "no walking"
#   symbol engraved filled: a 64 mm ring 5 mm wide, a footprint inside it, a 5 mm bar
#   across at 45 deg.
# - Stake 40 mm wide, 400 mm long with a 60 mm point, screwed behind the sign with two
#   4.5 mm screws countersunk 9 mm in the sign, 15 mm and 145 mm above the sign's bottom
#   edge on its centre line; the stake's top 10 mm above the upper screw, 3 mm pilot
#   holes in the stake.

thickness 6 mm

param t = 6 mm
w = 300 mm
body_h = 130 mm
rise = 30 mm
blades = 20
blade_w = 15 mm
arch_r = ((w / 2) ** 2 + rise ** 2) / (2 * rise)
screw_low = 15 mm
screw_high = 145 mm
stake_len = 400 mm
stake_w = 40 mm
stake_top = screw_high + 10 mm          # in the sign's frame
sym_x = -105 mm
sym_y = 75 mm

assembly lawn_sign {
    solid sign {
        # y = 0: the bottom edge of the body, the grass below it
        panel = Rectangle(center=(0, body_h / 2), width=w, height=body_h)
        cap = Intersect(Circle(center=(0, body_h + rise - arch_r), radius=arch_r),
                        Rectangle(center=(0, body_h + rise / 2), width=w, height=rise))
        for i in range(blades) {
            blade = Triangle(a=(-w / 2 + i * blade_w, 1), b=(-w / 2 + (i + 1) * blade_w, 1),
                             c=(-w / 2 + (i + 0.5) * blade_w + 3 mm,
                                -(20 mm if i % 3 == 1 else 12 mm)))
        }
        hole screws {
            low = Circle(center=(0, screw_low), diameter=4.5)
            high = Circle(center=(0, screw_high), diameter=4.5)
        }
        Countersink(screws, diameter=9)
        drawing words {
            keep = Text("KEEP OFF", position=(40, 85), size=30, font="sans:Bold",
                        valign="middle", fill=true, max_width=190)
            grass = Text("THE GRASS", position=(40, 40), size=20, font="sans:Bold",
                         valign="middle", fill=true, max_width=190)
        }
        drawing symbol {
            ring = Shell(Circle(center=(sym_x, sym_y), radius=27), 5, fill=true)
            sole = Ellipse(center=(sym_x + 2, sym_y + 4), rx=8, ry=13, rotation=-10 deg,
                           fill=true)
            heel = Ellipse(center=(sym_x - 2, sym_y - 16), rx=6, ry=7, fill=true)
            toe = Circle(center=(sym_x + 5, sym_y + 21), radius=3, fill=true)
            bar = Rectangle(center=(sym_x, sym_y), width=54, height=5, rotation=45 deg,
                            fill=true)
        }
        Fixed(panel)
        Fixed(words)
        Fixed(symbol)
    }

    solid stake {
        # y = 0: its top
        body = Polygon([(-stake_w / 2, 0), (stake_w / 2, 0), (stake_w / 2, -(stake_len - 60 mm)),
                        (0, -stake_len), (-stake_w / 2, -(stake_len - 60 mm))])
        hole pilots {
            a = Circle(center=(0, -(stake_top - screw_high)), diameter=3)
            b = Circle(center=(0, -(stake_top - screw_low)), diameter=3)
        }
        Fixed(body)
    }
    RightOf(stake, sign, gap=10)
    AlignTop(stake, sign)

    # in 3D: the sign's face in y = 0, its body's bottom edge 300 mm up; the stake behind
    Place(sign, position=(0, t, 300 mm), face="front", up="up")
    Place(stake, position=(0, 2 * t, 300 mm + stake_top), face="front", up="up")

    # the request's numbers
    assert sign.panel.width == 300 mm and sign.panel.height == 130 mm, "300 wide, 130 body"
    assert sign.cap.bb.top - sign.panel.bb.top == 30 mm, "arch rises 30 mm"
    assert len(sign.blade) == 20, "20 blades"
    assert sign.screws.high.center.y - sign.screws.low.center.y == 130 mm, "screws 15 and 145"
    assert sign.screws.low.center.y - sign.panel.bb.bottom == 15 mm, "lower screw 15 up"
    assert stake.body.bb.height == 400 mm and stake.body.bb.width == 40 mm, "stake 40 x 400"
    assert stake.pilots.b.center.y - stake.pilots.a.center.y == -130 mm, "pilots match screws"
    assert stake.body.bb.top - stake.pilots.a.center.y == 10 mm, "stake top 10 above"
    assert sign.words.keep.bb.width <= 190 mm and sign.words.grass.bb.width <= 190 mm,
        "text at most 190 wide"
    assert sign.symbol.ring.bb.width == 64 mm, "64 mm ring"
    assert sign.words.keep.bb.left - sign.symbol.ring.bb.right >= 5 mm, "symbol clear of text"
}
