# The studio's form of examples/generators/rack_and_pinion.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/gears.aidl"

# A pinion of fewer than 11 teeth has its tips cut into the rack's teeth (interference: the
# teeth have no profile shift), so its slider starts at 11; the axle's bore leaves a wall of
# more than 0.5 mm inside the pinion's root circle (module x (teeth - 2.5) across).
param teeth = 16, min = 11, max = 64, step = 1
param module = 2 mm, min = 0.5 mm, max = 6 mm, step = 0.25 mm
param rack_teeth = 12, min = 8, max = 48, step = 1
param height = 8 mm, min = 2 mm, max = 32 mm, step = 0.05 mm
param axle = 4 mm, min = 1 mm, max = min(16 mm, module * (teeth - 2.5) - 1.1 mm), step = 0.05 mm
param backlash = 0.05 mm, min = 0 mm, max = min(1 mm, module / 2), step = 0.05 mm  # more thins a small module's teeth to points
param thickness = 3 mm, min = 1 mm, max = 12 mm, step = 0.5 mm
param lift = 0 mm, min = 0 mm, max = 20 mm, step = 0.5 mm

thickness thickness

assembly slide {
    drive = rack_and_pinion(teeth=teeth, module=module, rack_teeth=rack_teeth, height=height,
                            axle=axle, backlash=backlash, thickness=thickness, lift=lift)
}
