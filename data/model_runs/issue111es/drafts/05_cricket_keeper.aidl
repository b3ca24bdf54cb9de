# Request: "A cricket keeper for the live crickets I feed my leopard gecko, in 3 mm clear
# acrylic: a finger-jointed box 200 mm long, 120 mm deep and 130 mm tall outside (lid
# included) with a lift-off lid. Through the lid, four 26 mm holes in a row along the
# front, 45 mm apart, their centres 35 mm in front of the lid's middle, for the cardboard
# tubes the crickets climb into (you lift a tube out and shake it over the gecko's dish).
# Behind them a vent of twelve slots 30 x 4 mm, 3 rows of 4, columns 40 mm apart and rows
# 10 mm apart, the rows' centres 15 to 35 mm behind the lid's middle. The lid's lip must
# have the same openings. CRICKETS fill-engraved, bold, 14 mm tall, in the middle of the
# front wall."

import "std/boxes.aidl"

units mm
thickness 3 mm
kerf 0.1 mm

tube_d = 26 mm
tube_pitch = 45 mm
tube_off = -35 mm        # tube centres from the lid's middle (toward the front)
vent_len = 30 mm
vent_w = 4 mm
vent_dx = 40 mm
vent_dy = 10 mm
vent_off = 15 mm         # first vent row from the lid's middle (toward the back)

def tube_row() -> hole {
    for i in range(4) {
        c = Circle(center=(-1.5 * tube_pitch + i * tube_pitch, 0), diameter=tube_d)
    }
}

def vent_slot() -> hole {
    s = Slot(center=(0, 0), length=vent_len, width=vent_w)
}

assembly keeper {
    box = lid_box(length=200 mm, width=120 mm, height=130 mm, thickness=3 mm)

    # the lid's openings
    tubes = tube_row()
    AlignCenterX(tubes, box.lid)
    tubes.c[0].center.y == box.lid.bb.center_y + tube_off
    CutInto(tubes, box.lid)
    vent = vent_slot()
    vent.s.center.x == box.lid.bb.center_x - 1.5 * vent_dx
    vent.s.center.y == box.lid.bb.center_y + vent_off
    vents = GridPattern(vent, 3, 4, (vent_dx, vent_dy))
    CutInto(vent, box.lid)

    # the same openings in the lip, about its own middle
    lip_tubes = tube_row()
    AlignCenterX(lip_tubes, box.lip)
    lip_tubes.c[0].center.y == box.lip.bb.center_y + tube_off
    CutInto(lip_tubes, box.lip)
    lip_vent = vent_slot()
    lip_vent.s.center.x == box.lip.bb.center_x - 1.5 * vent_dx
    lip_vent.s.center.y == box.lip.bb.center_y + vent_off
    lip_vents = GridPattern(lip_vent, 3, 4, (vent_dx, vent_dy))
    CutInto(lip_vent, box.lip)

    # the front wall's name
    drawing name {
        t = Text("CRICKETS", position=(0, 0), size=14, font="sans:Bold", valign="middle", fill=true)
    }
    CenterInside(name, box.body.front)
    CutInto(name, box.body.front)

    # the request's numbers
    assert box.body.front.bb.width == 200 mm, "200 mm long"
    assert box.body.left.bb.height == 120 mm, "120 mm deep"
    assert box.body.front.bb.height + 3 mm == 130 mm, "130 mm tall with the lid"
    assert len(tubes.c) == 4 and tubes.c[0].diameter == 26 mm, "four 26 mm tube holes"
    assert tubes.c[1].center.x - tubes.c[0].center.x == 45 mm, "tubes 45 mm apart"
    assert len(vents) == 12, "twelve vent slots"
    assert vents[1].s.center.x - vents[0].s.center.x == 40 mm, "vent columns 40 mm apart"
    assert vents[4].s.center.y - vents[0].s.center.y == 10 mm, "vent rows 10 mm apart"
    assert distance(tubes.c[0], vent.s) >= 5 mm, "tubes clear of the vents"
    assert box.lip.bb.top - lip_vents[11].s.bb.top >= 5 mm, "vents inside the lip"
    assert lip_tubes.c[0].bb.bottom - box.lip.bb.bottom >= 5 mm, "tube holes inside the lip"
    assert name.t.bb.width <= 200 mm - 2 * 20 mm, "name well inside the front"
}
