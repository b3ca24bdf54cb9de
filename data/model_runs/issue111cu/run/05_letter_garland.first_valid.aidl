# Request (parties): a "HAPPY BIRTHDAY" garland, 3 mm birch ply. Each letter is its own
# piece: the letter itself in bold sans, 80 mm cap height, hanging from a rail 12 mm tall
# (4 mm corner radii) that overlaps the letter's top by 4 mm and is as wide as the letter but
# at least 40 mm; two 4 mm holes in the rail, 24 mm apart, centred on it, 3 mm above the
# letter's cap line, for threading a ribbon. 13 pieces; hung in a row 80 mm apart, with an
# extra 60 mm between the two words.

thickness 3 mm

CAP = 80 mm
PITCH = 80 mm
WORD_GAP = 60 mm
letters = ["H", "A", "P", "P", "Y", "B", "I", "R", "T", "H", "D", "A", "Y"]

def letter_tag(ch="A") -> solid {
    glyph = Text(ch, position=(0, 0), size=CAP, font="sans:Bold")
    rail = RoundedRectangle(center=(glyph.center.x, CAP + 2 mm), width=max(glyph.bb.width, 40 mm),
                            height=12, corner_radius=4)
    hole strings {
        left = Circle(center=(-12, CAP + 3 mm), diameter=4)
        right = Circle(center=(12, CAP + 3 mm), diameter=4)
    }
    AlignCenterX(strings, rail)
}

def hang_x(i) = i * PITCH + (WORD_GAP if i >= 5 else 0 mm)

assembly garland {
    for i in range(len(letters)) {
        tag = letter_tag(ch=letters[i])
        tag.bb.center == (i * PITCH, 0)
        Place(tag, position=(hang_x(i), 0, 0), face="front", up="up")
    }

    assert len(tag) == 13, "13 pieces"
    assert tag[6].rail.bb.width == 40 mm, "the I's rail at least 40 mm"
    assert tag[0].strings.right.center.x - tag[0].strings.left.center.x == 24 mm, "holes 24 apart"
    assert tag[0].strings.left.diameter == 4 mm, "4 mm holes"
    assert tag[0].rail.bb.height == 12 mm, "rail 12 mm"
    assert hang_x(5) - hang_x(4) == PITCH + 60 mm, "60 mm between the words"
}
