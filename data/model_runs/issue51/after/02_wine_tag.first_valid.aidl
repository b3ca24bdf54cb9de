# Wine bottle neck tag: 90 x 50 mm rounded rectangle, "CABERNET 2024" engraved
# inside an engraved rectangular frame, and a hanging hole near the top.

param w = 90 mm
param h = 50 mm
param hang_d = 8 mm

solid tag {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=6)
    Fixed(body)

    hole hang {
        c = Circle(center=(0, 16), diameter=hang_d)
    }
    AlignCenterX(hang, body)
    hang.bb.top == body.bb.top - 5 mm

    drawing label {
        frame = Rectangle(center=(0, -6), width=78, height=26)
        name = Text("CABERNET 2024", position=(0, -6), size=7, valign="middle")
    }
    AlignCenterX(label, body)
    # the frame starts 4 mm under the hanging hole
    label.bb.top == hang.bb.bottom - 4 mm
}
