# Request: a "Letters to Santa" post box for the mantelpiece, 3 mm birch ply, finger-jointed
# (12 mm fingers), 160 wide x 110 deep x 220 tall outside. It is an open-bottomed box: it stands
# over the letters and is lifted off on Christmas Eve, so five panels: roof, front, back and
# two sides. The roof has a letter slot 120 x 10 mm, centred. The front carries, engraved and
# filled: a 5-point star (outer radius 22, inner 9) at the top, "LETTERS" and "TO SANTA" in a
# bold serif 16 mm tall, and "NORTH POLE" 9 mm single-stroke below; the art block centred on
# the front. Each side has an engraved 6-armed snowflake, 60 mm across, centred.

import "std/joints.aidl"

units mm
thickness 3 mm

def flake() -> drawing {
    drawing arm {
        spoke = Line((0, 0), (0, 30))
        b1 = Line((0, 18), (-7, 25))
        b2 = Line((0, 18), (7, 25))
        b3 = Line((0, 8), (-5, 13))
        b4 = Line((0, 8), (5, 13))
    }
    arms = CircularPattern(arm, 6, (0, 0))
}

assembly santa_mailbox {
    # made as an open-top finger box, then turned over: its bottom panel is the roof
    box = finger_box(length=160 mm, depth=110 mm, height=220 mm, thickness=3 mm, finger=12 mm,
                     closed=false)

    hole letter_slot { s = Slot(center=(0, 0), length=120, width=10) }
    CenterInside(letter_slot, box.bottom)
    CutInto(letter_slot, box.bottom)

    # drawn upside down (rotation 180) in the box's frame, since the box stands on its head
    drawing art {
        star = Star(center=(0, -62), points=5, outer_radius=22, inner_radius=9, rotation=180 deg,
                    fill=true)
        l1 = Text("LETTERS", position=(0, -20), size=16, font="serif:Bold", valign="middle",
                  rotation=180 deg, fill=true)
        l2 = Text("TO SANTA", position=(0, 6), size=16, font="serif:Bold", valign="middle",
                  rotation=180 deg, fill=true)
        l3 = Text("NORTH POLE", position=(0, 32), size=9, valign="middle", rotation=180 deg)
    }
    CenterInside(art, box.front)
    CutInto(art, box.front)

    left_flake = flake()
    right_flake = flake()
    CenterInside(left_flake, box.left)
    CenterInside(right_flake, box.right)
    CutInto(left_flake, box.left)
    CutInto(right_flake, box.right)

    Place(box, position=(0, 0, 220), rotation=(0, 180 deg, 0))

    # the request's numbers
    assert box.front.bb.width == 160 mm and box.front.bb.height == 220 mm, "front 160 x 220"
    assert box.left.bb.height == 110 mm, "110 deep"
    assert letter_slot.s.length == 120 mm and letter_slot.s.width == 10 mm, "slot 120 x 10"
    assert art.l1.size == 16 mm and art.l3.size == 9 mm, "letter sizes"
    assert len(left_flake.arms) == 6, "6 arms"
    assert left_flake.bb.height == 60 mm, "snowflake 60 across"
}
