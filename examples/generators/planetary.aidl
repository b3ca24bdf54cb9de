# A planetary gear set: a 12-tooth sun, three 18-tooth planets and a 48-tooth ring, module 2.
#   aidl render examples/generators/planetary.aidl --assembled -o planets.png
import "std/gears.aidl"

thickness 3 mm

assembly reducer {
    set = planetary(sun=12, planet=18, ring=48, planets=3, module=2 mm)
}
