# Request (workshop): a fit-test key for 3 mm birch plywood, to pick the slot width for my
# tab-and-slot boxes before cutting a whole job. A comb 150 x 55 mm with R3 corners. Along
# its top edge 7 open slots 15 mm deep, 2.7 to 3.3 mm wide in 0.1 mm steps, 18 mm apart
# centre to centre, the row centred on the comb; each width engraved 4 mm under its slot
# (3.5 mm text). A row of 5 round holes for 6 mm dowel, 5.8 to 6.2 mm in 0.1 mm steps, 25 mm
# apart, centred, their centres 32 mm below the top edge, each size engraved 6 mm under
# its hole. "3 MM PLY FIT KEY" engraved 8 mm above the bottom edge, 5 mm text. A 5 mm
# hanging hole 8 mm in from the top left corner (both ways). And a separate test strip
# 80 x 20 mm, R3 corners, engraved "TEST TAB", cut beside the comb 10 mm away, tops level.

units mm
thickness 3 mm
kerf 0.15 mm

param slot_depth = 15 mm, min = 8 mm, max = 25 mm
slot_pitch = 18 mm
dowel_pitch = 25 mm
widths = [2.7, 2.8, 2.9, 3.0, 3.1, 3.2, 3.3]
dowels = [5.8, 5.9, 6.0, 6.1, 6.2]

assembly fit_key {
    solid comb {
        body = RoundedRectangle(center=(0, 0), width=150, height=55, corner_radius=3)

        for i in range(len(widths)) {
            hole slot {
                r = Rectangle(center=((i - 3) * slot_pitch, 20), width=widths[i],
                              height=slot_depth + 1)
            }
            # open at the top edge: the cut runs 1 mm past it
            slot.bb.top == body.bb.top + 1
            drawing slot_label {
                t = Text(f"{widths[i]:.1f}", position=((i - 3) * slot_pitch, 8), size=3.5,
                         valign="top")
            }
            At(slot_label.t.position, slot.r.bottom.midpoint, dy=-4)
        }
        AlignCenterX(slot[3], body)
        for i in range(len(widths) - 1) {
            HorizontalDistance(slot[i].r.center, slot[i + 1].r.center, slot_pitch)
        }

        for j in range(len(dowels)) {
            hole dowel {
                c = Circle(center=((j - 2) * dowel_pitch, -4.5), diameter=dowels[j])
            }
            VerticalDistance(dowel.c.center, body.top.midpoint, 32)
            drawing dowel_label {
                t = Text(f"{dowels[j]:.1f}", position=((j - 2) * dowel_pitch, -12), size=3.5,
                         valign="top")
            }
            At(dowel_label.t.position, dowel.c.bottom, dy=-6)
        }
        AlignCenterX(dowel[2], body)
        for j in range(len(dowels) - 1) {
            HorizontalDistance(dowel[j].c.center, dowel[j + 1].c.center, dowel_pitch)
        }

        hole hang {
            c = Circle(center=(-67, 19.5), diameter=5)
        }
        At(hang.c.center, body.top_left, dx=8, dy=-8)

        drawing title {
            t = Text("3 MM PLY FIT KEY", position=(0, -19.5), size=5)
        }
        AlignCenterX(title, body)
        VerticalDistance(body.bottom.midpoint, title.t.position, 8)

        Fixed(body)
    }

    solid strip {
        body = RoundedRectangle(center=(125, 17.5), width=80, height=20, corner_radius=3)
        drawing mark {
            t = Text("TEST TAB", position=(125, 17.5), size=5, valign="middle")
        }
        CenterInside(mark, body)
    }
    RightOf(strip, comb, gap=10)
    AlignTop(strip, comb)

    # the request's numbers
    assert len(comb.slot) == 7, "7 test slots"
    assert abs(comb.slot[0].r.width - 2.7 mm) < 0.001 mm, "narrowest slot 2.7"
    assert abs(comb.slot[6].r.width - 3.3 mm) < 0.001 mm, "widest slot 3.3"
    assert abs(comb.body.bb.top - comb.slot[4].r.bb.bottom - 15 mm) < 0.001 mm, "slots 15 deep"
    assert abs(comb.slot[5].r.center.x - comb.slot[4].r.center.x - 18 mm) < 0.001 mm, "18 pitch"
    assert abs(comb.slot[3].r.center.x - comb.body.bb.center_x) < 0.001 mm, "slot row centred"
    assert len(comb.dowel) == 5, "5 dowel holes"
    assert abs(comb.dowel[0].c.diameter - 5.8 mm) < 0.001 mm, "smallest dowel hole 5.8"
    assert abs(comb.dowel[4].c.diameter - 6.2 mm) < 0.001 mm, "largest dowel hole 6.2"
    assert abs(comb.body.bb.top - comb.dowel[1].c.center.y - 32 mm) < 0.001 mm, "dowels 32 down"
    assert abs(comb.dowel[1].c.center.x - comb.dowel[0].c.center.x - 25 mm) < 0.001 mm, "25 apart"
    assert abs(comb.body.bb.width - 150 mm) < 0.001 mm and abs(comb.body.bb.height - 55 mm) < 0.001 mm, "comb 150 x 55"
    assert distance(comb.title, comb.dowel_label) >= 2 mm, "title clear of the dowel sizes"
    assert distance(comb.slot_label, comb.dowel) >= 2 mm, "slot sizes clear of the dowel holes"
    assert abs(strip.bb.left - comb.bb.right - 10 mm) < 0.001 mm, "strip 10 mm away"
}
