# The studio's form of examples/generators/cross_halving.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/joints.aidl"

# Two panels as tall as each other, each slotted halfway from opposite edges, so the two
# slots' depths add up to the height; each slot is as wide as the material.
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param height = 40 mm, min = 10 mm, max = 200 mm, step = 1 mm
param length_a = 80 mm, min = thickness + 10 mm, max = 400 mm, step = 1 mm
param length_b = 60 mm, min = thickness + 10 mm, max = 400 mm, step = 1 mm

thickness thickness

assembly cross {
    solid a {
        body = Rectangle(center=(0, 0), width=length_a, height=height)
        slot = cross_halving(depth=height / 2, thickness=thickness, cy=height / 2)
    }
    solid b {
        body = Rectangle(center=(length_a / 2 + 20 mm + length_b / 2, 0), width=length_b,
                         height=height)
        slot = cross_halving(depth=height / 2, thickness=thickness, rotation=180 deg,
                             cx=length_a / 2 + 20 mm + length_b / 2, cy=-height / 2)
    }
    # stood up, crossing at their slots: a in the x-z plane, b turned a quarter about z
    Place(a, rotation=(90 deg, 0, 0), position=(0, thickness / 2, height / 2))
    Place(b, rotation=(90 deg, 0, 90 deg),
          position=(-thickness / 2, -(length_a / 2 + 20 mm + length_b / 2), height / 2))
}
