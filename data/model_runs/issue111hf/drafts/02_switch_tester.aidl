# Request (electronics): a 3 x 3 tester for MX-style keyboard switches, to let people try
# nine switch types side by side. A stack of four acrylic layers, all 76 x 84 mm with 4 mm
# corner radii and an M3 clearance hole 4.5 mm in from both edges at each corner (M3 x 12
# flat-head screws from the top, nuts underneath):
# - top plate, 1.5 mm acrylic (MX clips need a 1.5 mm plate): nine 14.0 x 14.0 mm switch
#   cut-outs on a 19.05 mm pitch, the grid centred left-right with its centre 3 mm below the
#   plate's centre; under each cut-out its switch's name engraved 2.5 mm tall (top row RED,
#   BROWN, BLUE; middle CLEAR, GREEN, BLACK; bottom SILVER, YELLOW, WHITE), each name's
#   middle 9.5 mm below its switch's centre; "SWITCH TESTER" engraved 4 mm tall, centred in
#   the band above the grid; the four screw holes countersunk for 6 mm heads.
# - two spacer frames, 3 mm acrylic, each with a 58 x 60 mm window centred on the grid, for
#   the switch pins to hang in.
# - bottom plate, 3 mm acrylic, with four 10 mm circles engraved where the rubber feet go,
#   centred 26 mm left/right and 30 mm up/down from the plate's centre.
# Cut them side by side, 5 mm apart.

import "std/plates.aidl"

units mm
thickness 3 mm

pitch = 19.05 mm
plate_w = 76 mm
plate_h = 84 mm
grid_dy = -3 mm
switches = ["RED", "BROWN", "BLUE", "CLEAR", "GREEN", "BLACK", "SILVER", "YELLOW", "WHITE"]

def spacer() -> solid {
    base = mounting_plate(width=plate_w, height=plate_h, corner_radius=4, screw=3, inset=4.5)
    hole window {
        w = Rectangle(center=(0, grid_dy), width=58, height=60)
    }
    assert window.w.width == 58 mm and window.w.height == 60 mm, "58 x 60 window"
}

assembly switch_tester {
    solid top {
        thickness 1.5 mm
        base = mounting_plate(width=plate_w, height=plate_h, corner_radius=4, screw=3, inset=4.5)
        hole sw {
            c = Rectangle(center=(-pitch, grid_dy + pitch), width=14, height=14)
        }
        cutouts = GridPattern(sw, 3, 3, (pitch, -pitch))
        drawing names {
            for i in range(9) {
                t = Text(switches[i], position=(-pitch + (i % 3) * pitch,
                         grid_dy + pitch - (i // 3) * pitch - 9.5), size=2.5, valign="middle")
            }
        }
        drawing title {
            t = Text("SWITCH TESTER", position=(0, (grid_dy + pitch + 7 + plate_h / 2) / 2),
                     size=4, valign="middle")
        }
        Countersink(base.corner, diameter=6)

        assert len(cutouts) == 9, "nine switches"
        assert cutouts[0].c.width == 14 mm and cutouts[0].c.height == 14 mm, "14 x 14 cut-outs"
        assert cutouts[1].c.center.x - cutouts[0].c.center.x == 19.05 mm, "19.05 pitch"
        assert cutouts[0].c.center.y - cutouts[3].c.center.y == 19.05 mm, "19.05 pitch"
        assert cutouts[4].c.center.x - base.body.center.x == 0 mm, "grid centred left-right"
        assert cutouts[4].c.center.y - base.body.center.y == -3 mm, "grid 3 mm below centre"
        assert cutouts[0].c.center.y - names.t[0].position.y == 9.5 mm, "names 9.5 mm below"
        assert distance(names, sw) >= 1 mm, "names clear the cut-outs"
        assert distance(title, base.corner) >= 1 mm, "title clears the screws"
        assert base.corner[0].c.center.x - base.body.bb.left == 4.5 mm, "holes 4.5 mm in"
        assert base.corner[0].c.center.y - base.body.bb.bottom == 4.5 mm, "holes 4.5 mm in"
    }

    upper_spacer = spacer()
    lower_spacer = spacer()

    solid bottom {
        base = mounting_plate(width=plate_w, height=plate_h, corner_radius=4, screw=3, inset=4.5)
        drawing feet {
            for sx in [-1, 1] {
                for sy in [-1, 1] {
                    f = Circle(center=(26 * sx, 30 * sy), diameter=10)
                }
            }
        }
        assert distance(feet, base.corner) >= 2 mm, "feet clear the nuts' holes"
    }

    RightOf(upper_spacer, top, gap=5)
    AlignTop(upper_spacer, top)
    RightOf(lower_spacer, upper_spacer, gap=5)
    AlignTop(lower_spacer, upper_spacer)
    RightOf(bottom, lower_spacer, gap=5)
    AlignTop(bottom, lower_spacer)

    assert top.base.body.width == 76 mm and top.base.body.height == 84 mm, "76 x 84 plates"
    assert bottom.base.body.width == 76 mm and upper_spacer.base.body.height == 84 mm
}
