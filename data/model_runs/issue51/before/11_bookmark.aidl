# Bookmark 50 x 180 mm with rounded corners, a tassel hole at the top and a
# row of five leaf-shaped cut-outs down the middle.

param width = 50 mm
param length = 180 mm
param corner = 6 mm
param tassel_d = 5 mm
param leaves = 5
param leaf_len = 22 mm
param leaf_w = 11 mm
param leaf_pitch = 28 mm

solid bookmark {
    body = RoundedRectangle(center=(0, 0), width=width, height=length, corner_radius=corner)

    hole tassel {
        c = Circle(center=(0, length / 2 - 9), diameter=tassel_d)
    }
    AlignCenterX(tassel, body)
    VerticalDistance(tassel.c.center, body.top.midpoint, 9 mm)

    # pointed leaves along the center line, tips up and down
    hole leaf_row {
        for i in range(leaves) {
            leaf = Spline([(0, 45 - i * leaf_pitch - leaf_len / 2), (leaf_w / 2, 45 - i * leaf_pitch),
                           (0, 45 - i * leaf_pitch + leaf_len / 2), (-leaf_w / 2, 45 - i * leaf_pitch)],
                          closed=true, corners=[0, 2])
        }
    }
    Rigid(leaf_row.leaf)
    AlignCenterX(leaf_row, body)
    # the leaves sit centered in the part of the strip below the tassel hole
    leaf_row.bb.center_y == (tassel.bb.bottom + body.bb.bottom) / 2

    Fixed(body)
}
