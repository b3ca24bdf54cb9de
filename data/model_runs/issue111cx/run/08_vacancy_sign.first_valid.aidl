# Request: a "NO VACANCY" sign for the guest-house window, 3 mm ply, four layers held by
# 4 countersunk M4 screws 10 mm in from the corners (8 mm heads).
# - Front 320 x 120 mm, 8 mm rounded corners: "VACANCY" cut through as bold stencil
#   letters 30 mm high (at most 170 mm long), centred 52 mm right of the middle; on the
#   left a 50 x 28 mm window (4 mm corners) through which a turning wheel shows "NO".
# - Wheel: 100 mm across, turning on an M4 screw 100 mm left of the middle and 18 mm
#   below it, "NO" engraved filled 18 mm high, 26 mm above the pivot (behind the window);
#   36 grip notches (4 mm) round its rim; it sticks out below the sign's bottom edge so a
#   thumb turns it half a turn to hide "NO".
# - Spacer (the wheel's layer): the same outline, a 104 mm cavity round the wheel, open at
#   the bottom, and a big opening behind the letters (from 40 mm left of the middle to
#   15 mm from the right edge, 15 mm from top and bottom) so the back shows through them.
# - Back: the same outline; two 6 mm holes for the suction hooks, 100 mm either side of the
#   middle and 8 mm from the top edge, through the front, spacer and back.
import "std/fasteners.aidl"

thickness 3 mm

sign_w = 320 mm
sign_h = 120 mm
corner_r = 8 mm
screw_in = 10 mm
px = -100 mm                 # the wheel's pivot
py = -18 mm
wheel_d = 100 mm
no_r = 26 mm                 # "NO" and the window above the pivot

def layer() -> solid {
    plate = RoundedRectangle(center=(0, 0), width=sign_w, height=sign_h, corner_radius=corner_r)
    h = clearance_hole(size=4)
    corners = CornerPattern(h, plate, inset=screw_in)
    for s in [-1, 1] {
        hole hook { c = Circle(center=(s * 100 mm, sign_h / 2 - 8 mm), diameter=6) }
    }
}

assembly sign {
    solid front {
        base = layer()
        hole window {
            w = RoundedRectangle(center=(px, py + no_r), width=50, height=28, corner_radius=4)
        }
        hole word {
            letters = Text("VACANCY", position=(52, 0), size=30, font="sans:Bold", stencil=true,
                           valign="middle", max_width=170)
        }
        pivot = clearance_hole(size=4, cx=px, cy=py)
        Countersink(base.corners, diameter=8 mm)
        Countersink(pivot, diameter=8 mm)
    }

    solid spacer {
        base = layer()
        hole cavity { c = Circle(center=(px, py), diameter=wheel_d + 4 mm) }
        hole show_through {
            r = Rectangle(bottom_left=(-40, -sign_h / 2 + 15 mm), width=sign_w / 2 - 15 mm + 40 mm,
                          height=sign_h - 30 mm)
        }
    }

    solid wheel {
        disc = Circle(center=(px, py), diameter=wheel_d)
        axle = clearance_hole(size=4, cx=px, cy=py)
        for k in range(36) {
            hole notch {
                c = Circle(center=(px + wheel_d / 2 * cos(k * 10 deg), py + wheel_d / 2 * sin(k * 10 deg)),
                           diameter=4)
            }
        }
        drawing no {
            word = Text("NO", position=(px, py + no_r), size=18, font="sans:Bold", valign="middle",
                        fill=true)
        }
    }

    solid back {
        base = layer()
        pivot = clearance_hole(size=4, cx=px, cy=py)
    }

    # flat on the sheet
    Below(spacer, front, gap=8)
    AlignLeft(spacer, front)
    Below(back, spacer, gap=8)
    AlignLeft(back, spacer)
    RightOf(wheel, front, gap=8)
    AlignTop(wheel, front)

    # 3D: front at y 0..-3, wheel and spacer behind it, back last; the sign centred 60 mm up
    Place(front, position=(0, 0, sign_h / 2), face="front", up="up")
    Place(spacer, position=(0, 3, sign_h / 2), face="front", up="up")
    Place(wheel, position=(0, 3, sign_h / 2), face="front", up="up")
    Place(back, position=(0, 6, sign_h / 2), face="front", up="up")

    # the request's numbers
    assert front.base.plate.width == 320 mm and front.base.plate.height == 120 mm, "320 x 120"
    assert front.base.corners[0].c.center.x - front.base.plate.bb.left == 10 mm, "screws 10 mm in"
    assert front.window.w.center.y - wheel.disc.center.y == 26 mm, "window 26 mm above the pivot"
    assert (distance(wheel.disc.center, front.window.w.bb.top_left) <= wheel_d / 2 - 2 mm),
        "only the wheel shows through the window"
    assert spacer.base.plate.bb.bottom - wheel.disc.bb.bottom >= 6 mm, "the wheel sticks out below"
    assert front.word.letters.bb.width <= 170 mm, "VACANCY at most 170 mm long"
    assert front.word.letters.bb.left >= spacer.show_through.r.bb.left + 3 mm and
        front.word.letters.bb.right <= spacer.show_through.r.bb.right - 3 mm, "letters over the opening"
    assert wheel.disc.center.x == -100 mm and wheel.disc.center.y == -18 mm, "pivot 100 left, 18 down"
    assert len(wheel.notch) == 36, "36 grip notches"
}
