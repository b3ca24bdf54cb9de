# Request (holidays): a decorative Christmas porch sled, 6 mm ply, glued.
# Two runners 555 mm long and 150 mm high: a 20 mm bottom rail 480 mm long whose front
# curls up in a half ring (outer radius 75, 20 mm wide) into a 20 mm top rail running back
# to 40 mm from the rail's back end; three 24 mm posts between the rails (centred 52, 260
# and 440 mm from the back), their inside corners rounded 8 mm; the bottom rail's back end
# rounded 8 mm; a 12 mm hole through each curl, 65 mm in front of the curl's centre, for
# the pull-rope dowel. Each top rail has 2 tabs (40 mm) up through the seat.
# A seat 440 x 300 mm with 20 mm corners, the runners' middle planes 240 mm apart, with
# "LET IT SNOW" engraved filled (36 mm, serif bold) and a filled six-pointed star
# (25 / 10 mm radii) 60 mm in from each end.

units mm
thickness 6 mm

import "std/joints.aidl"

t = 6 mm
rail = 20 mm
bottom_len = 480 mm
curl_r = 75 mm
rail_start = 40 mm
post_w = 24 mm
posts_at = [52, 260, 440]
seat_l = 440 mm
seat_w = 300 mm
track = 240 mm

def runner() -> solid {
    bottom = Rectangle(bottom_left=(0, 0), width=bottom_len, height=rail)
    curl = Sector(center=(bottom_len, curl_r), radius=curl_r, inner_radius=curl_r - rail,
                  start_angle=-90 deg, end_angle=90 deg)
    top = Rectangle(bottom_left=(rail_start, 2 * curl_r - rail), width=bottom_len - rail_start, height=rail)
    tab_blank = Rectangle(bottom_left=(rail_start, 2 * curl_r), width=bottom_len - rail_start, height=t)
    for i in range(3) {
        post = Rectangle(center=(posts_at[i], curl_r), width=post_w, height=2 * curl_r - 2 * rail + 10)
        Fillet([post, bottom], 8 mm)
        Fillet([post, top], 8 mm)
    }
    Fillet([bottom.top_left, bottom.bottom_left], 8 mm)
    seat_tabs = tab_and_slot(part="tab", length=bottom_len - rail_start, thickness=t, tabs=2, tab=40 mm,
                             screw=0, cx=(bottom_len + rail_start) / 2, cy=2 * curl_r + t)
    hole dowel { c = Circle(center=(bottom_len + curl_r - rail / 2, curl_r), diameter=12) }
}

assembly sled {
    left_runner = runner()
    right_runner = runner()

    solid seat {
        body = RoundedRectangle(center=(0, 0), width=seat_l, height=seat_w, corner_radius=20)
        left_mortises = tab_and_slot(part="slot", length=seat_l, thickness=t, tabs=2, tab=40 mm, screw=0,
                                     cx=0, cy=-track / 2)
        right_mortises = tab_and_slot(part="slot", length=seat_l, thickness=t, tabs=2, tab=40 mm, screw=0,
                                      cx=0, cy=track / 2)
        drawing words {
            w = Text("LET IT SNOW", position=(0, 0), size=36, font="serif:Bold", valign="middle", fill=true)
        }
        drawing stars {
            s0 = Star(center=(-seat_l / 2 + 60, 0), points=6, outer_radius=25, inner_radius=10, fill=true)
            s1 = Star(center=(seat_l / 2 - 60, 0), points=6, outer_radius=25, inner_radius=10, fill=true)
        }
    }

    # 3D: runners stand in the planes y = -120 and y = 120, their curls to +x; the seat on top
    Place(left_runner, position=(-(bottom_len + rail_start) / 2, -track / 2 + t / 2, 0), face="front", up="up")
    Place(right_runner, position=(-(bottom_len + rail_start) / 2, track / 2 + t / 2, 0), face="front", up="up")
    Place(seat, position=(0, 0, 2 * curl_r))

    # on the sheet
    Above(right_runner, left_runner, gap=10)
    AlignLeft(right_runner, left_runner)
    RightOf(seat, left_runner, gap=10)
    AlignBottom(seat, left_runner)

    assert abs(left_runner.bb.width - 555 mm) < 0.01 mm, "runners 555 long"
    assert abs(left_runner.top.bb.top - left_runner.bottom.bb.bottom - 150 mm) < 0.01 mm, "150 high"
    assert left_runner.curl.radius == 75 mm and left_runner.curl.width == 20 mm, "curl R75, 20 wide"
    assert len(left_runner.post) == 3, "three posts"
    assert left_runner.dowel.c.diameter == 12 mm, "12 mm dowel hole"
    assert abs(left_runner.dowel.c.center.x - left_runner.curl.center.x - 65 mm) < 0.01 mm, "dowel 65 in front of the curl's centre"
    assert seat.body.bb.width == 440 mm and seat.body.bb.height == 300 mm, "seat 440 x 300"
    assert abs(seat.right_mortises.slot[0].bb.center_y - seat.left_mortises.slot[0].bb.center_y - 240 mm) < 0.01 mm, "runners 240 apart"
    assert abs(seat.stars.s0.center.x - seat.body.bb.left - 60 mm) < 0.01 mm, "stars 60 in"
    assert distance(seat.words, seat.stars) >= 5 mm, "the words clear the stars"
}
