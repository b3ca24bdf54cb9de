# Figure of docs/stdlib.md: a 12-tooth and a 20-tooth involute gear of module 4 in mesh.
# Drawn by `python docs/make_pictures.py` to docs/images/stdlib_gears.png.

import "std/gears.aidl"

assembly drive {
    pair = gear_pair(teeth1=12, teeth2=20, module=4 mm, bore1=6 mm, bore2=10 mm, backlash=0.1 mm)
}
