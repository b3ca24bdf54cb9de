# Request: a Longworth chuck for my wood lathe, to hold bowls by the rim while I turn the foot.
# Two 12 mm birch-ply discs, 300 mm across. Each disc has 6 curved slots 9 mm wide (for M8
# bolts with rubber bumpers) running from 60 mm to 130 mm out from the centre; the back disc's
# slots curve the other way, so turning the front disc moves the six crossings in and out
# together. Back disc: screwed to my 100 mm faceplate through 4 pilot holes 4 mm across on an
# 80 mm circle, a 10 mm hole in the centre for the M8 T-nut of the pivot. Front disc: an 8.5 mm
# pivot hole countersunk 17 mm across for an M8 flat head, two 12 mm holes for turning handles
# (dowels) 132 mm out, opposite each other between the slots, and "LONGWORTH 300" engraved
# round the pivot on a 40 mm circle.

units mm
thickness 12 mm
import "std/shapes.aidl"

disc_d = 300 mm
slot_w = 9 mm
r_in = 60 mm
r_out = 130 mm
arc_r = 90 mm      # each slot is an arc of a 90 mm circle that runs through the disc's centre
psi_in = 2 * asin(r_in / (2 * arc_r))
psi_out = 2 * asin(r_out / (2 * arc_r))

# one disc with its six slots; hand=1 curves one way, hand=-1 the mirror way
def chuck_disc(hand=1) -> solid {
    disc = Circle(center=(0, 0), diameter=disc_d)
    hole slots {
        for i in range(6) {
            s = ArcSlot(center=polar((0, 0), arc_r, i * 60 deg), radius=arc_r,
                        start_angle=(i * 60 deg + 180 deg + psi_in if hand > 0
                                     else i * 60 deg + 180 deg - psi_out),
                        end_angle=(i * 60 deg + 180 deg + psi_out if hand > 0
                                   else i * 60 deg + 180 deg - psi_in),
                        width=slot_w)
        }
    }
}

assembly chuck {
    solid back {
        d = chuck_disc(hand=-1)
        hole tnut { c = Circle(center=(0, 0), diameter=10) }
        pilots = bolt_circle(count=4, pcd=80, hole_d=4, start=45 deg)
    }

    solid front {
        d = chuck_disc(hand=1)
        hole pivot { c = Circle(center=(0, 0), diameter=8.5) }
        hole handles {
            h1 = Circle(center=polar((0, 0), 132, -14 deg), diameter=12)
            h2 = Circle(center=polar((0, 0), 132, 166 deg), diameter=12)
        }
        drawing label {
            ring = Circle(center=(0, 0), radius=40, construction=true)
            t = Text("LONGWORTH 300", along=ring, size=6)
        }
        Countersink(pivot, diameter=17)
    }

    # side by side on the sheet; stacked on the lathe
    RightOf(front, back, gap=10)
    AlignCenterY(front, back)
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 12))

    # the request's numbers
    assert len(front.d.slots.s) == 6, "six slots in the front disc"
    assert len(back.d.slots.s) == 6, "six slots in the back disc"
    assert front.d.disc.diameter == 300 mm, "300 mm discs"
    assert back.d.disc.diameter == 300 mm, "300 mm discs"
    assert front.d.slots.s[0].width == 9 mm, "9 mm slots"
    assert abs(distance(front.d.slots.s[0].start, front.d.disc.center) - 60 mm) < 0.01 mm,
        "front slot starts 60 mm out"
    assert abs(distance(front.d.slots.s[0].end, front.d.disc.center) - 130 mm) < 0.01 mm,
        "front slot ends 130 mm out"
    assert abs(distance(back.d.slots.s[0].start, back.d.disc.center) - 130 mm) < 0.01 mm,
        "back slot (other hand) starts at its outer end"
    assert abs(distance(back.d.slots.s[0].end, back.d.disc.center) - 60 mm) < 0.01 mm,
        "back slot ends 60 mm out"
    assert back.pilots.bolt[0].diameter == 4 mm, "4 mm pilot holes"
    assert len(back.pilots.bolt) == 4, "four faceplate screws"
    assert abs(distance(front.handles.h1.center, front.d.disc.center) - 132 mm) < 0.01 mm,
        "handles 132 mm out"
    assert distance(front.handles, front.d.slots) >= 10 mm, "handles clear of the slots"
    assert distance(front.label, front.d.slots) >= 3 mm, "label clear of the slots"
    assert distance(front.label, front.pivot) >= 3 mm, "label clear of the pivot"
    assert disc_d / 2 - (130 mm + 9 mm / 2) >= 10 mm, "a rim of at least 10 mm outside the slots"
}
