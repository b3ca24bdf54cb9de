# Request (workshop): a go/no-go gauge for sheet stock, cut from 3 mm acrylic. A 180 x 60 mm
# plate with 5 mm corner radii. Eight open slots come up from the bottom edge, each 20 mm deep,
# widths 3, 4, 5, 6, 9, 12, 15 and 18 mm (left to right); the first slot starts 12 mm from the
# left edge and 10 mm of material stands between neighbouring slots. Each slot's width is
# engraved above it (size 5, the label's baseline 4 mm above the slot's end). "SHEET GAUGE mm"
# is engraved along the top (size 6, baseline 10 mm below the top edge), and a 6 mm hanging
# hole sits 10 mm in from the top and right edges.

units mm
thickness 3 mm

widths = [3, 4, 5, 6, 9, 12, 15, 18]
depth = 20
web = 10
first_x = 12
plate_w = 180
plate_h = 60

def slot_left(i) = first_x + sum([widths[j] for j in range(i)]) + web * i

solid gauge {
    body = RoundedRectangle(bottom_left=(0, 0), width=plate_w, height=plate_h, corner_radius=5)

    for i in range(len(widths)) {
        hole slot {
            r = Rectangle(bottom_left=(slot_left(i), -1), width=widths[i], height=depth + 1)
        }
        drawing label {
            t = Text(str(widths[i]), position=(slot_left(i) + widths[i] / 2, depth + 4), size=5)
        }
    }

    drawing title {
        t = Text("SHEET GAUGE mm", position=(plate_w / 2 - 12, plate_h - 10), size=6)
    }

    hole hang {
        c = Circle(center=(plate_w - 10, plate_h - 10), diameter=6)
    }

    assert len(slot) == 8, "eight slots"
    assert body.bb.width == 180 mm and body.bb.height == 60 mm, "plate 180 x 60"
    assert slot[0].r.bb.left - body.bb.left == 12 mm, "first slot 12 mm from the left edge"
    assert slot[7].r.bb.width == 18 mm and slot[0].r.bb.width == 3 mm, "widths 3 .. 18"
    assert slot[3].r.bb.top - body.bb.bottom == 20 mm, "slots 20 mm deep"
    assert slot[5].r.bb.left - slot[4].r.bb.right == 10 mm, "10 mm web between slots"
    assert body.bb.right - slot[7].r.bb.right >= 10 mm, "material right of the last slot"
    assert body.bb.top - hang.c.center.y == 10 mm and body.bb.right - hang.c.center.x == 10 mm,
        "hanging hole 10 mm in"
    assert hang.c.diameter == 6 mm, "6 mm hanging hole"
    assert distance(title, hang) >= 2 mm, "title clear of the hanging hole"
}
