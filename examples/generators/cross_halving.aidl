# Two panels slotted halfway into each other at right angles (a cross-halving).
# Each gets a slot as wide as the material, 20 mm deep: one from its top edge,
# one from its bottom edge, so they cross over their 40 mm height.
import "std/joints.aidl"

thickness 3 mm

assembly cross {
    solid a {
        body = Rectangle(center=(0, 0), width=80, height=40)
        slot = cross_halving(depth=20 mm, thickness=3 mm, cy=20 mm)
    }
    solid b {
        body = Rectangle(center=(90, 0), width=60, height=40)
        slot = cross_halving(depth=20 mm, thickness=3 mm, rotation=180 deg, cx=90 mm, cy=-20 mm)
    }
    # stood up, crossing at their slots: a in the x-z plane, b turned a quarter about z
    Place(a, rotation=(90 deg, 0, 0), position=(0, 1.5, 20))
    Place(b, rotation=(90 deg, 0, 90 deg), position=(-1.5, -90, 20))
}
