# Request: a low display stand (jita) for a shohin bonsai, 6 mm walnut ply, glued.
# - Top 260 x 160 mm, R10 corners, its upper face 96 mm above the floor.
# - Two end legs, 90 mm tall under the top, 130 mm wide under the top flaring to
#   150 mm at the floor; each with an arch cut up from the floor edge, 100 mm wide
#   and 30 mm high with R15 upper corners, leaving two feet. Legs stand at x = -100
#   and +100 mm (200 mm apart, centre to centre) and go through the top with two
#   30 mm tenons each, flush with the top's upper face.
# - A stretcher 236 mm long and 40 mm tall, its underside 20 mm above the floor,
#   crossing each leg's middle by a cross-halving (15 mm deep in each part), its ends
#   standing 15 mm out past the legs' outer faces.
# - My seal engraved in the top's front right corner, between the right leg and the
#   end: a 14 mm square frame (R2) around "KM" in filled serif letters 6 mm tall.
# Slots 0.1 mm over for glue.

# FIX after the first valid program: W0513, "KM" at 6 mm came 0.15 mm from the 14 mm
# frame (seen in the PNG: the K and M touch the frame's sides). The frame is the
# seal's size, so the letters go down to 5.5 mm (the hint's limit was 5.52 mm).

units mm
thickness 6 mm
import "std/joints.aidl"

def leg() -> solid {
    # seen from the end: x across the stand's depth, y up from the floor
    body = Trapezoid(center=(0, 48), bottom_width=150, top_width=130, height=96)
    hole arch {
        a = RoundedRectangle(center=(0, 14), width=100, height=32,
                             corner_radii=[15, 15, 0, 0], overrun=true)
    }
    tenons = tab_and_slot(part="tab", length=130, thickness=6, tabs=2, tab=30, screw=0,
                          cx=0, cy=96)
    halving = cross_halving(depth=15, thickness=6, clearance=0.1, rotation=180 deg,
                            cx=0, cy=30)
}

assembly bonsai_stand {
    solid top {
        board = RoundedRectangle(center=(0, 0), width=260, height=160, corner_radius=10)
        mortise_r = tab_and_slot(part="slot", length=130, thickness=6, tabs=2, tab=30,
                                 screw=0, clearance=0.1, rotation=90 deg, cx=100, cy=0)
        mortise_l = tab_and_slot(part="slot", length=130, thickness=6, tabs=2, tab=30,
                                 screw=0, clearance=0.1, rotation=90 deg, cx=-100, cy=0)
        drawing seal {
            frame = RoundedRectangle(center=(116.5, -60), width=14, height=14, corner_radius=2)
            initials = Text("KM", position=(116.5, -60), size=5.5, font="serif:Bold",
                            valign="middle", fill=true)
        }
    }

    leg_r = leg()
    leg_l = leg()

    solid stretcher {
        bar = Rectangle(center=(0, 40), width=236, height=40)
        halving_r = cross_halving(depth=15, thickness=6, clearance=0.1, cx=100, cy=60)
        halving_l = cross_halving(depth=15, thickness=6, clearance=0.1, cx=-100, cy=60)
    }

    # flat on the sheet
    RightOf(leg_r, top, gap=10)
    AlignTop(leg_r, top)
    RightOf(leg_l, leg_r, gap=10)
    AlignTop(leg_l, leg_r)
    Below(stretcher, top, gap=10)
    AlignLeft(stretcher, top)

    # assembled: x along the stand, y its depth (front -y), z up from the floor
    Place(top, position=(0, 0, 90), face="up", up="back")
    Place(leg_r, position=(97, 0, 0), face="right", up="up")
    Place(leg_l, position=(-103, 0, 0), face="right", up="up")
    Place(stretcher, position=(0, 3, 0), face="front", up="up")

    # the request's numbers
    assert top.board.width == 260 mm and top.board.height == 160 mm, "top 260 x 160"
    assert leg_r.body.height - 6 mm == 90 mm, "legs 90 tall under the top"
    assert leg_r.body.top_width == 130 mm and leg_r.body.bottom_width == 150 mm,
        "legs 130 flaring to 150"
    assert leg_r.arch.a.width == 100 mm and leg_r.arch.a.bb.top - leg_r.body.bb.bottom == 30 mm,
        "arch 100 wide, 30 high"
    assert top.mortise_r.slot[0].bb.center_x - top.mortise_l.slot[0].bb.center_x == 200 mm,
        "legs 200 apart"
    assert len(top.mortise_r.slot) == 2, "two tenons per leg"
    assert stretcher.bar.width == 236 mm and stretcher.bar.height == 40 mm, "stretcher 236 x 40"
    assert stretcher.bar.bb.bottom - 0 mm == 20 mm, "stretcher 20 above the floor"
    assert stretcher.bar.bb.right - (stretcher.halving_r.cut.bb.center_x + 3 mm) == 15 mm,
        "stretcher ends 15 past the legs"
    assert (leg_r.halving.cut.bb.top - leg_r.arch.a.bb.top) + (stretcher.bar.bb.top - stretcher.halving_r.cut.bb.bottom) >= 30 mm,
        "halvings fill the 30 mm overlap"
    assert top.seal.frame.width == 14 mm, "seal 14 mm"
    assert top.seal.bb.left - (top.mortise_r.slot[0].bb.right) >= 4 mm, "seal clear of the leg"
    assert top.board.bb.right - top.seal.bb.right >= 4 mm, "seal clear of the end"
}
