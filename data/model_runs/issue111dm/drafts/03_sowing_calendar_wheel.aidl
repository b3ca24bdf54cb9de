# Request (garden): a sowing calendar wheel for the shed wall, 3 mm ply, two discs on a
# 5 mm Chicago screw. The base disc is 200 mm across with a hanging lug at the top (a 5 mm
# hole); the twelve months are engraved round its rim (JAN at the top, clockwise, names
# centred 90 mm out), with a divider line between each two months, and in each month's
# 30 degree sector what to sow then, two crops, engraved reading along the radius between
# 30 and 76 mm out. The top disc is 164 mm across with a 30 degree window from 28 to 78 mm
# out that shows one month's crops, a pointer at the window's middle reaching 85 mm out to
# the month's name, and "WHAT TO SOW" engraved filled under the screw, the right way up
# when the window is at the top.

thickness 3 mm

months = ["JAN", "FEB", "MAR", "APR", "MAY", "JUN", "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"]
crop1 = ["ONIONS", "BROAD BEANS", "PEAS", "BEETROOT", "COURGETTES", "LETTUCE",
         "KALE", "CABBAGE", "PAK CHOI", "GARLIC", "BROAD BEANS", "PLAN BEDS"]
crop2 = ["SWEET PEAS", "PARSNIPS", "CARROTS", "POTATOES", "FR. BEANS", "RADISH",
         "SPINACH", "TURNIPS", "ROCKET", "ONION SETS", "SWEET PEAS", "ORDER SEED"]
pin_d = 5 mm

def month_angle(i) = 90 deg - i * 30 deg

assembly sowing_wheel {
    solid base {
        disc = Circle(center=(0, 0), diameter=200)
        lug = Circle(center=(0, 100), radius=10)
        hole pin { c = Circle(center=(0, 0), diameter=pin_d) }
        hole hang { c = Circle(center=(0, 104), diameter=5) }
        drawing marks {
            ring = Circle(center=(0, 0), radius=90, construction=true)
            for i in range(12) {
                a = month_angle(i)
                if i >= 4 and i <= 8 {
                    name = Text(months[i], along=ring, angle=a, size=5, valign="middle", flip=true)
                } else {
                    name = Text(months[i], along=ring, angle=a, size=5, valign="middle")
                }
                d = a + 15 deg
                div = Line((28 * cos(d), 28 * sin(d)), (97 * cos(d), 97 * sin(d)))
                # crops read outward on the right half, inward on the left (kept upright)
                a1 = a + 6.5 deg
                a2 = a - 6.5 deg
                if cos(a) >= 0 {
                    c1 = Text(crop1[i], position=(31 * cos(a1), 31 * sin(a1)), size=4.5,
                              anchor="start", valign="middle", rotation=a1, max_width=44 mm)
                    c2 = Text(crop2[i], position=(31 * cos(a2), 31 * sin(a2)), size=4.5,
                              anchor="start", valign="middle", rotation=a2, max_width=44 mm)
                } else {
                    c1 = Text(crop1[i], position=(31 * cos(a2), 31 * sin(a2)), size=4.5,
                              anchor="end", valign="middle", rotation=a2 + 180 deg, max_width=44 mm)
                    c2 = Text(crop2[i], position=(31 * cos(a1), 31 * sin(a1)), size=4.5,
                              anchor="end", valign="middle", rotation=a1 + 180 deg, max_width=44 mm)
                }
            }
        }
    }

    solid top {
        disc = Circle(center=(0, 0), diameter=164)
        pointer = Triangle(center=(0, 81.5), base=14, height=7)
        hole pin { c = Circle(center=(0, 0), diameter=pin_d) }
        hole window {
            w = Sector(center=(0, 0), radius=78, start_angle=75 deg, end_angle=105 deg,
                       inner_radius=28)
        }
        drawing label {
            ring = Circle(center=(0, 0), radius=50, construction=true)
            words = Text("WHAT TO SOW", along=ring, size=9, font="sans:Bold", valign="middle",
                         flip=true, fill=true)
        }
    }

    RightOf(top, base, gap=10)
    AlignBottom(top, base)

    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(top, position=(0, 0, 3 mm), face="up", up="back")

    # the request's numbers
    assert len(base.marks.name) == 12 and len(base.marks.c1) == 12
    assert base.disc.diameter == 200 mm and top.disc.diameter == 164 mm
    assert top.pointer.bb.top - top.disc.center.y == 85 mm
    assert top.window.w.radius == 78 mm and top.window.w.inner_radius == 28 mm
}
