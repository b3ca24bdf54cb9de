# Request: Saw-blade angle setup blocks for my table saw. Four right-triangle gauges cut from
# 6 mm plywood. Each has a 100 mm bottom leg and a square vertical leg at its right end; the
# angle between the bottom leg and the long sloping edge is 15°, 22.5°, 30° and 45°. Engrave
# each block's angle on it ("22.5°"), 6 mm tall, and cut a 6 mm hole centred 10 mm in from both
# square edges (bottom and vertical) so they hang together on a key ring. The acute tip stays
# sharp: it is the measuring edge. Lay them out in a row, 5 mm apart, bottoms level.

units mm
thickness 6 mm
min_wall 0.3 mm   # the acute tip is meant sharp

param leg = 100 mm, min = 80 mm, max = 150 mm
param ring_hole = 6 mm, min = 4 mm, max = 8 mm

ANGLES = [15, 22.5, 30, 45]
LABELS = ["15°", "22.5°", "30°", "45°"]

def setup_block(angle=45 deg, label="45°", leg=100 mm, hole_d=6 mm) -> solid {
    # right angle at the bottom right, the acute measuring angle at the bottom left
    tri = Polygon([(0, 0), (leg, 0), (leg, leg * tan(angle))])
    hole eye {
        c = Circle(center=(leg - 10, 10), diameter=hole_d)
    }
    drawing label_text {
        t = Text(label, position=(0.6 * leg, 5), size=6)
    }
    # the ring hole 10 mm in from both square edges
    At(eye.c.center, tri.points[1], dx=-10, dy=10)
    # the label on the bottom leg, 5 mm up, left of the hole
    At(label_text.t.position, tri.points[0], dx=0.6 * leg, dy=5)

    assert abs(atan2(tri.bb.height, tri.bb.width) - angle) < 0.01 deg, "the block's angle"
    assert abs(tri.bb.width - leg) < 0.001 mm, "bottom leg length"
    # the label's top-left corner stays under the sloping edge, 1 mm clear
    assert label_text.bb.top - tri.bb.bottom <= (label_text.bb.left - tri.bb.left) * tan(angle) - 1 mm,
        "label under the sloping edge"
    assert label_text.bb.right <= eye.bb.left - 1 mm, "label clear of the hole"
    assert eye.bb.top - tri.bb.bottom <= (eye.bb.left - tri.bb.left) * tan(angle) - 1 mm,
        "hole under the sloping edge"
}

assembly angle_blocks {
    for i in range(4) {
        b = setup_block(angle=ANGLES[i] * 1 deg, label=LABELS[i], leg=leg, hole_d=ring_hole)
    }
    for i in range(1, 4) {
        RightOf(b[i], b[i - 1], gap=5)
        AlignBottom(b[i].tri, b[i - 1].tri)
    }
    assert len(b) == 4, "four blocks"
    assert abs(b[0].tri.bb.width - 100 mm) < 0.001 mm, "100 mm bottom leg"
    assert abs(b[0].eye.c.diameter - 6 mm) < 0.001 mm, "6 mm ring hole"
    assert abs(b[3].eye.c.center.x - (b[3].tri.bb.right - 10 mm)) < 0.001 mm, "hole 10 mm from the vertical edge"
    assert abs(b[3].eye.c.center.y - (b[3].tri.bb.bottom + 10 mm)) < 0.001 mm, "hole 10 mm from the bottom edge"
}
