# Request: a litter-trapping step for our cat Miso, set at the litter tray's exit: a
# finger-jointed box 450 x 300 x 120 mm (outside, lid included) in 6 mm ply. Its lift-off lid
# is a honeycomb of hexagonal holes, 20 mm across the flats with 5 mm webs, kept at least
# 15 mm in from the lid's edges, so litter falls through off her paws; the lid lifts off to
# empty the box. "MISO" engraved in filled bold letters 40 mm tall on the front wall.

import "std/boxes.aidl"

units mm
thickness 6 mm
kerf 0.15 mm

flats = 20 mm
web = 5 mm
rows = 12
cols = 16
dx = flats + web
dy = (flats + web) * sqrt(3) / 2
hex_h = 2 * flats / sqrt(3)                 # point to point, points up and down
field_w = (cols - 1) * dx + dx / 2 + flats  # odd rows sit half a step right
field_h = (rows - 1) * dy + hex_h

assembly litter_step {
    box = lid_box(length=450 mm, width=300 mm, height=120 mm, thickness=6 mm, finger=20 mm)

    hole lid_hex {
        h = RegularPolygon(center=(0, 0), across_flats=flats, sides=6, rotation=30 deg)
    }
    lid_grid = GridPattern(lid_hex, rows, cols, (dx, dy), stagger=true)
    lid_hex.h.center.x == box.lid.bb.center_x - field_w / 2 + flats / 2
    lid_hex.h.center.y == box.lid.bb.center_y - field_h / 2 + hex_h / 2
    CutInto(lid_hex, box.lid)

    # the same holes through the lip glued under the lid
    hole lip_hex {
        h = RegularPolygon(center=(0, 0), across_flats=flats, sides=6, rotation=30 deg)
    }
    lip_grid = GridPattern(lip_hex, rows, cols, (dx, dy), stagger=true)
    lip_hex.h.center.x == box.lip.bb.center_x - field_w / 2 + flats / 2
    lip_hex.h.center.y == box.lip.bb.center_y - field_h / 2 + hex_h / 2
    CutInto(lip_hex, box.lip)

    drawing name {
        t = Text("MISO", position=(0, 0), size=40, font="sans:Bold", valign="middle", fill=true)
    }
    CenterInside(name, box.body.front)
    CutInto(name, box.body.front)

    assert box.lid.bb.width == 450 mm and box.lid.bb.height == 300 mm, "450 x 300 lid"
    assert lid_hex.h.across_flats == 20 mm, "20 mm across the flats"
    assert lid_grid[1].h.center.x - lid_grid[0].h.center.x - 20 mm == 5 mm, "5 mm webs"
    assert field_w <= 450 mm - 2 * 15 mm and field_h <= 300 mm - 2 * 15 mm, "15 mm border"
    assert lid_hex.h.center.x - flats / 2 - box.lid.bb.left >= 15 mm, "15 mm border at the left"
    assert name.t.size == 40 mm, "40 mm letters"
}
