# Request: a note guide for my daughter's piano lessons, standing on the key slip behind
# two octaves of keys, C3 to B4 (14 white keys, 23.5 mm each). 3 mm ply strip 369 x 50
# (the keyboard drawing 329 wide, centred, 20 mm plain at each end). Engraved: the white
# keys' outlines in a band from 3 mm above the strip's bottom to 33 mm above it; the
# black keys (13.7 x 18, filled) on the white keys' boundaries (C#, D#, F#, G#, A#), their
# tops on the band's top; each white key's name (5 mm) in its lower part, the C keys as
# C3 and C4, a filled 2.4 mm dot under middle C (C4); each black key's name (4 mm) above
# it. Two feet 60 x 25 (R6 top corners) hold it upright, cross-halved with the strip
# 10 mm outside each end of the keyboard.

import "std/joints.aidl"

units mm
thickness 3 mm

t = 3 mm
key_w = 23.5 mm
keys = 14
names = ["C", "D", "E", "F", "G", "A", "B"]
strip_w = 369 mm
strip_h = 50 mm
band_bottom = -strip_h / 2 + 3 mm
band_top = -strip_h / 2 + 33 mm
black_w = 13.7 mm
black_h = 18 mm
x0 = -keys * key_w / 2         # left edge of C3
foot_x = keys * key_w / 2 + 10 mm
foot_l = 60 mm
foot_h = 25 mm

def has_black(k) = k % 7 != 0 and k % 7 != 3

assembly note_guide {
    solid strip {
        board = Rectangle(center=(0, 0), width=strip_w, height=strip_h)
        left_halving = cross_halving(depth=foot_h / 2, thickness=t, rotation=180 deg,
                                     cx=-foot_x, cy=-strip_h / 2)
        right_halving = cross_halving(depth=foot_h / 2, thickness=t, rotation=180 deg,
                                      cx=foot_x, cy=-strip_h / 2)
        drawing keyboard {
            bottom_line = Line((x0, band_bottom), (-x0, band_bottom))
            # the band's top edge runs between the black keys, not over their tops
            for i in range(keys) {
                top_seg = Line((x0 + i * key_w + (black_w / 2 if has_black(i) else 0 mm), band_top),
                               (x0 + (i + 1) * key_w - (black_w / 2 if has_black(i + 1) else 0 mm),
                                band_top))
            }
            for k in range(keys + 1) {
                if has_black(k) {
                    edge = Line((x0 + k * key_w, band_bottom), (x0 + k * key_w, band_top - black_h))
                    black = Rectangle(center=(x0 + k * key_w, band_top - black_h / 2), width=black_w,
                                      height=black_h, fill=true)
                } else {
                    edge = Line((x0 + k * key_w, band_bottom), (x0 + k * key_w, band_top))
                }
            }
        }
        drawing white_names {
            for i in range(keys) {
                n = Text(f"C{3 + i // 7}" if i % 7 == 0 else names[i % 7],
                         position=(x0 + (i + 0.5) * key_w, band_bottom + 7 mm), size=5,
                         valign="middle")
            }
            middle_c = Circle(center=(x0 + 7.5 * key_w, band_bottom + 2 mm), diameter=2.4,
                              fill=true)
        }
        drawing black_names {
            for k in range(keys + 1) {
                if has_black(k) {
                    s = Text(f"{names[(k - 1) % 7]}#", position=(x0 + k * key_w, band_top + 5 mm),
                             size=4, valign="middle")
                }
            }
        }
        assert len(white_names.n) == 14, "14 white keys named"
        assert len(black_names.s) == 10, "10 black keys named"
        assert white_names.n[1].position.x - white_names.n[0].position.x == 23.5 mm, "23.5 key pitch"
        assert board.width == 369 mm and board.height == 50 mm, "strip 369 x 50"
        assert keyboard.bb.width == 329 mm, "keyboard 329 wide"
        assert keyboard.bb.bottom - board.bb.bottom == 3 mm, "band 3 above the bottom"
        assert keyboard.bb.top - board.bb.bottom == 33 mm, "band 33 above the bottom"
        assert black_names.bb.top <= board.bb.top - 2 mm, "sharps inside the strip"
        assert distance(white_names, keyboard.black) >= 1 mm, "names clear of the black keys"
        assert distance(keyboard, left_halving) >= 3 mm, "keyboard clear of the feet"
    }

    def foot() -> solid {
        body = RoundedRectangle(center=(0, foot_h / 2), width=foot_l, height=foot_h,
                                corner_radii=[6 mm, 6 mm, 0 mm, 0 mm])
        halving = cross_halving(depth=foot_h / 2, thickness=t, cx=0 mm, cy=foot_h)
    }
    left_foot = foot()
    right_foot = foot()

    # flat on the sheet
    Below(left_foot, strip, gap=6)
    AlignLeft(left_foot, strip)
    RightOf(right_foot, left_foot, gap=6)
    AlignBottom(right_foot, left_foot)

    # assembled: the strip upright facing the player, the feet across it at its ends
    Place(strip, position=(0, t / 2, strip_h / 2), face="front", up="up")
    Place(left_foot, position=(-foot_x - t / 2, 0, 0), face="right", up="up")
    Place(right_foot, position=(foot_x - t / 2, 0, 0), face="right", up="up")

    assert strip.right_halving.cut.bb.height + right_foot.halving.cut.bb.height == 25 mm,
        "halvings add up to the feet's height"
}
