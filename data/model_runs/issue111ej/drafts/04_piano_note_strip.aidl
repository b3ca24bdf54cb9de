# Request (music): a note-name strip for a beginner at the piano. It stands on the key slip
# just behind the keys, two octaves from C3 to B4 long, in 3 mm ply. White keys 165 mm an
# octave (23.57 mm each), so the strip is 330 x 40 mm. On it, engraved filled: each white
# key's letter (sans bold, 10 mm caps, baseline 8 mm up, centred on its key; the Cs read
# "C3" and "C4"), a 13 x 14 mm block for each of the 10 black keys (centred on the line
# between C-D, D-E, F-G, G-A, A-B; 3 mm below the top edge), and a 0.3 mm line between
# neighbouring white keys from 17 mm up to the top. It stands on two feet 50 x 30 mm, R4
# corners, cross-halved 15 mm into each other: the slots in the strip from its bottom edge,
# on the D-E line of each octave; the feet cut below the strip, 6 mm apart.

units mm
thickness 3 mm

import "std/joints.aidl"

octave = 165 mm
key_w = octave / 7
whites = 14
names = ["C", "D", "E", "F", "G", "A", "B"]
black_after = [0, 1, 3, 4, 5]      # a black key after these white keys of an octave
strip_h = 40 mm
foot_h = 30 mm

def foot() -> solid {
    body = RoundedRectangle(center=(0, 0), width=50, height=foot_h, corner_radius=4)
    slot = cross_halving(depth=foot_h / 2, thickness=3 mm, cx=0 mm, cy=foot_h / 2)
}

assembly piano_strip {
    solid strip {
        body = Rectangle(bottom_left=(0, 0), width=whites * key_w, height=strip_h)
        for i in range(whites) {
            drawing name {
                t = Text(f"{names[i % 7]}{3 + i // 7}" if i % 7 == 0 else names[i % 7],
                         position=((i + 0.5) * key_w, 8), size=10, font="sans:Bold",
                         fill=true)
            }
        }
        for o in range(2) {
            for b in black_after {
                drawing black {
                    r = Rectangle(center=((o * 7 + b + 1) * key_w, strip_h - 3 - 7), width=13,
                                  height=14, fill=true)
                }
            }
        }
        drawing dividers {
            for k in range(1, whites) {
                l = Line((k * key_w, 17), (k * key_w, strip_h))
            }
        }
        slot_a = cross_halving(depth=foot_h / 2, thickness=3 mm, cx=2 * key_w, cy=0 mm,
                               rotation=180 deg)
        slot_b = cross_halving(depth=foot_h / 2, thickness=3 mm, cx=9 * key_w, cy=0 mm,
                               rotation=180 deg)
        Fixed(body)
    }

    left_foot = foot()
    right_foot = foot()
    Below(left_foot, strip, gap=6)
    AlignLeft(left_foot, strip)
    RightOf(right_foot, left_foot, gap=6)
    AlignTop(right_foot, left_foot)

    # standing: the strip faces the player, each foot across it under a slot
    Place(strip, position=(0, 0, 0), face="front", up="up")
    Place(left_foot, position=(2 * key_w - 1.5, -1.5, foot_h / 2), face="right", up="up")
    Place(right_foot, position=(9 * key_w - 1.5, -1.5, foot_h / 2), face="right", up="up")

    # the request's numbers
    assert abs(strip.body.width - 330 mm) < 0.01 mm and abs(strip.body.height - 40 mm) < 0.01 mm, "330 x 40"
    assert len(strip.name) == 14, "14 white keys, C3 to B4"
    assert strip.name[0].t.text == "C3" and strip.name[7].t.text == "C4" and strip.name[13].t.text == "B", "the Cs carry octaves"
    assert len(strip.black) == 2 and len(strip.black[0]) == 5, "10 black keys"
    assert abs(strip.body.bb.top - strip.black[0][0].r.bb.top - 3 mm) < 0.01 mm, "blocks 3 below the top"
    assert distance(strip.name, strip.slot_a) >= 1 mm and distance(strip.name, strip.slot_b) >= 1 mm, "letters clear of the slots"
    assert distance(strip.name, strip.black) >= 1 mm, "letters clear of the black keys"
    assert abs(strip.slot_a.depth + left_foot.slot.depth - 30 mm) < 0.01 mm, "halvings add to the foot's height"
    assert abs(left_foot.body.width - 50 mm) < 0.01 mm, "feet 50 long"
}
