# An internal (ring) gear of 40 teeth, module 2, on a 6 mm rim, with the
# 14-tooth pinion that runs inside it, both with 5 mm axle holes.
import "std/gears.aidl"
units mm

assembly gearset {
    ring = ring_gear(teeth=40, module=2 mm, rim=8 mm)
    pinion = spur_gear(teeth=14, module=2 mm, bore=5 mm, cx=-26 mm)
}
