# Issue 84: a lantern's side panel, a finger panel written at (0, 0) by its template, and a
# star cut out 28 mm left and 45 mm below its middle: the panel stays and the star goes to
# (-28, -45) (before: both moved halfway, the panel to (14, 22.5), the star to (-14, -22.5)).
import "std/joints.aidl"

thickness 3 mm

solid side_panel {
    edge = finger_panel(width=120 mm, height=160 mm, thickness=3 mm)
    hole star { s = Star(center=(0, 0), points=5, outer_radius=12, inner_radius=5) }
    At(star.s.center, edge.bb.center, dx=-28, dy=-45)
}
