# Request (garden): a rain chain to hang from the gutter outlet instead of a downpipe, cut from
# 3 mm outdoor cast acrylic. Each link is a 3D "cup" of two identical raindrop-shaped vanes,
# 60 mm wide and 104 mm tall lug to lug, slotted halfway into each other crosswise (0.2 mm
# clearance). Vane A is slotted from the bottom and hangs by a 6 mm hole in its top lug; vane B
# is slotted from the top and carries the next link's S-hook by a 6 mm hole in its bottom lug;
# every hole keeps 5 mm of material round it. Each vane has two drop-shaped windows, one in
# each wing. Links hang 120 mm apart on stainless S-hooks; 4 links shown (a 2.5 m chain: 21).

units mm
thickness 3 mm
import "std/joints.aidl"

param links = 4, min = 1, max = 30
t = 3 mm
vane_w = 60 mm
bulb_r = vane_w / 2
bulb_y = 35 mm
lug_r = 8 mm
hook_d = 6 mm
top_y = 88 mm          # top lug's centre
bottom_y = 0 mm        # bottom lug's centre
vane_h = top_y + lug_r - (bottom_y - lug_r)
mid_y = (top_y + lug_r + bottom_y - lug_r) / 2
link_pitch = 120 mm
gap = 0.2 mm

def vane(from_top=false) -> solid {
    drop = Hull(Circle(center=(0, bulb_y), radius=bulb_r), Circle(center=(0, top_y), radius=lug_r))
    lug = Circle(center=(0, bottom_y), radius=lug_r)
    for s in [-1, 1] {
        hole window {
            w = Hull(Circle(center=(s * 17, 28), radius=6), Point(s * 17, 44))
        }
    }
    if from_top {
        hole hook { c = Circle(center=(0, bottom_y), diameter=hook_d) }
        slot = cross_halving(depth=vane_h / 2, thickness=t, clearance=gap, cx=0, cy=top_y + lug_r)
    } else {
        hole hook { c = Circle(center=(0, top_y), diameter=hook_d) }
        slot = cross_halving(depth=vane_h / 2, thickness=t, clearance=gap, cx=0,
                             cy=bottom_y - lug_r, rotation=180 deg)
    }
}

assembly chain {
    for k in range(links) {
        a = vane(from_top=false)
        b = vane(from_top=true)
        a.bb.center == (k * 140, 0)
        b.bb.center == (k * 140 + 70, -120)
        # A in the x-z plane, B in the y-z plane, crossing on the chain's axis
        Place(a, position=(0, t / 2, -k * link_pitch), face="front", up="up")
        Place(b, position=(-t / 2, 0, -k * link_pitch), face="right", up="up")
    }

    assert a[0].bb.width == 60 mm, "vanes 60 mm wide"
    assert a[0].bb.height == 104 mm, "vanes 104 mm tall lug to lug"
    assert a[0].hook.c.diameter == 6 mm, "6 mm hook holes"
    assert top_y + lug_r - (a[0].hook.c.center.y + hook_d / 2) >= 5 mm, "5 mm round the top hole"
    assert b[0].hook.c.center.y - hook_d / 2 - (bottom_y - lug_r) >= 5 mm,
        "5 mm round the bottom hole"
    assert a[0].slot.depth + b[0].slot.depth == vane_h, "the halvings meet"
}
