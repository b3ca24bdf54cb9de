# Request: a cat cube (a cosy box to sleep in) from 6 mm birch ply, finger-jointed, 400 long
# x 380 deep x 360 tall outside, fingers 30 mm. In the front a door shaped like a cat's head:
# a round opening 190 mm across whose bottom is 60 mm above the floor (a sill that keeps the
# blanket in), with two pointed ears (tips rounded r6) rising to 128 mm above the circle's
# centre. The cat's name MILO engraved (filled) above the door, 30 mm tall, centred 318 mm
# up. In each side a paw-print window: an oval pad 60 x 48 and four round toes 22 mm across,
# toes toward the top. In the back a round air window 100 mm across, centred.

import "std/joints.aidl"

thickness 6 mm

def paw(up=90 deg) -> hole {
    pad = Ellipse(center=(0, 0), rx=30, ry=24, rotation=up - 90 deg)
    for a in [-50, -17, 17, 50] {
        toe = Circle(center=(48 * cos(up + a * 1 deg), 48 * sin(up + a * 1 deg)), diameter=22)
    }
}

assembly cat_cube {
    box = finger_box(length=400 mm, depth=380 mm, height=360 mm, thickness=6 mm,
                     finger=30 mm, closed=true, gap=10 mm)

    hole door {
        c = Circle(center=(0, 0), diameter=190)
        ear_l = Polygon([(-86.1, 40.1), (-40.1, 86.1), (-85, 128)])
        ear_r = Polygon([(86.1, 40.1), (85, 128), (40.1, 86.1)])
        Fillet([ear_l.points[2], ear_r.points[1]], 6)
    }
    AlignCenterX(door, box.front)
    door.c.center.y == box.front.bb.bottom + 155
    CutInto(door, box.front)

    drawing name {
        t = Text("MILO", position=(0, 0), size=30, font="serif:Bold", valign="middle",
                 fill=true)
    }
    AlignCenterX(name, box.front)
    name.t.position.y == box.front.bb.bottom + 318
    CutInto(name, box.front)

    paw_l = paw(up=180 deg)
    CenterInside(paw_l, box.left)
    CutInto(paw_l, box.left)
    paw_r = paw(up=0 deg)
    CenterInside(paw_r, box.right)
    CutInto(paw_r, box.right)

    hole air {
        c = Circle(center=(0, 0), diameter=100)
    }
    CenterInside(air, box.back)
    CutInto(air, box.back)

    assert box.front.bb.width == 400 mm and box.front.bb.height == 360 mm, "400 long, 360 tall"
    assert box.left.bb.height == 380 mm, "380 deep"
    assert door.c.diameter == 190 mm, "door 190 across"
    assert door.c.bb.bottom - box.front.bb.bottom == 60 mm, "sill 60 above the floor"
    assert door.bb.top - door.c.center.y <= 128 mm, "ears up to 128 above the centre"
    assert name.t.position.y - box.front.bb.bottom == 318 mm, "name centred 318 up"
    assert name.t.size == 30 mm, "name 30 tall"
    assert air.c.diameter == 100 mm, "air window 100"
    assert len(paw_l.toe) == 4, "four toes"
}
