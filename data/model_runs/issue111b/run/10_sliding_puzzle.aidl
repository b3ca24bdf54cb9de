# Sliding 15-puzzle, 3 mm plywood, three kinds of parts: a base plate 100 x 100 mm (R4 corners);
# a frame 100 x 100 mm (R4) with a centered square opening 81 x 81 mm (4 tiles of 20 mm + 1 mm
# play), glued on the base; 15 tiles 20 x 20 mm with R1.5 corners, each engraved with its
# number 1..15, 8 mm tall, centered. Layout: frame, base 10 mm to its right, the tiles in
# rows of 4 at 23 mm pitch 10 mm right of the base, top row aligned with the base's top.

units mm
thickness 3 mm

param tile = 20 mm, min = 15 mm, max = 30 mm
param play = 1 mm, min = 0.3 mm, max = 2 mm

def tile_part(n=1) -> solid {
    body = RoundedRectangle(center=(0, 0), width=tile, height=tile, corner_radius=1.5)
    drawing num {
        t = Text(str(n), position=(0, 0), size=8, valign="middle")
    }
}

assembly puzzle {
    solid frame {
        body = RoundedRectangle(center=(0, 0), width=100, height=100, corner_radius=4)
        hole opening {
            w = Rectangle(center=(0, 0), width=4 * tile + play, height=4 * tile + play)
        }
    }
    solid base {
        body = RoundedRectangle(center=(110, 0), width=100, height=100, corner_radius=4)
    }
    for i in range(15) {
        tl = tile_part(n=i + 1)
        tl.bb.center_x == 110 mm + 50 mm + 10 mm + tile / 2 + (i % 4) * 23 mm
        tl.bb.center_y == 50 mm - tile / 2 - (i // 4) * 23 mm
    }

    assert abs(frame.body.bb.width - 100 mm) < 0.001 mm and abs(frame.body.bb.height - 100 mm) < 0.001 mm, "frame 100 x 100"
    assert abs(frame.opening.w.width - 81 mm) < 0.001 mm and abs(frame.opening.w.height - 81 mm) < 0.001 mm, "opening 81 x 81"
    assert abs(base.body.bb.width - 100 mm) < 0.001 mm, "base 100 mm"
    assert len(tl) == 15, "15 tiles"
    assert abs(tl[0].body.width - 20 mm) < 0.001 mm, "tiles 20 mm"
    assert abs(base.bb.left - frame.bb.right - 10 mm) < 0.001 mm, "base 10 mm right of the frame"
    assert abs(tl[0].bb.left - base.bb.right - 10 mm) < 0.001 mm, "tiles 10 mm right of the base"
}
