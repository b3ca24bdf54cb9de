# Request: a set of twelve shower-curtain hooks cut from 3 mm clear acrylic, for a 25 mm
# shower rod. Each hook is a 5 mm wide strip with round ends: a top curl of 17.5 mm radius
# (centre line; 30 mm inside, so it slides freely on the rod) running from straight below
# its centre round over the top to 140 degrees, leaving an opening of at least 26 mm for the
# rod to drop in; a straight 34.5 mm shank down from the bottom of the curl; and a small
# bottom curl of 8 mm radius (centre line) that the curtain's grommet snaps over through a
# 3 mm gap between the curl's tip and the shank. Laid out 6 by 2 for cutting, 50 mm apart
# across and 100 mm apart down.

thickness 3 mm

rod = 25 mm
w = 5 mm                     # the strip's width
top_r = 17.5 mm
shank_len = 34.5 mm
eye_r = 8 mm

def hook() -> solid {
    curl = ArcSlot(center=(0, 0), radius=top_r, start_angle=-90 deg, end_angle=140 deg, width=w)
    shank = Slot(start=(0, -top_r), end=(0, -top_r - shank_len), width=w)
    eye = ArcSlot(center=(0, -top_r - shank_len - eye_r), radius=eye_r, start_angle=90 deg,
                  end_angle=390 deg, width=w)
    Rigid(curl, shank, eye)
}

assembly hooks {
    first = hook()
    set = GridPattern(first, 2, 6, (50 mm, -100 mm))

    assert len(set) == 12, "twelve hooks"
    assert first.curl.radius - w / 2 >= rod / 2 + 2.5 mm, "30 mm inside the curl: free on a 25 mm rod"
    assert distance(first.curl.end, first.shank.start) - w >= 26 mm, "the rod drops in through 26 mm"
    assert abs(distance(first.eye.end, first.shank.end) - w - 3 mm) < 0.1 mm, "a 3 mm snap gap"
    assert distance(first.shank.start, first.shank.end) == 34.5 mm, "shank 34.5 mm, curl to curl"
}
