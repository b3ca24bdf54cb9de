# Request (camping): a flat-pack toaster for the camp stove, 1.5 mm stainless steel.
# Base plate 180 x 180 mm, 10 mm corner radius, a heat spreader of 7 x 7 holes 6 mm across on a
# 12 mm grid in its middle, "CAMP TOASTER" marked along the front margin. Four bread racks
# 120 wide x 110 tall (tabs included), each with five 12 x 70 mm slots 20 mm apart, stand on the
# four sides 62 mm out from the centre, leaning 15 degrees outward so the slices lean on them and
# face the flame; each rack has two 20 mm tabs that drop into slots in the base, the slots 0.5 mm
# wider than the steel so the leaning tab goes through.

import "std/joints.aidl"

thickness 1.5 mm

t = 1.5 mm
lean = 15 deg
rack_out = 62 mm
# the leaning tab's foot print in the base: from the rack's bottom face line outward
tab_print = t / cos(lean) + t * tan(lean)
slot_at = rack_out + tab_print / 2

def rack() -> solid {
    frame = Rectangle(bottom_left=(-60, 0), width=120, height=110)
    tabs = tab_and_slot(part="tab", length=120 mm, thickness=2 mm, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole slot { s = Slot(center=(-40, 55), length=70, width=12, rotation=90 deg) }
    bars = LinearPattern(slot, 5, (20, 0))
}

# FIX after the first valid program: the unused template base_slots (a leftover, W0117) deleted

assembly toaster {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=180, height=180, corner_radius=10)
        hole vent { c = Circle(center=(-36, -36), diameter=6) }
        spreader = GridPattern(vent, 7, 7, 12)
        front_slots = tab_and_slot(part="slot", length=120 mm, thickness=1.5 mm, tabs=2, tab=20 mm,
                                   screw=0, clearance=0.5 mm, cx=0 mm, cy=-slot_at)
        back_slots = tab_and_slot(part="slot", length=120 mm, thickness=1.5 mm, tabs=2, tab=20 mm,
                                  screw=0, clearance=0.5 mm, cx=0 mm, cy=slot_at)
        left_slots = tab_and_slot(part="slot", length=120 mm, thickness=1.5 mm, tabs=2, tab=20 mm,
                                  screw=0, clearance=0.5 mm, rotation=90 deg, cx=-slot_at, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=120 mm, thickness=1.5 mm, tabs=2, tab=20 mm,
                                   screw=0, clearance=0.5 mm, rotation=90 deg, cx=slot_at, cy=0 mm)
        drawing mark {
            name = Text("CAMP TOASTER", position=(0, -78), size=6, valign="middle")
        }
    }
    front = rack()
    right = rack()
    back = rack()
    left = rack()

    # on the sheet
    RightOf(front, base, gap=5)
    AlignTop(front, base)
    Below(right, front, gap=5)
    AlignLeft(right, front)
    RightOf(back, front, gap=5)
    AlignTop(back, front)
    Below(left, back, gap=5)
    AlignLeft(left, back)

    # assembled: each rack's bottom face 62 mm out, turned 90 + 15 deg about x (leaning out)
    Place(base, position=(0, 0, 0))
    Place(front, position=(0, -rack_out, 0), rotation=(90 deg + lean, 0, 0))
    Place(right, position=(rack_out, 0, 0), rotation=(90 deg + lean, 0, 90 deg))
    Place(back, position=(0, rack_out, 0), rotation=(90 deg + lean, 0, 180 deg))
    Place(left, position=(-rack_out, 0, 0), rotation=(90 deg + lean, 0, 270 deg))

    # the request's numbers
    assert base.plate.bb.width == 180 mm and base.plate.bb.height == 180 mm, "base 180 x 180"
    assert len(base.spreader) == 49, "7 x 7 holes"
    assert base.vent.c.diameter == 6 mm, "6 mm holes"
    assert base.spreader[1].c.center.x - base.spreader[0].c.center.x == 12 mm, "12 mm grid"
    assert (base.spreader[48].c.center.x + base.spreader[0].c.center.x) / 2 == base.plate.center.x, "grid centred"
    assert front.frame.bb.width == 120 mm and front.frame.bb.height == 110 mm, "racks 120 x 110"
    assert len(front.bars) == 5, "five slots"
    assert front.slot.s.bb.width == 12 mm and front.slot.s.bb.height == 70 mm, "slots 12 x 70"
    assert front.bars[1].s.center.x - front.bars[0].s.center.x == 20 mm, "slots 20 apart"
    assert len(base.front_slots.slot) == 2, "two tabs a rack"
    assert base.front_slots.slot[0].bb.height == 2 mm, "slots 0.5 wider than the steel"
    assert tab_print <= 2 mm, "the leaning tab goes through the slot"
}
