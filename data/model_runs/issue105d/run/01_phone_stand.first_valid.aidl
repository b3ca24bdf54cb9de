# Phone stand back panel: 80 x 120 mm plate, 6 mm rounded corners; a charging-cable
# slot 12 mm wide and 25 mm deep, open at the bottom edge, centred; a slot 40 x 3 mm
# for the foot piece, centred, its centre 35 mm above the bottom edge.
param w = 80 mm, min = 60 mm, max = 120 mm
param h = 120 mm, min = 90 mm, max = 180 mm
thickness 3 mm

solid stand {
    body = RoundedRectangle(center=(0, 0), width=w, height=h, corner_radius=6)
    hole cable {
        s = Rectangle(center=(0, -50), width=12, height=25)
    }
    hole foot_slot {
        s = Rectangle(center=(0, -25), width=40, height=3)
    }
    AlignCenterX(cable, body)
    AlignBottom(cable, body)
    AlignCenterX(foot_slot, body)
    At(foot_slot.s.center, body.bb.bottom_left, dx=w / 2, dy=35)
    assert cable.bb.height == 25 mm, "slot 25 mm deep"
    assert cable.bb.width == 12 mm, "slot 12 mm wide"
    assert foot_slot.bb.bottom > cable.bb.top, "foot slot clear of the cable slot"
}
