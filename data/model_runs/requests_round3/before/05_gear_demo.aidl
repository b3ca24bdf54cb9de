# A gear demonstrator: a 160 x 100 mm base plate and three meshing spur gears
# (module 2; 20, 30 and 15 teeth) on axles, the gears standing 10 mm above the plate.
import "std/gears.aidl"

param m = 2 mm
param z1 = 20
param z2 = 30
param z3 = 15
param axle_d = 4 mm        # axle (dowel) diameter
param bore_d = 4.2 mm      # the gears turn freely on the axles
param lift = 10 mm         # gap between the plate and the gears
param t = 3 mm

thickness 3 mm

c12 = m * (z1 + z2) / 2            # 50 mm
c23 = m * (z2 + z3) / 2            # 45 mm
# axle x positions: the row of gears centred on the plate
x1 = -(c12 + c23 + m * (z3 + 2) / 2 - m * (z1 + 2) / 2) / 2
x2 = x1 + c12
x3 = x2 + c23
gy = 110 mm                        # where the gears lie in the flat layout
ay = -75 mm                        # where axles and spacers lie in the flat layout

assembly demo {
    solid plate {
        body = Rectangle(center=(0, 0), width=160, height=100)
        hole axle_holes {
            h1 = Circle(center=(x1, 0), diameter=axle_d)
            h2 = Circle(center=(x2, 0), diameter=axle_d)
            h3 = Circle(center=(x3, 0), diameter=axle_d)
        }
        Fixed(body)
        Fixed(axle_holes.h1)
        Fixed(axle_holes.h2)
        Fixed(axle_holes.h3)
    }

    # the gears, in mesh: a tooth of one sits in a gap of the next
    g1 = spur_gear(teeth=z1, module=m, bore=bore_d, phase=0 deg, cx=x1, cy=gy)
    g2 = spur_gear(teeth=z2, module=m, bore=bore_d, phase=180 deg / z2, cx=x2, cy=gy)
    g3 = spur_gear(teeth=z3, module=m, bore=bore_d, phase=180 deg, cx=x3, cy=gy)
    Fixed(g1)
    Fixed(g2)
    Fixed(g3)

    # axles: 4 mm dowels through the plate, a spacer and the gear
    for i in range(3) {
        solid axle {
            thickness t + lift + t
            pin = Circle(center=(-60 + 15 * i, ay), diameter=axle_d)
        }
        solid spacer {
            thickness lift
            sleeve = Circle(center=(20 + 20 * i, ay), diameter=10)
            hole bore { c = Circle(center=(20 + 20 * i, ay), diameter=bore_d) }
            Concentric(bore.c, sleeve)
        }
        Fixed(axle)
        Fixed(spacer)
    }

    # assembled: plate on z = 0, spacers on the plate, gears on the spacers
    xs = [x1, x2, x3]
    Place(g1, position=(0, -gy, t + lift))
    Place(g2, position=(0, -gy, t + lift))
    Place(g3, position=(0, -gy, t + lift))
    for i in range(3) {
        Place(axle[i], position=(xs[i] + 60 - 15 * i, -ay, 0))
        Place(spacer[i], position=(xs[i] - 20 - 20 * i, -ay, t))
    }
}
