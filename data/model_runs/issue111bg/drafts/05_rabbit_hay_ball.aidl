# Request (pets): a forage ball for our rabbits, stuffed with hay, cut from 4 mm untreated
# poplar ply and slotted together without glue. Two discs 100 mm across, cross-halved at right
# angles into a 3D star: one slotted from its rim to its centre from the top, the other from
# the bottom, the slots 4 mm + 0.1 mm clearance wide. Each disc has six 22 mm holes evenly
# round a 32 mm radius, none on the slot's line, to poke the hay through.

units mm
thickness 4 mm
import "std/joints.aidl"

T = 4 mm
D = 100 mm

def disc(from_top=true) -> solid {
    body = Circle(center=(0, 0), diameter=D)
    hole port { c = Circle(center=(32, 0), diameter=22) }
    ports = CircularPattern(port, 6, body.center)
    if from_top {
        slot = cross_halving(depth=D / 2, thickness=T, clearance=0.1 mm, cx=0 mm, cy=D / 2)
    } else {
        slot = cross_halving(depth=D / 2, thickness=T, clearance=0.1 mm, rotation=180 deg,
                             cx=0 mm, cy=-D / 2)
    }
}

assembly hay_ball {
    upper = disc(from_top=true)
    lower = disc(from_top=false)

    # flat on the sheet
    RightOf(lower, upper, gap=10)
    AlignCenterY(lower, upper)

    # assembled: one disc in the x-z plane, the other in the y-z plane, crossing on z
    Place(upper, position=(0, T / 2, D / 2), rotation=(90 deg, 0, 0))
    Place(lower, position=(-T / 2, 0, D / 2), rotation=(90 deg, 0, 90 deg))

    # the request's numbers
    assert upper.body.diameter == 100 mm, "discs 100 across"
    assert len(upper.ports) == 6, "six holes"
    assert upper.port.c.diameter == 22 mm, "22 mm holes"
    assert distance(upper.ports[1].c.center, upper.body.center) == 32 mm, "on a 32 mm radius"
    assert upper.slot.cut.bb.width == 4.1 mm, "4 mm + 0.1 clearance"
    assert upper.slot.cut.bb.height + lower.slot.cut.bb.height == 100 mm, "the slots meet"
    assert upper.slot.cut.bb.bottom == upper.body.center.y, "rim to centre"
    assert upper.ports[1].c.center.x - 11 mm - upper.slot.cut.bb.right >= 2 mm, "holes clear of the slot"
}
