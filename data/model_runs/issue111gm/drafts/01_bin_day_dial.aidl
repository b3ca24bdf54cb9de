# Request (home): a "bin day" dial for the hallway wall, 3 mm birch ply, 5 layers.
# Back plate 150 x 200 mm, 8 mm corner radii, two keyholes (8 mm head, 4 mm slot,
# 10 mm long, slot upward) 120 mm apart with their heads 30 mm below the top edge.
# A 160 mm disc turns on a 5 mm Chicago screw at the plate's centre; it stands
# 5 mm past each side edge so a thumb can turn it. Four labels on the disc, one per
# quarter, their middles on a 55 mm radius, 7 mm capitals: GENERAL, RECYCLING,
# GARDEN, FOOD (each reads upright when turned to the top).
# A spacer layer: the plate's outline minus a 164 mm circle about the pivot (so two
# pieces, top and bottom), with a 11 mm relief slot over each keyhole for the screw head.
# A front plate the same outline with a window: a ring segment from radius 40 to
# 75 mm, 70 degrees wide, centred straight above the pivot; "BIN DAY" engraved filled
# (10 mm, sans bold) centred 12 mm below the top edge, and "OUT ON WEDNESDAY NIGHT"
# (5 mm) 20 mm above the bottom edge.
# Four M3 screws 10 mm in from each corner through front, spacer and back: countersunk
# (6.5 mm) in the front, M3 nut traps in the back. Pivot holes 5.3 mm in all layers.

units mm
thickness 3 mm

import "std/fasteners.aidl"
import "std/plates.aidl"

plate_w = 150 mm
plate_h = 200 mm
corner_r = 8 mm
disc_d = 160 mm
gap_d = 164 mm
label_r = 55 mm
pivot_d = 5.3 mm
labels = ["GENERAL", "RECYCLING", "GARDEN", "FOOD"]
screw_at = [(-65, -90), (65, -90), (65, 90), (-65, 90)]

def outline() = RoundedRectangle(center=(0, 0), width=plate_w, height=plate_h, corner_radius=corner_r)

def pivot_hole() -> hole {
    c = Circle(center=(0, 0), diameter=pivot_d)
}

assembly bin_dial {
    solid back {
        body = outline()
        pivot = pivot_hole()
        kl = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=-60, cy=70)
        kr = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, direction=90 deg, cx=60, cy=70)
        for i in range(4) {
            nut = nut_trap(size=3, cx=screw_at[i][0], cy=screw_at[i][1])
        }
    }

    solid spacer_top {
        body = Intersect(outline(), Rectangle(center=(0, 50), width=plate_w + 10, height=100))
        hole well { c = Circle(center=(0, 0), diameter=gap_d) }
        hole relief_l { s = Slot(start=(-60, 70), end=(-60, 80), width=11) }
        hole relief_r { s = Slot(start=(60, 70), end=(60, 80), width=11) }
        sl = clearance_hole(size=3, cx=-65, cy=90)
        sr = clearance_hole(size=3, cx=65, cy=90)
    }

    solid spacer_bottom {
        body = Intersect(outline(), Rectangle(center=(0, -50), width=plate_w + 10, height=100))
        hole well { c = Circle(center=(0, 0), diameter=gap_d) }
        sl = clearance_hole(size=3, cx=-65, cy=-90)
        sr = clearance_hole(size=3, cx=65, cy=-90)
    }

    solid disc {
        rim = Circle(center=(0, 0), diameter=disc_d)
        pivot = pivot_hole()
        drawing words {
            ring = Circle(center=(0, 0), radius=label_r, construction=true)
            for k in range(4) {
                w = Text(labels[k], along=ring, angle=(90 + 90 * k) * 1 deg, size=7, valign="middle")
            }
        }
    }

    solid front {
        body = outline()
        pivot = pivot_hole()
        hole window {
            w = Sector(center=(0, 0), radius=75, inner_radius=40, start_angle=55 deg, end_angle=125 deg)
        }
        for i in range(4) {
            screw = clearance_hole(size=3, cx=screw_at[i][0], cy=screw_at[i][1])
        }
        Countersink(screw, diameter=6.5 mm)
        drawing title {
            t = Text("BIN DAY", position=(0, plate_h / 2 - 12), size=10, font="sans:Bold",
                     valign="middle", fill=true)
        }
        drawing note {
            n = Text("OUT ON WEDNESDAY NIGHT", position=(0, -plate_h / 2 + 20), size=5, valign="middle")
        }
    }

    # 3D: a stack lying face up, back plate at the bottom
    Place(back, position=(0, 0, 0))
    Place(spacer_top, position=(0, 0, 3))
    Place(spacer_bottom, position=(0, 0, 3))
    Place(disc, position=(0, 0, 3))
    Place(front, position=(0, 0, 6))

    # on the sheet: side by side
    RightOf(spacer_top, back, gap=10)
    AlignTop(spacer_top, back)
    Below(spacer_bottom, spacer_top, gap=10)
    AlignLeft(spacer_bottom, spacer_top)
    RightOf(disc, spacer_top, gap=10)
    AlignTop(disc, back)
    RightOf(front, disc, gap=10)
    AlignTop(front, back)

    # the request's numbers
    assert back.body.bb.width == 150 mm and back.body.bb.height == 200 mm, "plate 150 x 200"
    assert disc.rim.diameter - front.body.bb.width == 2 * 5 mm, "disc 5 mm past each side"
    assert abs(back.kr.head_hole.center.x - back.kl.head_hole.center.x - 120 mm) < 0.01 mm, "keyholes 120 apart"
    assert abs(back.body.bb.top - back.kl.head_hole.center.y - 30 mm) < 0.01 mm, "keyhole heads 30 below the top"
    assert len(disc.words.w) == 4, "four labels"
    assert front.window.w.radius == 75 mm and front.window.w.inner_radius == 40 mm, "window 40 to 75"
    assert spacer_top.well.c.diameter == 164 mm, "164 mm clearance circle"
    assert abs(front.body.bb.top - front.title.t.position.y - 12 mm) < 0.01 mm, "title 12 below the top"
    assert abs(front.note.n.position.y - front.body.bb.bottom - 20 mm) < 0.01 mm, "note 20 above the bottom"
}
