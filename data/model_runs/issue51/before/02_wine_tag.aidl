# Wine bottle neck tag: rounded rectangle 90 x 50 mm, "CABERNET 2024" engraved inside an
# engraved rectangular frame, hanging hole near the top.

param w = 90 mm
param h = 50 mm
param r = 6 mm
param hole_d = 8 mm

solid tag {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=r)
    Fixed(body)

    hole hang {
        c = Circle(center=(0, 17), diameter=hole_d)
    }
    AlignCenterX(hang, body)
    VerticalDistance(hang.c.center, body.top.midpoint, 8 mm)

    drawing frame {
        f = Rectangle(center=(0, -5), width=w - 12, height=26)
    }
    AlignCenterX(frame, body)
    Below(frame, hang, gap=3 mm)

    drawing label {
        t = Text("CABERNET 2024", position=(0, -5), size=7, valign="middle")
    }
    CenterInside(label, frame)
}
