# A wall screwed onto a base with a tab-and-slot joint and captive M3 nuts.
# The wall's two tabs go through the base's slots; an M3 x 16 screw through
# the base's hole runs up the wall's T-slot into a nut held in its pocket.
#   aidl render examples/generators/tab_and_slot.aidl --assembled -o joint.png
import "std/joints.aidl"

thickness 3 mm

assembly joint {
    solid base {
        body = Rectangle(center=(0, 0), width=80, height=60)
        slots = tab_and_slot(part="slot", length=60 mm, thickness=3 mm, screw=3)
    }
    solid wall {
        body = Rectangle(center=(0, 60), width=60, height=40)
        tabs = tab_and_slot(part="tab", length=60 mm, thickness=3 mm, screw=3,
                            rotation=180 deg, cy=40 mm)
    }
    # the wall stood up on the base: its middle over the slots, its tabs through them
    Place(wall, rotation=(90 deg, 0, 0), position=(0, 1.5, -40))
}
