# The studio's form of examples/generators/gear_train.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/gears.aidl"

# The axle bores every gear, the smallest (12 teeth) too: its root circle is module x (12 - 2.5)
# across, and the bore leaves a wall of more than 0.5 mm in it. With no backlash the teeth
# meet flank on flank (the fit check, W0517): the play starts at 0.05 mm.
param module = 2 mm, min = 0.5 mm, max = 6 mm, step = 0.25 mm
param axle = 4 mm, min = 1 mm, max = min(16 mm, module * 9.5 - 1.1 mm), step = 0.05 mm
param backlash = 0.05 mm, min = 0.05 mm, max = min(1 mm, module / 2), step = 0.05 mm  # more thins a small module's teeth to points
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param lift = 0 mm, min = 0 mm, max = 20 mm, step = 0.5 mm

thickness thickness

assembly drive {
    train = gear_train(teeth=[12, 36, 12, 30], module=module, axle=axle, backlash=backlash,
                       thickness=thickness, lift=lift)
}
