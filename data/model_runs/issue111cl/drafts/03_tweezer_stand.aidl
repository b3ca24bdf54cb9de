# Request: a bench stand for my six electronics tweezers, from 3 mm ply. An open-ended box
# 120 mm long, 40 mm deep and 70 mm tall: a top plate with a row of six 12 x 4 mm slots
# (16 mm apart, centred) that the tweezers drop through tips-first, a bottom plate their tips
# rest on, and two end panels; the four corners finger-jointed (fingers about 8 mm). The
# tweezer type is engraved behind each slot: SS, AA, 3C, 5, 7, ESD. Front and back stay open
# so I can see the tips.

import "std/joints.aidl"

units mm
thickness 3 mm

param ply = 3 mm, min = 2 mm, max = 6 mm
param length = 120 mm, min = 90 mm, max = 200 mm
param depth = 40 mm, min = 30 mm, max = 60 mm
param height = 70 mm, min = 50 mm, max = 100 mm
param slot_pitch = 16 mm, min = 12 mm, max = 20 mm

kinds = ["SS", "AA", "3C", "5", "7", "ESD"]
count = 6

assembly tweezer_stand {
    solid top_plate {
        panel = finger_panel(width=length, height=depth, thickness=ply, finger=8 mm,
                             left="fingers", right="fingers", top="flat", bottom="flat",
                             cx=0 mm, cy=0 mm)
        hole slots {
            for i in range(count) {
                s = Slot(center=((i - (count - 1) / 2) * slot_pitch, -4), length=12, width=4,
                         rotation=90 deg)
            }
        }
        drawing labels {
            for i in range(count) {
                t = Text(kinds[i], position=((i - (count - 1) / 2) * slot_pitch, 10), size=4,
                         valign="middle")
            }
        }
    }

    solid bottom_plate {
        panel = finger_panel(width=length, height=depth, thickness=ply, finger=8 mm,
                             left="fingers", right="fingers", top="flat", bottom="flat",
                             cx=0 mm, cy=0 mm)
    }

    def end_panel() -> solid {
        panel = finger_panel(width=depth, height=height, thickness=ply, finger=8 mm,
                             left="flat", right="flat", top="slots", bottom="slots",
                             cx=0 mm, cy=0 mm)
    }
    left_end = end_panel()
    right_end = end_panel()

    # flat on the sheet: ends beside the top plate, the bottom plate below it
    Below(bottom_plate, top_plate, gap=8)
    AlignCenterX(bottom_plate, top_plate)
    LeftOf(left_end, top_plate, gap=8)
    RightOf(right_end, top_plate, gap=8)
    AlignTop(left_end, top_plate)
    AlignTop(right_end, top_plate)

    # assembled: x along the length, y the depth, z up
    Place(bottom_plate, position=(0, 0, 0))
    Place(top_plate, position=(0, 0, height - ply))
    # an end panel's x (depth) -> world y, its y (height) -> world z, its thickness -> world x
    Place(left_end, position=(-length / 2, 0, height / 2), rotation=(90 deg, 0, 90 deg))
    Place(right_end, position=(length / 2 - ply, 0, height / 2), rotation=(90 deg, 0, 90 deg))

    assert len(top_plate.slots.s) == 6, "six slots"
    assert top_plate.slots.s[1].center.x - top_plate.slots.s[0].center.x == 16 mm, "16 mm apart"
    assert top_plate.slots.s[0].length == 12 mm and top_plate.slots.s[0].width == 4 mm, "12 x 4 slots"
    assert top_plate.panel.outline.width == 120 mm and top_plate.panel.outline.height == 40 mm, "120 x 40 top"
    assert left_end.panel.outline.height == 70 mm, "70 mm tall"
    assert top_plate.slots.s[5].center.x + top_plate.slots.s[0].center.x == 2 * top_plate.panel.outline.center.x, "row centred"
}
