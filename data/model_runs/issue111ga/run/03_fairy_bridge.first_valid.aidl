# Request: an arched footbridge for a fairy garden, 3 mm birch ply (varnished for outdoors).
# The walkway is an arc that spans 160 mm and rises 25 mm (radius 140.5 mm), 50 mm wide
# between two arched side rails. Thirteen deck slats, 10 mm wide, 5 degrees apart along the
# arc, each with a 5 mm wide tab at both ends through a mortise in each side (0.1 mm fit).
# Each side is an arched band from 10 mm under the walkway to a handrail 35 mm over it, with
# six round-ended windows between posts, cut off flat at the bottom into feet 10 mm below
# the ends of the walkway arc.

t = 3 mm
thickness t

span = 160 mm
rise = 25 mm
walk_r = (square(span / 2) + square(rise)) / (2 * rise)     # 140.5 mm
cy = rise - walk_r                                          # the arc's centre, under the deck
walk_w = 50 mm
slats = 13
slat_w = 10 mm
step = 5 deg
tab_w = 5 mm
fit = 0.1 mm
foot_y = -10 mm

# the angle of slat i from the top of the arc (positive: to the left)
def slat_a(i) = (i - (slats - 1) / 2) * step

def side() -> solid {
    band = Intersect(
        Sector(center=(0, cy), radius=walk_r + 35 mm, start_angle=45 deg, end_angle=135 deg,
               inner_radius=walk_r - 10 mm),
        Rectangle(corner=(-150 mm, foot_y), opposite=(150 mm, 100 mm)))
    hole windows {
        for i in range(6) {
            w = ArcSlot(center=(0, cy), radius=walk_r + 18.5 mm,
                        start_angle=90 deg - 33 deg + 2.16 deg + i * 11 deg,
                        end_angle=90 deg - 33 deg + 9.56 deg - 2.16 deg + i * 11 deg,
                        width=12 mm)
        }
    }
    hole mortises {
        for i in range(slats) {
            m = Rectangle(center=(walk_r * cos(90 deg + slat_a(i)), cy + walk_r * sin(90 deg + slat_a(i))),
                          width=tab_w + fit, height=t + fit, rotation=slat_a(i))
        }
    }
}

def slat() -> solid {
    board = Rectangle(center=(0, 0), width=walk_w, height=slat_w)
    tab_l = Rectangle(corner=(-walk_w / 2 - t, -tab_w / 2), opposite=(-walk_w / 2, tab_w / 2))
    tab_r = Rectangle(corner=(walk_w / 2, -tab_w / 2), opposite=(walk_w / 2 + t, tab_w / 2))
}

assembly bridge {
    left = side()
    right = side()
    for i in range(slats) {
        s = slat()
    }

    # flat on the sheet: the two sides one above the other, the slats in two rows under them
    Below(right, left, gap=4)
    AlignLeft(right, left)
    for i in range(slats) {
        Below(s[i], right, gap=4 + (i // 7) * (slat_w + 4))
        if i % 7 == 0 {
            AlignLeft(s[i], right)
        } else {
            RightOf(s[i], s[i - 1], gap=4)
        }
    }

    # assembled: the sides stand 50 mm apart, feet on the ground (z 0), the slats follow the arc
    Place(right, position=(0, -walk_w / 2, -foot_y), face="front", up="up")
    Place(left, position=(0, walk_w / 2, -foot_y), face="back", up="up")
    for i in range(slats) {
        Place(s[i], position=((walk_r - t / 2) * cos(90 deg + slat_a(i)), 0,
                              -foot_y + cy + (walk_r - t / 2) * sin(90 deg + slat_a(i))),
              rotation=(-slat_a(i), 0, 90 deg))
    }

    # the request's numbers
    assert abs(walk_r - 140.5 mm) < 0.01 mm, "an arc of radius 140.5 over 160 mm, 25 mm rise"
    assert len(s) == 13, "thirteen slats"
    assert s[0].board.width == 50 mm and s[0].board.height == 10 mm, "50 mm walkway, 10 mm slats"
    assert s[0].bb.width == 56 mm, "a 3 mm tab at each end"
    assert len(left.windows.w) == 6, "six windows"
    assert left.band.bb.bottom == -10 mm, "feet 10 mm below the ends of the walkway arc"
    assert left.mortises.m[0].width == 5.1 mm, "5 mm tabs in 5.1 mm mortises"
}
