# Luggage tag: a 90 x 55 mm plate with 6 mm rounded corners (3 mm acrylic), a
# 12 x 5 mm strap slot centered 8 mm from the left edge, and the owner's name
# "ANNA KOWALSKI" engraved 7 mm tall (at most 66 mm wide: shrunk to fit), with a phone number "+48 600 123 456"
# 4 mm tall below it, both centered in the area right of the slot.

units mm
thickness 3 mm

solid tag {
    body = RoundedRectangle(center=(0, 0), width=90, height=55, corner_radius=6)

    hole strap {
        s = Slot(center=(-37, 0), length=12, width=5, rotation=90)
    }
    AlignCenterY(strap, body)
    HorizontalDistance(body.left.midpoint, strap.s.center, 8)

    drawing name {
        t = Text("ANNA KOWALSKI", position=(8, 5), size=7, valign="middle", max_width=66)
    }
    drawing phone {
        t = Text("+48 600 123 456", position=(8, -8), size=4, valign="middle")
    }
    Below(phone, name, gap=6)
    AlignCenterX(phone, name)
    # the text block centered between the slot and the right edge
    name.bb.center_x == (strap.bb.right + body.bb.right) / 2
    (name.bb.top + phone.bb.bottom) / 2 == body.bb.center_y
}
