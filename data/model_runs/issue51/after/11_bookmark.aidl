# A bookmark 50 x 180 mm with rounded corners, a tassel hole at the top
# and a row of five leaf-shaped cut-outs down the middle.

param width = 50 mm
param length = 180 mm
param corner = 6 mm
param tassel_d = 6 mm
param leaves = 5
param pitch = 28 mm
param leaf_h = 22 mm
param leaf_w = 11 mm

solid bookmark {
    body = RoundedRectangle(center=(0, 0), width=width, height=length, corner_radius=corner)
    Fixed(body)

    hole tassel {
        c = Circle(center=(0, length / 2 - 10), diameter=tassel_d)
    }
    AlignCenterX(tassel, body)
    VerticalDistance(tassel.c.center, body.top.midpoint, 10 mm)

    # leaves: pointed at top and bottom, widest a little below the middle
    for i in range(leaves) {
        hole leaf {
            y0 = 52 - i * pitch
            s = Spline([(0, y0 - leaf_h / 2), (leaf_w / 2, y0 - leaf_h / 5), (leaf_w / 2 - 1, y0 + leaf_h / 5),
                        (0, y0 + leaf_h / 2), (-leaf_w / 2 + 1, y0 + leaf_h / 5), (-leaf_w / 2, y0 - leaf_h / 5)],
                       closed=true, corners=[0, 3])
        }
    }
}
