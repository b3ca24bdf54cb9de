# Request: drill templates for a guitar fuzz pedal in a Hammond 1590B box (60 x 112 x 31 mm),
# cut from 3 mm MDF and taped onto the box's faces. Each hole gets a 2 mm pilot hole through
# the template, its finished size engraved as a ring, and its name and size engraved under the
# ring (3.5 mm text). Top (60 x 112, corners r5): footswitch 12 mm at 25 mm from the bottom
# end, LED 5 mm at 62 mm, VOL and TONE pots 7 mm at 90 mm, 17 mm left and right of the centre
# line; "1590B TOP" engraved 4 mm near the top end. Top end (60 x 31): DC jack 12 mm, centred.
# Sides (112 x 31): IN on the right side and OUT on the left (seen from above, footswitch
# towards the player), 9.5 mm jacks 30 mm from the top end and 15 mm below the top face.

thickness 3 mm

box_w = 60 mm
box_l = 112 mm
box_h = 31 mm

def pilot(x=0 mm, y=0 mm) -> hole {
    c = Circle(center=(x, y), diameter=2)
}

def mark(x=0 mm, y=0 mm, d=10 mm, label="") -> drawing {
    ring = Circle(center=(x, y), diameter=d)
    name = Text(label, position=(x, y - d / 2 - 5), size=3.5)
}

assembly templates {
    # the top face: centred on (0, 0), its bottom (footswitch) end at y = -box_l / 2
    solid top {
        plate = RoundedRectangle(center=(0, 0), width=box_w, height=box_l, corner_radius=5)
        p_fs = pilot(x=0 mm, y=-box_l / 2 + 25)
        p_led = pilot(x=0 mm, y=-box_l / 2 + 62)
        p_vol = pilot(x=-17 mm, y=-box_l / 2 + 90)
        p_tone = pilot(x=17 mm, y=-box_l / 2 + 90)
        m_fs = mark(x=0 mm, y=-box_l / 2 + 25, d=12 mm, label="FOOT 12")
        m_led = mark(x=0 mm, y=-box_l / 2 + 62, d=5 mm, label="LED 5")
        m_vol = mark(x=-17 mm, y=-box_l / 2 + 90, d=7 mm, label="VOL 7")
        m_tone = mark(x=17 mm, y=-box_l / 2 + 90, d=7 mm, label="TONE 7")
        drawing title { w = Text("1590B TOP", position=(0, box_l / 2 - 9), size=4) }
    }

    # the top end: its bottom edge on the box's floor (y = 0)
    solid end {
        plate = Rectangle(bottom_left=(-box_w / 2, 0), width=box_w, height=box_h)
        p_dc = pilot(x=0 mm, y=box_h / 2)
        m_dc = mark(x=0 mm, y=box_h / 2, d=12 mm, label="DC 12")
    }

    # the sides, seen from outside: x along the box (the right side's top end at +x, the
    # left side's at -x), y up from the floor
    solid right {
        plate = Rectangle(bottom_left=(-box_l / 2, 0), width=box_l, height=box_h)
        p_in = pilot(x=box_l / 2 - 30, y=box_h - 15)
        m_in = mark(x=box_l / 2 - 30, y=box_h - 15, d=9.5 mm, label="IN 9.5")
    }
    solid left {
        plate = Rectangle(bottom_left=(-box_l / 2, 0), width=box_l, height=box_h)
        p_out = pilot(x=-box_l / 2 + 30, y=box_h - 15)
        m_out = mark(x=-box_l / 2 + 30, y=box_h - 15, d=9.5 mm, label="OUT 9.5")
    }

    # flat on the sheet: the end and the sides to the right of the top, stacked
    RightOf(end, top, gap=5)
    AlignTop(end, top)
    Below(right, end, gap=5)
    AlignLeft(right, end)
    Below(left, right, gap=5)
    AlignLeft(left, right)

    # on the box (floor at z = 0, top face at z = box_h), engraved faces outward
    Place(top, position=(0, 0, box_h))
    Place(end, rotation=(90 deg, 0, 180 deg), position=(0, box_l / 2, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(box_w / 2, 0, 0))
    Place(left, rotation=(90 deg, 0, -90 deg), position=(-box_w / 2, 0, 0))

    assert top.plate.bb.width == 60 mm and top.plate.bb.height == 112 mm, "top 60 x 112"
    assert end.plate.bb.width == 60 mm and end.plate.bb.height == 31 mm, "end 60 x 31"
    assert right.plate.bb.width == 112 mm and right.plate.bb.height == 31 mm, "sides 112 x 31"
    assert top.p_fs.c.diameter == 2 mm, "2 mm pilots"
    assert top.p_fs.c.center.y - top.plate.bb.bottom == 25 mm, "footswitch 25 from the bottom end"
    assert top.m_fs.ring.diameter == 12 mm, "footswitch 12"
    assert top.p_led.c.center.y - top.plate.bb.bottom == 62 mm, "LED at 62"
    assert top.m_led.ring.diameter == 5 mm, "LED 5"
    assert top.p_vol.c.center.y - top.plate.bb.bottom == 90 mm, "pots at 90"
    assert top.plate.bb.center_x - top.p_vol.c.center.x == 17 mm, "VOL 17 left"
    assert top.p_tone.c.center.x - top.plate.bb.center_x == 17 mm, "TONE 17 right"
    assert top.m_vol.ring.diameter == 7 mm and top.m_tone.ring.diameter == 7 mm, "pots 7"
    assert end.m_dc.ring.diameter == 12 mm, "DC 12"
    assert right.plate.bb.right - right.p_in.c.center.x == 30 mm, "IN 30 from the top end"
    assert left.p_out.c.center.x - left.plate.bb.left == 30 mm, "OUT 30 from the top end"
    assert right.plate.bb.top - right.p_in.c.center.y == 15 mm, "IN 15 below the top face"
    assert left.plate.bb.top - left.p_out.c.center.y == 15 mm, "OUT 15 below the top face"
    assert right.m_in.ring.diameter == 9.5 mm and left.m_out.ring.diameter == 9.5 mm, "jacks 9.5"
}
