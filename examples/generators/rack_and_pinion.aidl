# A rack of 12 teeth and a 16-tooth pinion of module 2 meshing it, on a base plate.
#   aidl render examples/generators/rack_and_pinion.aidl --assembled -o rack.png
import "std/gears.aidl"

thickness 3 mm

assembly slide {
    drive = rack_and_pinion(teeth=16, module=2 mm, rack_teeth=12)
}
