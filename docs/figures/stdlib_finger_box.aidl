# Figure of docs/stdlib.md: the six panels of a finger-jointed box, laid out as a net.
# Drawn by `python docs/make_pictures.py` to docs/images/stdlib_finger_box.png.
# render: --png-width 520

import "std/joints.aidl"

kerf 0.15 mm
thickness 3 mm

assembly kit {
    box = finger_box(length=120 mm, depth=80 mm, height=50 mm, thickness=3 mm, finger=10 mm)
}
