# Request: a "shut the box" dice game, 3 mm birch ply. An open finger-jointed tray 240 x 160 mm
# and 40 mm tall (outside, 10 mm fingers) with "SHUT THE BOX" engraved filled, 12 mm bold,
# centred on the outside of its front. Nine flip tiles 22 x 50 mm (top corners r3) numbered 1
# to 9 (engraved filled, 14 mm bold figures centred 32 mm up), each with a 6.5 mm pivot hole
# 8 mm up from its bottom edge, stand side by side 24 mm apart on a 6 mm dowel along the back
# of the tray, the dowel's axis 40 mm behind the tray's centre line. The dowel runs through
# two cheeks 30 x 16 mm (6.2 mm holes, 8 mm above the floor) glued into the floor by a 10 mm
# tenon each, one at each end of the row, 1 mm clear of the end tiles.

import "std/joints.aidl"

thickness 3 mm

t = 3 mm
pitch = 24 mm
axis_y = 40 mm
axis_up = 8 mm
# the cheeks' inner faces, 1 mm clear of the end tiles
cheek_x = 4 * pitch + 11 mm + 1 mm

def tile_t(n=1) -> solid {
    body = RoundedRectangle(bottom_left=(-11, 0), width=22, height=50, corner_radii=[3, 3, 0, 0])
    hole pivot { c = Circle(center=(0, axis_up), diameter=6.5) }
    drawing num {
        d = Text(str(n), position=(0, 32), size=14, font="sans:Bold", fill=true,
                 valign="middle")
    }
}

def cheek_t() -> solid {
    # the tenon's tip on y = 0, the cheek's shoulders t above it, on the floor
    body = Rectangle(bottom_left=(-15, 0), width=30, height=16 + t)
    tenon = tab_and_slot(part="tab", length=30 mm, thickness=t, tabs=1, tab=10 mm, screw=0,
                         rotation=180 deg, cx=0 mm, cy=0 mm)
    hole axle { c = Circle(center=(0, t + axis_up), diameter=6.2) }
}

assembly game {
    box = finger_box(length=240 mm, depth=160 mm, height=40 mm, thickness=t, finger=10 mm,
                     closed=false)

    drawing title {
        w = Text("SHUT THE BOX", position=(0, 0), size=12, font="sans:Bold", fill=true,
                 valign="middle")
    }
    CenterInside(title, box.front)
    CutInto(title, box.front)

    # mortises for the cheeks' tenons in the floor (the bottom lies at the net's centre)
    left_mortise = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=10 mm,
                                screw=0, rotation=90 deg, cx=-cheek_x - t / 2, cy=axis_y)
    right_mortise = tab_and_slot(part="slot", length=30 mm, thickness=t, tabs=1, tab=10 mm,
                                 screw=0, rotation=90 deg, cx=cheek_x + t / 2, cy=axis_y)
    CutInto(left_mortise, box.bottom)
    CutInto(right_mortise, box.bottom)

    for i in range(9) {
        tile = tile_t(n=i + 1)
        # stood up on the floor, its pivot on the dowel's axis
        Place(tile, rotation=(90 deg, 0, 0), position=((i - 4) * pitch, axis_y + t / 2, t))
    }
    for i in range(1, 9) {
        RightOf(tile[i], tile[i - 1], gap=4)
        AlignBottom(tile[i], tile[0])
    }
    Below(tile[0], box, gap=10)
    AlignLeft(tile[0], box)

    left_cheek = cheek_t()
    right_cheek = cheek_t()
    RightOf(left_cheek, tile[8], gap=6)
    RightOf(right_cheek, left_cheek, gap=4)
    AlignBottom(left_cheek, tile[0])
    AlignBottom(right_cheek, tile[0])
    Place(left_cheek, rotation=(90 deg, 0, 90 deg), position=(-cheek_x - t, axis_y, 0))
    Place(right_cheek, rotation=(90 deg, 0, 90 deg), position=(cheek_x, axis_y, 0))

    assert box.front.bb.width == 240 mm and box.front.bb.height == 40 mm, "240 long, 40 tall"
    assert box.left.bb.height == 160 mm, "160 deep"
    assert len(tile) == 9, "nine tiles"
    assert tile[0].body.bb.width == 22 mm and tile[0].body.bb.height == 50 mm, "tiles 22 x 50"
    assert tile[0].pivot.c.diameter == 6.5 mm, "6.5 pivot holes"
    assert tile[0].pivot.c.center.y - tile[0].body.bb.bottom == 8 mm, "pivot 8 up"
    assert tile[0].num.bb.center_y - tile[0].body.bb.bottom == 32 mm, "figures 32 up"
    assert left_cheek.axle.c.diameter == 6.2 mm, "6.2 cheek holes"
    assert left_cheek.axle.c.center.y - left_cheek.body.bb.bottom - t == 8 mm, "8 above the floor"
    assert left_cheek.body.bb.width == 30 mm and left_cheek.body.bb.height - t == 16 mm, "cheeks 30 x 16"
    assert cheek_x - (4 * pitch + 11 mm) == 1 mm, "1 mm clear of the end tiles"
    assert cheek_x + t < 240 mm / 2 - t, "cheeks inside the tray"
    assert title.bb.width < box.front.bb.width - 40 mm, "title fits the front"
}
