# Request (holidays): a Hanukkah gelt box for chocolate coins, 3 mm ply, a finger-jointed
# box with a lift-off lid, 140 x 100 x 60 mm outside. On the lid a Star of David 56 mm
# point to point (two interlaced triangles) engraved in the middle; on the front "HAPPY
# HANUKKAH" engraved in 9 mm serif capitals, centred; on the back a hanukkiah engraved,
# centred: nine 4 x 20 mm candles 10 mm apart on a 90 mm base line, the middle one (the
# shamash) raised 5 mm on a block, each with a teardrop flame.

units mm
thickness 3 mm

import "std/boxes.aidl"

assembly gelt {
    box = lid_box(length=140 mm, width=100 mm, height=60 mm, thickness=3 mm, finger=10 mm)

    drawing star {
        up = RegularPolygon(center=(0, 0), radius=28, sides=3, rotation=90 deg)
        down = RegularPolygon(center=(0, 0), radius=28, sides=3, rotation=270 deg)
    }
    CenterInside(star, box.lid)
    CutInto(star, box.lid)

    drawing greeting {
        t = Text("HAPPY HANUKKAH", (0, 0), size=9, font="serif", valign="middle")
    }
    CenterInside(greeting, box.body.front)
    CutInto(greeting, box.body.front)

    drawing menorah {
        base = Line((-45, 0), (45, 0))
        block = Rectangle(center=(0, 2.5), width=6, height=5)
        for i in range(9) {
            lift = 5 if i == 4 else 0
            candle = Rectangle(center=(-40 + 10 * i, 10 + lift), width=4, height=20)
            flame = Hull(Circle(center=(-40 + 10 * i, 23.5 + lift), radius=1.8),
                         Point(-40 + 10 * i, 28.5 + lift))
        }
    }
    CenterInside(menorah, box.body.back)
    CutInto(menorah, box.body.back)

    assert box.lid.bb.width == 140 mm and box.lid.bb.height == 100 mm, "lid 140 x 100"
    assert star.up.radius * 2 == 56 mm, "star 56 mm point to point"
    assert len(menorah.candle) == 9, "nine candles"
    assert menorah.candle[1].center.x - menorah.candle[0].center.x == 10 mm, "10 mm apart"
    assert menorah.candle[4].bb.bottom - menorah.candle[0].bb.bottom == 5 mm, "shamash raised 5 mm"
    assert menorah.base.length == 90 mm, "90 mm base line"
    assert greeting.bb.width <= box.body.front.bb.width - 20 mm, "greeting clear of the fingers"
    assert menorah.bb.height <= box.body.back.bb.height - 12 mm, "menorah clear of the fingers"
}
