# Request (workshop): a flip stop for the T-track on top of my mitre-saw fence, all 6 mm birch ply.
# - Base 100 x 60 mm, corners r3, lies on the fence top, its front edge flush with the fence face.
#   Two 6.5 mm holes for M6 T-bolts, 60 mm apart, on a line 30 mm from the front edge.
# - Two cheeks 60 mm long x 51 mm tall stand on the base, glued into it by two 10 mm tabs each
#   along the 40 mm of their bottom edge that sits on the base; they overhang the front edge by
#   20 mm, and the overhang reaches down over the base's front edge as a 6 mm lip.
#   Their inner faces are 6.5 mm apart (a 6 mm arm + 0.5 mm play).
#   A 6.5 mm pivot hole in each, 8 mm from the cheek's front edge, 30 mm above the base top.
# - The flip arm, 20 x 110 mm, top corners r10, hangs between the cheeks on an M6 bolt; its
#   pivot hole 12 mm below its top; "STOP" engraved along its face. It must clear the base's
#   front edge by 2 mm.
import "std/joints.aidl"

thickness 6 mm

T = 6 mm            # ply
BOLT = 6.5 mm       # M6 clearance
PLAY = 0.25 mm      # each side of the arm
CHEEK_X = T / 2 + PLAY + T / 2   # cheek mid-plane from the arm's mid-plane

# cheek drawn in its own frame: u = depth (world y, front edge of base at u = 0), v = height (z)
def cheek() -> solid {
    plate = Rectangle(bottom_left=(-20, 0), width=60, height=51)
    tabs = tab_and_slot(part="tab", length=40 mm, thickness=T, tabs=2, tab=10 mm, screw=0,
                        rotation=180 deg, cx=20 mm, cy=0 mm)
    hole pivot {
        c = Circle(center=(-12, T + 30), diameter=BOLT)
    }
}

assembly flip_stop {
    solid base {
        body = RoundedRectangle(bottom_left=(-50, 0), width=100, height=60, corner_radius=3)
        hole tbolts {
            a = Circle(center=(-30, 30), diameter=BOLT)
            b = Circle(center=(30, 30), diameter=BOLT)
        }
        slot_r = tab_and_slot(part="slot", length=40 mm, thickness=T, tabs=2, tab=10 mm, screw=0,
                              rotation=90 deg, cx=CHEEK_X, cy=20 mm)
        slot_l = tab_and_slot(part="slot", length=40 mm, thickness=T, tabs=2, tab=10 mm, screw=0,
                              rotation=90 deg, cx=-CHEEK_X, cy=20 mm)
        assert tbolts.b.center.x - tbolts.a.center.x == 60 mm, "T-bolts 60 mm apart"
        assert tbolts.a.center.y - body.bb.bottom == 30 mm, "T-bolts 30 mm from the front edge"
    }

    left = cheek()
    right = cheek()

    solid arm {
        body = RoundedRectangle(bottom_left=(-22, T + 30 + 12 - 110), width=20, height=110,
                                corner_radii=[10, 10, 0, 0])
        hole pivot {
            c = Circle(center=(-12, T + 30), diameter=BOLT)
        }
        drawing label {
            word = Text("STOP", position=(-12, -20), size=10, valign="middle", rotation=90 deg)
        }
        assert body.bb.top - pivot.c.center.y == 12 mm, "pivot 12 mm below the arm's top"
    }

    # request's numbers, in each part's own frame
    assert left.pivot.c.center.x - left.plate.bb.left == 8 mm, "pivot 8 mm from the cheek's front"
    assert left.pivot.c.center.y - T == 30 mm, "pivot 30 mm above the base top"
    assert arm.body.bb.right <= -2 mm, "arm clears the base's front edge by 2 mm"
    assert 2 * CHEEK_X - T == 6.5 mm, "cheeks' inner faces 6.5 mm apart"

    # 3D: cheek and arm frames (u, v, w) -> world (w, u, v)
    Place(left, position=(-CHEEK_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(right, position=(CHEEK_X - T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))
    Place(arm, position=(-T / 2, 0, 0), rotation=(90 deg, 0, 90 deg))

    # flat on the sheet: side by side
    RightOf(left, base, gap=5)
    RightOf(right, left, gap=5)
    RightOf(arm, right, gap=5)
    AlignBottom(left, base)
    AlignBottom(right, base)
    AlignBottom(arm, base)
}
