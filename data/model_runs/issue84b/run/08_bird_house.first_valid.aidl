# Bird house from 3 mm plywood: a 120 x 120 mm floor; front and back gables 120
# mm wide, 110 mm to the eaves and 150 mm to the peak (the front with a 32 mm
# entry hole 80 mm up and a 6 mm perch hole 55 mm up); two 114 x 110 mm sides
# between the gables; two 90 x 140 mm roof panels resting on the gables' slopes.
# Placed in 3D for the assembled view.

thickness 3 mm

param slope = atan2(40, 60)

assembly house {
    solid floor { r = Rectangle(center=(0, 0), width=120, height=120) }
    solid front {
        g = Polygon([(-60, 0), (60, 0), (60, 110), (0, 150), (-60, 110)])
        hole entry { c = Circle(center=(0, 80), diameter=32) }
        hole perch { c = Circle(center=(0, 55), diameter=6) }
    }
    solid back { g = Polygon([(-60, 0), (60, 0), (60, 110), (0, 150), (-60, 110)]) }
    solid left { r = Rectangle(bottom_left=(-57, 0), width=114, height=110) }
    solid right { r = Rectangle(bottom_left=(-57, 0), width=114, height=110) }
    solid roof_l { r = Rectangle(bottom_left=(-90, -70), width=90, height=140) }
    solid roof_r { r = Rectangle(bottom_left=(0, -70), width=90, height=140) }

    Place(floor, position=(0, 0, 0))
    # gables stand on the floor at its front and back edges: (x, y, z) -> (x, -z, y)
    Place(front, rotation=(90 deg, 0, 0), position=(0, -57, 3))
    Place(back, rotation=(90 deg, 0, 0), position=(0, 60, 3))
    # sides stand between the gables: (x, y, z) -> (z, x, y)
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-60, 0, 3))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(57, 0, 3))
    # roof panels from the ridge down each slope
    Place(roof_l, rotation=(0, -slope, 0), position=(0, 0, 153))
    Place(roof_r, rotation=(0, slope, 0), position=(0, 0, 153))
}
