# A gear demonstrator: a 160 x 100 mm base plate and three meshing spur gears
# (module 2; 20, 30 and 15 teeth) on axles, the gears 10 mm above the plate.
import "std/gears.aidl"

param m = 2 mm
param axle = 4 mm
param lift = 10 mm
param z1 = 20
param z2 = 30
param z3 = 15
param t = 3 mm

thickness t

# axle positions on the plate (plate centred at the origin), gears in a row
x1 = -m * (z1 + 2 * z2 + z3) / 4
x2 = x1 + m * (z1 + z2) / 2
x3 = x2 + m * (z2 + z3) / 2

assembly demo {
    solid plate {
        body = Rectangle(center=(0, 0), width=160, height=100)
        hole a1 { c = Circle(center=(x1, 0), diameter=axle) }
        hole a2 { c = Circle(center=(x2, 0), diameter=axle) }
        hole a3 { c = Circle(center=(x3, 0), diameter=axle) }
    }
    Fixed(plate)
    # gears laid out flat above the plate for cutting; tooth of gear1 toward gear2,
    # gear2 a gap toward gear1 (half a tooth turned), gear3 a tooth into gear2's gap
    g1 = spur_gear(teeth=z1, module=m, bore=axle, backlash=0.05 mm, phase=0 deg, cx=x1, cy=90)
    g2 = spur_gear(teeth=z2, module=m, bore=axle, backlash=0.05 mm, phase=180 deg + 180 deg / z2, cx=x2, cy=90)
    g3 = spur_gear(teeth=z3, module=m, bore=axle, backlash=0.05 mm, phase=180 deg, cx=x3, cy=90)
    # the axles (4 mm pins through plate and gear) and 10 mm spacer sleeves that
    # hold each gear 10 mm above the plate
    xs = [x1, x2, x3]
    for i in range(3) {
        solid axle_pin {
            thickness t + lift + t
            c = Circle(center=(-60 + i * 12, -70), diameter=axle)
        }
        solid spacer {
            thickness lift
            ring = Circle(center=(-60 + i * 12, -85), diameter=8)
            hole bore { c = Circle(center=(-60 + i * 12, -85), diameter=axle) }
        }
        Place(axle_pin, position=(xs[i] + 60 - i * 12, 70, 0))
        Place(spacer, position=(xs[i] + 60 - i * 12, 85, t))
    }
    Place(plate, position=(0, 0, 0))
    Place(g1, position=(0, -90, t + lift))
    Place(g2, position=(0, -90, t + lift))
    Place(g3, position=(0, -90, t + lift))
}
