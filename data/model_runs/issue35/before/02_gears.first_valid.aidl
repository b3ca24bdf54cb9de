# A pair of meshing spur gears (20 and 40 teeth, module 2 mm) on a mounting
# plate with a bore for each shaft.

import stdlib.gears

param module = 2 mm
param z1 = 20
param z2 = 40
param bore = 6 mm

r1 = module * z1 / 2     # pitch radius of the pinion
r2 = module * z2 / 2     # pitch radius of the wheel
centers = r1 + r2        # centre distance

assembly gearset {
    solid plate {
        base = RoundedRectangle(center=(centers / 2, 0), width=centers + 2 * r2 + 30,
                                height=2 * r2 + 30, corner_radius=5)
        hole shaft1 {
            b = Circle(center=(0, 0), diameter=bore)
        }
        hole shaft2 {
            b = Circle(center=(centers, 0), diameter=bore)
        }
        HorizontalDistance(shaft1.b.center, shaft2.b.center, centers)
        AlignCenterY(shaft1, shaft2)
        CenterInside(self, base)
    }

    pinion = spur_gear(teeth=z1, module=module, bore=bore)
    wheel = spur_gear(teeth=z2, module=module, bore=bore)

    At(pinion.bb.center, plate.shaft1.b.center)
    At(wheel.bb.center, plate.shaft2.b.center)
}
