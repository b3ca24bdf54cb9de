# Request: a fingerpost for our allotment site, from 12 mm exterior ply, all in one plane.
# The post is 100 mm wide and 1000 mm tall to the tip of a 40 mm pointed top; its foot goes
# into a metal post spike, bolted through two 8.5 mm holes 40 and 120 mm up. "PLOT 14"
# engraved filled up the post, 40 mm high, centred 500 mm up. Three arrow arms 70 mm high,
# reaching 360 mm from the post's edge to a 35 mm point: "POND 35 m" to the left and
# "VEG PATCH 20 m" to the right, both centred 860 mm up, and "SHED 15 m" to the right
# 760 mm up; their words engraved filled, 28 mm high at most, 15 mm clear of each end.
# Each arm hangs on the post's edge by a glued sliding dovetail: two tails 12 mm deep over
# the arm's full height, 0.1 mm clearance. It must fit the 1300 x 900 mm laser bed.

import "std/joints.aidl"

thickness 12 mm

post_w = 100 mm
arm_h = 70 mm
reach = 360 mm
tip = 35 mm
dt = 12 mm

def arm(label="", dir=1) -> solid {
    body = Polygon([(-dir * dt, -arm_h / 2), (dir * (reach - tip), -arm_h / 2), (dir * reach, 0 mm),
                    (dir * (reach - tip), arm_h / 2), (-dir * dt, arm_h / 2)])
    tails = dovetail(part="tail", length=arm_h, depth=dt, tails=2, clearance=0.1 mm,
                     rotation=dir * 90 deg, cx=0 mm, cy=0 mm)
    drawing words {
        t = Text(label, position=(dir * (reach - tip) / 2, 0 mm), size=28, font="sans:Bold",
                 valign="middle", fill=true, max_width=reach - tip - 30 mm)
    }
}

assembly fingerpost {
    solid post {
        body = Polygon([(-50, 0), (50, 0), (50, 960), (0, 1000), (-50, 960)])
        pond_socket = dovetail(part="socket", length=arm_h, depth=dt, tails=2, clearance=0.1 mm,
                               rotation=-90 deg, cx=-post_w / 2, cy=860 mm)
        veg_socket = dovetail(part="socket", length=arm_h, depth=dt, tails=2, clearance=0.1 mm,
                              rotation=90 deg, cx=post_w / 2, cy=860 mm)
        shed_socket = dovetail(part="socket", length=arm_h, depth=dt, tails=2, clearance=0.1 mm,
                               rotation=90 deg, cx=post_w / 2, cy=760 mm)
        hole spike {
            low = Circle(center=(0, 40), diameter=8.5)
            high = Circle(center=(0, 120), diameter=8.5)
        }
        drawing plot {
            t = Text("PLOT 14", position=(0, 500), size=40, font="sans:Bold", rotation=90,
                     valign="middle", fill=true)
        }
    }

    pond = arm(label="POND 35 m", dir=-1)
    veg = arm(label="VEG PATCH 20 m", dir=1)
    shed = arm(label="SHED 15 m", dir=1)

    Place(post, position=(0, 0, 0), face="front", up="up")
    # in the post's own plane (z = 0 in its frame), each joint line on the post's edge
    Place(pond, on=post, position=(-post_w / 2, 860, 0))
    Place(veg, on=post, position=(post_w / 2, 860, 0))
    Place(shed, on=post, position=(post_w / 2, 760, 0))

    # flat on the sheet: the arms in a column beside the post
    RightOf(pond, post, gap=10)
    AlignTop(pond, post)
    Below(veg, pond, gap=10)
    AlignLeft(veg, pond)
    Below(shed, veg, gap=10)
    AlignLeft(shed, veg)

    assert post.body.bb.width == 100 mm and post.body.bb.height == 1000 mm
    assert post.body.bb.top - 40 mm == 960 mm, "a 40 mm pointed top"
    assert post.spike.low.center.y - post.body.bb.bottom == 40 mm
    assert post.spike.high.center.y - post.body.bb.bottom == 120 mm
    assert post.plot.t.size == 40 mm
    assert veg.body.bb.height == 70 mm
    assert veg.body.bb.right - 0 mm == 360 mm, "reach from the post's edge"
    assert veg.words.t.size <= 28 mm and pond.words.t.size <= 28 mm and shed.words.t.size <= 28 mm
    assert veg.words.bb.left >= 15 mm and veg.words.bb.right <= 360 mm - 35 mm - 15 mm
    assert pond.words.bb.right <= -15 mm and pond.words.bb.left >= -360 mm + 35 mm + 15 mm
    # each part fits the 1300 x 900 bed, the post lying along its long side
    assert max(post.bb.width, post.bb.height) <= 1300 mm and min(post.bb.width, post.bb.height) <= 900 mm, "fits the laser bed"
    assert veg.bb.width <= 1300 mm and veg.bb.height <= 900 mm
}
