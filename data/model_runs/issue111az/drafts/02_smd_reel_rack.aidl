# Request: a bench rack for 7-inch SMD tape reels (178 mm across, 12 mm wide), cut from
# 3 mm ply. Two side plates 140 mm deep and 145 mm tall (a 60 mm tall foot tapering up to a
# rounded top of 25 mm radius) carry an 8 mm wooden dowel in an 8.4 mm U-notch from the top,
# the dowel's centre 120 mm above the bench. The sides stand 100 mm apart inside (eight
# reels), held by two cross bars 40 mm tall, 10 mm in from the front and back edges, each
# joined to each side with two 10 mm tabs and an M3 screw in a captive nut. The front bar
# is engraved "SMD REELS", the back bar "8 mm DOWEL". The reels must clear the bars by 5 mm.

thickness 3 mm

import "std/joints.aidl"

t = 3 mm
depth = 140 mm
axle_h = 120 mm
top_r = 25 mm
inner = 100 mm
bar_h = 40 mm
bar_in = 10 mm
reel_d = 178 mm

def side_plate() -> solid {
    body = Hull(Rectangle(bottom_left=(-depth / 2, 0), width=depth, height=60 mm),
                Circle(center=(0, axle_h), radius=top_r))
    hole notch {
        u = Slot(start=(0, axle_h), end=(0, axle_h + top_r + 5 mm), width=8.4 mm, overrun=true)
    }
    front = tab_and_slot(part="slot", length=bar_h, thickness=t, tabs=2, tab=10 mm, screw=3,
                         rotation=90 deg, cx=-depth / 2 + bar_in + t / 2, cy=bar_h / 2)
    back = tab_and_slot(part="slot", length=bar_h, thickness=t, tabs=2, tab=10 mm, screw=3,
                        rotation=90 deg, cx=depth / 2 - bar_in - t / 2, cy=bar_h / 2)
}

def cross_bar(label="SMD") -> solid {
    body = Rectangle(center=(0, 0), width=inner + 2 * t, height=bar_h)
    lt = tab_and_slot(part="tab", length=bar_h, thickness=t, tabs=2, tab=10 mm, screw=3,
                      rotation=90 deg, cx=-(inner / 2 + t), cy=0 mm)
    rt = tab_and_slot(part="tab", length=bar_h, thickness=t, tabs=2, tab=10 mm, screw=3,
                      rotation=-90 deg, cx=inner / 2 + t, cy=0 mm)
    drawing mark {
        word = Text(label, position=(0, 0), size=8 mm, valign="middle", max_width=70 mm)
    }
}

assembly reel_rack {
    left = side_plate()
    right = side_plate()
    front_bar = cross_bar(label="SMD REELS")
    back_bar = cross_bar(label="8 mm DOWEL")

    # flat on the sheet
    RightOf(right, left, gap=5 mm)
    Above(front_bar, left, gap=5 mm)
    AlignLeft(front_bar, left)
    RightOf(back_bar, front_bar, gap=5 mm)
    AlignBottom(back_bar, front_bar)

    # in 3D: sides stand across the rack (their x: depth, y: up, thickness: along the dowel)
    Place(left, position=(-(inner / 2 + t), 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(inner / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(front_bar, position=(0, -depth / 2 + bar_in + t, bar_h / 2), rotation=(90 deg, 0, 0))
    Place(back_bar, position=(0, depth / 2 - bar_in, bar_h / 2), rotation=(90 deg, 0, 0))

    # the request's numbers
    assert left.body.bb.width == 140 mm, "sides 140 deep"
    assert left.body.bb.height == 145 mm, "sides 145 tall"
    assert left.notch.u.start.y - left.body.bb.bottom == 120 mm, "dowel centre 120 up"
    assert left.notch.u.width == 8.4 mm, "8.4 mm notch"
    assert front_bar.body.bb.width - 2 * t == 100 mm, "100 mm between the sides"
    assert front_bar.body.bb.height == 40 mm, "bars 40 tall"
    # (a slot half's box includes its screw's clearance hole: measure to the slots' middle)
    assert left.front.bb.center_x - left.body.bb.left == 10 mm + t / 2, "front bar 10 in"
    assert left.body.bb.right - left.back.bb.center_x == 10 mm + t / 2, "back bar 10 in"
    # the reel (radius 89) clears the inner top corner of each bar by 5 mm
    assert sqrt((left.notch.u.start.x - left.front.bb.right) ** 2 +
                (left.notch.u.start.y - left.front.bb.top) ** 2) >= reel_d / 2 + 5 mm,
           "reels clear the front bar"
    assert sqrt((left.back.bb.left - left.notch.u.start.x) ** 2 +
                (left.notch.u.start.y - left.back.bb.top) ** 2) >= reel_d / 2 + 5 mm,
           "reels clear the back bar"
}
