# Request: a Halloween trick-or-treat sweet box, cut from 3 mm ply: a rounded box 200 mm
# long, 150 mm wide, 120 mm tall (outside), corners R50, its wall bent round on living
# hinges (the std flex box), with a lift-off lid. "TRICK OR TREAT" engraved filled in a
# bold serif across the middle of the wall's long straight face (the side opposite the
# seam), at most 90 mm wide; a bat silhouette 80 mm across cut through the middle of the
# lid, which is also the finger hole to lift it.

units mm
thickness 3 mm
import "std/boxes.aidl"

assembly cauldron {
    box = flex_box(length=200 mm, width=150 mm, height=120 mm, radius=50 mm, thickness=3 mm)

    drawing label {
        t = Text("TRICK OR TREAT", position=(0, 0), size=12, font="serif:Bold",
                 valign="middle", fill=true, max_width=90 mm)
    }
    CutInto(label, box.wall)
    AlignCenterX(label.t.position, box.wall)
    AlignCenterY(label.t.position, box.wall)

    hole bat {
        wings = Polygon([(0, 6), (3, 13), (6, 7), (14, 10), (26, 15), (40, 14), (35, 2),
                         (28, 6), (22, -2), (15, 2), (8, -7), (0, -12)], mirror="y")
    }
    CutInto(bat, box.lid)
    CenterInside(bat, box.lid)
    # FIX after the first valid program: the lid's lip is a whole plate glued under the lid,
    # so the bat was a blind pocket (the lip showed through it, no finger hole). Cut the same
    # bat through the lid's lip.
    hole lip_bat {
        wings = Polygon([(0, 6), (3, 13), (6, 7), (14, 10), (26, 15), (40, 14), (35, 2),
                         (28, 6), (22, -2), (15, 2), (8, -7), (0, -12)], mirror="y")
    }
    CutInto(lip_bat, box.lip[1])
    CenterInside(lip_bat, box.lip[1])

    # the request's numbers
    assert box.length == 200 mm and box.width == 150 mm and box.height == 120 mm, "200 x 150 x 120"
    assert box.radius == 50 mm, "corners R50"
    assert label.t.bb.width <= 90 mm, "the words fit the straight face"
    assert bat.bb.width == 80 mm, "bat 80 across"
}
