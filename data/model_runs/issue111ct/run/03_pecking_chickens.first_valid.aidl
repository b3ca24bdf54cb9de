# Request: the old folk toy "pecking hens" in 6 mm ply. A round paddle 200 mm across with a
# 150 x 32 mm handle (rounded end, 8 mm hanging hole 15 mm from its end); three hens stand on
# it 60 mm from the centre at 90, 210 and 330 degrees, each facing the centre, glued by a
# 10 mm tenon (one tab) into a mortise. Each hen's head and neck is a separate piece that
# pivots on a 3 mm dowel through a 3.4 mm hole (body hole 3.1 mm, a press fit for the dowel)
# 12 mm in front of and 42 mm above the foot's middle; a string from a 2 mm hole in the neck
# drops through a 4 mm hole in the paddle to a 40 mm wooden weight disc (4 mm centre hole)
# below. Swinging the paddle makes the hens peck. Engraved: a ring of 7 seeds at the centre
# and an eye on each head.

import "std/joints.aidl"

thickness 6 mm

param t = 6 mm, min = 4 mm, max = 7 mm
hen_r = 60 mm
angles = [90 deg, 210 deg, 330 deg]
pivot = (12, 42)          # the head's pivot in the body's frame (foot middle at (0, 0))
string_at = (7, 9)        # the string hole in the head's frame (pivot at (0, 0))

def hen_body() -> solid {
    leg = Rectangle(bottom_left=(-8, 0), width=16, height=20)
    body = Ellipse(center=(-5, 35), rx=28, ry=20)
    tail = Polygon([(-20, 45), (-42, 70), (-30, 40)])
    foot = tab_and_slot(part="tab", length=16 mm, thickness=t, tabs=1, tab=10 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole pin { c = Circle(center=pivot, diameter=3.1) }
    Fixed(body)
    Fixed(pin)
}

def hen_head() -> solid {
    neck = Slot(start=(0, 0), end=(14, 18), width=10)
    head = Circle(center=(16, 22), radius=9)
    beak = Polygon([(23, 25), (33, 21), (23, 17)])
    comb1 = Circle(center=(11, 31), radius=3.5)
    comb2 = Circle(center=(16, 33), radius=3.5)
    comb3 = Circle(center=(21, 31), radius=3.5)
    counter = Slot(start=(0, 0), end=(-22, -4), width=9)
    hole pin { c = Circle(center=(0, 0), diameter=3.4) }
    hole string { c = Circle(center=string_at, diameter=2) }
    drawing eye { e = Circle(center=(19, 24), radius=1.5, fill=true) }
    Fixed(neck)
    Fixed(head)
    Fixed(pin)
    Fixed(string)
    Fixed(eye)
}

assembly toy {
    solid paddle {
        disc = Circle(center=(0, 0), diameter=200)
        handle = RoundedRectangle(center=(0, -170), width=32, height=150, corner_radius=16)
        hole hang { c = Circle(center=(0, -230), diameter=8) }
        for a in angles {
            mortise = tab_and_slot(part="slot", length=16 mm, thickness=t, tabs=1, tab=10 mm,
                                   screw=0, rotation=a, cx=hen_r * cos(a), cy=hen_r * sin(a))
            # the hen faces the centre: along d = -(cos a, sin a); its head lies on the side
            # f = (-sin a, cos a), one thickness over
            hole string_hole {
                c = Circle(center=(hen_r * cos(a) - (pivot[0] + string_at[0]) * cos(a) - t * sin(a),
                                   hen_r * sin(a) - (pivot[0] + string_at[0]) * sin(a) + t * cos(a)),
                           diameter=4)
            }
        }
        drawing seeds {
            for k in range(7) {
                s = Ellipse(center=(14 * cos(k * 360 deg / 7), 14 * sin(k * 360 deg / 7)),
                            rx=3, ry=1.5, rotation=k * 360 deg / 7, fill=true)
            }
        }
        Fixed(disc)
        Fixed(handle)
        Fixed(hang)
        Fixed(seeds)
        assert disc.diameter == 200 mm
        assert handle.height == 150 mm and handle.width == 32 mm
        assert hang.c.center.y - handle.bb.bottom == 15 mm
        assert len(mortise) == 3 and len(string_hole) == 3
        assert len(seeds.s) == 7
    }

    solid weight {
        disc = Circle(center=(0, 0), diameter=40)
        hole bore { c = Circle(center=(0, 0), diameter=4) }
        Fixed(disc)
        Fixed(bore)
    }

    for i in range(3) {
        a = angles[i]
        hen = hen_body()
        head = hen_head()
        # on the sheet: a column of hens and heads right of the paddle
        RightOf(hen, paddle, gap=10)
        hen.bb.top == paddle.bb.top - i * 85 mm
        RightOf(head, hen, gap=10)
        AlignTop(head, hen)
        # in 3D
        Place(hen, position=(hen_r * cos(a) + t / 2 * sin(a), hen_r * sin(a) - t / 2 * cos(a), 0),
              face=(-sin(a), cos(a), 0), up="up")
        Place(head, position=(hen_r * cos(a) + t / 2 * sin(a) - pivot[0] * cos(a),
                              hen_r * sin(a) - t / 2 * cos(a) - pivot[0] * sin(a), pivot[1]),
              face=(-sin(a), cos(a), 0), up="up")
    }
    Below(weight, paddle, gap=10)
    AlignLeft(weight, paddle)
    Place(paddle, position=(0, 0, 0), face="up")
    Place(weight, position=(0, 0, -120), face="up")
    AllowOverlap(weight, paddle)

    assert len(hen) == 3 and len(head) == 3
    assert hen[0].pin.c.diameter == 3.1 mm and head[0].pin.c.diameter == 3.4 mm
    assert head[0].string.c.diameter == 2 mm and paddle.string_hole[0].c.diameter == 4 mm
    assert weight.disc.diameter == 40 mm
}
