# Request (garden): a gravity latch for a garden gate, cut from 6 mm HDPE, three parts.
# - Latch bar 200 x 25 mm, its pivot end fully rounded (R12.5), its nose corners R4; an M6
#   pivot hole 15 mm from the pivot end, on the bar's centre line; a thumb lift: a round-ended
#   tab 18 mm wide standing 22 mm above the bar's top edge, its centre 40 mm from the nose,
#   joined with R3 fillets; "CLOSE THE GATE" engraved (serif outlines, 7 mm) along the bar
#   between the pivot and the lift.
# - Keeper for the post: 70 mm wide, a 27 mm wide notch (bar + 2 mm) 35 mm deep whose floor is
#   65 mm above the keeper's bottom; the horn on the gate side is a ramp rising from 70 mm at
#   the outer edge to 95 mm at the notch so the bar rides up and drops in; the far horn stands
#   110 mm tall as the stop. Corners rounded R3 (horn tops R5). Three countersunk M4 screw holes
#   (8 mm heads): two at 20 mm up, 15 mm in from each side, one centred 45 mm up.
# - A 30 mm washer with an M6 hole to go under the pivot bolt's head.

units mm
thickness 6 mm
import "std/fasteners.aidl"

param bar_len = 200 mm, min = 150 mm, max = 300 mm
param bar_h = 25 mm, min = 20 mm, max = 35 mm
notch_w = bar_h + 2 mm

assembly gate_latch {
    solid bar {
        body = RoundedRectangle(center=(0, 0), width=bar_len, height=bar_h,
                                corner_radii=[bar_h / 2, 4, 4, bar_h / 2])
        lift = Slot(center=(bar_len / 2 - 40, bar_h / 2), length=2 * 22 + 18, width=18,
                    rotation=90)
        Fillet([lift, body], 3)
        pivot = clearance_hole(size=6)
        pivot.c.center == (body.bb.left + 15, body.center.y)
        drawing words {
            w = Text("CLOSE THE GATE", position=(0, 0), size=7, font="serif",
                     valign="middle")
        }
        AlignCenterY(words, body)
        # centred between the pivot hole and the lift tab
        words.bb.center_x == (pivot.c.center.x + lift.bb.left) / 2
    }

    solid keeper {
        outline = Polygon([(0, 0), (70, 0), (70, 110), (48.5, 110), (48.5, 65), (21.5, 65),
                           (21.5, 95), (0, 70)])
        Fillet([outline.points[0], outline.points[1], outline.points[7]], 3)
        Fillet([outline.points[2], outline.points[3], outline.points[6]], 5)
        hole screws {
            a = Circle(center=(15, 20), diameter=4.5)
            b = Circle(center=(55, 20), diameter=4.5)
            c = Circle(center=(35, 45), diameter=4.5)
        }
        Countersink(screws, diameter=8)
    }

    solid washer {
        ring = Circle(center=(0, 0), diameter=30)
        bolt = clearance_hole(size=6)
        Concentric(bolt.c, ring)
    }

    Fixed(bar)
    RightOf(keeper, bar, gap=15)
    AlignBottom(keeper, bar)
    Below(washer, bar, gap=15)
    AlignLeft(washer, bar)

    # the request's numbers
    assert bar.body.bb.width == 200 mm and bar.body.bb.height == 25 mm, "bar 200 x 25"
    assert bar.pivot.c.center.x - bar.body.bb.left == 15 mm, "pivot 15 mm from the end"
    assert abs(bar.lift.bb.top - bar.body.bb.top - 22 mm) < 0.01 mm, "lift 22 mm above the bar"
    assert abs(bar.body.bb.right - bar.lift.center.x - 40 mm) < 0.01 mm, "lift 40 mm from nose"
    assert notch_w == 27 mm, "notch = bar + 2 mm"
    assert (keeper.outline.points[3].x - keeper.outline.points[4].x == 0 and
            keeper.outline.points[3].x - keeper.outline.points[6].x == notch_w), "notch 27 wide"
    assert keeper.outline.points[3].y - keeper.outline.points[4].y == 45 mm, "stop above floor"
    assert keeper.outline.points[4].y - keeper.outline.points[0].y == 65 mm, "floor 65 mm up"
    assert keeper.bb.width == 70 mm, "keeper 70 wide"
    assert bar.words.bb.right < bar.lift.bb.left - 3 mm, "the words clear the lift"
}
