# Request: a tooth fairy box as a gift for my niece, 3 mm birch ply: a finger-jointed box with a
# hinged lid, 80 long x 60 wide x 45 tall outside (fingers at least 8 mm). On the lid, engraved
# filled: a molar tooth (a smooth outline 20 wide, 23 tall) in the middle, a five-pointed star
# (10 across) each side of it with its centre 22 from the tooth's centre, and AMELIA (bold italic
# serif, 7 tall) under the tooth. On the front: TOOTH FAIRY engraved filled (bold italic serif,
# 8 tall), centred, and a 16 mm half-round finger pull cut into the middle of its top edge so
# the lid is easy to lift.

import "std/boxes.aidl"

units mm
thickness 3 mm
kerf 0.15 mm

assembly fairy {
    box = hinged_box(length=80 mm, width=60 mm, height=45 mm, thickness=3 mm, finger=8 mm)

    drawing lid_art {
        tooth = Spline([(-10, 6), (-5, 11), (0, 8.5), (5, 11), (10, 6), (9, -2), (6.5, -12),
                        (3, -11), (0, -4), (-3, -11), (-6.5, -12), (-9, -2)],
                       closed=true, corners=[8], fill=true)
        left_star = Star(center=(-22, 0), points=5, outer_radius=5, inner_radius=2, fill=true)
        right_star = Star(center=(22, 0), points=5, outer_radius=5, inner_radius=2, fill=true)
        name = Text("AMELIA", position=(0, -20), size=7, font="serif:Bold Italic",
                    valign="middle", fill=true)
        Rigid(self)
    }
    CenterInside(lid_art, box.lid)
    CutInto(lid_art, box.lid)

    drawing front_word {
        t = Text("TOOTH FAIRY", position=(0, 0), size=8, font="serif:Bold Italic",
                 valign="middle", fill=true)
    }
    AlignCenterX(front_word, box.front)
    front_word.t.position.y == box.front.bb.center_y - 3 mm
    CutInto(front_word, box.front)

    hole pull {
        c = Circle(center=(0, 0), diameter=16)
    }
    pull.c.center.x == box.front.bb.center_x
    pull.c.center.y == box.front.bb.top
    CutInto(pull, box.front)

    # the request's numbers
    assert box.length == 80 mm and box.width == 60 mm and box.height == 45 mm, "80 x 60 x 45"
    assert box.finger >= 8 mm, "fingers 8 or more"
    assert lid_art.tooth.points[4].x - lid_art.tooth.points[0].x == 20 mm, "tooth 20 wide"
    assert lid_art.tooth.points[1].y - lid_art.tooth.points[6].y == 23 mm, "tooth 23 tall"
    assert lid_art.right_star.center.x - lid_art.left_star.center.x == 44 mm, "stars 22 each side"
    assert lid_art.left_star.outer_radius == 5 mm, "stars 10 across"
    assert distance(lid_art.name, lid_art.tooth) >= 2 mm, "name clear of the tooth"
    assert lid_art.bb.width <= box.lid.bb.width - 10 mm, "art inside the lid"
    assert distance(front_word, pull) >= 3 mm, "words clear of the finger pull"
    assert pull.c.diameter == 16 mm, "16 mm pull"
}
