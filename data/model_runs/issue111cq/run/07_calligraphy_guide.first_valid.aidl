# Request: a ruling template for practising Italic with a 4 mm nib, 3 mm MDF, A4 landscape
# (297 x 210 mm), corners R5. Three writing rows; each row has four pencil slots (1.5 mm wide):
# ascender line 34 mm above the baseline, waist line 20 mm (x-height = 5 nib widths), the
# baseline, and the descender line 14 mm below; rows 56 mm apart, the first baseline 38 mm above
# the sheet's middle. Each slot line is 235 mm long in 4 segments of 55 mm with 5 mm bridges,
# centred. Along the top margin 12 short slant slots (15 mm, 1.5 wide) every 20 mm, leaning
# 5 deg from vertical to the right, to start the slant lines. Labels ASC / X / BASE / DESC
# engraved 3.5 mm at the left of each line; a nib ladder of five filled 4 mm squares
# (alternating 4 mm left/right) from the first row's baseline up to its waist line, at the
# right; a thumb notch R12 in the middle of the right edge; a title line engraved 4 mm high
# 7 mm above the bottom edge.

units mm
thickness 3 mm

plate_w = 297 mm
plate_h = 210 mm
nib = 4 mm
offs = [34 mm, 20 mm, 0 mm, -14 mm]
names = ["ASC", "X", "BASE", "DESC"]
row_pitch = 56 mm
base0 = 38 mm
seg = 55 mm
bridge = 5 mm

def base_y(r) = base0 - r * row_pitch

solid guide {
    body = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=5)
    hole rules {
        for r in range(3) {
            for l in range(4) {
                for k in range(4) {
                    s = Slot(center=(-1.5 * (seg + bridge) + k * (seg + bridge),
                                     base_y(r) + offs[l]), length=seg, width=1.5)
                }
            }
        }
    }
    hole slants {
        for i in range(12) {
            s = Slot(center=(-110 + i * 20, 89.5), length=15, width=1.5, rotation=85 deg)
        }
    }
    hole thumb { c = Circle(center=(plate_w / 2, 0), radius=12) }
    drawing labels {
        for r in range(3) {
            for l in range(4) {
                t = Text(names[l], position=(-128, base_y(r) + offs[l]), size=3.5,
                         valign="middle")
            }
        }
        title = Text("ITALIC - NIB 4 MM - X-HEIGHT 5 NIBS - SLANT 5 DEG",
                     position=(0, -plate_h / 2 + 7), size=4)
    }
    drawing ladder {
        for k in range(5) {
            sq = Rectangle(bottom_left=(126 + 4 * (k % 2), base0 + k * nib), width=nib,
                           height=nib, fill=true)
        }
    }

    # the request's numbers
    assert body.bb.width == 297 mm and body.bb.height == 210 mm, "A4 landscape"
    assert offs[1] - offs[2] == 5 * nib, "x-height 5 nibs"
    assert offs[0] - offs[1] == 14 mm and offs[2] - offs[3] == 14 mm, "asc/desc 14"
    assert len(slants.s) == 12, "12 slant slots"
    assert rules.s[0][0][3].center.x + seg / 2 - (rules.s[0][0][0].center.x - seg / 2)
        == 235 mm, "lines 235 long"
    assert len(ladder.sq) == 5, "5 ladder squares"
    assert ladder.sq[4].bb.top - ladder.sq[0].bb.bottom == 20 mm, "ladder = x-height"
}
