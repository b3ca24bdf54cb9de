# Request: a marathon pace band for a 3:30 finish, cut from 1 mm white polypropylene and
# engraved. A strap 26 mm wide: a 240 mm band (left corners R4) with three 2 x 18 mm
# adjusting slots 8, 15 and 22 mm from its left end, and at its right end a 14 mm wide,
# 12 mm long neck ending in a 22 mm wide, 10 mm long arrow tab that squeezes through a slot
# and catches. Engraved (single-stroke): a "GOAL 3:30" column and a "PACE 4:59" column (per km),
# then the splits at 5, 10, ..., 40 km and the finish (42.195 km, "FIN") as h:mm:ss,
# each column 18 mm wide with the distance (3.5 mm) over the time (3 mm), and a short line
# between columns.

thickness 1 mm
min_wall 0.5 mm

param goal_min = 210, min = 150, max = 330
goal_s = goal_min * 60
marathon = 42.195
col = 18 mm
band_len = 240 mm
band_w = 26 mm
dists = [5, 10, 15, 20, 25, 30, 35, 40, marathon]

def split_s(d) = floor(d * goal_s / marathon + 0.5)
def hms(s) = f"{floor(s / 3600):.0f}:{floor(s % 3600 / 60):02.0f}:{s % 60:02.0f}"
def ms(s) = f"{floor(s / 60):.0f}:{s % 60:02.0f}"
def col_x(i) = 40 + i * col
def dist_label(d) = "FIN" if d > 42 else f"{d:.0f}K"

solid band {
    strap = RoundedRectangle(bottom_left=(0, -band_w / 2), width=band_len, height=band_w,
                             corner_radii=[4, 0, 0, 4])
    neck = Rectangle(bottom_left=(band_len - 1, -7), width=13, height=14)
    arrow = Polygon([(band_len + 12, -11), (band_len + 17, -11), (band_len + 22, -3),
                     (band_len + 22, 3), (band_len + 17, 11), (band_len + 12, 11)])
    hole adjust {
        for x in [8, 15, 22] {
            s = Rectangle(center=(x, 0), width=2, height=18)
        }
    }
    drawing marks {
        goal_k = Text("GOAL", position=(col_x(0), 5), size=3.5, valign="middle")
        goal_v = Text(ms(goal_min), position=(col_x(0), -5), size=3, valign="middle")
        pace_k = Text("PACE", position=(col_x(1), 5), size=3.5, valign="middle")
        pace_v = Text(ms(floor(goal_s / marathon + 0.5)), position=(col_x(1), -5), size=3,
                      valign="middle")
        for i in range(len(dists)) {
            k = Text(dist_label(dists[i]), position=(col_x(i + 2), 5), size=3.5, valign="middle")
            v = Text(hms(split_s(dists[i])), position=(col_x(i + 2), -5), size=3, valign="middle")
        }
        for i in range(len(dists) + 1) {
            sep = Line((col_x(i) + col / 2, -8), (col_x(i) + col / 2, 8))
        }
    }

    # the request's numbers
    assert strap.height == 26 mm and strap.width == 240 mm, "band 26 x 240"
    assert len(adjust.s) == 3, "three adjusting slots"
    assert adjust.s[0].center.x - strap.bb.left == 8 mm and adjust.s[2].center.x - strap.bb.left == 22 mm,
        "slots 8 to 22 in"
    assert adjust.s[0].width == 2 mm and adjust.s[0].height == 18 mm, "slots 2 x 18"
    assert arrow.bb.width == 10 mm and arrow.bb.height == 22 mm, "arrow 22 wide, 10 long"
    assert arrow.bb.left - strap.bb.right == 12 mm and neck.height == 14 mm, "neck 14 x 12"
    assert arrow.bb.height > adjust.s[0].height and neck.height < adjust.s[0].height,
        "the neck passes a slot, the arrow catches"
    assert len(marks.v) == 9, "eight 5 km splits and the finish"
    assert split_s(marathon) == 3 * 3600 + 30 * 60, "the finish split is 3:30:00"
    assert ms(floor(goal_s / marathon + 0.5)) == "4:59", "4:59 per km"
    assert marks.v[8].bb.right <= strap.bb.right - 2 mm, "last split on the band"
    assert distance(marks.goal_k, adjust) >= 3 mm, "first column clear of the slots"
    assert marks.v[0].bb.width <= col - 2 mm, "a time fits its column"
}
