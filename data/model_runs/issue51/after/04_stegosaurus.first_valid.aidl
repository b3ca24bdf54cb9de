# Toy stegosaurus silhouette, about 150 mm long, built from several shapes:
# body, head, tail, four legs and a row of back plates, with a hanging hole.
# The dinosaur faces right (+x).

param body_rx = 45 mm
param body_ry = 22 mm
param leg_w = 12 mm
param leg_h = 30 mm
param plates = 5

solid stego {
    body = Ellipse(center=(0, 0), rx=body_rx, ry=body_ry)
    Fixed(body)

    head = Ellipse(center=(56, -6), rx=15, ry=8, rotation=-15)
    tail = Polygon([(-30, 10), (-80, 4), (-30, -14)])

    # four legs, their feet on one ground line
    back_leg1 = RoundedRectangle(center=(-30, -26), width=leg_w, height=leg_h, corner_radius=3)
    back_leg2 = RoundedRectangle(center=(-14, -26), width=leg_w, height=leg_h, corner_radius=3)
    front_leg1 = RoundedRectangle(center=(18, -26), width=leg_w, height=leg_h, corner_radius=3)
    front_leg2 = RoundedRectangle(center=(32, -26), width=leg_w, height=leg_h, corner_radius=3)
    AlignBottom(back_leg1, back_leg2)
    AlignBottom(back_leg2, front_leg1)
    AlignBottom(front_leg1, front_leg2)
    back_leg1.bb.bottom == body.bb.bottom - 14 mm

    # back plates along the top of the body, sunk 4 mm into it
    for i in range(plates) {
        px = -32 mm + i * 16 mm
        plate = Triangle(center=(px, body_ry * sqrt(1 - (px / body_rx) ** 2) + 4),
                         base=14, height=18)
    }

    hole hang {
        c = Circle(center=(0, 6), diameter=5)
    }
    AlignCenterX(hang, body)
}
