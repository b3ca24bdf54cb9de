# Request (signs): a STOP sign for the kids' bike track in the garden, all 6 mm: a red cast
# acrylic octagon 200 mm across the flats (flats top and bottom), its centre 600 mm above
# the ground; a frosted border band engraved filled, 6 mm wide, 6 mm in from the edge; "STOP"
# engraved filled in bold letters 50 mm tall (at most 160 mm wide) in its middle. It slides
# onto a 6 mm ply post 50 mm wide by a flat dovetail (two tails, 12 mm deep, 10 degrees,
# 0.1 mm clearance) at its bottom flat. The post flares at the ground to a foot 240 mm wide
# (20 mm tall at its ends, narrowing to the post over 90 mm) and is cross-halved with a
# second foot, a 240 mm trapezoid 80 mm tall and 120 mm wide at its top; both feet have an
# arch 140 mm wide and 25 mm high; halving slots 6.2 mm wide, 40 mm from each side.

import "std/joints.aidl"

units mm
thickness 6 mm

t = 6 mm
c_h = 600 mm          # the octagon's centre above the ground
flats = 200 mm
bottom = c_h - flats / 2
dt_depth = 12 mm

def sign_face() -> solid {
    face = RegularPolygon(center=(0, c_h), across_flats=flats, sides=8, rotation=22.5 deg)
    drawing border {
        band = RegularPolygon(center=(0, c_h), across_flats=flats - 12, sides=8,
                              rotation=22.5 deg, fill=true)
        hole inner {
            r = RegularPolygon(center=(0, c_h), across_flats=flats - 24, sides=8,
                               rotation=22.5 deg)
        }
        # FIX after the first valid program: W0516, the band (6 to 12 mm in) ran across the
        # 12 mm deep dovetail sockets; it now stops 1 mm either side of the joint's 50 mm
        hole joint_gap {
            r = Rectangle(center=(0, bottom + 9), width=52, height=8)
        }
    }
    drawing word {
        w = Text("STOP", (0, c_h), size=50, font="sans:Bold", valign="middle", fill=true,
                 max_width=160)
    }
    socket = dovetail(part="socket", length=50 mm, depth=dt_depth, tails=2, angle=10 deg,
                      clearance=0.1 mm, cx=0, cy=bottom)
}

def post() -> solid {
    body = Polygon([(-120, 0), (120, 0), (120, 20), (25, 110), (25, bottom + dt_depth),
                    (-25, bottom + dt_depth), (-25, 110), (-120, 20)])
    tails = dovetail(part="tail", length=50 mm, depth=dt_depth, tails=2, angle=10 deg,
                     cx=0, cy=bottom)
    hole arch {
        e = Ellipse(center=(0, 0), rx=70, ry=25)
    }
    halving = cross_halving(depth=40 mm, thickness=t, clearance=0.2 mm, rotation=180 deg,
                            cx=0, cy=0)
}

def cross_foot() -> solid {
    body = Trapezoid(center=(0, 40), bottom_width=240, top_width=120, height=80)
    hole arch {
        e = Ellipse(center=(0, 0), rx=70, ry=25)
    }
    halving = cross_halving(depth=40 mm, thickness=t, clearance=0.2 mm, cx=0, cy=80)
}

assembly stop_sign {
    sign = sign_face()
    pole = post()
    foot = cross_foot()

    # flat on the sheet
    RightOf(pole, sign, gap=10)
    AlignBottom(pole, sign)
    RightOf(foot, pole, gap=10)
    AlignBottom(foot, pole)

    # in 3D: the sign and post in the x-z plane, the foot across them
    Place(sign, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(pole, rotation=(90 deg, 0, 0), position=(0, t / 2, 0))
    Place(foot, rotation=(90 deg, 0, 90 deg), position=(-t / 2, 0, 0))

    assert sign.face.bb.height == 200 mm, "200 across the flats"
    assert sign.face.bb.center_y - pole.body.bb.bottom == 600 mm, "centre 600 up"
    assert sign.word.w.bb.width <= 160 mm, "STOP at most 160 wide"
    assert pole.body.bb.width == 240 mm and foot.body.bb.width == 240 mm, "feet 240 wide"
    assert pole.halving.depth + foot.halving.depth == foot.body.bb.height, "the slots meet"
    assert pole.tails.depth == 12 mm and pole.tails.tails == 2, "two 12 mm tails"
}
