# Request: a gift box for a fountain pen, cut from 3 mm walnut ply. Outside 50 mm wide,
# 180 mm long and 35 mm high, finger-jointed, with a lid that slides out lengthwise. The lid
# carries the name "Eleanor" engraved filled in an italic serif, 12 mm letters, along its
# length in the middle, and three 12 x 4 mm thumb-grip slots (8 mm apart) across its front end,
# the nearest 12 mm from that end. A loose 3 mm insert lies on the floor between the lid's
# liners, 0.5 mm smaller than the space, with a 150 x 14 mm pen channel and a 22 mm thumb
# hole over the channel's middle to lift the pen out.

import "std/boxes.aidl"

thickness 3 mm

param box_w = 50 mm, min = 40, max = 80
param box_l = 180 mm, min = 150, max = 220
param box_h = 35 mm, min = 25, max = 50

t = 3 mm

assembly gift {
    # length runs across (left to right), width front to back: the lid slides along the 180
    box = sliding_lid_box(length=box_w, width=box_l, height=box_h, thickness=t, finger=10 mm)

    drawing name {
        n = Text("Eleanor", position=(0, 0), size=12, rotation=90 deg, font="serif:Italic",
                 valign="middle", fill=true)
    }
    CenterInside(name, box.lid)
    CutInto(name, box.lid)

    hole grip {
        for i in range(3) {
            s = Slot(center=(0, i * 8), length=12, width=4)
        }
    }
    AlignCenterX(grip, box.lid)
    grip.s[0].center.y == box.lid.bb.bottom + 12 mm
    CutInto(grip, box.lid)

    solid insert {
        card = Rectangle(center=(0, 0), width=box_w - 4 * t - 0.5 mm, height=box_l - 2 * t - 0.5 mm)
        hole channel {
            pen = Slot(center=(0, 0), length=150, width=14, rotation=90 deg)
            thumb = Circle(center=(0, 0), diameter=22)
        }
    }
    RightOf(insert, box, gap=8)
    AlignBottom(insert, box)
    Place(insert, position=(0, 0, t))

    assert insert.card.bb.width == 50 mm - 12 mm - 0.5 mm, "insert 0.5 under the space between the liners"
    assert insert.channel.pen.length == 150 mm and insert.channel.pen.width == 14 mm, "pen channel 150 x 14"
    assert grip.s[2].center.y - grip.s[0].center.y == 16 mm, "three slots 8 apart"
    assert box.width == 180 mm and box.length == 50 mm and box.height == 35 mm, "outside 50 x 180 x 35"
}
