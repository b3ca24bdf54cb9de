# A bird house from 4 mm plywood: a 120 x 120 mm floor, front and back
# pentagons 120 mm wide with 150 mm walls and a peak at 190 mm, the front with
# a 32 mm entry hole centred 100 mm up and an 8 mm perch hole 70 mm up, two
# sides 112 x 150 mm between front and back, and two roof panels 90 x 140 mm
# meeting at the ridge. Cut flat, shown assembled.
thickness 4 mm
param t = 4 mm

def gable() -> solid {
    wall = Polygon([(-60, 0), (60, 0), (60, 150), (0, 190), (-60, 150)])
}

assembly birdhouse {
    solid floor { r = Rectangle(center=(0, 0), width=120, height=120) }
    solid front {
        wall = Polygon([(-60, 0), (60, 0), (60, 150), (0, 190), (-60, 150)])
        hole entry { c = Circle(center=(0, 100), diameter=32) }
        hole perch { c = Circle(center=(0, 70), diameter=8) }
    }
    back = gable()
    solid left_side { r = Rectangle(bottom_left=(-56, 0), width=112, height=150) }
    solid right_side { r = Rectangle(bottom_left=(-56, 0), width=112, height=150) }
    solid roof_right { r = Rectangle(bottom_left=(0, -70), width=90, height=140) }
    solid roof_left { r = Rectangle(bottom_left=(-90, -70), width=90, height=140) }

    Place(floor, position=(0, 0, 0))
    Place(front, rotation=(90 deg, 0, 0), position=(0, -56, t))
    Place(back, rotation=(90 deg, 0, 0), position=(0, 60, t))
    Place(left_side, rotation=(90 deg, 0, 90 deg), position=(-60, 0, t))
    Place(right_side, rotation=(90 deg, 0, 90 deg), position=(56, 0, t))
    Place(roof_right, rotation=(0, atan(40 / 60), 0), position=(0, 0, 190 + t))
    Place(roof_left, rotation=(0, -atan(40 / 60), 0), position=(0, 0, 190 + t))
}
