# Request (crafts): a flat-pack yarn swift (skein winder) in 6 mm birch ply, no glue.
# - Two arms 580 mm long, standing on edge, 40 mm tall above the hub; they cross at their
#   middles in a cross halving (one slotted 20 mm from the top, the other 20 mm from the
#   bottom). Each arm stands on a 120 mm hub disc with two 15 mm tenons (30 mm either side of
#   the middle) into mortises in the disc; beyond the disc the arm reaches 6 mm lower, down
#   past the disc's top face.
# - Peg notches 10 mm deep in the arms' top edges at 150, 180, 210, 240 and 270 mm from the
#   centre on both ends; next to each, engraved, the skein length the four pegs give there
#   (4 x r x sqrt 2, in cm): 85 ... 153.
# - Four pegs 20 x 90 mm with round tops (R10), each with a 36 mm slot from the bottom so it
#   straddles an arm at a notch, its bottom flush with the arm's bottom.
# - The hub disc: the two pairs of mortises at right angles, and 4 M4 holes (4.5 mm) on a
#   70 mm circle at 45 deg for a lazy-susan bearing.
# All slots 0.2 mm wider than the 6 mm ply.

units mm
thickness 6 mm

import "std/joints.aidl"
import "std/shapes.aidl"

param t = 6 mm, min = 5 mm, max = 7 mm
half_len = 290 mm
arm_h = 40 mm           # above the hub's top face
fit = 0.2 mm
radii = [150, 180, 210, 240, 270]
def skein_cm(r) = round(4 * r * sqrt(2) / 10)

# an arm: y = 0 is the tenons' tips (the hub's underside); its body rises from y = t
def arm(from_top=true) -> solid {
    body = Rectangle(bottom_left=(-half_len, 0), width=2 * half_len, height=arm_h + t)
    tenons = tab_and_slot(part="tab", length=120, thickness=t, tabs=2, tab=15, screw=0,
                          rotation=180, cx=0, cy=0)
    if from_top {
        halving = cross_halving(depth=arm_h / 2, thickness=t, clearance=fit, cx=0,
                                cy=arm_h + t)
    } else {
        halving = cross_halving(depth=arm_h / 2, thickness=t, clearance=fit, rotation=180,
                                cx=0, cy=t)
    }
    for i in range(len(radii)) {
        notch_r = cross_halving(depth=10, thickness=t, clearance=fit, cx=radii[i],
                                cy=arm_h + t)
        notch_l = cross_halving(depth=10, thickness=t, clearance=fit, cx=-radii[i],
                                cy=arm_h + t)
    }
    drawing marks {
        for i in range(len(radii)) {
            right = Text(str(skein_cm(radii[i])), position=(radii[i], arm_h + t - 14), size=5,
                         valign="top")
            left = Text(str(skein_cm(radii[i])), position=(-radii[i], arm_h + t - 14), size=5,
                        valign="top")
        }
    }
}

assembly yarn_swift {
    arm_a = arm(from_top=true)
    arm_b = arm(from_top=false)

    solid hub {
        disc = Circle(center=(0, 0), diameter=120)
        along_a = tab_and_slot(part="slot", length=120, thickness=t, tabs=2, tab=15, screw=0,
                               clearance=fit, cx=0, cy=0)
        along_b = tab_and_slot(part="slot", length=120, thickness=t, tabs=2, tab=15, screw=0,
                               clearance=fit, rotation=90, cx=0, cy=0)
        bearing = bolt_circle(count=4, pcd=70, hole_d=4.5, start=45 deg)
        Concentric(bearing.pitch, disc)
    }

    solid peg {
        body = RoundedRectangle(bottom_left=(0, 0), width=20, height=90,
                                corner_radii=[10, 10, 0, 0])
        straddle = cross_halving(depth=36, thickness=t, clearance=fit, rotation=180, cx=10,
                                 cy=0)
    }
    pegs = LinearPattern(peg, 4, (30, 0))

    arm_a.bb.bottom_left == (0, 0)
    Above(arm_b, arm_a, gap=10)
    AlignLeft(arm_b, arm_a)
    Above(hub, arm_b, gap=10)
    AlignLeft(hub, arm_b)
    Above(peg, arm_b, gap=10)
    RightOf(peg, hub, gap=15)

    # the request's numbers
    assert arm_a.body.bb.width == 580 mm, "arms 580 long"
    assert arm_a.halving.depth + arm_b.halving.depth == arm_h, "halvings add to 40"
    assert arm_h == 40 mm, "40 mm above the hub"
    assert len(arm_a.notch_r) == 5 and len(arm_a.notch_l) == 5, "5 notches each end"
    assert peg.straddle.depth + arm_a.notch_r[0].depth == arm_h + t,
        "peg bottom flush with the arm's bottom"
    assert skein_cm(150) == 85 and skein_cm(270) == 153, "skein lengths 85 ... 153 cm"
    assert len(pegs) == 4, "four pegs"
    assert peg.body.bb.width == 20 mm and peg.body.bb.height == 90 mm, "pegs 20 x 90"
    assert hub.disc.diameter == 120 mm, "hub 120"
}
