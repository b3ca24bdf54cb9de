# Request (signs): a "NO JUNK MAIL" sign for my letterbox, two layers of 3 mm acrylic glued
# together: a white front plate 150 x 45 mm (6 mm corner radius) with "NO JUNK MAIL" cut
# through in 12 mm bold stencil letters (the red back plate shows through them) and
# "thank you" engraved 5 mm tall under them, and a red back plate of the same outline. Two
# 3.5 mm screw holes through both plates, 9 mm in from the short ends on the centre line,
# countersunk on the front for 7 mm heads. Show it assembled.

thickness 3 mm

param letter_h = 12 mm, min = 8 mm, max = 14 mm

def plate_outline() -> solid {
    body = RoundedRectangle(center=(0, 0), width=150, height=45, corner_radius=6)
    hole screws {
        l = Circle(center=(-66, 0), diameter=3.5)
        r = Circle(center=(66, 0), diameter=3.5)
    }
}

assembly sign {
    solid front {
        body = RoundedRectangle(center=(0, 0), width=150, height=45, corner_radius=6)
        hole screws {
            l = Circle(center=(-66, 0), diameter=3.5)
            r = Circle(center=(66, 0), diameter=3.5)
        }
        Countersink(screws, diameter=7)
        hole words {
            t = Text("NO JUNK MAIL", position=(0, 4), size=letter_h, font="sans:Bold",
                     valign="middle", stencil=true)
        }
        drawing thanks {
            t = Text("thank you", position=(0, -15), size=5)
        }
    }

    back = plate_outline()

    Below(back, front, gap=8)
    AlignCenterX(back, front)

    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3))

    assert front.body.width == 150 mm and front.body.height == 45 mm
    assert front.screws.l.center.x - front.body.bb.left == 9 mm, "9 mm in from the end"
    assert front.body.bb.right - front.screws.r.center.x == 9 mm, "9 mm in from the end"
    assert front.words.t.size == 12 mm, "12 mm letters"
    assert front.words.bb.left > front.screws.l.center.x + 3.5 mm and
        front.words.bb.right < front.screws.r.center.x - 3.5 mm, "letters clear of the screw heads"
    assert front.thanks.t.size == 5 mm
}
