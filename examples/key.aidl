# A house key: a round bow with a key-ring hole, a shoulder, a straight blade
# whose teeth (the bitting) are made by a loop, and a pointed tip.
# Try: --set blade_length=65  --set bow_d=34  --set blade_h=10

param bow_d = 30 mm  # diameter of the bow (the part you hold)
param blade_length = 55 mm
param blade_h = 8 mm  # height of the blade above the teeth

cuts = [3, 1.5, 4, 2, 3.5, 2.5]  # depth of each tooth, in mm (the key's code)
pitch = blade_length / (len(cuts) + 1.5)
x0 = bow_d / 2 + 4  # where the blade starts

solid key {
    solid bow {
        ring = Circle(center=(0, 0), diameter=bow_d)
        hole keyring {
            eye = Circle(center=(-bow_d / 4, 0), diameter=bow_d / 4)
        }
        # the key-ring hole sits on the bow's axis, toward the outer end
        AlignCenterY(keyring, ring)
        HorizontalDistance(keyring.eye.center, ring.center, bow_d / 4)
    }

    solid shoulder {
        stop = Rectangle(center=(x0 - 2, 0), width=6, height=blade_h + 7)
    }

    solid blade {
        shank = Rectangle(bottom_left=(x0, -blade_h / 2), width=blade_length, height=blade_h)
        # the tip: a bevel from the bottom edge up to the top edge
        tip = Triangle(shank.top_right, shank.bottom_right,
                       (x0 + blade_length + 0.7 * blade_h, blade_h / 2))
        Horizontal(tip.a, tip.c)

        # the teeth hang under the blade, one per cut
        for i in range(len(cuts)) {
            xc = x0 + (i + 1) * pitch
            solid tooth {
                t = Polygon([(xc - 0.45 * pitch, -blade_h / 2), (xc + 0.45 * pitch, -blade_h / 2),
                             (xc + 0.15 * pitch, -blade_h / 2 - cuts[i]),
                             (xc - 0.15 * pitch, -blade_h / 2 - cuts[i])])
            }
            Below(tooth, shank)
            tooth.bb.center_x == shank.bb.left + (i + 1) * pitch
        }

        # the warding groove along the blade
        drawing groove {
            g = Line((x0 + 2, 0), (x0 + blade_length - 2, 0))
        }
        AlignCenterY(groove, shank)
        groove.bb.left == shank.bb.left + 2
    }

    # bow | shoulder | blade, all on one axis
    AlignCenterY(shoulder, bow)
    AlignCenterY(blade.shank, shoulder)
    # overlaps the bow enough that the bow's rim meets the shoulder's top and bottom edges
    # (at 1 mm it left the shoulder's side in a narrow V a laser cannot cut: W0519)
    shoulder.bb.left == bow.bb.right - 2.5
    RightOf(blade.shank, shoulder, gap=-1)
}
