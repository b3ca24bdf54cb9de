# The studio's form of examples/generators/tab_and_slot.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/joints.aidl"

# A wall on a base: `tabs` tabs `tab` wide over the joint's `length`, an M`screw` screw and
# its captive nut between each two. Each pitch (length / tabs) holds a tab and the nut's
# pocket (about 2.2 x the screw), and the wall is taller than the screw's T-slot.
param screw = 3, min = 2, max = 6, step = 1  # M2 to M6
param thickness = 3 mm, min = 1.5 mm, max = 8 mm, step = 0.5 mm
param tabs = 2, min = 2, max = 6, step = 1
param length = 60 mm, min = tabs * (screw * 2.2 mm + 8 mm), max = 300 mm, step = 1 mm
param tab = 10 mm, min = 4 mm, max = length / tabs - screw * 2.2 mm - 3 mm, step = 0.5 mm
param height = 40 mm, min = thickness + screw * 4 mm + 8 mm, max = 200 mm, step = 1 mm

thickness thickness

assembly joint {
    solid base {
        body = Rectangle(center=(0, 0), width=length + 20 mm, height=60)
        slots = tab_and_slot(part="slot", length=length, thickness=thickness, tabs=tabs,
                             tab=tab, screw=screw)
    }
    solid wall {
        body = Rectangle(center=(0, 40 mm + height / 2), width=length, height=height)
        tabs = tab_and_slot(part="tab", length=length, thickness=thickness, tabs=tabs, tab=tab,
                            screw=screw, rotation=180 deg, cy=40 mm)
    }
    # the wall stood up on the base: its middle over the slots, its tabs through them
    Place(wall, rotation=(90 deg, 0, 0), position=(0, thickness / 2, -40))
}
