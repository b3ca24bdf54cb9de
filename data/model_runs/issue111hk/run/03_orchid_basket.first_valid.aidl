# Request (garden): a hanging slat basket for a vanda orchid, the log-cabin kind, cut from 6 mm
# exterior ply. Square, slats 170 mm long and 12 mm tall crossing 140 mm apart (centre to
# centre), 8 layers: each slat notched half its height (6 mm, 0.1 mm clearance) from below
# where it crosses the slats under it, so each layer rises 6 mm and the basket stands 54 mm
# tall. The bottom layer is two base slats with no notches under them, but three notches on
# top (35 mm apart) holding three 6 mm tall floor slats flush with their tops, for the roots
# and the bark to rest on. The two top slats have a 4 mm hole in each end, 9 mm from the
# crossing, for the four hanging wires. 19 parts: 2 base, 12 wall, 2 top, 3 floor slats.

import "std/joints.aidl"

units mm
thickness 6 mm

param t = 6 mm, min = 3, max = 9
param h = 12 mm, min = 8, max = 20        # slat height
param span = 140 mm, min = 100, max = 200 # between crossing slats, centre to centre
param slat_l = 170 mm, min = 130, max = 240
param fit = 0.1 mm, min = 0, max = 0.3

layers = 8
floor_pitch = 35 mm
floor_l = span + t + 8 mm                  # 4 mm past each base slat
eye_x = span / 2 + 9 mm                    # hanging hole from the slat's middle

def base_slat() -> solid {
    body = Rectangle(center=(0, 0), width=slat_l, height=h)
    for i in range(3) {
        n = cross_halving(depth=h / 2, thickness=t, clearance=fit, cx=(i - 1) * floor_pitch,
                          cy=h / 2)
    }
}

def wall_slat(hang=false) -> solid {
    body = Rectangle(center=(0, 0), width=slat_l, height=h)
    left = cross_halving(depth=h / 2, thickness=t, clearance=fit, rotation=180 deg,
                         cx=-span / 2, cy=-h / 2)
    right = cross_halving(depth=h / 2, thickness=t, clearance=fit, rotation=180 deg,
                          cx=span / 2, cy=-h / 2)
    if hang {
        hole eyes {
            a = Circle(center=(-eye_x, 0), diameter=4)
            b = Circle(center=(eye_x, 0), diameter=4)
        }
    }
}

def floor_slat() -> solid {
    body = Rectangle(center=(0, 0), width=floor_l, height=h / 2)
}

assembly basket {
    # layer 0: the base slats along x, at y = -span/2 and +span/2
    for s in range(2) {
        base = base_slat()
        base.bb.center == (0, s * 18 mm)
        Place(base, position=(0, (s - 0.5) * span + t / 2, h / 2), face="front", up="up")
    }
    # the floor slats along y, in the base slats' top notches
    for i in range(3) {
        fl = floor_slat()
        fl.bb.center == (0, (2 + i) * 18 mm)
        Place(fl, position=((i - 1) * floor_pitch + t / 2, 0, h - h / 4), face="left", up="up")
    }
    # layers 1 to 6: odd layers along y, even ones along x
    for k in range(1, layers - 1) {
        for s in range(2) {
            w = wall_slat()
            w.bb.center == (0, (5 + (k - 1) * 2 + s) * 18 mm)
            if k % 2 == 1 {
                Place(w, position=((s - 0.5) * span + t / 2, 0, k * h / 2 + h / 2), face="left",
                      up="up")
            } else {
                Place(w, position=(0, (s - 0.5) * span + t / 2, k * h / 2 + h / 2), face="front",
                      up="up")
            }
        }
    }
    # layer 7: the top slats along y, with the hanging holes
    for s in range(2) {
        top = wall_slat(hang=true)
        top.bb.center == (0, (17 + s) * 18 mm)
        Place(top, position=((s - 0.5) * span + t / 2, 0, (layers - 1) * h / 2 + h / 2),
              face="left", up="up")
    }
}

assert len(basket.base) + sum([len(r) for r in basket.w]) + len(basket.top) + len(basket.fl) == 19, "19 parts"
assert sum([len(r) for r in basket.w]) == 12, "12 wall slats"
assert abs(basket.base[0].body.width - 170 mm) < 0.01 mm, "slats 170 mm long"
assert abs(basket.base[0].body.height - 12 mm) < 0.01 mm, "slats 12 mm tall"
assert abs(basket.w[0][0].right.cut.bb.center_x - basket.w[0][0].left.cut.bb.center_x - 140 mm) < 0.01 mm,
    "crossings 140 mm apart"
assert abs(basket.w[0][0].left.cut.bb.height - 6 mm) < 0.01 mm, "notches half the slat's height"
assert abs(basket.base[0].n[1].cut.bb.center_x - basket.base[0].n[0].cut.bb.center_x - 35 mm) < 0.01 mm,
    "floor notches 35 mm apart"
assert abs(12 mm + (layers - 1) * 6 mm - 54 mm) < 0.01 mm, "54 mm tall"
assert abs(basket.top[0].eyes.b.center.x - basket.top[0].right.cut.bb.center_x - 9 mm) < 0.01 mm,
    "hanging hole 9 mm past the crossing"
assert basket.top[0].body.bb.right - basket.top[0].eyes.b.center.x - 2 mm >= 2 mm, "wall past the hanging hole"
