# A corner of two panels joined by a finger joint along one edge.
# The base's back edge starts with a tab, the wall's bottom edge with a gap,
# so the fingers of one fill the gaps of the other.
import "std/joints.aidl"

thickness 3 mm

assembly corner {
    solid base {
        body = Rectangle(center=(0, 0), width=100, height=60)
        fingers = finger_edge(length=100 mm, thickness=3 mm, finger=10 mm, start="tab", cy=30 mm)
    }
    solid wall {
        body = Rectangle(center=(0, 60), width=100, height=40)
        fingers = finger_edge(length=100 mm, thickness=3 mm, finger=10 mm, start="gap",
                              rotation=180 deg, cy=40 mm)
    }
    # the wall stood up along the base's back edge, over its last 3 mm
    Place(wall, rotation=(90 deg, 0, 0), position=(0, 30, -40))
}
