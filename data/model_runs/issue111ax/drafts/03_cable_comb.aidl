# Request (electronics): a cable comb to dress 12 Ethernet patch cables (6 mm) into a neat
# bundle behind my network rack, 4 mm acrylic. A 100 x 50 mm plate with 4 mm rounded
# corners. Two rows of six 6.5 mm holes at 14 mm pitch, the rows 20 mm apart, centred on the
# plate. Each hole opens to the nearest long edge through a 4.5 mm entry slit, so a cable
# snaps in without unplugging it (top row to the top edge, bottom row to the bottom edge).
# Port numbers engraved 3 mm tall between the rows: 1-6 under the top row, 7-12 over the
# bottom row. An M3 clearance hole at each end, 6 mm from the end, to tie it to the rack.
units mm
thickness 4 mm
import "std/fasteners.aidl"

param pitch = 14 mm, min = 10, max = 16
param cable = 6.5 mm, min = 4, max = 8
param slit = 4.5 mm, min = 3, max = 6

W = 100 mm
H = 50 mm
ROW = 10 mm    # each row's centre from the plate's centre line

solid comb {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=4)

    hole ports {
        for i in range(6) {
            top = Circle(center=(-2.5 * pitch + i * pitch, ROW), diameter=cable)
            top_slit = Rectangle(center=(-2.5 * pitch + i * pitch, (ROW + H / 2 + 1) / 2),
                                 width=slit, height=H / 2 + 1 - ROW)
            bot = Circle(center=(-2.5 * pitch + i * pitch, -ROW), diameter=cable)
            bot_slit = Rectangle(center=(-2.5 * pitch + i * pitch, -(ROW + H / 2 + 1) / 2),
                                 width=slit, height=H / 2 + 1 - ROW)
        }
    }

    left_screw = clearance_hole(size=3, cx=-W / 2 + 6, cy=0)
    right_screw = clearance_hole(size=3, cx=W / 2 - 6, cy=0)

    drawing numbers {
        for i in range(6) {
            upper = Text(str(i + 1), position=(-2.5 * pitch + i * pitch, 3.5), size=3,
                         valign="middle")
            lower = Text(str(i + 7), position=(-2.5 * pitch + i * pitch, -3.5), size=3,
                         valign="middle")
        }
    }

    assert body.bb.width == 100 mm and body.bb.height == 50 mm, "100 x 50 plate"
    assert len(ports.top) + len(ports.bot) == 12, "12 cables"
    assert ports.top[1].center.x - ports.top[0].center.x == 14 mm, "14 mm pitch"
    assert ports.top[0].center.y - ports.bot[0].center.y == 20 mm, "rows 20 mm apart"
    assert ports.top[0].diameter == 6.5 mm, "6.5 mm holes"
    assert ports.top_slit[0].width == 4.5 mm, "4.5 mm entry slits"
    assert left_screw.c.center.x - body.bb.left == 6 mm, "screw 6 mm from the end"
    assert numbers.upper[0].bb.top < ports.top[0].center.y - 3.25 mm, "numbers clear of the holes"
}
