# Office desk nameplate: a 200 x 60 mm plate of 3 mm acrylic that stands upright on two feet
# 60 mm long and 24 mm tall, crossed into it by cross halving (12 mm slot up from the plate's
# bottom edge 70 mm either side of the centre, 12 mm slot down from each foot's top edge in
# its middle; 0.1 mm clearance). The name "ALEX MORGAN" in sans Bold 14 mm, filled engraving,
# centred on the plate. Plate corners R4, foot top corners R4.

import "std/joints.aidl"

thickness 3 mm
param name_size = 14 mm, min = 8 mm, max = 18 mm

def foot() -> solid {
    body = RoundedRectangle(center=(0, 0), width=60, height=24, corner_radii=[4, 4, 0, 0])
    slot = cross_halving(depth=12 mm, thickness=3 mm, clearance=0.1 mm, cx=0 mm, cy=12 mm)
}

assembly nameplate {
    solid plate {
        body = RoundedRectangle(center=(0, 0), width=200, height=60, corner_radius=4)
        left_slot = cross_halving(depth=12 mm, thickness=3 mm, clearance=0.1 mm,
                                  rotation=180 deg, cx=-70 mm, cy=-30 mm)
        right_slot = cross_halving(depth=12 mm, thickness=3 mm, clearance=0.1 mm,
                                   rotation=180 deg, cx=70 mm, cy=-30 mm)
        drawing name {
            word = Text("ALEX MORGAN", (0, 0), size=name_size, font="sans:Bold", fill=true,
                        valign="middle")
        }
        CenterInside(name, body)
    }
    foot_a = foot()
    foot_b = foot()
    Below(foot_a, plate, gap=10)
    Below(foot_b, plate, gap=10)
    AlignLeft(foot_a, plate)
    AlignRight(foot_b, plate)

    assert plate.body.bb.width == 200 mm and plate.body.bb.height == 60 mm, "plate 200 x 60"
    assert foot_a.body.bb.width == 60 mm and foot_a.body.bb.height == 24 mm, "foot 60 x 24"
    assert plate.left_slot.cut.bb.height == 12 mm, "plate slot 12 deep"
    assert foot_a.slot.cut.bb.height == 12 mm, "foot slot 12 deep"
    assert plate.left_slot.cut.bb.height + foot_a.slot.cut.bb.height == 24 mm, "depths add to the foot's height"
    assert abs(plate.left_slot.cut.bb.width - 3.1 mm) < 0.001, "slot 3 mm + 0.1 clearance"
    assert plate.left_slot.cut.bb.center_x - plate.body.bb.center_x == -70 mm, "slot 70 left"
    assert plate.right_slot.cut.bb.center_x - plate.body.bb.center_x == 70 mm, "slot 70 right"
    assert abs(foot_a.slot.cut.bb.center_x - foot_a.body.bb.center_x) < 0.001, "foot slot in its middle"
    assert plate.name.bb.width < plate.body.bb.width - 20 mm, "name fits with margin"
}
