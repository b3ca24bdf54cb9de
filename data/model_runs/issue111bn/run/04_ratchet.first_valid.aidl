# Request: an orchestral ratchet (a rattle: swing it round its handle and a wooden tongue clicks
# over a toothed wheel), layered from 3 mm birch ply. An 8 mm dowel is the axle and handle. On it
# a 10-tooth wheel, module 4 (48 mm over the tips), with an 8 mm bore to glue it to the dowel.
# Round it swings a frame: two plates 60 wide x 170 long with round ends, an 8.6 mm hole in the
# centre of one round end so they spin freely on the dowel; between the plates at the far end a
# 45 mm spacer block glued to both, with a 4 mm wide tongue cut from the same piece reaching
# toward the wheel and pressing 3 mm into the teeth. "RATCHET" engraved 7 mm tall along the top
# plate, centred between the wheel's tips and the block.

import "std/gears.aidl"

thickness 3 mm
T = 3 mm
PLATE_L = 170 mm
PLATE_W = 60 mm
AXLE_TO_FAR = PLATE_L - PLATE_W / 2      # axle to the far round end's centre... plus its radius
BLOCK_L = 45 mm
TEETH = 10
MODULE = 4 mm
TIP_R = MODULE * (TEETH + 2) / 2
BITE = 3 mm
TONGUE_W = 4 mm

def plate(label=false) -> solid {
    outline = Slot(start=(0, 0), end=(PLATE_L - PLATE_W, 0), width=PLATE_W)
    hole axle { c = Circle(center=(0, 0), diameter=8.6) }
    if label {
        drawing name {
            t = Text("RATCHET", position=((TIP_R + PLATE_L - PLATE_W / 2 - BLOCK_L) / 2, 0), size=7,
                     valign="middle")
        }
    }
    Fixed(outline)
}

assembly ratchet {
    bottom = plate()
    top = plate(label=true)
    wheel = spur_gear(teeth=TEETH, module=MODULE, bore=8 mm, phase=180 deg / TEETH)

    solid block {
        # written in the frame's coordinates: the axle at (0, 0)
        body = RoundedRectangle(bottom_left=(PLATE_L - PLATE_W / 2 - BLOCK_L, -PLATE_W / 2),
                                width=BLOCK_L, height=PLATE_W,
                                corner_radii=[0, PLATE_W / 2, PLATE_W / 2, 0])
        tongue = Rectangle(bottom_left=(TIP_R - BITE, -TONGUE_W / 2),
                           width=PLATE_L - PLATE_W / 2 - BLOCK_L - (TIP_R - BITE) + 1 mm,
                           height=TONGUE_W)
        Fixed(body)
        assert body.bb.width == 45 mm, "block 45 long"
        # the axle sits 30 mm in from the plates' near end, 140 from the far end
        assert tongue.bb.left - (body.bb.right - (PLATE_L - PLATE_W / 2)) == 24 mm - 3 mm,
            "tongue 3 mm into the 48 mm wheel"
    }

    assert top.outline.bb.width == 170 mm and top.outline.bb.height == 60 mm, "plates 60 x 170"
    assert wheel.tip.diameter == 48 mm, "wheel 48 over the tips"
    assert wheel.teeth == 10, "10 teeth"

    # sheet
    RightOf(top, bottom, gap=6)
    AlignCenterY(top, bottom)
    Below(block, bottom, gap=6)
    AlignRight(block, top)
    Below(wheel, bottom, gap=6)
    AlignLeft(wheel, bottom)

    # 3D: the layers stacked on the axle (z up): bottom plate, wheel and block, top plate
    Place(bottom, position=(0, 0, 0))
    Place(wheel, position=(0, 0, T))
    Place(block, position=(0, 0, T))
    Place(top, position=(0, 0, 2 * T))
    AllowOverlap(wheel, block)    # the tongue presses into the teeth: that is the click
}
