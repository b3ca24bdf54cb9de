# Request (camping, winter): a knock-down ice-fishing tip-up in 9 mm marine ply. The frame is
# one cross-shaped piece: an arm 450 x 40 mm that lies across the ice hole on its edge, and a
# mast 40 mm wide through its middle, reaching 350 mm below the ice and 200 mm above it with
# a round top. A second arm, 450 x 40 (R5 corners), slides through a 9.2 x 40.2 mm mortise in
# the frame's crossing to make the cross. Under water, a spool turns on an M8 bolt (8.5 mm
# hole) 320 mm below the ice: two 70 mm flanges and a 30 mm hub glued together, a 6 mm crank
# peg hole 25 mm off centre in one flange. A 5 mm line guide hole in the mast 30 mm below the
# ice. A flag 196 mm long x 16 wide with round ends swings on an M4 bolt (4.5 mm hole) 185 mm
# above the ice, with a 70 x 50 pennant at its tip and a star cut in it. Engraved on the
# arm: the owner's name and phone "J LINDQVIST 070 555 0123" (as the rules ask) and "TIP-UP".

units mm
thickness 9 mm

T = 9 mm
arm_l = 450 mm
arm_h = 40 mm
mast_w = 40 mm
below = 350 mm
above = 200 mm
spool_z = -320 mm
flag_z = 185 mm

def disc(d=70 mm, crank=false) -> solid {
    c = Circle(center=(0, 0), diameter=d)
    hole axle { a = Circle(center=(0, 0), diameter=8.5) }
    if crank {
        hole peg { p = Circle(center=(25, 0), diameter=6) }
    }
}

assembly tip_up {
    solid frame {
        arm = Rectangle(center=(0, arm_h / 2), width=arm_l, height=arm_h)
        mast = RoundedRectangle(bottom_left=(-mast_w / 2, -below), width=mast_w,
                                height=below + above, corner_radii=[mast_w / 2, mast_w / 2, 0, 0])
        hole mortise { m = Rectangle(center=(0, arm_h / 2), width=T + 0.2 mm, height=arm_h + 0.2 mm) }
        hole bolt { c = Circle(center=(0, spool_z), diameter=8.5) }
        hole guide { c = Circle(center=(0, -30), diameter=5) }
        hole pivot { c = Circle(center=(0, flag_z), diameter=4.5) }
        drawing marks {
            owner = Text("J LINDQVIST 070 555 0123", position=(-120, arm_h / 2), size=6,
                         valign="middle")
            title = Text("TIP-UP", position=(120, arm_h / 2), size=14, font="sans:Bold",
                         valign="middle", fill=true)
        }
    }

    solid arm_b {
        bar = RoundedRectangle(center=(0, arm_h / 2), width=arm_l, height=arm_h, corner_radius=5)
    }

    solid flag {
        # FIX after the first valid program: the stem's round top poked 0.46 mm over the
        # pennant's top edge (W0520); the stem now ends inside the pennant, which starts at
        # the stem's left edge
        stem = RoundedRectangle(center=(0, 71), width=16, height=158, corner_radius=8)
        pennant = Polygon([(-8, 188), (70, 163), (-8, 138)])
        hole pivot { c = Circle(center=(0, 0), diameter=4.5) }
        hole star { s = Star(center=(22, 163), points=5, outer_radius=8, inner_radius=3.5) }
    }

    flange_a = disc(d=70 mm, crank=true)
    hub = disc(d=30 mm)
    flange_b = disc(d=70 mm)

    # flat on the sheet
    RightOf(arm_b, frame, gap=10)
    AlignTop(arm_b, frame)
    Below(flag, arm_b, gap=10)
    AlignLeft(flag, arm_b)
    RightOf(flange_a, flag, gap=10)
    AlignTop(flange_a, flag)
    RightOf(flange_b, flange_a, gap=5)
    AlignTop(flange_b, flange_a)
    Below(hub, flange_a, gap=5)
    AlignLeft(hub, flange_a)

    # assembled: the ice at z = 0, the frame in the x-z plane, arm_b along y
    Place(frame, position=(0, T / 2, 0), face="front", up="up")
    Place(arm_b, position=(-T / 2, 0, 0), face="right", up="up")
    Place(flag, position=(0, -T / 2, flag_z), face="front", up="up")
    Place(flange_b, position=(0, -T / 2 - 1 mm, spool_z), face="front", up="up")
    Place(hub, position=(0, -T / 2 - 1 mm - T, spool_z), face="front", up="up")
    Place(flange_a, position=(0, -T / 2 - 1 mm - 2 * T, spool_z), face="front", up="up")

    # the request's numbers
    assert frame.arm.bb.width == 450 mm and frame.arm.bb.height == 40 mm, "arm 450 x 40"
    assert arm_b.bar.bb.width == 450 mm and arm_b.bar.bb.height == 40 mm, "second arm 450 x 40"
    assert frame.arm.bb.bottom - frame.mast.bb.bottom == 350 mm, "mast 350 below the ice"
    assert frame.mast.bb.top - frame.arm.bb.bottom == 200 mm, "mast 200 above the ice"
    assert frame.mortise.m.bb.width == 9.2 mm and frame.mortise.m.bb.height == 40.2 mm, "mortise 9.2 x 40.2"
    assert frame.arm.bb.bottom - frame.bolt.c.center.y == 320 mm, "spool 320 below the ice"
    assert frame.pivot.c.center.y - frame.arm.bb.bottom == 185 mm, "flag pivot 185 above"
    assert frame.arm.bb.bottom - frame.guide.c.center.y == 30 mm, "guide 30 below"
    assert flange_a.c.diameter == 70 mm and hub.c.diameter == 30 mm, "70 flanges, 30 hub"
    assert distance(flange_a.peg.p.center, flange_a.c.center) == 25 mm, "crank 25 off centre"
    assert flag.pennant.bb.top - flag.stem.bb.bottom == 196 mm and flag.stem.bb.width == 16 mm, "flag 196 x 16"
    assert flag.pennant.bb.right - flag.stem.bb.center_x == 70 mm and flag.pennant.bb.height == 50 mm, "pennant 70 x 50"
    assert frame.marks.owner.bb.right < frame.mortise.bb.left - (mast_w / 2 - T / 2),
        "the name stays on the left arm, clear of the mast"
}
