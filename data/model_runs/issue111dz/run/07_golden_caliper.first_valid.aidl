# Request: a golden-mean caliper for the science club, 3 mm acrylic, joined by M4 rivets
# (4.3 mm holes). Two legs hinged at the top, their tips 200 mm from the hinge; a middle
# pointer whose tip always lies on the line between the legs' tips and divides it in the
# golden ratio (the long part : the short part = 1.618), at any opening.
# Linkage: the pointer is pinned to leg B 0.618 x 200 mm from the hinge and runs parallel to
# leg A for 0.382 x 200 mm to its tip; a link pinned to leg A (half of 0.382 x 200 from the
# hinge) and to the pointer (the same distance from its pin) keeps it parallel (a
# parallelogram). Legs 18 mm wide at the hinge, tapering to a sharp tip; pointer and link
# 14 mm wide. Engraved: "GOLDEN MEAN" on leg B, "φ = 1.618" on leg A (5 mm).

import "std/fasteners.aidl"

thickness 3 mm

L = 200 mm
PHI = (1 + sqrt(5)) / 2
OE = L / PHI              # leg B: hinge to the pointer's pin
EC = L - OE               # pointer: pin to tip
OF = EC / 2               # leg A: hinge to the link's pin
FG = OE                   # link: pin to pin
A1 = -100 deg             # leg A's direction in the assembled view
A2 = -80 deg              # leg B's direction

def leg(pin=50 mm) -> solid {
    blade = Hull(Circle(center=(0, 0), radius=9), Circle(center=(150, 0), radius=7),
                 Point(L, 0))
    hinge = clearance_hole(size=4, fit="fine", cx=0 mm, cy=0 mm)
    pin_hole = clearance_hole(size=4, fit="fine", cx=pin, cy=0 mm)
}

assembly caliper {
    leg_a = leg(pin=OF)
    leg_b = leg(pin=OE)
    solid pointer {
        blade = Hull(Circle(center=(0, 0), radius=7), Circle(center=(OF, 0), radius=7),
                     Point(EC, 0))
        pin_e = clearance_hole(size=4, fit="fine", cx=0 mm, cy=0 mm)
        pin_g = clearance_hole(size=4, fit="fine", cx=OF, cy=0 mm)
    }
    solid link {
        bar = Slot(start=(0, 0), end=(FG, 0), radius=7)
        pin_f = clearance_hole(size=4, fit="fine", cx=0 mm, cy=0 mm)
        pin_g = clearance_hole(size=4, fit="fine", cx=FG, cy=0 mm)
    }
    drawing phi {
        t = Text("φ = 1.618", position=(105, 0), size=5, font="sans", valign="middle")
    }
    drawing name {
        t = Text("GOLDEN MEAN", position=(75, 0), size=5, valign="middle")
    }
    CutInto(phi, leg_a)
    CutInto(name, leg_b)

    # flat layout
    Below(leg_b, leg_a, gap=6)
    AlignLeft(leg_b, leg_a)
    Below(pointer, leg_b, gap=6)
    AlignLeft(pointer, leg_b)
    Below(link, pointer, gap=6)
    AlignLeft(link, pointer)

    # 3D: lying flat, opened; leg B at the bottom, leg A and the pointer on it, the link on top
    Place(leg_b, position=(0, 0, 0), rotation=(0, 0, A2))
    Place(leg_a, position=(0, 0, 3), rotation=(0, 0, A1))
    Place(pointer, position=(OE * cos(A2), OE * sin(A2), 3), rotation=(0, 0, A1))
    Place(link, position=(OF * cos(A1), OF * sin(A1), 6), rotation=(0, 0, A2))

    # the request's numbers: tips 200 from the hinge, and the pointer's tip divides A-B by phi
    ax = L * cos(A1)
    ay = L * sin(A1)
    bx = L * cos(A2)
    by = L * sin(A2)
    cx_ = OE * cos(A2) + EC * cos(A1)
    cy_ = OE * sin(A2) + EC * sin(A1)
    assert leg_a.blade.bb.right == 200 mm, "tips 200 mm from the hinge"
    assert abs((cx_ - ax) * (by - ay) - (cy_ - ay) * (bx - ax)) < 1e-6 mm * mm,
        "the pointer's tip is on the line A-B"
    assert abs(sqrt((cx_ - ax) ** 2 + (cy_ - ay) ** 2) / sqrt((bx - cx_) ** 2 + (by - cy_) ** 2)
               - 1.618) < 0.001, "A-C : C-B = 1.618"
    assert pointer.pin_e.c.diameter == 4.3 mm, "4.3 mm rivet holes"
    assert leg_a.blade.bb.height == 18 mm, "legs 18 wide at the hinge"
}
