# A tablet stand: two pieces of 4 mm plywood slotted together at right angles
# (cross-halving joint). Back piece 150 x 120 mm, front support 120 x 100 mm.
import "std/joints.aidl"

thickness 4 mm
kerf 0.2 mm

assembly stand {
    solid back {
        body = Rectangle(center=(0, 0), width=150, height=120)
        # slot from the bottom edge up to the middle of the back piece
        slot = cross_halving(depth=60 mm, thickness=4 mm, rotation=90 deg)
        Coincident(slot.cut.bottom.midpoint, body.bottom.midpoint)
    }
    solid front {
        body = Rectangle(center=(170, 0), width=120, height=100)
        # slot from the top edge down to the middle of the support
        slot = cross_halving(depth=50 mm, thickness=4 mm, rotation=-90 deg)
        Coincident(slot.cut.top.midpoint, body.top.midpoint)
    }
    RightOf(front, back, gap=10)
    AlignBottom(front, back)
}
