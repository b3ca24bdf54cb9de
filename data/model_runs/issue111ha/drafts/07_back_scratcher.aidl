# Request (gifts): "A back scratcher for my dad, from 6 mm oak-veneered ply: 420 mm long from
# the end of the handle to the tip of the middle finger. A round-ended handle 25 mm wide that
# tapers to 18 mm where it meets the hand; the hand a 44 mm palm with five 9 mm fingers with
# round tips fanned 20 degrees apart, reaching 48 mm from the palm's centre. An 8 mm hole in
# the handle end to hang it on a hook, and DAD'S BACK SCRATCHER engraved filled along the
# handle in 7 mm bold capitals."

thickness 6 mm

param length = 420 mm, min = 350 mm, max = 500 mm
param grip_w = 25 mm, min = 20 mm, max = 32 mm
param neck_w = 18 mm, min = 14 mm, max = 24 mm
param palm_d = 44 mm, min = 36 mm, max = 56 mm
param finger_w = 9 mm, min = 7 mm, max = 12 mm
param reach = 48 mm, min = 40 mm, max = 60 mm
param fan = 20 deg, min = 14 deg, max = 24 deg

# the palm's centre: the middle fingertip (reach + half a finger) lands at `length`
palm_x = length - reach - finger_w / 2

solid scratcher {
    handle = Hull(Circle(center=(grip_w / 2, 0), diameter=grip_w),
                  Circle(center=(palm_x - 15 mm, 0), diameter=neck_w))
    palm = Circle(center=(palm_x, 0), diameter=palm_d)
    for i in range(5) {
        finger = Slot(start=polar((palm_x, 0), 10 mm, (i - 2) * fan),
                      end=polar((palm_x, 0), reach, (i - 2) * fan), width=finger_w)
    }

    hole hang {
        c = Circle(center=(grip_w / 2, 0), diameter=8)
    }

    drawing name {
        t = Text("DAD'S BACK SCRATCHER", position=((grip_w + palm_x - 15 mm) / 2 + 10 mm, 0),
                 size=7, font="sans:Bold", fill=true, valign="middle")
    }

    assert finger[2].end.x + finger_w / 2 - handle.bb.left == 420 mm, "420 mm to the middle fingertip"
    assert handle.bb.height == 25 mm, "25 mm handle"
    assert len(finger) == 5, "five fingers"
    assert distance(finger[0].end, finger[1].end) - finger_w >= 6 mm, "fingertips stand apart"
    assert distance(name, hang) >= 10 mm, "name clear of the hanging hole"
    assert name.bb.right <= palm.bb.left - 15 mm, "name on the handle, not on the hand"
    assert name.bb.height <= 16 mm, "name within the handle's width"
}
