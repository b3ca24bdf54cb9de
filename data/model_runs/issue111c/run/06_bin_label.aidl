# Storage-bin label: a 90 x 30 mm plate with R3 corners, "SCREWS" cut through
# as stencil letters in a sans Bold font, 12 mm cap height, centered; two 3.5 mm
# holes 6 mm in from the left and right ends on the center line, for pop rivets.
thickness 3 mm

solid label {
    plate = RoundedRectangle(center=(0, 0), width=90, height=30, corner_radius=3)
    hole word {
        t = Text("SCREWS", position=(0, 0), size=12, font="sans:Bold", valign="middle",
                 stencil=true)
    }
    CenterInside(word, plate)
    hole rivet {
        c = Circle(center=(-39, 0), diameter=3.5)
    }
    AlignCenterY(rivet, plate)
    rivet.c.center.x == plate.bb.left + 6 mm
    other = Mirrored(rivet, about=Line((0, -20), (0, 20), construction=true))
}

assert label.plate.bb.width == 90 mm and label.plate.bb.height == 30 mm, "90 x 30"
assert label.rivet.c.center.x - label.plate.bb.left == 6 mm, "rivet 6 mm in from the left"
assert label.plate.bb.right - label.other.c.center.x == 6 mm, "rivet 6 mm in from the right"
assert label.word.t.size == 12 mm, "12 mm letters"
assert label.word.bb.left > label.rivet.bb.right + 2 mm, "text clear of the rivets"
assert label.other.bb.left > label.word.bb.right + 2 mm, "text clear of the rivets"
