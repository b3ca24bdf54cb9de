# Request: an anniversary gift, a wooden sleeve for a 6 oz stainless hip flask (its body 95 mm
# wide and 25 mm thick: flat faces 70 mm wide between round sides of 12.5 mm radius), cut from
# 3 mm birch ply and wrapped round the flask's lower 100 mm. Two living hinges bend round the
# sides (inside radius 13 mm: 0.5 mm clearance); the ends meet at the middle of the back in a
# flat sliding dovetail seam, 3 tails 8 mm deep at 10 deg, 0.1 mm clearance, glued. On the
# front face: an engraved frame 62 x 90 with R4 corners, "J & M" in bold serif 16 mm tall,
# "TEN YEARS" 5 mm and "2016 - 2026" 6 mm tall below it, filled.

thickness 3 mm

import "std/plates.aidl"
import "std/joints.aidl"

T = 3 mm
flat = 70 mm                    # each flat face
r_in = 13 mm                    # inside radius round a side
bend = pi * (r_in + T / 2)      # one side's length at the sheet's middle
H = 100 mm
L = 2 * flat + 2 * bend         # round the flask, seam to seam
x_seam = L / 2                  # the front is centred at x = 0; the seam at +-x_seam
x_hinge = flat / 2 + bend / 2   # the hinges' centres
dt_depth = 8 mm

solid sleeve {
    body = Rectangle(center=(0, 0), width=L, height=H)
    # the right end reaches across the seam's band: its tails
    band = Rectangle(corner=(x_seam, -H / 2), opposite=(x_seam + dt_depth, H / 2))
    tails = dovetail(part="tail", length=H, depth=dt_depth, tails=3, angle=10 deg,
                     rotation=-90 deg, cx=x_seam, cy=0)
    # the left end takes them
    sockets = dovetail(part="socket", length=H, depth=dt_depth, tails=3, angle=10 deg,
                       clearance=0.1 mm, rotation=-90 deg, cx=-x_seam, cy=0)
    hinge_l = living_hinge(width=bend, height=H, cx=-x_hinge, cy=0)
    hinge_r = living_hinge(width=bend, height=H, cx=x_hinge, cy=0)
    drawing front {
        frame = RoundedRectangle(center=(0, 0), width=62, height=90, corner_radius=4)
        names = Text("J & M", position=(0, 12), size=16, font="serif:Bold", valign="middle",
                     fill=true, max_width=54 mm)
        years = Text("TEN YEARS", position=(0, -14), size=5, font="serif:Bold",
                     valign="middle", fill=true)
        dates = Text("2016 - 2026", position=(0, -26), size=6, font="serif:Bold",
                     valign="middle", fill=true)
    }

    # the request's numbers
    assert body.height == 100 mm, "covers 100 mm"
    assert body.width == 2 * 70 mm + 2 * pi * (13 mm + 3 mm / 2), "wraps the flask"
    assert hinge_r.width == pi * (13 mm + 3 mm / 2), "hinge as wide as the bend"
    assert tails.depth == 8 mm and tails.tails == 3 and sockets.clearance == 0.1 mm,
        "3 tails, 8 deep, 0.1 clearance"
    assert front.frame.width == 62 mm and front.frame.height == 90 mm, "frame 62 x 90"
    assert front.bb.left >= -70 mm / 2 + 3 mm and front.bb.right <= 70 mm / 2 - 3 mm,
        "engraving on the flat front face"
    assert distance(front, hinge_r) >= 3 mm and distance(front, hinge_l) >= 3 mm,
        "engraving clear of the hinges"
    assert front.names.size <= 16 mm and front.years.size == 5 mm and front.dates.size == 6 mm,
        "text sizes"
    assert distance(front.names, front.years) >= 3 mm and distance(front.years, front.dates) >= 2 mm,
        "lines apart"
}

# stood up with its back-left quarter facing the back; bent round the flask's sides with
# the engraved face outside
Place(sleeve, position=(0, 0, 0), face="back", up="up")
Bend(sleeve, at=-x_hinge, angle=-180 deg, radius=r_in)
Bend(sleeve, at=x_hinge, angle=-180 deg, radius=r_in)
