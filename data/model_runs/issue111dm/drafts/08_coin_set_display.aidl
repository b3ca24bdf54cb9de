# Request (gifts): a birth-year coin display for a new baby, 3 mm cherry ply. A plaque
# 220 x 150 mm with R8 corners, glued up from a face layer with a pocket for each of the
# eight 2026 coins (1p 20.3, 2p 25.9, 5p 18.0, 10p 24.5, 20p 21.4, 50p 27.3, GBP1 23.43,
# GBP2 28.4 mm across; each pocket 0.6 mm larger) and a plain back layer. The pockets are in
# two rows of four at 50 mm pitch (row centres 22 mm above and 30 mm below the middle), each
# with its value engraved filled 20 mm under its centre ("1p" ... "£2"). "LILY 2026" is
# engraved filled across the top (serif, 14 mm), "BORN 14 MARCH 2026" under the coins.
# The plaque stands upright in a base 240 x 60 mm (R8): a plain bottom and two layers with
# a slot 222 x 6.3 mm that holds the plaque 6 mm deep.

thickness 3 mm
t = 3 mm

plaque_w = 220 mm
plaque_h = 150 mm
names = ["1p", "2p", "5p", "10p", "20p", "50p", "£1", "£2"]
coin_d = [20.3, 25.9, 18.0, 24.5, 21.4, 27.3, 23.43, 28.4]
slack = 0.6 mm
pitch = 50 mm
slot_w = 6.3 mm

def coin_x(i) = (i % 4 - 1.5) * pitch
def coin_y(i) = 22 mm if i < 4 else -30 mm

def base_layer() -> solid {
    plate = RoundedRectangle(center=(0, 0), width=240, height=60, corner_radius=8)
    hole groove { r = Rectangle(center=(0, 5), width=plaque_w + 2 mm, height=slot_w) }
}

assembly coin_display {
    solid face {
        plate = RoundedRectangle(center=(0, 0), width=plaque_w, height=plaque_h, corner_radius=8)
        for i in range(8) {
            hole pocket { c = Circle(center=(coin_x(i), coin_y(i)), diameter=coin_d[i] * 1 mm + slack) }
        }
        drawing words {
            for i in range(8) {
                v = Text(names[i], position=(coin_x(i), coin_y(i) - 20 mm), size=5, font="sans:Bold",
                         valign="middle", fill=true)
            }
            title = Text("LILY 2026", position=(0, 56), size=14, font="serif:Bold",
                         valign="middle", fill=true)
            born = Text("BORN 14 MARCH 2026", position=(0, -63), size=5, font="sans",
                        valign="middle", fill=true)
        }
    }

    solid back {
        plate = RoundedRectangle(center=(0, 0), width=plaque_w, height=plaque_h, corner_radius=8)
    }

    solid base {
        plate = RoundedRectangle(center=(0, 0), width=240, height=60, corner_radius=8)
    }
    low = base_layer()
    high = base_layer()

    # on the sheet
    RightOf(back, face, gap=8)
    AlignTop(back, face)
    Below(base, face, gap=8)
    AlignLeft(base, face)
    Below(low, base, gap=8)
    AlignLeft(low, base)
    RightOf(high, base, gap=8)
    AlignTop(high, base)

    # in 3D: the base flat, the plaque upright in its groove (face layer in front)
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(low, position=(0, 0, t), face="up", up="back")
    Place(high, position=(0, 0, 2 * t), face="up", up="back")
    Place(face, position=(0, 5 mm, t + plaque_h / 2), face="front", up="up")
    Place(back, position=(0, 5 mm + t, t + plaque_h / 2), face="front", up="up")

    # the request's numbers
    assert len(face.pocket) == 8
    assert face.pocket[7].c.diameter == 28.4 mm + 0.6 mm
    assert face.pocket[2].c.diameter == 18.0 mm + 0.6 mm
    assert face.pocket[1].c.center.x - face.pocket[0].c.center.x == 50 mm
    assert face.pocket[0].c.center.y - face.plate.center.y == 22 mm
    assert face.plate.center.y - face.pocket[4].c.center.y == 30 mm
    assert face.pocket[5].c.center.y - face.words.v[5].position.y == 20 mm
    assert face.plate.width == 220 mm and face.plate.height == 150 mm
    assert low.groove.r.height == 6.3 mm and low.groove.r.width == 222 mm
    assert slot_w >= 2 * t, "the groove takes both plaque layers"
}
