# Request (signs): a "STAFF ONLY" door sign in two layers of 3 mm acrylic. The letters are
# cut from black acrylic as one piece: "STAFF ONLY" in sans bold, 40 mm cap height, all
# letters standing on a 4 mm rail (from 3 mm under the baseline to 1 mm above it) exactly
# as wide as the words. They are glued on a clear backer: a plate with R6 corners, 10 mm
# of margin above, below and left/right of the letters and rail, plus 20 mm more at each end
# for a sign standoff: one M6 clearance hole at each end, centred in the height, 12 mm in
# from the end. The letters sit centred on the backer.

import "std/fasteners.aidl"

thickness 3 mm

assembly sign {
    solid letters {
        word = Text("STAFF ONLY", position=(0, 0), size=40, font="sans:Bold")
        rail = Rectangle(center=(word.center.x, -1 mm), width=word.bb.width, height=4 mm)
    }

    solid backer {
        plate = RoundedRectangle(center=(0, 0), width=100, height=50, corner_radius=6)
        left_hole = clearance_hole(size=6)
        right_hole = clearance_hole(size=6)
        AlignCenterY(left_hole.c, plate)
        AlignCenterY(right_hole.c, plate)
        left_hole.c.center.x == plate.bb.left + 12 mm
        right_hole.c.center.x == plate.bb.right - 12 mm
    }
    # the backer's size follows the letters: 10 mm margin, 20 mm more at each end
    backer.plate.bb.width == letters.bb.width + 2 * 10 mm + 2 * 20 mm
    backer.plate.bb.height == letters.bb.height + 2 * 10 mm

    # laid out flat: the letters under the backer
    Below(letters, backer, gap=5)
    AlignCenterX(letters, backer)

    # assembled: the backer on the door, the letters centred on it
    Place(backer, position=(0, 0, 0), face="front", up="up")
    Place(letters, position=(backer.plate.center.x - letters.bb.center_x,
                             -3 mm,
                             backer.plate.center.y - letters.bb.center_y),
          face="front", up="up")

    # the request's numbers
    assert letters.word.size == 40 mm, "40 mm cap height"
    assert letters.rail.bb.width == letters.word.bb.width, "rail as wide as the words"
    assert letters.rail.bb.bottom == letters.word.position.y - 3 mm, "rail 3 under the baseline"
    assert letters.rail.bb.top == letters.word.position.y + 1 mm, "rail 1 above the baseline"
    assert backer.plate.bb.height - letters.bb.height == 2 * 10 mm, "10 mm margin top and bottom"
    assert backer.plate.bb.width - letters.bb.width == 2 * 10 mm + 2 * 20 mm, "ends 30 mm"
    assert backer.left_hole.c.center.x - backer.plate.bb.left == 12 mm, "hole 12 in"
    assert backer.plate.bb.right - backer.right_hole.c.center.x == 12 mm, "hole 12 in"
    # the standoff cap (about 19 mm across) stays off the letters
    assert (backer.plate.bb.width - letters.bb.width) / 2 - 12 mm - 19 mm / 2 >= 5 mm,
        "standoff caps clear of the letters"
}
