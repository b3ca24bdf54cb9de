# Request (music): a flat-pack clarinet stand from 6 mm birch ply: two plates that slot
# together crosswise (a cross halving, 0.15 mm clearance), standing on four feet.
# - Both plates: feet spanning 160 mm, 8 mm tall at their tips, each foot 18 mm long on the
#   floor with a 5 mm high relief between them; from the feet a cone for the bell to sit on,
#   64 mm wide 14 mm up, narrowing to 30 mm wide 80 mm up.
# - The main plate goes on above the cone as a 12 mm wide peg into the lower joint's bore,
#   up to 150 mm, its top corners rounded 3 mm; a 6 mm shoulder from the cone to the peg
#   (80 to 86 mm up). The owner's name ELLA engraved filled, 6 mm bold, reading upwards on
#   the cone 14 mm left of the middle.
# - The second plate stops at the top of the cone (80 mm, flat top).
# - The halving slots meet halfway up the overlap (from the relief at 5 mm to 80 mm): the main
#   plate slotted from below, the second from above.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
relief = 5 mm
cone_top = 80 mm
halve = (cone_top - relief) / 2

assembly clarinet_stand {
    solid main {
        body = Polygon([(0, 150), (6, 150), (6, 86), (15, 80), (32, 14), (80, 8), (80, 0),
                        (62, 0), (60, relief), (0, relief)], mirror="y")
        slot = cross_halving(depth=halve, thickness=t, clearance=0.15, rotation=180 deg,
                             cx=0, cy=relief)
        drawing name {
            n = Text("ELLA", position=(-14, 35), size=6, font="sans:Bold", valign="middle",
                     rotation=90 deg, fill=true)
        }
        Fillet([body.points[1], body.points[17]], 3)
    }

    solid second {
        body = Polygon([(0, cone_top), (15, cone_top), (32, 14), (80, 8), (80, 0), (62, 0),
                        (60, relief), (0, relief)], mirror="y")
        slot = cross_halving(depth=halve, thickness=t, clearance=0.15, cx=0, cy=cone_top)
    }

    RightOf(second, main, gap=10)
    AlignBottom(second, main)

    assert main.body.bb.width == 160 mm and main.body.bb.height == 150 mm
    assert second.body.bb.width == 160 mm and second.body.bb.height == 80 mm
    assert main.body.points[1].x - main.body.points[17].x == 12 mm, "12 mm peg"
    assert main.slot.cut.bb.height + second.slot.cut.bb.height == 75 mm, "halvings meet"
    assert main.slot.cut.bb.top == second.slot.cut.bb.bottom, "slots meet at one height"
    assert distance(main.name, main.slot) >= 2 mm
    assert main.name.bb.left >= main.body.bb.center_x - 14 mm - 3.5 mm
}
