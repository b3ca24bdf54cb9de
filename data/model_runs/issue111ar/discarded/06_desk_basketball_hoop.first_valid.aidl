# Request (sport): a desk basketball hoop for a 40 mm ping-pong ball, 3 mm plywood, 3 parts.
# Backboard: 180 x 120 mm, 4 mm corner radii, standing on two 20 mm tabs (3 mm long, below the
# 120 mm) glued into mortises in the base; "HOOPS" cut through as 14 mm bold stencil letters,
# centred, their top 10 mm below the board's top; an engraved 60 x 45 shooter's square, centred,
# its bottom edge 3 mm above the rim's mortise; the rim's mortise centred, 30 mm below the board's
# centre. Rim: a ring 60 mm outside, 50 mm inside, with twelve 1.5 mm net holes on a 55 mm circle
# (at 15, 45, 75 ... degrees), and a 24 mm wide arm whose single 14 mm tenon (3 mm long) is glued
# into the backboard's mortise; the arm's shoulders stand 45 mm from the ring's centre. Base:
# 180 x 140 mm, 4 mm corner radii, the backboard's mortises 10 mm from the back edge (to their
# middle); engraved on it a 50 wide x 56 deep lane in front of the backboard and a free-throw
# semicircle of radius 25 mm about the lane's front end. Parts laid flat, 6 mm apart.

import "std/joints.aidl"

thickness 3 mm
t = 3 mm

assembly hoop {
    solid backboard {
        body = RoundedRectangle(center=(0, 0), width=180, height=120, corner_radius=4)
        foot = Rectangle(center=(0, -60 - t / 2), width=180, height=t)
        legs = tab_and_slot(part="tab", length=180 mm, thickness=t, tabs=2, tab=20 mm, screw=0,
                            rotation=180 deg, cx=0 mm, cy=-60 mm - t)
        mortise = tab_and_slot(part="slot", length=24 mm, thickness=t, tabs=1, tab=14 mm,
                               screw=0, cx=0 mm, cy=-30 mm)
        hole name {
            word = Text("HOOPS", (0, 50), size=14, font="sans:Bold", stencil=true, valign="top")
        }
        drawing square {
            s = Rectangle(center=(0, -30 + t / 2 + 3 + 22.5), width=60, height=45)
        }
        Fixed(body)
    }
    solid rim {
        ring = Circle(center=(0, 0), diameter=60)
        arm = Rectangle(center=(0, 36.5), width=24, height=23)
        hole bore {
            c = Circle(center=(0, 0), diameter=50)
        }
        hole net {
            c = Circle(center=(27.5 * cos(15 deg), 27.5 * sin(15 deg)), diameter=1.5)
        }
        holes = CircularPattern(net, 12, ring.center)
        tenon = tab_and_slot(part="tab", length=24 mm, thickness=t, tabs=1, tab=14 mm, screw=0,
                             cx=0 mm, cy=48 mm)
    }
    solid base {
        body = RoundedRectangle(center=(0, 0), width=180, height=140, corner_radius=4)
        mortises = tab_and_slot(part="slot", length=180 mm, thickness=t, tabs=2, tab=20 mm,
                                screw=0, cx=0 mm, cy=60 mm)
        drawing court {
            lane = Rectangle(center=(0, 60 - t / 2 - 28), width=50, height=56)
            free_throw = Arc(center=(0, 60 - t / 2 - 56), radius=25, start_angle=180, end_angle=360)
        }
        Fixed(body)
    }

    RightOf(base, backboard, gap=6)
    AlignTop(base, backboard)
    RightOf(rim, base, gap=6)
    AlignTop(rim, base)

    assert abs(backboard.body.width - 180 mm) < 0.01 mm and abs(backboard.body.height - 120 mm) < 0.01 mm, "backboard 180 x 120"
    assert abs(backboard.bb.bottom - (backboard.body.bb.bottom - 3 mm)) < 0.01 mm, "tabs 3 mm below"
    assert abs(backboard.body.bb.top - backboard.name.bb.top - 10 mm) < 0.5 mm, "HOOPS 10 mm below the top"
    assert abs(backboard.square.s.width - 60 mm) < 0.01 mm and abs(backboard.square.s.height - 45 mm) < 0.01 mm, "60 x 45 square"
    assert abs(backboard.square.s.bb.bottom - backboard.mortise.bb.top - 3 mm) < 0.01 mm, "square 3 above the mortise"
    assert abs(backboard.mortise.bb.center_y - backboard.body.center.y + 30 mm) < 0.01 mm, "mortise 30 below the centre"
    assert abs(backboard.mortise.bb.width - 14 mm) < 0.01 mm, "14 mm mortise"
    assert abs(rim.ring.diameter - 60 mm) < 0.01 mm and abs(rim.bore.c.diameter - 50 mm) < 0.01 mm, "60 / 50 ring"
    assert len(rim.holes) == 12, "twelve net holes"
    assert abs(rim.arm.width - 24 mm) < 0.01 mm, "24 mm arm"
    assert abs(rim.bb.top - rim.ring.center.y - 48 mm) < 0.01 mm, "tenon tip 45 + 3 from the ring's centre"
    assert abs(base.body.width - 180 mm) < 0.01 mm and abs(base.body.height - 140 mm) < 0.01 mm, "base 180 x 140"
    assert abs(base.body.bb.top - base.mortises.bb.center_y - 10 mm) < 0.01 mm, "mortises 10 from the back"
    assert abs(base.court.lane.width - 50 mm) < 0.01 mm and abs(base.court.lane.height - 56 mm) < 0.01 mm, "50 x 56 lane"
}
