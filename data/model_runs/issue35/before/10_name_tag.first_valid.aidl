# A name tag 80 x 30 mm with rounded corners, a hole for a key ring at the left
# end and the name "ALEX" engraved, centred in the space right of the hole.

param name = "ALEX"
param width = 80 mm
param height = 30 mm
param ring_d = 6 mm

solid tag {
    card = RoundedRectangle(center=(0, 0), width=width, height=height, corner_radius=5)
    Fixed(card)

    hole ring {
        eye = Circle(center=(-width / 2 + 7, 0), diameter=ring_d)
    }
    AlignCenterY(ring, card)
    HorizontalDistance(card.left.midpoint, ring.eye.center, 7 mm)

    drawing label {
        word = Text(name, (5, 0), size=14, valign="middle")
    }
    AlignCenterY(label, card)
    # centred between the ring hole and the right edge
    label.bb.center_x == (ring.bb.right + card.bb.right) / 2
}
