# Dog tag: a 38 mm x 24 mm tag with 6 mm rounded corners and a 4 mm ring hole whose
# centre is 5 mm in from the left end, centred vertically; the dog's name "BUDDY"
# engraved 7 mm tall and a phone number "555-0142" engraved 3.5 mm tall under it,
# both centred in the space to the right of the hole.
solid tag {
    body = RoundedRectangle(center=(0, 0), width=38, height=24, corner_radius=6)
    hole ring { c = Circle(center=(-14, 0), diameter=4) }
    At(ring.c.center, body.left.midpoint, dx=5)

    drawing text {
        name = Text("BUDDY", position=(3, 2), size=7, max_width=24)
        phone = Text("555-0142", position=(3, -6), size=3.5)
    }
    Below(text.phone, text.name, gap=2)
    AlignCenterX(text.phone, text.name)
    # centred between the hole's right edge and the tag's right end
    text.bb.center_x == (ring.bb.right + body.bb.right) / 2
    AlignCenterY(text, body)
}
