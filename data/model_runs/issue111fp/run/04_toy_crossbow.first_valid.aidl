# Request: a rubber-band toy crossbow that shoots 6 mm dowel bolts with foam tips, from 6 mm
# ply, glued as a three-layer stock. Stock 330 mm long (butt at x 0, muzzle at x 330), top
# at y 0, fore-end 28 deep, butt 44 deep at its end, a pistol grip 28 wide at its foot
# hanging to 105 below the top. The two side layers stand 4 mm above the core from x 100 to
# the muzzle, so the core's top and the sides make a 6 x 4 mm groove the bolt rides in.
# The core is two pieces (rear to x 108, front from x 134): the gap between is the trigger's
# cavity. The trigger (6 mm ply) pivots on a 6 mm dowel at (120, -14) through both sides;
# its nose stands 6 mm above the rails and holds the band; its blade hangs 30 below the
# stock. The prod (bow) is 240 long, 24 wide in the middle tapering to 14 at the tips, with
# a 6 mm band notch on its rear edge 6 mm from each tip; it slides through a 24 x 6.3 slot
# centred at (304, -14) in all three layers. Corners rounded: butt R6, grip foot R10,
# muzzle R4. "SOFT TIPS ONLY - NEVER AT FACES" engraved on the right side.

thickness 6 mm

PIVOT = (120, -14)
SLOT_C = (304, -14)

# the side layers' outline: the rails step up 4 mm at x 100
SIDE_PTS = [(0, 0), (100, 0), (100, 4), (330, 4), (330, -28), (106, -28), (98, -105),
            (70, -105), (74, -40), (0, -44)]

def side(label=false) -> solid {
    outline = Polygon(SIDE_PTS)
    Fillet([outline.points[0], outline.points[9]], 6)
    Fillet([outline.points[6], outline.points[7]], 10)
    Fillet([outline.points[3], outline.points[4]], 4)
    hole pivot { c = Circle(center=PIVOT, diameter=6.2) }
    hole prod_slot { r = Rectangle(center=SLOT_C, width=24, height=6.3) }
    if label {
        drawing warning {
            t = Text("SOFT TIPS ONLY - NEVER AT FACES", position=(215, -12), size=4,
                     valign="middle")
        }
    }
}

assembly crossbow {
    right_side = side(label=true)
    left_side = side()
    solid core_rear {
        outline = Polygon([(0, 0), (108, 0), (106, -28), (98, -105), (70, -105), (74, -40),
                           (0, -44)])
        Fillet([outline.points[0], outline.points[6]], 6)
        Fillet([outline.points[3], outline.points[4]], 10)
    }
    solid core_front {
        r = Rectangle(bottom_left=(134, -28), width=196, height=28)
        Fillet([r.bottom_right, r.top_right], 4)
        hole prod_slot { r = Rectangle(center=SLOT_C, width=24, height=6.3) }
    }
    solid trigger {
        lever = Polygon([(113, 10), (121, 10), (126, -12), (127, -40), (123, -58), (115, -58),
                         (117, -40), (114, -12)])
        Fillet(2)
        hole pivot { c = Circle(center=PIVOT, diameter=6.2) }
    }
    solid prod {
        limb = Polygon([(-120, -7), (-12, -12), (12, -12), (120, -7), (120, 7), (12, 12),
                        (-12, 12), (-120, 7)])
        hole notches {
            l = Circle(center=(-114, -7), diameter=6)
            r = Circle(center=(114, -7), diameter=6)
        }
    }

    # flat on the sheet: each part beside the last
    Below(left_side, right_side, gap=8)
    AlignLeft(left_side, right_side)
    Below(core_rear, left_side, gap=8)
    AlignLeft(core_rear, left_side)
    RightOf(core_front, core_rear, gap=8)
    AlignTop(core_front, core_rear)
    Below(prod, core_front, gap=8)
    AlignLeft(prod, core_front)
    RightOf(trigger, right_side, gap=8)
    AlignTop(trigger, right_side)

    # in 3D the crossbow points along +x, up is +z; layers stacked across y
    Place(right_side, position=(0, -3, 0), face="front", up="up")
    Place(core_rear, position=(0, 3, 0), face="front", up="up")
    Place(core_front, position=(0, 3, 0), face="front", up="up")
    Place(trigger, position=(0, 3, 0), face="front", up="up")
    Place(left_side, position=(0, 9, 0), face="front", up="up")
    # the prod lies flat through the slot, its notched edge toward the butt
    Place(prod, position=(304, 0, -17), face="up", up="+x")

    # the request's numbers
    assert right_side.outline.bb.width == 330 mm, "stock 330 long"
    assert right_side.outline.bb.top - core_front.r.bb.top == 4 mm, "rails 4 above the core"
    assert trigger.lever.bb.top - right_side.outline.bb.top == 6 mm, "nose 6 above the rails"
    assert -28 mm - trigger.lever.bb.bottom == 30 mm, "blade 30 below the fore-end"
    assert core_front.r.bb.left - 134 mm == 0 mm and trigger.lever.bb.right <= 134 mm - 4 mm,
        "trigger clear of the front core"
    assert prod.limb.bb.width == 240 mm, "prod 240 long"
    assert prod.limb.bb.height == 24 mm, "prod 24 wide"
    assert 24 mm == right_side.prod_slot.r.width, "slot fits the prod's middle"
    assert 6 mm + 6 mm + 6 mm <= 2 * 12 mm, "the 18 mm stack stays in the prod's untapered middle"
}
