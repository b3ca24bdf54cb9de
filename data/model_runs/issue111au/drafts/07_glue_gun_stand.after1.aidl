# Request: a stand for a full-size hot-glue gun, 4 mm plywood, three parts. A
# base 140 x 90 mm with 8 mm rounded corners; two uprights standing across it,
# each 90 mm wide and held by two glued 20 mm tabs in slots in the base. The
# front upright is 60 mm tall with a U-notch 14 mm wide and 25 mm deep for the
# nozzle; the rear upright, 60 mm behind it, is 95 mm tall with a U-notch 40 mm
# wide and 30 mm deep for the gun's barrel, so the gun rests nose-down. The
# front upright stands 35 mm behind the base's front edge; a 30 mm circle and
# "HOT" are engraved on the base where the nozzle drips, 15 mm in front of it.

import "std/joints.aidl"

units mm
thickness 4 mm

param ply = 4 mm, min = 3 mm, max = 6 mm
param base_l = 140 mm, min = 120 mm, max = 200 mm
param base_w = 90 mm, min = 70 mm, max = 120 mm
param up_w = 90 mm, min = 60 mm, max = 120 mm
param spacing = 60 mm, min = 40 mm, max = 90 mm
param tab = 20 mm, min = 10 mm, max = 30 mm

def upright(tall=60 mm, notch_w=14 mm, notch_d=25 mm) -> solid {
    plate = Rectangle(bottom_left=(-up_w / 2, 0), width=up_w, height=tall)
    strip = Rectangle(bottom_left=(-up_w / 2, -ply), width=up_w, height=ply)
    tabs = tab_and_slot(part="tab", length=up_w, thickness=ply, tabs=2, tab=tab, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-ply)
    hole notch {
        u = Slot(start=(0, tall - notch_d + notch_w / 2), end=(0, tall + notch_w), width=notch_w)
    }
}

assembly glue_gun_stand {
    solid base {
        plate = RoundedRectangle(center=(0, 0), width=base_l, height=base_w, corner_radius=8)
        # uprights stand across the base; the front one 35 mm in from the front
        # (left, -x) edge, the rear one 60 mm behind it
        front_slots = tab_and_slot(part="slot", length=up_w, thickness=ply, tabs=2, tab=tab,
                                   screw=0, rotation=90 deg, cx=-base_l / 2 + 35 mm, cy=0 mm)
        rear_slots = tab_and_slot(part="slot", length=up_w, thickness=ply, tabs=2, tab=tab,
                                  screw=0, rotation=90 deg, cx=-base_l / 2 + 35 mm + spacing,
                                  cy=0 mm)
        # FIX after the first valid program: a 30 mm ring centred 15 mm in front
        # of the upright's middle ran 2 mm under the upright's foot; it is now
        # centred in the strip between the front edge and the upright's face
        drawing drip {
            ring = Circle(center=(-base_l / 2 + (35 mm - ply / 2) / 2, 0), diameter=30)
            word = Text("HOT", position=(-base_l / 2 + (35 mm - ply / 2) / 2, 0), size=7,
                        valign="middle")
        }
    }
    front = upright(tall=60 mm, notch_w=14 mm, notch_d=25 mm)
    rear = upright(tall=95 mm, notch_w=40 mm, notch_d=30 mm)

    RightOf(front, base, gap=10)
    AlignBottom(front, base)
    RightOf(rear, front, gap=10)
    AlignBottom(rear, front)

    assert base.plate.width == 140 mm and base.plate.height == 90 mm, "base 140 x 90"
    assert front.plate.height == 60 mm and rear.plate.height == 95 mm, "uprights 60 and 95 tall"
    assert front.plate.width == 90 mm, "uprights 90 wide"
    assert front.notch.u.width == 14 mm and rear.notch.u.width == 40 mm, "notch widths"
    assert front.plate.bb.top - front.notch.u.bb.bottom == 25 mm, "nozzle notch 25 deep"
    assert rear.plate.bb.top - rear.notch.u.bb.bottom == 30 mm, "barrel notch 30 deep"
    assert base.drip.ring.bb.right < base.front_slots.slot[0].bb.left, "drip ring clear of the upright"
    assert rear.tabs.tabs == 2 and rear.tabs.tab == 20 mm, "two 20 mm tabs"
}
