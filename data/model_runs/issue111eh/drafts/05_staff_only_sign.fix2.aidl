# Request (signs): a "STAFF ONLY" door sign in two layers of 3 mm acrylic. The letters are
# cut from black acrylic as one piece: "STAFF ONLY" in sans bold, 40 mm cap height, all
# letters standing on a 4 mm rail (from 3 mm under the baseline to 1 mm above it) exactly
# as wide as the words. They are glued on a clear backer: a plate with R6 corners, 10 mm
# of margin above, below and left/right of the letters and rail, plus 20 mm more at each end
# for a sign standoff: one M6 clearance hole at each end, centred in the height, 12 mm in
# from the end. The letters sit centred on the backer.
#
# FIX after the first valid program: the rail joined every letter's foot, so the F's read as
# E's ("STAFE ONLY"). Now each letter is its own piece (one solid per letter), 3 mm apart
# box to box, 18 mm between the words, on one baseline; the backer keeps its margins round
# them. The letters lie on the backer where they are glued (they overlap it on purpose; lift
# them together on transfer tape); no 3D Place. (Fix 2: the engraved baseline guide of fix 1
# showed between the letters on clear acrylic: dropped.)

import "std/fasteners.aidl"

thickness 3 mm

chars = ["S", "T", "A", "F", "F", "O", "N", "L", "Y"]

assembly sign {
    for i in range(9) {
        solid letter {
            t = Text(chars[i], position=(i * 32 mm, 0), size=40, font="sans:Bold",
                     anchor="start")
        }
    }
    Fixed(letter[0])
    for i in range(1, 9) {
        RightOf(letter[i], letter[i - 1], gap=(18 mm if i == 5 else 3 mm))
        letter[i].t.position.y == letter[0].t.position.y
    }

    solid backer {
        # by two corners: its size is set by the letters (below), its corners rounded R6
        plate = Rectangle(corner=(-40, -20), opposite=(330, 50))
        Fillet(plate, 6 mm)
        left_hole = clearance_hole(size=6)
        right_hole = clearance_hole(size=6)
        AlignCenterY(left_hole.c, plate)
        AlignCenterY(right_hole.c, plate)
        left_hole.c.center.x == plate.bb.left + 12 mm
        right_hole.c.center.x == plate.bb.right - 12 mm
    }
    # margins: 10 mm round the letters, 20 mm more at each end
    backer.plate.bb.left == letter[0].bb.left - 30 mm
    backer.plate.bb.right == letter[8].bb.right + 30 mm
    backer.plate.bb.bottom == letter[0].t.position.y - 10 mm
    backer.plate.bb.top == letter[0].t.position.y + 40 mm + 10 mm
    AllowOverlap(letter, backer)

    # the request's numbers
    assert letter[0].t.size == 40 mm, "40 mm cap height"
    assert len(letter) == 9, "nine letters: STAFF ONLY"
    assert letter[5].bb.left - letter[4].bb.right == 18 mm, "word space 18"
    assert backer.left_hole.c.center.x - backer.plate.bb.left == 12 mm, "hole 12 in"
    assert backer.plate.bb.right - backer.right_hole.c.center.x == 12 mm, "hole 12 in"
    # the standoff cap (about 19 mm across) stays off the letters
    assert letter[0].bb.left - backer.left_hole.c.center.x - 19 mm / 2 >= 5 mm,
        "standoff caps clear of the letters"
}
