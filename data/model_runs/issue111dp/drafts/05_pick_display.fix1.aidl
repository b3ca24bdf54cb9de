# Request (music): a wall frame for twelve guitar picks from gigs, three 3 mm layers 240 x
# 200 mm with R8 corners. The picks are the standard 351 shape, 27 mm wide and 30 mm tall.
# Back layer: a keyhole (8 mm head, 4 mm slot, 8 mm long, upward) at the top centre, 20 mm
# below the top edge. Middle layer: 12 pick-shaped pockets 0.5 mm bigger than a pick all
# round, 4 columns x 3 rows at 50 mm pitch, centred; a 12 x 24 mm slot over the keyhole for
# the screw head. Front layer: a window 2.5 mm smaller than a pick over each pocket, so the
# pick is held but shows; under each window the gig engraved (4 mm strokes); the title
# "PICKS FROM THE ROAD" engraved filled at the top, serif bold, 10 mm.

import "std/plates.aidl"

thickness 3 mm

t = 3 mm
frame_w = 240 mm
frame_h = 200 mm
pitch = 50 mm
gigs = ["LEEDS 19", "YORK 19", "HULL 20", "BATH 21", "BRISTOL 21", "CARDIFF 22",
        "DERBY 22", "LEEDS 23", "OSLO 23", "GHENT 24", "LILLE 24", "HOME 25"]

def col_x(i) = (i % 4 - 1.5) * pitch
def row_y(i) = (1 - i // 4) * pitch

# a 351 pick, 27 x 30 mm, its box centred on (x, y), grown by grow (negative: shrunk)
def pick(x=0 mm, y=0 mm, grow=0 mm) -> hole {
    p = Offset(Hull(Circle(center=(x - 6.5 mm, y + 8 mm), radius=7),
                    Circle(center=(x + 6.5 mm, y + 8 mm), radius=7),
                    Circle(center=(x, y - 12.5 mm), radius=2.5)), grow)
}

# FIX after the first valid program: a left-over template `layer_body` (W0117) deleted.

assembly pick_frame {
    solid back {
        body = RoundedRectangle(center=(0, 0), width=frame_w, height=frame_h, corner_radius=8)
        hang = keyhole(head=8 mm, slot_width=4 mm, length=8 mm, cx=0, cy=frame_h / 2 - 20 mm)
        Fixed(body)
        assert body.bb.top - hang.head_hole.center.y == 20 mm
    }

    solid middle {
        body = RoundedRectangle(center=(0, 0), width=frame_w, height=frame_h, corner_radius=8)
        for i in range(12) {
            pocket = pick(x=col_x(i), y=row_y(i), grow=0.5 mm)
        }
        hole screw_room { s = Slot(center=(0, frame_h / 2 - 20 mm + 4 mm), length=24, width=12,
                                   rotation=90 deg) }
        Fixed(body)
        assert len(pocket) == 12
        assert pocket[0].bb.width > 27.99 mm and pocket[0].bb.width < 28.01 mm, "pick + 0.5 all round"
        assert pocket[0].bb.height > 30.99 mm and pocket[0].bb.height < 31.01 mm
        assert pocket[1].bb.center_x - pocket[0].bb.center_x == 50 mm
        assert pocket[0].bb.top - pocket[4].bb.top == 50 mm
    }

    solid front {
        body = RoundedRectangle(center=(0, 0), width=frame_w, height=frame_h, corner_radius=8)
        for i in range(12) {
            window = pick(x=col_x(i), y=row_y(i), grow=-2.5 mm)
        }
        drawing labels {
            for i in range(12) {
                g = Text(gigs[i], position=(col_x(i), row_y(i) - 25 mm), size=4)
            }
            title = Text("PICKS FROM THE ROAD", position=(0, frame_h / 2 - 18 mm), size=10,
                         font="serif:Bold", valign="middle", fill=true)
        }
        Fixed(body)
        assert len(window) == 12 and len(labels.g) == 12
    }

    # flat on the sheet
    RightOf(middle, back, gap=6)
    AlignTop(middle, back)
    Below(front, back, gap=6)
    AlignLeft(front, back)

    # assembled on the wall: back, middle, front, each facing the room
    Place(back, position=(0, 0, 0), face="front", up="up")
    Place(middle, position=(0, -t, 0), face="front", up="up")
    Place(front, position=(0, -2 * t, 0), face="front", up="up")
}
