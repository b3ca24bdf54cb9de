# A gear pair from the standard library (import "std/gears.aidl"): a
# 12-tooth pinion meshing a 36-tooth wheel (3:1) of module 1.5 mm, true
# involute teeth (as tangent circular arcs within 0.001 mm of the involute).
# `gear_pair` places them at the center distance m * (z1 + z2) / 2 = 36 mm.
# Try: --set wheel_teeth=90 --set module=1mm  --set backlash=0.1mm

import "std/gears.aidl"

param pinion_teeth = 12, min = 8, max = 40
param wheel_teeth = 36, min = 20, max = 120
param module = 1.5 mm, min = 0.5 mm, max = 3 mm, step = 0.25 mm
param backlash = 0.05 mm

# the bores follow the module: the pinion's (3 mm at 1.5 mm) leaves a wall inside the root
# circle of its fewest teeth (module x (8 - 2.5) across); the wheel's is 8 mm where that
# leaves a wall of 0.55 mm (less on a wheel of few small teeth)
assembly drive {
    pair = gear_pair(teeth1=pinion_teeth, teeth2=wheel_teeth, module=module,
                     bore1=2 * module, bore2=min(8 mm, module * (wheel_teeth - 2.5) - 1.1 mm),
                     backlash=backlash)
    Fixed(pair.gear1.hub.center)
}
