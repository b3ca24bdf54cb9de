# Request (toys): "A 'Shoot the Moon' tabletop skill game in 6 mm ply. A 25 mm steel ball rides
# on two 8 mm steel rods; the player holds the rods at the low end and spreads and closes them
# to make the ball roll uphill, then drops it into a scoring hole. Parts:
# - base board 500 x 120 mm, R10 corners; four 30 mm scoring holes on its centre line at 150,
#   230, 310 and 390 mm from the player's (left) end, scoring 10, 25, 50, 100 (engraved 8 mm
#   figures below each hole); 'SHOOT THE MOON' engraved near the player's end;
# - the far upright, 120 wide, standing 100 mm above the base, its centre line 20 mm in from
#   the far end, two glued tabs 30 mm wide into mortises in the base; two 8.2 mm rod holes
#   80 mm above the base, 16 mm apart centre to centre; a crescent moon (28 mm across) cut
#   through it above the rods;
# - the player's rest, 120 wide, standing 40 mm above the base, centre line 20 mm in from the
#   player's end, same tabs, with an 80 mm wide, 12 mm deep notch in its top for the rods."

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
base_l = 500 mm
base_w = 120 mm
hole_x = [150, 230, 310, 390]
scores = [10, 25, 50, 100]
upright_h = 100 mm   # above the base
rod_up = 80 mm
rod_pitch = 16 mm
rest_h = 40 mm
end_in = 20 mm

# the moon: a 14 mm circle with a 12 mm circle bitten out of it, 7 mm to the right
moon_r = 14 mm
bite_r = 12 mm
bite_dx = 7 mm
tip_x = (bite_dx ** 2 + moon_r ** 2 - bite_r ** 2) / (2 * bite_dx)
tip_y = sqrt(moon_r ** 2 - tip_x ** 2)

def stand(h=40 mm) -> solid {
    # flat: tab tips on y = 0, the shoulders t higher rest on the base
    body = Rectangle(bottom_left=(-base_w / 2, 0), width=base_w, height=h + t)
    feet = tab_and_slot(part="tab", length=base_w, thickness=t, tabs=2, tab=30 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    assert body.bb.height - t == h, "stands h above the base"
}

assembly shoot_the_moon {
    solid base {
        board = RoundedRectangle(bottom_left=(0, -base_w / 2), width=base_l, height=base_w,
                                 corner_radius=10)
        hole cups {
            for i in range(4) {
                c = Circle(center=(hole_x[i], 0), diameter=30)
            }
        }
        far_mortise = tab_and_slot(part="slot", length=base_w, thickness=t, tabs=2, tab=30 mm,
                                   screw=0, rotation=90 deg, cx=base_l - end_in, cy=0 mm)
        rest_mortise = tab_and_slot(part="slot", length=base_w, thickness=t, tabs=2, tab=30 mm,
                                    screw=0, rotation=90 deg, cx=end_in, cy=0 mm)
        drawing score_marks {
            for i in range(4) {
                s = Text(str(scores[i]), position=(hole_x[i], -33), size=8, valign="middle")
            }
        }
        drawing title {
            n = Text("SHOOT THE MOON", position=(end_in + 55, 0), size=7, valign="middle",
                     rotation=90 deg)
        }
        assert board.bb.width == 500 mm and board.bb.height == 120 mm, "base 500 x 120"
        assert len(cups.c) == 4, "four scoring holes"
        assert cups.c[0].center.x - board.bb.left == 150 mm, "first hole 150 from the player"
        assert cups.c[3].center.x - board.bb.left == 390 mm, "last hole 390 from the player"
        assert far_mortise.bb.center_x - board.bb.left == 500 mm - 20 mm, "upright 20 in"
        assert distance(score_marks, cups) >= 2 mm, "scores clear of the holes"
        assert distance(title, cups) >= 2 mm and distance(title, rest_mortise) >= 2 mm,
            "title clear of holes and mortise"
    }

    solid upright {
        frame = stand(h=upright_h)
        hole rods {
            left = Circle(center=(-rod_pitch / 2, t + rod_up), diameter=8.2)
            right = Circle(center=(rod_pitch / 2, t + rod_up), diameter=8.2)
        }
        hole moon {
            outer = Arc(start=(tip_x, tip_y), through=(-moon_r, 0), end=(tip_x, -tip_y))
            inner = Arc(start=(tip_x, -tip_y), through=(bite_dx - bite_r, 0), end=(tip_x, tip_y))
        }
        AlignCenterX(moon, rods)
        moon.bb.bottom == rods.bb.top + 10 mm
        assert rods.right.center.x - rods.left.center.x == 16 mm, "rods 16 apart"
        assert rods.left.center.y - frame.body.bb.bottom - t == 80 mm, "rods 80 above the base"
        assert frame.body.bb.top - moon.bb.top >= 5 mm, "moon inside the upright"
    }

    solid rest {
        frame = stand(h=rest_h)
        hole notch {
            r = Rectangle(center=(0, t + rest_h), width=80, height=24)
        }
        assert frame.body.bb.top - notch.r.bb.bottom == 12 mm, "notch 12 deep"
    }

    Below(upright, base, gap=10)
    AlignLeft(upright, base)
    RightOf(rest, upright, gap=10)
    AlignBottom(rest, upright)
}
