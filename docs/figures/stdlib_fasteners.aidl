# Figure of docs/stdlib.md: a bracket with two M3 clearance holes, two M3 nut traps and an M4 T-slot.
# Drawn by `python docs/make_pictures.py` to docs/images/stdlib_fasteners.png.

import "std/fasteners.aidl"

solid bracket {
    body = RoundedRectangle(center=(0, 0), width=60 mm, height=30 mm, corner_radius=3 mm)
    Fixed(body)
    for i in range(2) {
        bolt = clearance_hole(size=3, fit="medium", cx=-22 mm + i * 44 mm)
        bolt.c.center == (-22 mm + i * 44 mm, 6 mm)
        nut = nut_trap(size=3, cx=-22 mm + i * 44 mm, cy=-6 mm)
        nut.hex.center == (-22 mm + i * 44 mm, -6 mm)
    }
    joint = t_slot(size=4, length=14 mm, nut_depth=7 mm, cy=15 mm)
    joint.slot.center.x == 0 mm
    AlignTop(joint, body)    # the slot's mouth on the edge: 14 mm into the bracket
}
