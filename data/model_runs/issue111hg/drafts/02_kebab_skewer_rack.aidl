# Request (kitchen): a table rack for eight round metal kebab skewers (5 mm, about 400 mm
# long), cut from 6 mm birch ply. Two uprights, each 150 mm wide and 110 mm tall including
# the 6 mm tabs that stand in the base, with rounded top corners (15 mm) and a 40 mm round
# cut-out in the middle; along the top edge eight U-notches 6 mm wide and 10 mm deep (round
# bottom) at a 15 mm pitch, centred. The uprights stand 250 mm apart (centre to centre) on a
# 360 x 150 mm base with 10 mm corner radii, each with two 30 mm glued tabs in slots of
# 0.1 mm clearance. A 60 x 20 mm hand-hold slot across each end of the base, centred 25 mm
# from the end, and "KEBABS" engraved filled in bold serif, 20 mm high, in the middle of
# the base.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
up_w = 150 mm
up_h = 110 mm
spacing = 250 mm
base_l = 360 mm
base_d = 150 mm
notches = 8
pitch = 15 mm
notch_w = 6 mm
notch_d = 10 mm

def upright() -> solid {
    body = RoundedRectangle(center=(0, up_h / 2), width=up_w, height=up_h,
                            corner_radii=[15 mm, 15 mm, 0 mm, 0 mm])
    # two tabs on the bottom edge (tips at y = 0), the panel above them
    feet = tab_and_slot(part="tab", length=up_w, thickness=t, tabs=2, tab=30 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=0 mm)
    hole window {
        c = Circle(center=(0, up_h / 2), diameter=40)
    }
    hole notch {
        # a slot whose round end is the notch bottom, running up past the top edge
        s = Slot(center=(-(notches - 1) * pitch / 2, up_h), length=2 * notch_d,
                 width=notch_w, rotation=90 deg)
    }
    row = LinearPattern(notch, notches, (pitch, 0))
    assert len(row) == 8, "eight notches"
    assert row[1].s.center.x - row[0].s.center.x == 15 mm, "15 mm pitch"
    assert body.bb.top - row[0].s.bb.bottom == 10 mm, "10 mm deep"
}

assembly rack {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=base_l, height=base_d, corner_radius=10)
        left_slots = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=30 mm,
                                  screw=0, clearance=0.1 mm, rotation=90 deg,
                                  cx=-spacing / 2, cy=0 mm)
        right_slots = tab_and_slot(part="slot", length=up_w, thickness=t, tabs=2, tab=30 mm,
                                   screw=0, clearance=0.1 mm, rotation=90 deg,
                                   cx=spacing / 2, cy=0 mm)
        hole grips {
            l = Slot(center=(-base_l / 2 + 25 mm, 0), length=60, width=20, rotation=90 deg)
            r = Slot(center=(base_l / 2 - 25 mm, 0), length=60, width=20, rotation=90 deg)
        }
        drawing name {
            word = Text("KEBABS", (0, 0), size=20, font="serif:Bold", fill=true,
                        valign="middle")
        }
        assert distance(name, left_slots) >= 5 mm, "name clear of the slots"
    }

    left = upright()
    right = upright()

    Above(left, base, gap=15)
    AlignLeft(left, base)
    RightOf(right, left, gap=15)
    AlignBottom(right, left)

    # in 3D: the base flat, the uprights standing in its slots, tabs through the base
    Place(base, position=(0, 0, 0), face="up")
    # FIX after the first valid program: facing "left", the part's top face lies t towards -x
    # from the position, so its bottom face is at -spacing/2 + t/2 (W0517 named the collision)
    Place(left, position=(-spacing / 2 + t / 2, 0, 0), face="left", up="up")
    Place(right, position=(spacing / 2 - t / 2, 0, 0), face="right", up="up")

    assert base.right_slots.bb.center_x - base.left_slots.bb.center_x == 250 mm,
        "uprights 250 apart"
    assert base.body.bb.width == 360 mm and base.body.bb.height == 150 mm, "base size"
    assert left.body.bb.width == 150 mm and left.body.bb.height == 110 mm, "upright size"
    assert base.body.bb.right - base.grips.r.center.x == 25 mm, "grip 25 mm from the end"
}
