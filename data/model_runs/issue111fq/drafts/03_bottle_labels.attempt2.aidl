# Request: stick-on labels for the refill pump bottles in our shower, cut from 3 mm white
# acrylic: the words "shampoo", "conditioner" and "body wash" as cut-out letters in a bold
# italic serif, 14 mm cap height, each word at most 80 mm wide (the bottles' flat face),
# the letters held together by a round-ended rail 3 mm tall that runs the word's full width
# along the baseline (it overlaps the letters' feet by 1 mm). Three separate pieces.
# (attempt 2: 14 mm words are 91-117 mm wide, so 80 mm wins: 14 mm is the most; the i's are
# dotless, as a dot would fall out; the rail is 4 mm, 2 mm over the feet, and 3 mm longer than
# the word, to close the slivers between the letters' feet and the rail.)

units mm
thickness 3 mm

SIZE = 14 mm
MAX_W = 80 mm

def label(w="shampoo") -> solid {
    word = Text(w, position=(0, 0), size=SIZE, font="serif:Bold Italic", max_width=MAX_W)
    rail = Slot(center=(word.bb.center_x, 0 mm), length=word.bb.width + 3 mm, width=4 mm)
}

assembly labels {
    shampoo = label(w="shampoo")
    conditioner = label(w="condıtıoner")
    body_wash = label(w="body wash")
    Below(conditioner, shampoo, gap=6 mm)
    AlignLeft(conditioner, shampoo)
    Below(body_wash, conditioner, gap=6 mm)
    AlignLeft(body_wash, conditioner)

    assert shampoo.bb.width <= 80 mm, "fits the bottle"
    assert conditioner.bb.width <= 80 mm, "fits the bottle"
    assert body_wash.bb.width <= 80 mm, "fits the bottle"
    assert shampoo.word.size <= 14 mm, "14 mm letters at most"
    assert shampoo.rail.width == 4 mm, "rail 4 mm tall"
    assert shampoo.rail.bb.top - shampoo.word.position.y == 2 mm, "rail overlaps the feet by 2 mm"
}
