# Request (toys): a memory (pairs) game for a 4-year-old, 3 mm ply.
# - 16 tiles 40 x 40 mm with R4 corners: 8 pairs of bold symbols about 28 mm across,
#   engraved filled on one face (star, heart, circle, triangle, hexagon, diamond,
#   plus, house); the other face blank. Cut on a 45 mm pitch in a 4 x 4 block.
# - A finger-jointed box with a lift-off lid holding the tiles in two stacks of 8:
#   inside 84 x 42 mm and 26 mm deep (floor to the lid's lip), 10 mm fingers,
#   "MEMORY" engraved on the lid, bold, filled, 10 mm high.
# - Assembled: the tiles stacked in the box.

import "std/boxes.aidl"

thickness 3 mm

param tile = 40 mm
param pitch = 45 mm

def tile_piece(kind=0) -> solid {
    body = RoundedRectangle(center=(0, 0), width=tile, height=tile, corner_radius=4)
    drawing sym {
        if kind == 0 {
            s = Star(center=(0, 0), points=5, outer_radius=15, inner_radius=6.5, fill=true)
        } elif kind == 1 {
            s = Polygon([(0.85 * 16 * sin(i * 5 deg) ** 3,
                          0.85 * (13 * cos(i * 5 deg) - 5 * cos(i * 10 deg) -
                                  2 * cos(i * 15 deg) - cos(i * 20 deg)))
                         for i in range(72)], fill=true)
        } elif kind == 2 {
            s = Circle(center=(0, 0), radius=13, fill=true)
        } elif kind == 3 {
            s = Triangle(center=(0, 0), base=30, height=26, fill=true)
        } elif kind == 4 {
            s = RegularPolygon(center=(0, 0), radius=14, sides=6, fill=true)
        } elif kind == 5 {
            s = RegularPolygon(center=(0, 0), radius=15, sides=4, fill=true)
        } elif kind == 6 {
            s = Polygon([(-4.5, 14), (4.5, 14), (4.5, 4.5), (14, 4.5), (14, -4.5), (4.5, -4.5),
                         (4.5, -14), (-4.5, -14), (-4.5, -4.5), (-14, -4.5), (-14, 4.5),
                         (-4.5, 4.5)], fill=true)
        } else {
            s = Polygon([(-12, -13), (12, -13), (12, 3), (0, 14), (-12, 3)], fill=true)
        }
    }
    Fixed(body)
    CenterInside(sym, body)
}

assembly memory_game {
    for i in range(16) {
        t = tile_piece(kind=i // 2)
        # FIX after the first valid program: the tiles are laid out left of the box, and the
        # box is no longer moved by a relation (moving it on the sheet moved it in 3D too,
        # so the stacks stood 200 mm beside it in --assembled)
        t.bb.center == ((i % 4) * pitch - 300 mm, -(i // 4) * pitch)
        # assembled: two stacks of 8 in the box
        Place(t, position=((i % 2) * 42 mm - 21 mm, 0, 3 mm + (i // 2) * 3 mm), face="up")
    }

    box = lid_box(length=84 mm, width=42 mm, height=26 mm, thickness=3 mm, finger=10 mm,
                  outside=false)

    drawing label {
        word = Text("MEMORY", position=(0, 0), size=10, font="sans:Bold", valign="middle",
                    fill=true)
    }
    CutInto(label, box.lid)
    CenterInside(label, box.lid)

    # the request's numbers
    assert len(t) == 16, "16 tiles"
    assert t[0].body.width == 40 mm and t[0].body.height == 40 mm, "40 x 40 tiles"
    # (the 45 mm sheet pitch is not asserted: the tiles are Placed, and an assert reads a
    # Placed part where it is written, before the sheet's layout moves it)
    assert pitch - tile == 5 mm, "45 mm pitch leaves 5 mm between tiles"
    assert 2 * 40 mm <= 84 mm and 40 mm <= 42 mm, "two stacks side by side fit inside"
    assert 8 * 3 mm <= 26 mm, "a stack of 8 fits under the lip"
}
