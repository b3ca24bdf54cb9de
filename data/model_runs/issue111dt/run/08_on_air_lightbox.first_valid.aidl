# Request: an "ON AIR" light box for my podcast studio door, in 3 mm ply: a closed
# finger-jointed box 240 x 60 x 100 mm (wide x deep x tall), 15 mm fingers. The words ON AIR
# cut right through the front as bold stencil letters (their counters held by bridges), at
# most 200 mm wide and 50 mm tall, centred. Behind the front, a 3 mm opal acrylic diffuser
# 230 x 90 mm glued to the front's inside. An LED strip inside lights it. The back gets two
# keyholes 150 mm apart, 25 mm below its top edge, and an 8 mm hole for the USB lead 20 mm
# from its right end and 15 mm up. A 12 mm hole for a push switch in the top, 20 mm from its
# right end, centred front to back.

import "std/joints.aidl"
import "std/plates.aidl"

units mm
thickness 3 mm

t = 3 mm

assembly on_air {
    box = finger_box(length=240 mm, depth=60 mm, height=100 mm, thickness=t, finger=15 mm)

    hole letters {
        word = Text("ON AIR", position=(0, 0), size=50, font="sans:Bold", valign="middle",
                    stencil=true, max_width=200 mm)
    }
    CenterInside(letters, box.front)
    CutInto(letters, box.front)

    hole mount {
        a = keyhole(cx=-75 mm, cy=0 mm)
        b = keyhole(cx=75 mm, cy=0 mm)
    }
    AlignCenterX(mount, box.back)
    mount.a.head_hole.center.y == box.back.bb.top - 25 mm
    CutInto(mount, box.back)

    hole usb {
        c = Circle(center=(0, 0), diameter=8)
    }
    usb.c.center.x == box.back.bb.right - 20 mm
    usb.c.center.y == box.back.bb.bottom + 15 mm
    CutInto(usb, box.back)

    hole switch {
        c = Circle(center=(0, 0), diameter=12)
    }
    switch.c.center.x == box.lid.bb.right - 20 mm
    AlignCenterY(switch, box.lid)
    CutInto(switch, box.lid)

    # the diffuser, drawn as seen from the front (y is height above the box's underside)
    solid diffuser {
        thickness 3 mm
        sheet = Rectangle(center=(0, 50), width=230, height=90)
    }
    RightOf(diffuser, box, gap=10)
    AlignBottom(diffuser, box)
    # against the front's inside face (the front's outer face is y = -30)
    Place(diffuser, position=(0, -30 + t + 3 mm, 0), face="front", up="up")

    # the request's numbers
    assert box.length == 240 mm and box.depth == 60 mm and box.height == 100 mm, "box size"
    assert letters.bb.width <= 200 mm and letters.bb.height <= 50 mm + 5 mm, "letters fit"
    assert mount.b.head_hole.center.x - mount.a.head_hole.center.x == 150 mm,
        "keyholes 150 apart"
    assert diffuser.sheet.width == 230 mm and diffuser.sheet.height == 90 mm, "diffuser size"
    # the diffuser fits inside between the side walls and between bottom and top
    assert diffuser.sheet.width <= 240 mm - 2 * t and diffuser.sheet.height <= 100 mm - 2 * t,
        "diffuser fits inside"
}
