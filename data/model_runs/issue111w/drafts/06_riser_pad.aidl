# Sport: a skateboard riser pad, 3 mm polycarbonate, 64 mm wide (across the
# board) x 89 mm long (along it), 6 mm rounded corners. It takes both truck
# hole patterns: 1-5/8 in across, 2-1/8 in along ("new school") and 2-1/2 in
# along ("old school"): on each side the two holes of a row merge into one
# slot 5.2 mm wide (for 10-32 bolts) from the new-school hole to the
# old-school hole. A 14 x 30 mm lightening slot in the middle, along the
# board.

thickness 3 mm
param bolt_d = 5.2 mm, min = 4.5, max = 6

across = 1.625 in
new_along = 2.125 in
old_along = 2.5 in

solid pad {
    body = RoundedRectangle(center=(0, 0), width=64, height=89, corner_radius=6)
    hole bolts {
        for sx in [-1, 1] {
            up = Slot(start=(sx * across / 2, new_along / 2), end=(sx * across / 2, old_along / 2), width=bolt_d)
            down = Slot(start=(sx * across / 2, -new_along / 2), end=(sx * across / 2, -old_along / 2), width=bolt_d)
        }
    }
    hole middle {
        s = Slot(center=(0, 0), length=30, width=14, rotation=90)
    }
    assert body.bb.width == 64 mm and body.bb.height == 89 mm, "pad 64 x 89"
    assert bolts.up[1].start.x - bolts.up[0].start.x == 1.625 in, "1-5/8 in across"
    assert bolts.up[0].start.y - bolts.down[0].start.y == 2.125 in, "new school 2-1/8 in"
    assert bolts.up[0].end.y - bolts.down[0].end.y == 2.5 in, "old school 2-1/2 in"
    assert middle.s.length == 30 mm and middle.s.width == 14 mm, "lightening slot 14 x 30"
}
