# Request: a desk sand-timer frame for a 3-minute hourglass vial 40 mm across and 110 mm
# tall, cut from 6 mm walnut ply (5 parts). Two 80 mm end discs; three pillars standing
# radially at 120 degrees (one at the back, 90 deg), 12 mm deep, their inner edges 24 mm
# from the centre so the vial has 4 mm play all round; 112 mm clear between the discs (2 mm
# for the vial). Each pillar has an 8 mm tenon at each end glued through a mortise in each
# disc, and a shallow elliptical scoop (8 mm deep, 80 mm long) along its outer edge, its
# corners rounded 3 mm. The top disc is engraved "3 MIN" (filled bold, 10 mm) in the middle.

import "std/joints.aidl"

thickness 6 mm

T = 6 mm
DISC_D = 80 mm
VIAL_D = 40 mm
VIAL_H = 110 mm
CLEAR = 112 mm        # between the discs
R_IN = 24 mm          # pillar's inner edge from the centre
DEPTH = 12 mm         # pillar, radially
TENON = 8 mm
ANG = [90 deg, 210 deg, 330 deg]

def pillar() -> solid {
    # inner edge at x = 0, shoulders at y = 0 and y = CLEAR, tenon tips T beyond
    body = Rectangle(bottom_left=(0, -T), width=DEPTH, height=CLEAR + 2 * T)
    lo = tab_and_slot(part="tab", length=DEPTH, thickness=T, tabs=1, tab=TENON, screw=0,
                      rotation=180 deg, cx=DEPTH / 2, cy=-T)
    hi = tab_and_slot(part="tab", length=DEPTH, thickness=T, tabs=1, tab=TENON, screw=0,
                      rotation=0 deg, cx=DEPTH / 2, cy=CLEAR + T)
    hole scoop {
        e = Ellipse(center=(DEPTH + 8 mm - 8 mm + 8 mm, CLEAR / 2), rx=16 mm, ry=40 mm)
    }
    Fillet([body, scoop.e], 3 mm)
}

def disc(label="") -> solid {
    d = Circle(center=(0, 0), diameter=DISC_D)
    for i in range(3) {
        m = tab_and_slot(part="slot", length=DEPTH, thickness=T, tabs=1, tab=TENON, screw=0,
                         rotation=ANG[i], cx=(R_IN + DEPTH / 2) * cos(ANG[i]),
                         cy=(R_IN + DEPTH / 2) * sin(ANG[i]))
    }
    if len(label) > 0 {
        drawing mark {
            t = Text(label, position=(0, 0), size=10, font="sans:Bold", fill=true,
                     valign="middle")
        }
    }
}

assembly sand_timer {
    bottom = disc()
    top = disc(label="3 MIN")
    RightOf(top, bottom, gap=6)
    AlignCenterY(top, bottom)

    for i in range(3) {
        p = pillar()
        Place(p, position=(R_IN * cos(ANG[i]) - T / 2 * sin(ANG[i]),
                           R_IN * sin(ANG[i]) + T / 2 * cos(ANG[i]), T),
              rotation=(90 deg, 0, ANG[i]))
    }
    # on the sheet: the pillars in a row to the right of the discs
    RightOf(p[0], top, gap=6)
    RightOf(p[1], p[0], gap=6)
    RightOf(p[2], p[1], gap=6)
    AlignBottom(p[0], bottom)
    AlignBottom(p[1], bottom)
    AlignBottom(p[2], bottom)

    Place(bottom, position=(0, 0, 0))
    Place(top, position=(0, 0, T + CLEAR))

    assert CLEAR - VIAL_H == 2 mm, "2 mm for the vial between the discs"
    assert R_IN - VIAL_D / 2 == 4 mm, "4 mm play round the vial"
    assert p[0].body.bb.height - 2 * T == 112 mm, "112 mm between the shoulders"
    assert bottom.d.diameter == 80 mm, "80 mm discs"
    assert DISC_D / 2 - (R_IN + DEPTH) >= 3 mm, "wood outside the mortises"
}
