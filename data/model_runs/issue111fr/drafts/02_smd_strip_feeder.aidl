# Request: a hand-assembly feeder for cut strips of 8 mm SMD tape, three layers of 3 mm
# acrylic screwed together with four M3 screws (holes 6 mm in from each corner):
# - all layers 160 x 110 mm, corners R4;
# - base: plain;
# - spacer: six channels 8.4 mm wide for the tape at 14 mm pitch, centred on the plate,
#   each starting 30 mm from the left edge and open at the right edge so a strip slides in;
# - cover: over each channel a 5 mm window (the components show, the tape's edges stay
#   under the lips), from 32 mm from the left edge to 12 mm short of the right edge;
#   each window's part value engraved at its left, 4 mm tall, starting 4 mm from the left
#   edge: 10k, 4k7, 1k, 100n, 10u, LED (top to bottom); and a scale above the top window,
#   ticks every 4 mm (the tape's pitch) from the windows' start, long ticks and numbers
#   every 20 mm.

import "std/fasteners.aidl"

thickness 3 mm

W = 160 mm
H = 110 mm
PITCH = 14 mm
LANES = 6
CH_W = 8.4 mm
WIN_W = 5 mm
CH_X0 = -W / 2 + 30 mm
WIN_X0 = -W / 2 + 32 mm
WIN_X1 = W / 2 - 12 mm
LABELS = ["10k", "4k7", "1k", "100n", "10u", "LED"]
def lane_y(i) = (LANES - 1) / 2 * PITCH - i * PITCH
CORNERS = [(-W / 2 + 6 mm, -H / 2 + 6 mm), (W / 2 - 6 mm, -H / 2 + 6 mm),
           (W / 2 - 6 mm, H / 2 - 6 mm), (-W / 2 + 6 mm, H / 2 - 6 mm)]

def layer(kind="base") -> solid {
    body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=4)
    for p in CORNERS {
        screw = clearance_hole(size=3, cx=p[0], cy=p[1])
    }
    if kind == "spacer" {
        hole channels {
            for i in range(LANES) {
                ch = Rectangle(corner=(CH_X0, lane_y(i) - CH_W / 2),
                               opposite=(W / 2 + 2 mm, lane_y(i) + CH_W / 2))
            }
        }
    }
    if kind == "cover" {
        hole windows {
            for i in range(LANES) {
                win = Rectangle(corner=(WIN_X0, lane_y(i) - WIN_W / 2),
                                opposite=(WIN_X1, lane_y(i) + WIN_W / 2))
            }
        }
        drawing labels {
            for i in range(LANES) {
                t = Text(LABELS[i], position=(-W / 2 + 4 mm, lane_y(i)), size=4,
                         anchor="start", valign="middle")
            }
        }
        drawing scale {
            for i in range(30) {
                tick = Line((WIN_X0 + i * 4 mm, 44), (WIN_X0 + i * 4 mm, 44 + (4 if i % 5 == 0 else 2)))
            }
            for j in range(6) {
                n = Text(str(j * 20), position=(WIN_X0 + j * 20 mm, 49.5), size=3)
            }
        }
    }
}

assembly feeder {
    base = layer(kind="base")
    spacer = layer(kind="spacer")
    cover = layer(kind="cover")

    # flat: spacer right of the base, cover below the base
    RightOf(spacer, base, gap=6)
    AlignBottom(spacer, base)
    Below(cover, base, gap=6)
    AlignLeft(cover, base)

    # assembled: stacked
    Place(base, position=(0, 0, 0))
    Place(spacer, position=(0, 0, 3))
    Place(cover, position=(0, 0, 6))

    assert base.body.bb.width == 160 mm and base.body.bb.height == 110 mm, "160 x 110"
    assert len(spacer.channels.ch) == 6 and len(cover.windows.win) == 6, "six lanes"
    assert spacer.channels.ch[0].bb.center_y - spacer.channels.ch[1].bb.center_y == 14 mm,
        "14 mm pitch"
    assert spacer.channels.ch[0].bb.height == 8.4 mm, "channels 8.4 wide"
    assert cover.windows.win[0].bb.height == 5 mm, "windows 5 wide"
    assert spacer.channels.ch[0].bb.left - spacer.body.bb.left == 30 mm, "channels start 30 in"
    assert spacer.channels.ch[0].bb.right >= spacer.body.bb.right, "channels open at the right"
    assert cover.windows.win[0].bb.left - cover.body.bb.left == 32 mm, "windows start 32 in"
    assert cover.body.bb.right - cover.windows.win[0].bb.right == 12 mm, "windows stop 12 short"
    assert (spacer.channels.ch[0].bb.center_y + spacer.channels.ch[5].bb.center_y) / 2 ==
        spacer.body.bb.center_y, "channels centred"
    assert base.screw[0].c.center.x - base.body.bb.left == 6 mm, "screws 6 in"
    assert base.screw[0].c.diameter == 3.4 mm, "M3 clearance"
    assert distance(cover.labels, cover.windows) >= 2 mm, "labels clear of the windows"
    assert distance(cover.scale, cover.windows) >= 2 mm, "scale clear of the windows"
    assert cover.scale.tick[1].start.x - cover.scale.tick[0].start.x == 4 mm, "4 mm ticks"
    assert cover.body.bb.top - cover.scale.bb.top >= 1 mm, "scale on the plate"
}
