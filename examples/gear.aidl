# A gear pair: a small pinion driving a larger spoked wheel. Both gears come
# from templates in parts/gears.aidl (imported relatively); the teeth of each
# gear are made by a loop inside the template. The two centers are held one
# pitch-radius sum apart so the gears mesh; the wheel's teeth are turned half
# a tooth so a pinion tooth sits in a wheel gap.
# Try: --set wheel_teeth=40  --set pinion_teeth=10  --set module=3

import "parts/gears.aidl"

param pinion_teeth = 12, min = 8, max = 40, step = 1
param wheel_teeth = 30, min = 20, max = 80, step = 1
param module = 2 mm

center_distance = module * (pinion_teeth + wheel_teeth) / 2

assembly gear_train {
    pinion = spur_gear(teeth=pinion_teeth, module=module, bore=5 mm)
    wheel = spoked_gear(teeth=wheel_teeth, module=module, bore=8 mm,
                        phase=180 deg + 180 deg / wheel_teeth, cx=center_distance)

    # the pinion stays put; the wheel meshes with it on the same horizontal line
    Fixed(pinion.hub.center)
    HorizontalDistance(pinion.hub.center, wheel.g.hub.center, center_distance)
    VerticalDistance(pinion.hub.center, wheel.g.hub.center, 0 mm)

    # engraved center line through both axles
    drawing centers {
        axis = Line((-module * pinion_teeth / 2 - 10 mm, 0), (center_distance + module * wheel_teeth / 2 + 10 mm, 0))
    }
    Horizontal(centers.axis)
    OnLine(pinion.hub.center, centers.axis)
}
