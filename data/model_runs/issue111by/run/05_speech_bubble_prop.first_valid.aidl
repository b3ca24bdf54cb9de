# Request: "A photo-booth speech bubble prop for a 40th birthday party, 3 mm poplar ply. The
# bubble is an oval 240 x 150 mm with a pointed tail at its lower left: the tail's tip 40 mm
# below the oval's bottom and 100 mm left of its centre, its root about 45 mm wide, the
# corners where tail meets oval rounded r5. Engraved filled in sans bold: FORTY & on one line
# and FABULOUS under it, the letters 26 mm tall, each line at most 190 mm wide, and an
# engraved border line 6 mm in from the oval. A handle stick 300 x 18 mm with fully rounded
# ends and a 6 mm hanging hole 15 mm from its bottom end is glued behind the bubble, 20 mm
# right of the centre, its top end 60 mm up inside the oval."

units mm
thickness 3 mm

oval_w = 240 mm
oval_h = 150 mm
tip_drop = 40 mm
tip_left = 100 mm
letter = 26 mm
line_max = 190 mm
border_in = 6 mm
stick_len = 300 mm
stick_w = 18 mm
stick_x = 20 mm
stick_up = 60 mm

assembly prop {
    solid bubble {
        oval = Ellipse(center=(0, 0), rx=oval_w / 2, ry=oval_h / 2)
        tail = Polygon([(-80, -50), (-40, -65), (-tip_left, -oval_h / 2 - tip_drop)])
        Fillet([oval, tail], 5)
        drawing words {
            l1 = Text("FORTY &", position=(0, 20), size=letter, font="sans:Bold",
                      valign="middle", max_width=line_max, fill=true)
            l2 = Text("FABULOUS", position=(0, -22), size=letter, font="sans:Bold",
                      valign="middle", max_width=line_max, fill=true)
        }
        drawing border {
            e = Ellipse(center=(0, 0), rx=oval_w / 2 - border_in, ry=oval_h / 2 - border_in)
        }
        Concentric(border.e, oval)
    }

    solid stick {
        bar = RoundedRectangle(center=(0, 0), width=stick_w, height=stick_len,
                               corner_radius=stick_w / 2)
        hole hang { c = Circle(center=(0, -stick_len / 2 + 15), diameter=6) }
    }

    RightOf(stick, bubble, gap=10)
    AlignTop(stick, bubble)
    # assembled: the stick glued behind, its top stick_up above the oval's bottom
    Place(bubble, position=(0, 0, 0))
    Place(stick, position=(stick_x, -oval_h / 2 + stick_up - stick_len / 2, -3 mm))

    # the request's numbers
    assert abs(bubble.oval.bb.width - 240 mm) < 0.01 and abs(bubble.oval.bb.height - 150 mm) < 0.01,
        "oval 240 x 150"
    assert abs((bubble.oval.bb.bottom - bubble.tail.bb.bottom) - 40 mm) < 0.01, "tip 40 below"
    assert abs((bubble.oval.center.x - bubble.tail.bb.left) - 100 mm) < 0.01, "tip 100 left"
    assert bubble.words.l1.bb.width <= 190 mm and bubble.words.l2.bb.width <= 190 mm,
        "lines at most 190 wide"
    # 26 mm letters unless a line would pass 190 mm: then max_width shrinks that line (W0113)
    assert abs(bubble.words.l1.size - 26 mm) < 0.01 and bubble.words.l2.size <= 26 mm and
        bubble.words.l2.size > 25 mm, "letters 26 tall, FABULOUS shrunk a little to fit"
    assert abs((bubble.oval.bb.width - bubble.border.e.bb.width) - 2 * 6 mm) < 0.01,
        "border 6 mm in"
    # the words stay inside the border
    assert bubble.words.bb.left > bubble.border.e.bb.left and
        bubble.words.bb.right < bubble.border.e.bb.right and
        bubble.words.bb.top < bubble.border.e.bb.top and
        bubble.words.bb.bottom > bubble.border.e.bb.bottom, "words inside the border"
    assert abs(stick.bar.bb.height - 300 mm) < 0.01 and abs(stick.bar.bb.width - 18 mm) < 0.01,
        "stick 300 x 18"
    assert abs((stick.hang.c.center.y - stick.bar.bb.bottom) - 15 mm) < 0.01, "hole 15 from the end"
}
