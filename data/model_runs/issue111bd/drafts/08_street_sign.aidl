# Request (signs): a crossed street-name sign for the corner of our garden path, from 6 mm
# exterior ply. Two blades 450 x 120 mm, corners rounded 10 mm, cross-halved at their middles
# (MAPLE AVE slotted 60 mm up from its bottom edge, OAK ST 60 mm down from its top edge, so
# both stand with tops and bottoms level). Each blade: a 4 mm engraved filled border 8 mm in
# from the edge, broken where the halving slot crosses it, and its name engraved filled in
# 40 mm bold letters, the first word centred 115 mm left of the middle and the second 115 mm
# right (the post is in the middle). Both blades stand on a 89 x 89 mm cap plate (for a 4x4
# post) on two 20 mm tenons each, into mortises that cross at the cap's middle; the cap has
# four countersunk M4 screw holes (9 mm heads) 14.5 mm in from its corners.

import "std/joints.aidl"
import "std/fasteners.aidl"

thickness 6 mm

t = 6 mm
blade_l = 450 mm
blade_h = 120 mm
cap_w = 89 mm
halving = 60 mm
word_x = 115 mm

def blade(first="MAPLE", second="AVE", from_top=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=blade_l, height=blade_h, corner_radius=10)
    if from_top {
        halving_slot = cross_halving(depth=halving, thickness=t, cx=0 mm, cy=blade_h / 2)
    } else {
        halving_slot = cross_halving(depth=halving, thickness=t, rotation=180 deg, cx=0 mm,
                                     cy=-blade_h / 2)
    }
    feet = tab_and_slot(part="tab", length=cap_w, thickness=t, tabs=2, tab=20 mm, screw=0,
                        rotation=180 deg, cx=0 mm, cy=-blade_h / 2)
    drawing face {
        border = Shell(RoundedRectangle(center=(0, 0), width=blade_l - 16 mm, height=blade_h - 16 mm,
                                        corner_radius=4), -4 mm, fill=true)
        w1 = Text(first, position=(-word_x, 0), size=40, font="sans:Bold", valign="middle", fill=true)
        w2 = Text(second, position=(word_x, 0), size=40, font="sans:Bold", valign="middle", fill=true)
        # FIX after the first valid program: W0516, a gap exactly the slot's width ended the
        # border on the slot's cut edges; 1 mm clear each side
        hole gap {
            if from_top {
                r = Rectangle(bottom_left=(-t / 2 - 1 mm, blade_h / 2 - halving), width=t + 2 mm,
                              height=halving + 1 mm)
            } else {
                r = Rectangle(bottom_left=(-t / 2 - 1 mm, -blade_h / 2 - 1 mm), width=t + 2 mm,
                              height=halving + 1 mm)
            }
        }
    }
}

assembly street_sign {
    maple = blade(first="MAPLE", second="AVE", from_top=false)
    oak = blade(first="OAK", second="ST", from_top=true)
    solid cap {
        plate = Rectangle(center=(0, 0), width=cap_w, height=cap_w)
        maple_mortise = tab_and_slot(part="slot", length=cap_w, thickness=t, tabs=2, tab=20 mm,
                                     screw=0, cx=0 mm, cy=0 mm)
        oak_mortise = tab_and_slot(part="slot", length=cap_w, thickness=t, tabs=2, tab=20 mm,
                                   screw=0, rotation=90 deg, cx=0 mm, cy=0 mm)
        screw = clearance_hole(size=4)
        screws = CornerPattern(screw, plate, inset=14.5)
        Countersink(screws, diameter=9 mm)
        Fixed(plate)
    }

    # on the sheet
    Fixed(maple)
    Above(oak, maple, gap=10)
    AlignLeft(oak, maple)
    RightOf(cap, maple, gap=10)
    AlignBottom(cap, maple)

    # assembled: the cap on the post top, MAPLE AVE along x (read from -y), OAK ST along y
    Place(cap, position=(0, 0, 0))
    Place(maple, rotation=(90 deg, 0, 0), position=(0, t / 2, blade_h / 2))
    Place(oak, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, blade_h / 2))

    # the request's numbers
    assert maple.body.width == 450 mm and maple.body.height == 120 mm, "blades 450 x 120"
    assert maple.halving_slot.cut.bb.height == 60 mm and oak.halving_slot.cut.bb.height == 60 mm, "halved 60 each"
    assert maple.halving_slot.cut.bb.height + oak.halving_slot.cut.bb.height == blade_h, "tops and bottoms level"
    assert maple.halving_slot.cut.bb.bottom == maple.body.bb.bottom, "MAPLE slotted from the bottom"
    assert oak.halving_slot.cut.bb.top == oak.body.bb.top, "OAK slotted from the top"
    assert maple.face.w1.position.x - maple.body.center.x == -115 mm, "first word 115 left"
    assert maple.face.w2.position.x - maple.body.center.x == 115 mm, "second word 115 right"
    assert cap.plate.width == 89 mm, "cap 89 square"
    assert len(cap.screws) == 4, "four screws"
    assert cap.screws[0].c.center.x - cap.plate.bb.left == 14.5 mm, "screws 14.5 in"
}
