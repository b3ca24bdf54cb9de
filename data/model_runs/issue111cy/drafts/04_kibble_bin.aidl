# Request (pets): a dry-food bin for the dog, to hold a 5 kg bag of kibble, 6 mm birch ply.
# A finger-jointed box 320 mm long, 220 mm deep, 300 mm tall outside (lid included), 20 mm
# fingers, with a lid that turns on pins at the back. The lid has a finger hole to lift it:
# a 70 x 25 mm rounded slot, centred left to right, its centre 30 mm from the lid's front edge.
# The front carries, engraved filled: a paw print (a 56 x 44 mm oval pad and four 20 x 28 mm
# oval toes above it, the outer two tilted out by 20 degrees) with its box's centre 60 mm
# above the front's centre, and the dog's name "BISCUIT" in bold letters 40 mm high (at most
# 240 mm wide), centred 50 mm below the front's centre. Nothing is cut through the walls, so
# no kibble can spill.

import "std/boxes.aidl"

thickness 6 mm

assembly kibble_bin {
    box = hinged_box(length=320 mm, width=220 mm, height=300 mm, thickness=6 mm,
                     finger=20 mm, outside=true)

    hole finger_hole {
        s = Slot(center=(0, 0), length=70 mm, width=25 mm)
    }
    AlignCenterX(finger_hole, box.lid)
    finger_hole.s.center.y == box.lid.bb.bottom + 30 mm
    CutInto(finger_hole, box.lid)

    drawing paw {
        pad = Ellipse(center=(0, 0), rx=28 mm, ry=22 mm, fill=true)
        toe_1 = Ellipse(center=(-36 mm, 30 mm), rx=10 mm, ry=14 mm, rotation=20 deg, fill=true)
        toe_2 = Ellipse(center=(-13 mm, 44 mm), rx=10 mm, ry=14 mm, fill=true)
        toe_3 = Ellipse(center=(13 mm, 44 mm), rx=10 mm, ry=14 mm, fill=true)
        toe_4 = Ellipse(center=(36 mm, 30 mm), rx=10 mm, ry=14 mm, rotation=-20 deg, fill=true)
        Rigid(self)
    }
    AlignCenterX(paw, box.front)
    paw.bb.center_y == box.front.bb.center_y + 60 mm
    CutInto(paw, box.front)

    drawing name {
        t = Text("BISCUIT", position=(0, 0), size=40 mm, font="sans:Bold", valign="middle",
                 fill=true, max_width=240 mm)
    }
    AlignCenterX(name, box.front)
    name.t.position.y == box.front.bb.center_y - 50 mm
    CutInto(name, box.front)

    # the request's numbers
    assert box.lid.bb.width == 320 mm, "320 mm long"
    assert box.front.bb.height + 6 mm == 300 mm, "300 mm tall with the lid"
    assert finger_hole.s.length == 70 mm and finger_hole.s.width == 25 mm, "70 x 25 finger hole"
    assert finger_hole.s.center.y - box.lid.bb.bottom == 30 mm, "30 mm from the lid's front"
    assert paw.pad.rx * 2 == 56 mm and paw.pad.ry * 2 == 44 mm, "56 x 44 pad"
    assert paw.toe_2.rx * 2 == 20 mm and paw.toe_2.ry * 2 == 28 mm, "20 x 28 toes"
    assert paw.toe_2.bb.bottom > paw.pad.bb.top, "toes above the pad"
    assert paw.bb.center_y - box.front.bb.center_y == 60 mm, "paw 60 mm above the centre"
    assert box.front.bb.center_y - name.t.position.y == 50 mm, "name 50 mm below the centre"
    assert name.t.bb.width <= 240 mm, "name at most 240 mm wide"
}
