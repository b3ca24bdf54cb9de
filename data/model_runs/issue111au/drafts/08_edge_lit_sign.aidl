# Request: an edge-lit LED night light as a christening gift, four parts. The
# sign is 3 mm clear acrylic, 150 mm wide and 120 mm tall with 12 mm rounded
# corners; engraved on it: a crescent moon 50 mm across, three five-pointed
# stars 12 mm across in the moon's opening, and the name "MILA" in bold filled
# letters 22 mm tall. Below the sign a tab 100 mm wide and 6 mm long drops
# through a slot (0.2 mm clearance) in the base to sit on the LED strip. The
# base is a stack of three 4 mm plywood plates 160 x 40 mm: the top plate with
# the slot; a spacer with a 130 x 16 mm pocket for the LED strip and a cable
# notch 8 mm wide out of its back edge; the bottom plate. Four M3 flat-head
# screws, 10 mm in from the ends and 8 mm in from the long edges, hold the stack:
# countersunk in the top plate, clearance holes in the spacer, nut traps in
# the bottom plate.

import "std/fasteners.aidl"

units mm
thickness 4 mm

param sign_w = 150 mm, min = 100 mm, max = 200 mm
param sign_h = 120 mm, min = 80 mm, max = 180 mm
param acrylic = 3 mm, min = 2 mm, max = 5 mm
param tab_w = 100 mm, min = 60 mm, max = 140 mm
param tab_l = 6 mm, min = 4 mm, max = 8 mm
param fit = 0.2 mm, min = 0 mm, max = 0.4 mm
param base_l = 160 mm, min = 120 mm, max = 220 mm
param base_w = 40 mm, min = 30 mm, max = 60 mm

# the crescent: the moon's disc less a second disc moved up and right;
# its tips are where the two circles cross
moon_c = (-35, 12)
moon_r = 25 mm
bite_d = 12 mm
bite_r = 22 mm
bite_dir = 30 deg
ux = cos(bite_dir)
uy = sin(bite_dir)
cross_a = (bite_d ** 2 + moon_r ** 2 - bite_r ** 2) / (2 * bite_d)
cross_h = sqrt(moon_r ** 2 - cross_a ** 2)

# screw positions, 10 mm in from the ends and 8 mm in from the long edges
sx = base_l / 2 - 10 mm
sy = base_w / 2 - 8 mm
screws = [(-sx, -sy), (sx, -sy), (-sx, sy), (sx, sy)]

assembly night_light {
    solid sign {
        thickness 3 mm
        panel = RoundedRectangle(center=(0, 0), width=sign_w, height=sign_h, corner_radius=12)
        tab = Rectangle(center=(0, -sign_h / 2 - tab_l / 2), width=tab_w, height=tab_l)
        drawing art {
            tip1 = Point(moon_c[0] + cross_a * ux - cross_h * uy, moon_c[1] + cross_a * uy + cross_h * ux)
            tip2 = Point(moon_c[0] + cross_a * ux + cross_h * uy, moon_c[1] + cross_a * uy - cross_h * ux)
            outer = Arc(start=tip1, through=Point(moon_c[0] - moon_r * ux, moon_c[1] - moon_r * uy),
                        end=tip2)
            inner = Arc(start=tip1,
                        through=Point(moon_c[0] + (bite_d - bite_r) * ux, moon_c[1] + (bite_d - bite_r) * uy),
                        end=tip2)
            s1 = Star(center=(-2, 40), points=5, outer_radius=6, inner_radius=2.5)
            s2 = Star(center=(18, 28), points=5, outer_radius=6, inner_radius=2.5)
            s3 = Star(center=(8, 10), points=5, outer_radius=6, inner_radius=2.5)
            name = Text("MILA", position=(0, -35), size=22, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }

    solid top {
        plate = RoundedRectangle(center=(0, 0), width=base_l, height=base_w, corner_radius=4)
        hole slot {
            s = Rectangle(center=(0, 0), width=tab_w + fit, height=acrylic + fit)
        }
        for i in range(4) {
            h = clearance_hole(size=3, cx=screws[i][0], cy=screws[i][1])
        }
        Countersink(h, diameter=6.5 mm)
    }

    solid spacer {
        plate = RoundedRectangle(center=(0, 0), width=base_l, height=base_w, corner_radius=4)
        hole pocket {
            p = Rectangle(center=(0, 0), width=130, height=16)
            cable = Rectangle(center=(50, -base_w / 2 + 5.5), width=8, height=13)
        }
        for i in range(4) {
            h = clearance_hole(size=3, cx=screws[i][0], cy=screws[i][1])
        }
    }

    solid bottom {
        plate = RoundedRectangle(center=(0, 0), width=base_l, height=base_w, corner_radius=4)
        for i in range(4) {
            n = nut_trap(size=3, cx=screws[i][0], cy=screws[i][1])
        }
    }

    Below(top, sign, gap=10)
    AlignCenterX(top, sign)
    Below(spacer, top, gap=8)
    AlignCenterX(spacer, top)
    Below(bottom, spacer, gap=8)
    AlignCenterX(bottom, spacer)

    assert sign.panel.width == 150 mm and sign.panel.height == 120 mm, "sign 150 x 120"
    assert sign.tab.width == 100 mm and sign.tab.height == 6 mm, "tab 100 x 6"
    assert top.slot.s.width == 100.2 mm and top.slot.s.height == 3.2 mm, "slot 0.2 mm clearance"
    assert abs(distance(sign.art.outer.through, sign.art.inner.through) - 15 mm) < 0.01 mm, "crescent 15 mm at its widest"
    assert 2 * moon_r == 50 mm, "moon 50 mm across"
    assert sign.art.s1.outer_radius == 6 mm, "stars 12 mm across"
    assert sign.art.name.size == 22 mm, "name 22 mm tall"
    assert len(top.h) == 4 and len(bottom.n) == 4, "four screws"
    assert top.plate.width == 160 mm and top.plate.height == 40 mm, "base 160 x 40"
    assert spacer.pocket.p.width == 130 mm and spacer.pocket.p.height == 16 mm, "LED pocket"
}
