# Request (crafts): a jeweller's bench pin for sawing and filing silver, 12 mm birch ply,
# two parts. A holder plate 160 x 100 mm screwed flat to the bench top at its front edge
# with four countersunk M5 screws (at x = +-60 mm, 40 and 80 mm back from the front edge,
# 10.4 mm heads). The pin drops into the holder's front edge on a flat sliding dovetail
# (two tails, 120 mm long, 15 mm deep, 12 degrees, 0.15 mm clearance) so it can be turned
# over or replaced. The pin sticks out 110 mm in front of the joint line, 120 mm wide
# there tapering to 90 mm at its tip, with the classic V slot: 30 mm wide at the tip,
# 60 mm deep, ending in a 10 mm round hole. "R. KAUR" engraved (single stroke, 8 mm)
# on the holder between the screws.

units mm
thickness 12 mm
import "std/joints.aidl"
import "std/fasteners.aidl"

assembly bench_pin {
    solid holder {
        body = Rectangle(bottom_left=(-80, 0), width=160, height=100)
        sock = dovetail(part="socket", length=120 mm, depth=15 mm, tails=2, angle=12 deg,
                        clearance=0.15 mm, cx=0, cy=0)
        for p in [(-60, 40), (60, 40), (-60, 80), (60, 80)] {
            screw = clearance_hole(size=5, cx=p[0], cy=p[1])
        }
        Countersink(screw, diameter=10.4)
        drawing mark {
            t = Text("R. KAUR", position=(0, 60), size=8, valign="middle")
        }
        Fixed(body)
    }
    solid pin {
        root = Rectangle(bottom_left=(-60, 0), width=120, height=15)
        taper = Trapezoid(center=(0, -55), bottom_width=90, top_width=120, height=110)
        tails = dovetail(part="tail", length=120 mm, depth=15 mm, tails=2, angle=12 deg,
                         cx=0, cy=0)
        hole vee {
            tri = Polygon([(-15.5, -112), (15.5, -112), (0, -50)])
            apex = Circle(center=(0, -50), diameter=10)
        }
        Fixed(root)
    }

    # flat on the sheet: the pin beside the holder
    RightOf(pin, holder, gap=10)
    AlignTop(pin, holder)

    # on the bench: holder flat, the pin's tails in its sockets
    Place(holder, position=(0, 0, 0), face="up")
    Place(pin, position=(0, 0, 0), face="up")

    assert holder.body.bb.width == 160 mm and holder.body.bb.height == 100 mm, "holder size"
    assert len(holder.screw) == 4, "four screws"
    assert holder.screw[0].c.diameter >= 5 mm, "M5 clearance"
    assert holder.screw[0].c.center.y - holder.body.bb.bottom == 40 mm, "screws 40 back"
    assert holder.screw[2].c.center.y - holder.body.bb.bottom == 80 mm, "screws 80 back"
    assert holder.screw[1].c.center.x - holder.screw[0].c.center.x == 120 mm, "screws +-60"
    assert holder.sock.depth == 15 mm and pin.tails.depth == 15 mm, "15 mm dovetail"
    assert holder.sock.length == 120 mm and pin.tails.length == 120 mm, "120 mm dovetail"
    assert pin.root.bb.bottom - pin.taper.bb.bottom == 110 mm, "pin sticks out 110"
    assert pin.taper.top_width == 120 mm and pin.taper.bottom_width == 90 mm, "taper"
    assert pin.vee.apex.center.y - pin.taper.bb.bottom == 60 mm, "V 60 deep"
    assert pin.vee.apex.diameter == 10 mm, "10 mm hole"
    assert distance(holder.mark, holder.screw[0]) >= 5 mm, "name clear of the screws"
    assert holder.mark.bb.bottom >= holder.sock.bb.top + 5 mm, "name clear of the joint"
}
