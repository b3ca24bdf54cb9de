# Request: a soft recovery cone (e-collar) for a 4.5 kg cat, cut from 0.8 mm polypropylene
# sheet. Flat it is an annular sector: inner radius 60 mm, outer radius 180 mm, 270 degrees
# round. It closes by overlapping its ends: the end at 0 degrees carries 3 arrow tabs (stem
# 10 wide x 6 long, barbed head 22 wide, 18 mm out from the edge in all) at 85, 120 and
# 155 mm from the centre; the other end (at 270 degrees) has 3 slots 20 x 1.5 mm, running
# along the edge 10 mm in from it, at the same radii. Five collar loops (each a pair of
# 17 x 2 mm slits across the radius, at 68 and 80 mm from the centre) at 20, 80, 135, 190
# and 250 degrees let the cat's own collar thread through. Every corner rounded R3.

units mm
thickness 0.8 mm
min_wall 0.5 mm

param r_in = 60 mm, min = 45, max = 80
param r_out = 180 mm, min = 140, max = 220
tab_r = [85 mm, 120 mm, 155 mm]
loop_a = [20 deg, 80 deg, 135 deg, 190 deg, 250 deg]

solid cone {
    body = Sector(center=(0, 0), radius=r_out, start_angle=0, end_angle=270,
                  inner_radius=r_in)
    solid tabs {
        for i in range(3) {
            t = Polygon([(tab_r[i] - 5, 0.5), (tab_r[i] + 5, 0.5), (tab_r[i] + 5, -6),
                         (tab_r[i] + 11, -6), (tab_r[i], -18), (tab_r[i] - 11, -6),
                         (tab_r[i] - 5, -6)])
        }
    }
    hole slots {
        for i in range(3) {
            s = Slot(center=(-10, -tab_r[i]), length=20, width=1.5, rotation=90)
        }
    }
    hole loops {
        for j in range(5) {
            a = Slot(center=polar((0, 0), 68 mm, loop_a[j]), length=17, width=2,
                     rotation=loop_a[j] + 90 deg)
            b = Slot(center=polar((0, 0), 80 mm, loop_a[j]), length=17, width=2,
                     rotation=loop_a[j] + 90 deg)
        }
    }
    Fillet(3 mm)

    assert body.inner_radius == 60 mm and body.radius == 180 mm, "60 / 180 radii"
    assert len(tabs.t) == 3 and len(slots.s) == 3, "3 tabs, 3 slots"
    assert tabs.bb.bottom == -18 mm, "tabs 18 out"
    assert slots.s[1].center.y == -120 mm and slots.s[1].center.x == -10 mm, "slot 10 in"
    assert len(loops.a) == 5, "5 collar loops"
    assert distance(loops.a[0].center, body.center) == 68 mm, "inner slit at 68"
    assert distance(loops.b[0].center, body.center) == 80 mm, "outer slit at 80"
}
