# Request: a "hedgehog highway" surround for the 13 x 13 cm gap cut at the foot of a garden
# fence panel, in 6 mm exterior ply. Plate 240 wide x 230 tall, top corners R10, its bottom
# edge on the ground. The opening is 130 wide and 130 tall, open at the bottom: straight
# sides 65 mm up, then a half-round top. "HEDGEHOG HIGHWAY" engraved filled (sans bold,
# 12 mm capitals) along an arc 15 mm above the opening; a filled engraved hedgehog (a spiky
# back about 48 mm long, a pointed snout) at the top centre. Four countersunk holes for M4
# (No. 8) wood screws: two in the legs 30 mm up, two near the top corners, 8 mm heads.

units mm
thickness 6 mm
import "std/fasteners.aidl"

gap_w = 130 mm
gap_h = 130 mm
r_top = gap_w / 2

solid highway {
    plate = RoundedRectangle(bottom_left=(-120, 0), width=240, height=230,
                             corner_radii=[10, 10, 0, 0])
    hole gap {
        straight = Rectangle(bottom_left=(-gap_w / 2, -1), width=gap_w, height=gap_h - r_top + 1,
                             overrun=true)
        round_top = Circle(center=(0, gap_h - r_top), radius=r_top)
    }
    leg_l = clearance_hole(size=4, cx=-(gap_w / 2 + 27.5 mm), cy=30 mm)
    leg_r = clearance_hole(size=4, cx=gap_w / 2 + 27.5 mm, cy=30 mm)
    top_l = clearance_hole(size=4, cx=-100 mm, cy=210 mm)
    top_r = clearance_hole(size=4, cx=100 mm, cy=210 mm)
    Countersink([leg_l, leg_r, top_l, top_r], diameter=8 mm)

    drawing words {
        ring = Circle(center=(0, gap_h - r_top), radius=r_top + 15, construction=true)
        title = Text("HEDGEHOG HIGHWAY", along=ring, size=12, font="sans:Bold", fill=true)
    }
    drawing hog {
        back = Intersect(Star(center=(0, 170), points=18, outer_radius=24, inner_radius=19),
                         Rectangle(bottom_left=(-30, 170), width=60, height=30), fill=true)
        snout = Triangle((18, 170), (18, 184), (34, 171), fill=true)
        front_foot = Circle(center=(10, 168), radius=2.5, fill=true)
        hind_foot = Circle(center=(-12, 168), radius=2.5, fill=true)
    }

    assert plate.bb.width == 240 mm and plate.bb.height == 230 mm, "plate 240 x 230"
    assert gap.round_top.bb.width == 130 mm, "opening 130 wide"
    assert gap.round_top.bb.top - plate.bb.bottom == 130 mm, "opening 130 tall"
    assert words.title.size == 12 mm, "12 mm capitals"
    assert distance(words, gap) >= 10 mm, "title clear of the opening"
    assert distance(words, [top_l, top_r, leg_l, leg_r]) >= 5 mm, "title clear of the screws"
    assert distance(hog, words) >= 3 mm, "hedgehog clear of the title"
    assert hog.bb.top <= plate.bb.top - 10 mm, "hedgehog inside the plate"
    assert leg_l.c.center.y - plate.bb.bottom == 30 mm, "leg screws 30 up"
}
