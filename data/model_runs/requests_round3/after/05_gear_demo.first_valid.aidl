# A gear demonstrator: a 160 x 100 mm base plate and three meshing spur gears
# (module 2; 20, 30 and 15 teeth) on axles, the gears 10 mm above the plate.
import "std/gears.aidl"

thickness 3 mm

assembly demo {
    train = gear_train(teeth=[20, 30, 15], module=2 mm, axle=4 mm, lift=10 mm)
}
