# Request (holidays): a stand-up Christmas snowman for a mantelpiece, 4 mm poplar ply, two
# parts. Three overlapping snowballs 80, 60 and 44 mm across, each ball's centre 10 mm less
# than the sum of the two radii from the next; a top hat (36 x 24 crown on a 52 x 5 brim)
# on the head; a 70 x 16 mm plinth under the bottom ball. Engraved face: two 4 mm eyes 8 mm
# either side of the head's centre and a smile (an arc of radius 10 below them); three 5 mm
# button holes cut down the middle ball. A 130 x 16 mm foot crosses the plinth by a cross
# halving (8 mm deep in each from the middle), "LET IT SNOW" engraved on the foot (5 mm).
units mm
thickness 4 mm
import "std/joints.aidl"

assembly snowman {
    solid figure {
        base = Circle(center=(0, 40), diameter=80)
        mid = Circle(center=(0, 100), diameter=60)
        head = Circle(center=(0, 145), diameter=44)
        plinth = Rectangle(corner=(-35, -6), opposite=(35, 10))
        brim = Rectangle(center=(0, 165), width=52, height=5)
        crown = Rectangle(center=(0, 180), width=36, height=24)
        Distance(base.center, mid.center, 40 + 30 - 10)
        Distance(mid.center, head.center, 30 + 22 - 10)
        Vertical(base.center, mid.center)
        Vertical(mid.center, head.center)
        Fixed(base)
        Above(crown, brim, gap=-0.5)
        brim.center.y == head.center.y + 22 - 1
        AlignCenterX(brim, head)
        AlignCenterX(crown, head)
        AlignCenterX(plinth, base)
        plinth.bb.top == base.bb.bottom + 6
        hole buttons {
            for i in range(3) {
                b = Circle(center=(0, 88 + i * 12), diameter=5)
            }
        }
        buttons.bb.center_y == mid.center.y
        AlignCenterX(buttons, mid)
        drawing face {
            el = Circle(center=(-8, 149), diameter=4)
            er = Circle(center=(8, 149), diameter=4)
            smile = Arc(center=(0, 149), radius=10, start_angle=215 deg, end_angle=325 deg)
        }
        AlignCenterX(face, head)
        face.el.center.y == head.center.y + 4
        h = cross_halving(depth=8 mm, thickness=4 mm, rotation=180 deg, cx=0 mm, cy=-6 mm)
        assert plinth.width == 70 mm and plinth.height == 16 mm, "plinth size"
        assert face.er.center.x - face.el.center.x == 16 mm, "eyes 8 either side"
    }
    solid foot {
        bar = Rectangle(center=(120, -40), width=130, height=16)
        h2 = cross_halving(depth=8 mm, thickness=4 mm, cx=120 mm, cy=-32 mm)
        drawing words {
            t = Text("LET IT SNOW", (120, -44), size=5, valign="middle")
        }
        assert bar.width == 130 mm, "foot 130 long"
    }
    assert figure.h.depth + foot.h2.depth == 16 mm, "halvings add to 16"
}
