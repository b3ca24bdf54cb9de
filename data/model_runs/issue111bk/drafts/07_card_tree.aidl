# Request: a Christmas-card tree for the mantelpiece, cut from 6 mm birch ply: a three-tier
# pine silhouette 300 mm tall (trunk bottom to star tip) and 240 mm wide at the bottom tier,
# tiers 240 / 190 / 130 wide and 110 / 100 / 90 tall (98 after the fix below), a 40 x 40 trunk, a five-point star
# (radius 22) on the top. Twelve card slits, 1 mm wide and 25 mm deep, cut square into the
# sloping edges, two on each side of each tier (at 20 % and 45 % of the edge from its outer
# corner), so greeting cards stand out from the tree. The year 2026 engraved on the trunk.
# It stands on a 160 x 40 foot (an arch 100 wide and 8 high under it) cross-halved into the
# trunk, the slots 20 mm deep each with 0.2 mm clearance.

import "std/joints.aidl"

thickness 6 mm

t = 6 mm
B = [240, 190, 130]   # tier widths
Y0 = [40, 110, 180]   # tier bottoms
# FIX after the first valid program: the top tier was 90 tall, its apex (y 270) only 1 mm
# above the star's lower notch (y 269), so the star hung on a 1.4 mm neck that would snap;
# 98 tall, the apex reaches the star's centre and the neck is 12 mm wide
H = [110, 100, 98]    # tier heights
depth = 25 mm         # slit depth

def edge_len(k) = sqrt((B[k] / 2) ** 2 + H[k] ** 2)

assembly card_tree {
    solid tree {
        trunk = Rectangle(bottom_left=(-20, 0), width=40, height=40)
        for k in range(3) {
            tier = Triangle(center=(0, Y0[k] + H[k] / 2), base=B[k], height=H[k])
        }
        star = Star(center=(0, 278), points=5, outer_radius=22, inner_radius=9)
        for k in range(3) {
            for s in [-1, 1] {
                for f in [0.2, 0.45] {
                    hole slit {
                        # from 3 mm outside the sloping edge, square to it, 25 mm in
                        e = Slot(start=(s * B[k] / 2 * (1 - f) + 3 * s * H[k] / edge_len(k),
                                        Y0[k] + f * H[k] + 3 * (B[k] / 2) / edge_len(k)),
                                 end=(s * B[k] / 2 * (1 - f) - (depth - 0.5) * s * H[k] / edge_len(k),
                                      Y0[k] + f * H[k] - (depth - 0.5) * (B[k] / 2) / edge_len(k)),
                                 width=1)
                    }
                }
            }
        }
        foot_slot = cross_halving(depth=20, thickness=t, clearance=0.2, rotation=180 deg,
                                  cx=0, cy=0)
        drawing year {
            y = Text("2026", position=(0, 30), size=8, valign="middle")
        }
        Fixed(trunk)
        assert star.bb.top - trunk.bb.bottom == 300 mm, "300 tall"
        assert tier[0].base == 240 mm and tier[1].base == 190 mm and tier[2].base == 130 mm,
            "tiers 240 / 190 / 130"
        assert len(slit) == 3, "three tiers of slits"
        assert trunk.width == 40 mm and trunk.height == 40 mm, "trunk 40 x 40"
    }

    solid foot {
        body = RoundedRectangle(center=(0, 20), width=160, height=40, corner_radii=[8, 8, 0, 0])
        hole arch {
            a = Ellipse(center=(0, 0), rx=50, ry=8)
        }
        tree_slot = cross_halving(depth=20, thickness=t, clearance=0.2, rotation=0 deg,
                                  cx=0, cy=40)
        Fixed(body)
        assert body.width == 160 mm and body.height == 40 mm, "foot 160 x 40"
    }

    RightOf(foot, tree, gap=10)
    AlignBottom(foot, tree)

    # in 3D: the tree in the plane y = 0, the foot across it in the plane x = 0
    Place(tree, position=(0, t / 2, 0), rotation=(90 deg, 0, 0))
    Place(foot, position=(-t / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
}
