# Toy stegosaurus silhouette, about 150 mm long, built from several shapes:
# body, head, tail, four legs and a row of back plates; hanging hole in the body.

param body_rx = 42 mm
param body_ry = 20 mm
param leg_w = 11 mm
param leg_h = 22 mm
param plates = 7

solid stego {
    body = Ellipse(center=(0, 0), rx=body_rx, ry=body_ry)
    Fixed(body)

    # head on a short neck, low at the front (left)
    neck = Trapezoid(center=(-45, -4), bottom_width=18, top_width=12, height=14, rotation=90)
    head = Ellipse(center=(-62, -8), rx=13, ry=7, rotation=-10)

    # tail tapering to a point at the back (right)
    tail = Polygon([(30, 10), (30, -12), (78, 2)])

    # four legs
    legs_x = [-28, -12, 12, 28]
    for i in range(4) {
        leg = Rectangle(center=(legs_x[i], -body_ry - 6), width=leg_w, height=leg_h)
    }

    # back plates along the top of the body, tallest in the middle
    for i in range(plates) {
        px = -30 mm + i * 10 mm
        ph = 10 mm + 6 mm * (1 - abs(px) / 30 mm)
        plate = Triangle(center=(px, body_ry * sqrt(1 - (px / body_rx) ** 2) + ph / 2 - 3),
                         base=9, height=ph)
    }

    # hanging hole in the body under the middle plate
    hole hang {
        c = Circle(center=(0, 10), diameter=4)
    }
    AlignCenterX(hang, body)
}
