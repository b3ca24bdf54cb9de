# Request: a farm-gate sign, 6 mm exterior ply, hung by two chains. A backing board 520 x 240
# with 20 mm corner radii and two 6 mm chain holes 30 mm in from the sides and 15 mm down
# from the top. Glued on it, cut separately (to paint another colour): "FRESH EGGS" in bold
# sans capitals 40 mm high, standing on a rail 8 mm tall as wide as the word (the letters
# sink 2 mm into the rail), the word's middle 60 mm right of the board's middle and its
# baseline 20 mm above it; and a hen facing the word, about 130 mm tall: an oval body
# 90 x 64, a round head on a neck, a three-lobed comb, a beak, a wattle, a tail, two legs with
# feet, and a 5 mm eye cut through. "£3 A DOZEN" is engraved filled, 26 mm high, under the
# word (its middle 50 mm below the board's middle, 60 mm right of it).
# (Changed after attempt 1: the word is 323 mm wide, not the ~290 I had guessed, and ran into
# the hen at 40 mm right; 60 mm right leaves 11 mm between them and 38 mm to the right edge.)

thickness 6 mm

W = 520 mm
chars = ["F", "R", "E", "S", "H", "E", "G", "G", "S"]
H = 240 mm

assembly sign {
    solid board {
        body = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=20)
        Fixed(body)
        hole chains {
            for s in [-1, 1] {
                c = Circle(center=(s * (W / 2 - 30 mm), H / 2 - 15 mm), diameter=6)
            }
        }
        drawing price {
            p = Text("£3 A DOZEN", position=(60, -50), size=26, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }

    # FIX after the first valid program: the rail under the letters closed the F's foot
    # and it read as an E ("ERESH EGGS"); the letters are cut and glued on one by one instead
    # (W0504's hint: each letter a solid of its own in an assembly), 4 mm apart, 16 mm
    # between the words, the word's middle 60 mm right of the board's and its baseline 20 up
    assembly word {
        for i in range(len(chars)) {
            solid letter { g = Text(chars[i], position=(60, 20), size=40, font="sans:Bold") }
        }
        for i in range(1, len(chars)) {
            RightOf(letter[i], letter[i - 1], gap=(16 mm if i == 5 else 4 mm))
        }
        (letter[0].bb.left + letter[len(chars) - 1].bb.right) / 2 == 60 mm
    }

    solid hen {
        body = Ellipse(center=(-180, -10), rx=45, ry=32)
        tail = Polygon([(-212, -2), (-248, 40), (-232, 46), (-200, 18)])
        neck = Hull(Circle(center=(-140, 35), radius=16), Circle(center=(-152, 5), radius=20))
        for i in range(3) {
            comb = Circle(center=(-148 + 8 * i, 52 + (2 if i == 1 else 0)), radius=5)
        }
        beak = Polygon([(-126, 39), (-113, 34), (-126, 29)])
        wattle = Circle(center=(-128, 22), radius=4)
        for x in [-190, -170] {
            leg = Rectangle(center=(x, -52), width=4, height=26)
            foot = Rectangle(center=(x + 4, -65), width=16, height=4)
        }
        hole eye { e = Circle(center=(-137, 39), diameter=5) }
    }

    # flat: the word and the hen under the board on the sheet
    Below(word, board, gap=10)
    AlignLeft(word, board)
    RightOf(hen, word, gap=10)
    AlignTop(hen, word)

    # assembled: the board faces the lane; the word and the hen glued on its face, where drawn
    Place(board, position=(0, 0, 0), face="front", up="up")
    Place(word, position=(0, -6 mm, 0), face="front", up="up")
    Place(hen, position=(0, -6 mm, 0), face="front", up="up")

    assert board.body.bb.width == 520 mm and board.body.bb.height == 240 mm
    assert word.letter[0].g.size == 40 mm
    assert word.letter[0].g.position.y - board.body.center.y == 20 mm
    assert hen.bb.height <= 135 mm and hen.bb.height >= 125 mm, "hen about 130 tall"
    assert hen.bb.right < word.bb.left, "the hen clear of the word"
    assert board.price.p.position.y - board.body.center.y == -50 mm
}
