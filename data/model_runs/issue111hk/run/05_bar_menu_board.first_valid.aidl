# Request (parties): a standing drinks menu for the bar at our garden party, 6 mm birch ply,
# 220 mm wide and 360 mm tall. My laser bed is 300 x 200, so the board is cut as two halves
# joined across the middle by a flat sliding dovetail (3 tails, 12 mm deep, 10 deg, 0.1 mm
# clearance): the lower half 180 mm plus the tails, the upper half 180 mm. On the upper half:
# "DRINKS" engraved filled in bold serif, 30 mm tall, 23 mm below the top edge to its top; a
# filled cocktail-glass pictogram under it (a 40 mm wide, 25 mm deep bowl on a 3 mm stem and a
# 24 mm foot) and a rule line 160 mm long under that. On the lower half, five drinks in 7 mm
# engraved stroke text, 20 mm apart, names flush left and prices flush right, 20 mm in from
# the edges: APEROL SPRITZ 6.50, MOJITO 7.00, GIN & TONIC 6.00, ELDERFLOWER COOLER 3.50,
# LEMONADE 2.00; "CHEERS!" 6 mm tall under them. It stands in two 150 x 40 mm feet (top
# corners rounded 10 mm) crossing the board 70 mm either side of its middle, by cross
# halvings 20 mm deep in the board's bottom edge and 20 mm deep in each foot's top edge.

import "std/joints.aidl"

units mm
thickness 6 mm

param t = 6 mm, min = 3, max = 9
param fit = 0.1 mm, min = 0, max = 0.3

board_w = 220 mm
half_h = 180 mm
tail_d = 12 mm
foot_x = 70 mm
drinks = ["APEROL SPRITZ", "MOJITO", "GIN & TONIC", "ELDERFLOWER COOLER", "LEMONADE"]
prices = ["6.50", "7.00", "6.00", "3.50", "2.00"]

def foot() -> solid {
    body = RoundedRectangle(center=(0, 0), width=150, height=40, corner_radii=[10, 10, 0, 0])
    halving = cross_halving(depth=20 mm, thickness=t, clearance=fit, cx=0 mm, cy=20 mm)
}

assembly menu {
    solid lower {
        body = Rectangle(bottom_left=(-board_w / 2, 0), width=board_w, height=half_h + tail_d)
        tails = dovetail(part="tail", length=board_w, depth=tail_d, tails=3, angle=10 deg,
                         cx=0 mm, cy=half_h)
        left_slot = cross_halving(depth=20 mm, thickness=t, clearance=fit, rotation=180 deg,
                                  cx=-foot_x, cy=0 mm)
        right_slot = cross_halving(depth=20 mm, thickness=t, clearance=fit, rotation=180 deg,
                                   cx=foot_x, cy=0 mm)
        drawing list {
            for i in range(5) {
                name = Text(drinks[i], (-board_w / 2 + 20 mm, 160 mm - i * 20 mm), size=7,
                            anchor="start")
                price = Text(prices[i], (board_w / 2 - 20 mm, 160 mm - i * 20 mm), size=7,
                             anchor="end")
            }
            cheers = Text("CHEERS!", (0, 45), size=6)
        }
    }

    solid upper {
        body = Rectangle(bottom_left=(-board_w / 2, half_h), width=board_w, height=half_h)
        sockets = dovetail(part="socket", length=board_w, depth=tail_d, tails=3, angle=10 deg,
                           clearance=fit, cx=0 mm, cy=half_h)
        drawing title {
            word = Text("DRINKS", (0, 2 * half_h - 23 mm), size=30, font="serif:Bold",
                        valign="top", fill=true)
        }
        drawing glass {
            bowl = Triangle(center=(0, 282.5), base=40, height=25, rotation=180 deg, fill=true)
            stem = Rectangle(center=(0, 260), width=3, height=20, fill=true)
            base = Rectangle(center=(0, 249), width=24, height=3, fill=true)
        }
        drawing rule {
            r = Line((-80, 235), (80, 235))
        }
    }

    left_foot = foot()
    right_foot = foot()

    # on the sheet
    RightOf(upper, lower, gap=10)
    AlignBottom(upper, lower)
    Above(left_foot, lower, gap=10)
    AlignLeft(left_foot, lower)
    RightOf(right_foot, left_foot, gap=10)
    AlignBottom(right_foot, left_foot)

    # in 3D: the board stands upright, the feet across it
    Place(lower, position=(0, t / 2, 0), face="front", up="up")
    Place(upper, position=(0, t / 2, 0), face="front", up="up")
    Place(left_foot, position=(-foot_x + t / 2, 0, 20), face="left", up="up")
    Place(right_foot, position=(foot_x + t / 2, 0, 20), face="left", up="up")
}

assert abs(menu.lower.body.width - 220 mm) < 0.01 mm, "220 mm wide"
assert abs(menu.lower.body.height - 12 mm + menu.upper.body.height - 360 mm) < 0.01 mm, "360 mm tall"
assert menu.lower.bb.width <= 300 mm and menu.lower.bb.height <= 200 mm, "lower half fits the bed"
assert menu.upper.bb.width <= 300 mm and menu.upper.bb.height <= 200 mm, "upper half fits the bed"
assert len(menu.lower.list.name) == 5, "five drinks"
assert abs(menu.lower.list.name[0].position.y - menu.lower.list.name[1].position.y - 20 mm) < 0.01 mm, "20 mm apart"
assert menu.lower.list.name[3].bb.right < menu.lower.list.price[3].bb.left - 10 mm, "longest name clear of its price"
assert menu.lower.list.bb.top < menu.lower.tails.bb.bottom - 5 mm, "list clear of the dovetail"
assert menu.upper.rule.bb.bottom > menu.upper.sockets.bb.top + 5 mm, "rule clear of the dovetail"
assert abs(menu.upper.body.bb.top - menu.upper.title.bb.top - 23 mm) < 0.5 mm, "title 23 mm below the top"
assert menu.upper.glass.bb.top < menu.upper.title.bb.bottom - 5 mm, "glass under the title"
assert abs(menu.upper.glass.bowl.bb.width - 40 mm) < 0.01 mm, "40 mm bowl"
assert abs(menu.lower.right_slot.cut.bb.center_x - menu.lower.left_slot.cut.bb.center_x - 140 mm) < 0.01 mm,
    "feet 70 mm either side"
assert abs(menu.left_foot.body.width - 150 mm) < 0.01 mm and abs(menu.left_foot.body.height - 40 mm) < 0.01 mm, "150 x 40 feet"
