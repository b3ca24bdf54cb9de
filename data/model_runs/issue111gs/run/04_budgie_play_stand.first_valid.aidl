# Request: a tabletop play stand for our two budgies, 6 mm birch ply, 10 mm hardwood
# dowels for perches and ladder rungs.
# - A finger-jointed open tray 300 x 200 mm, 40 mm tall (outside), to catch the mess;
#   "KIWI & MANGO" engraved in filled bold letters 14 mm tall, centred on its front.
# - Two posts 80 mm wide standing 250 mm above the tray's floor, round-topped (R40),
#   at x = -110 and +110 mm (centres), each fixed through the tray's bottom by two
#   20 mm tenons flush with its underside.
# - Each post has 10.2 mm dowel holes (for 10 mm dowels) at 40, 75 and 110 mm above
#   the floor (ladder rungs) and at 185 and 225 mm (perches).
# - Between the posts a seed-cup platform 80 mm deep, its underside 140 mm above the
#   floor, fixed by one 40 mm through-tenon into each post (flush with the posts'
#   outer faces), with two 55 mm holes for seed cups, 90 mm apart, centred.
# Slots 0.1 mm over for glue.

units mm
thickness 6 mm
import "std/joints.aidl"

def post() -> solid {
    # seen from the right end: x across the post (the stand's depth), y up from the
    # tray bottom's underside (the tray floor is y = 6)
    body = Rectangle(center=(0, 113), width=80, height=226)
    cap = Circle(center=(0, 216), radius=40)
    hole dowels {
        for h in [40, 75, 110, 185, 225] {
            c = Circle(center=(0, h + 6), diameter=10.2)
        }
    }
    feet = tab_and_slot(part="tab", length=80, thickness=6, tabs=2, tab=20, screw=0,
                        rotation=180 deg, cx=0, cy=0)
    shelf = tab_and_slot(part="slot", length=80, thickness=6, tabs=1, tab=40, screw=0,
                         clearance=0.1, cx=0, cy=6 + 140 + 3)
}

assembly play_stand {
    box = finger_box(length=300, depth=200, height=40, thickness=6, finger=15, closed=false)

    drawing name {
        t = Text("KIWI & MANGO", position=(0, 0), size=14, font="sans:Bold", valign="middle",
                 fill=true)
    }
    CenterInside(name, box.front)
    CutInto(name, box.front)

    mortise_r = tab_and_slot(part="slot", length=80, thickness=6, tabs=2, tab=20, screw=0,
                             clearance=0.1, rotation=90 deg, cx=110, cy=0)
    mortise_l = tab_and_slot(part="slot", length=80, thickness=6, tabs=2, tab=20, screw=0,
                             clearance=0.1, rotation=90 deg, cx=-110, cy=0)
    CutInto(mortise_r, box.bottom)
    CutInto(mortise_l, box.bottom)

    post_r = post()
    post_l = post()

    solid platform {
        slab = Rectangle(center=(0, 0), width=226, height=80)
        end_l = tab_and_slot(part="tab", length=80, thickness=6, tabs=1, tab=40, screw=0,
                             rotation=90 deg, cx=-113, cy=0)
        end_r = tab_and_slot(part="tab", length=80, thickness=6, tabs=1, tab=40, screw=0,
                             rotation=-90 deg, cx=113, cy=0)
        hole cups {
            a = Circle(center=(-45, 0), diameter=55)
            b = Circle(center=(45, 0), diameter=55)
        }
    }

    # flat on the sheet, beside and under the box's net
    RightOf(post_r, box, gap=10)
    AlignTop(post_r, box)
    RightOf(post_l, post_r, gap=10)
    AlignTop(post_l, post_r)
    Below(platform, box, gap=10)
    AlignLeft(platform, box)

    # assembled: the box stands on z = 0 centred on x = y = 0
    Place(post_r, position=(107, 0, 0), face="right", up="up")
    Place(post_l, position=(-113, 0, 0), face="right", up="up")
    Place(platform, position=(0, 0, 146), face="up", up="back")

    # the request's numbers
    assert post_r.cap.bb.top - 6 mm == 250 mm, "posts 250 above the floor"
    assert post_r.body.width == 80 mm and post_r.cap.radius == 40 mm, "posts 80 wide, R40 top"
    assert len(post_r.dowels.c) == 5, "five dowel holes"
    assert post_r.dowels.c[0].diameter == 10.2 mm, "10.2 mm holes"
    assert post_r.dowels.c[0].center.y - 6 mm == 40 mm and post_r.dowels.c[2].center.y - 6 mm == 110 mm,
        "rungs 40 ... 110 up"
    assert post_r.dowels.c[4].center.y - 6 mm == 225 mm, "top perch 225 up"
    assert post_r.shelf.slot[0].bb.bottom - 6 mm >= 139.9 mm and post_r.shelf.slot[0].bb.bottom - 6 mm <= 140 mm,
        "platform underside 140 up"
    assert platform.slab.height == 80 mm, "platform 80 deep"
    assert platform.cups.b.center.x - platform.cups.a.center.x == 90 mm, "cups 90 apart"
    assert platform.cups.a.diameter == 55 mm, "55 mm cup holes"
    assert platform.slab.width == 2 * 113 mm, "tenons flush with the posts' outer faces"
    assert mortise_r.slot[0].bb.center_x - mortise_l.slot[0].bb.center_x == 220 mm, "posts 220 apart"
    assert name.t.size == 14 mm, "name 14 mm"
    assert post_r.dowels.c[2].bb.top + 3 mm <= post_r.shelf.slot[0].bb.bottom, "rungs clear of the platform"
}
