# Request (camping): a lantern post for a tent pitch, 9 mm birch ply, two boards cross-halved
# into a + section. The stake: 40 mm wide, 400 mm tall, its lower 100 mm tapered to a point
# for the ground. The hook board: 40 mm wide, standing from 150 mm above the stake's tip to a
# shepherd's crook: its shaft narrows to a 16 mm arm over its top 80 mm (from 440 to 520 mm
# up), the arm arcs over on a 40 mm radius (to its centre line), drops 50 mm, then curls up on
# an 18 mm radius, leaving a throat of at least 20 mm for a lantern's bail. The halving: a
# 9.2 mm slot 125 mm up into the hook board from its bottom and 125 mm down into the stake
# from its top (the + runs 250 mm, from 150 to 400 mm). "PITCH 7" filled-engraved up the hook
# board's shaft, 14 mm sans Bold.

units mm
thickness 9 mm
import "std/joints.aidl"

assembly lantern_post {
    solid stake {
        body = Polygon([(20, 0), (40, 100), (40, 400), (0, 400), (0, 100)])
        slot = cross_halving(depth=125 mm, thickness=9 mm, clearance=0.2 mm, cx=20 mm, cy=400 mm)
    }
    solid hook {
        shaft = Polygon([(0, 150), (40, 150), (40, 440), (28, 520), (12, 520), (0, 440)])
        crook = ArcSlot(center=(60, 520), radius=40, start_angle=0 deg, end_angle=180 deg, width=16)
        drop = Slot(start=(100, 520), end=(100, 470), width=16)
        curl = ArcSlot(center=(82, 470), radius=18, start_angle=180 deg, end_angle=360 deg, width=16)
        slot = cross_halving(depth=125 mm, thickness=9 mm, clearance=0.2 mm, rotation=180 deg,
                             cx=20 mm, cy=150 mm)
        drawing name {
            t = Text("PITCH 7", position=(20, 360), size=14, rotation=90 deg, font="sans:Bold",
                     valign="middle", fill=true)
        }
    }
    RightOf(hook, stake, gap=10)
    AlignBottom(hook, stake)
    # the stake across x, the hook board across y, both centred on the post's axis
    Place(stake, position=(-20, 4.5, 0), face="front", up="up")
    Place(hook, position=(-4.5, -20, 0), face="right", up="up")

    assert stake.body.bb.width == 40 mm and stake.body.bb.height == 400 mm, "stake 40 x 400"
    assert stake.body.points[4].y - stake.body.points[0].y == 100 mm, "100 mm spike"
    assert hook.shaft.bb.width == 40 mm, "hook board 40 wide"
    assert hook.shaft.bb.bottom - stake.body.bb.bottom == 150 mm, "hook board from 150 mm up"
    assert hook.crook.radius == 40 mm and hook.crook.width == 16 mm, "40 mm crook, 16 mm arm"
    assert hook.drop.start.y - hook.drop.end.y == 50 mm, "50 mm drop"
    assert hook.curl.radius == 18 mm, "18 mm curl"
    assert (hook.drop.start.x - hook.drop.width / 2) - (hook.curl.start.x + hook.curl.width / 2) >= 20 mm, "20 mm throat"
    assert stake.slot.depth + hook.slot.depth == 400 mm - 150 mm, "halvings meet over the 250 mm overlap"
    assert stake.slot.depth == 125 mm and hook.slot.depth == 125 mm, "125 mm each"
}
