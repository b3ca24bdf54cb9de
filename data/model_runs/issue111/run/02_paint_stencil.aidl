# Paint stencil: 170 x 60 mm plate with 5 mm rounded corners; the word "PAINT" cut
# through as bridged stencil letters, font sans Bold, 28 mm cap height, centered;
# four 4 mm pin holes 6 mm in from each corner.

param word_size = 28 mm, min = 15 mm, max = 35 mm

solid stencil_plate {
    body = RoundedRectangle(center=(0, 0), width=170, height=60, corner_radius=5)
    hole letters {
        word = Text("PAINT", position=(0, 0), size=word_size, font="sans:Bold",
                    valign="middle", stencil=true)
    }
    CenterInside(letters, body)
    hole pin {
        c = Circle(center=(0, 0), diameter=4)
    }
    CornerPattern(pin, body, inset=6)
    assert letters.bb.left > pin.bb.right + 5 mm, "letters clear of the pin holes"
}
assert stencil_plate.body.bb.width == 170 mm and stencil_plate.body.bb.height == 60 mm, "plate 170 x 60"
assert stencil_plate.letters.word.size == 28 mm, "28 mm letters"
assert stencil_plate.pin.c.diameter == 4 mm, "4 mm pin holes"
