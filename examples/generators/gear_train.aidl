# A gear train of four spur gears of module 2 in a row on a plate with their axle holes.
#   aidl render examples/generators/gear_train.aidl --assembled -o train.png
import "std/gears.aidl"

thickness 3 mm

assembly drive {
    train = gear_train(teeth=[12, 36, 12, 30], module=2 mm, axle=4 mm)
}
