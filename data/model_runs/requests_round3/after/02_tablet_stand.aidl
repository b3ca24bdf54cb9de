# A tablet stand: two pieces of 4 mm plywood slotted together at right angles
# (cross-halving joint). Back piece 150 x 120 mm, front support 120 x 100 mm.
import "std/joints.aidl"

param t = 4 mm

thickness t
kerf 0.2 mm

assembly stand {
    solid back {
        body = Rectangle(center=(0, 0), width=150, height=120)
        # slot from the middle of the bottom edge (y = -60) up half the height
        slot = cross_halving(depth=60 mm, thickness=t, rotation=180 deg, cx=0 mm, cy=-60 mm)
    }
    solid front {
        body = Rectangle(center=(160, -10), width=120, height=100)
        # slot from the middle of the top edge (y = 40) down half the height
        slot = cross_halving(depth=50 mm, thickness=t, rotation=0 deg, cx=160 mm, cy=40 mm)
    }
    Rigid(back)
    Rigid(front)
    RightOf(front.body, back.body, gap=10)
    AlignBottom(front.body, back.body)
}
