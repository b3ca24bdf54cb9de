# Request: stick-on labels for the refill pump bottles in our shower, cut from 3 mm white
# acrylic: the words "shampoo", "conditioner" and "body wash" as cut-out letters in a bold
# italic serif, 14 mm cap height, each word at most 80 mm wide (the bottles' flat face),
# the letters held together by a round-ended rail 3 mm tall that runs the word's full width
# along the baseline (it overlaps the letters' feet by 1 mm). Three separate pieces.
# (attempt 2: 14 mm words are 91-117 mm wide, so 80 mm wins: 14 mm is the most; the i's are
# dotless, as a dot would fall out; the rail is 4 mm, 2 mm over the feet, and 3 mm longer than
# the word, to close the slivers between the letters' feet and the rail.)
# (attempt 3: the longer rail made the labels 82 wide: the word fits 76 mm so the label stays
# within 80; the rail reaches 2.6 mm up, over the a's crotch, and every corner is rounded
# 0.4 mm, which fills the nicks where a slanted stroke meets the rail.)
# (attempt 4: no Fillet (E0407: a font's curves cannot be filleted); one size, 9 mm, for all
# three words (conditioner, the longest, fits 76 mm at 9 mm), so the rail meets the same
# letter shapes on each; the rail 3 mm tall, its top 0.6 mm over the baseline.)
# FIX after the first valid program: W0515 found four slivers, each in the crotch of an a or
# a d (between the bowl's foot and the stem, closed by the rail), 0.4 mm^2 each; the rail's
# top goes up to 2 mm over the baseline, above the crotches.

units mm
thickness 3 mm

SIZE = 9 mm
MAX_W = 76 mm

def label(w="shampoo") -> solid {
    word = Text(w, position=(0, 0), size=SIZE, font="serif:Bold Italic")
    rail = Slot(center=(word.bb.center_x, 0.5 mm), length=word.bb.width + 3 mm, width=3 mm)
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
    assert conditioner.word.bb.width <= 76 mm, "the longest word fits"
    assert shampoo.rail.width == 3 mm, "rail 3 mm tall"
    assert shampoo.rail.bb.top - shampoo.word.position.y == 2 mm, "rail 2 mm over the feet"
}
