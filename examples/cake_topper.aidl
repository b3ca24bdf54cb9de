# A birthday cake topper cut from 3 mm acrylic in one piece: the words in a
# bold font (the letters' outlines are the part, issue 112), a rail exactly as
# wide as the words under their baseline that joins every letter, and two
# stems that go into the cake. The A's legs and the rail leave a window: the
# font's own.
# Try: --set words='"HAPPY 40"'  --set stem_length=90  --set font_style='"serif:Bold"'

param words = "HAPPY 30"
param font_style = "sans:Black"
param size = 22 mm, min = 10 mm, max = 40 mm
param stem_length = 70 mm, min = 30 mm, max = 120 mm
param stem_width = 6 mm, min = 4 mm, max = 12 mm

thickness 3 mm

solid topper {
    word = Text(words, position=(0, 0), size=size, font=font_style)
    # under the baseline, overlapping the letters' feet by 1 mm: one piece
    rail = Rectangle(center=(word.center.x, -size / 10), width=word.bb.width,
                     height=size / 5 + 2 mm)
    left = Rectangle(center=(-25, -stem_length / 2), width=stem_width, height=stem_length)
    right = Rectangle(center=(25, -stem_length / 2), width=stem_width, height=stem_length)
    # the stems a quarter of the words' width either side of their middle
    left.center.x == word.center.x - word.bb.width / 4
    right.center.x == word.center.x + word.bb.width / 4
}
