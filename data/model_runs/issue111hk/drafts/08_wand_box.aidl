# Request (gifts): a presentation box for a hand-turned wand I am giving my nephew Alex, 3 mm
# birch ply: a finger-jointed pencil-box with a lid that slides out along its length, 330 mm
# long, 60 mm wide, 45 mm tall outside (10 mm fingers, 0.3 mm lid clearance). On the lid,
# reading along its length from the finger pull: "ALEX" engraved filled in bold serif, 20 mm
# tall, centred on the lid, and under it the wand-maker's line "CHERRY - 12 IN - PHOENIX
# FEATHER" engraved 4.5 mm tall; at the lid's far end a column of three filled five-pointed
# stars (10 mm across the tips), 14 mm apart, the first 15 mm from that end. Everything at
# least 4 mm in from the lid's edges and clear of the finger pull.

import "std/boxes.aidl"

units mm
thickness 3 mm

param t = 3 mm, min = 2, max = 6

assembly gift {
    # length is across the lid (x on the sheet), width along it: the lid slides out lengthwise
    box = sliding_lid_box(length=60 mm, width=330 mm, height=45 mm, thickness=t,
                          finger=10 mm, clearance=0.3 mm)

    drawing label {
        name = Text("ALEX", (0, 0), size=20, font="serif:Bold", fill=true, rotation=90 deg,
                    valign="middle")
        maker = Text("CHERRY - 12 IN - PHOENIX FEATHER", (17, 0), size=4.5, rotation=90 deg,
                     valign="middle")
    }
    Rigid(label)
    AlignCenterX(label, box.lid)
    AlignCenterY(label.name, box.lid)
    CutInto(label, box.lid)

    drawing stars {
        for i in range(3) {
            s = Star(center=(0, -i * 14 mm), points=5, outer_radius=5, inner_radius=2, fill=true)
        }
    }
    Rigid(stars)
    AlignCenterX(stars, box.lid)
    stars.s[0].center.y == box.lid.bb.top - 15 mm
    CutInto(stars, box.lid)
}

assert abs(gift.box.width - 330 mm) < 0.01 mm and abs(gift.box.length - 60 mm) < 0.01 mm, "330 x 60 outside"
assert abs(gift.box.height - 45 mm) < 0.01 mm, "45 mm tall"
assert len(gift.stars.s) == 3, "three stars"
assert abs(gift.stars.s[0].center.y - gift.stars.s[1].center.y - 14 mm) < 0.01 mm, "stars 14 mm apart"
assert abs(gift.stars.s[0].outer_radius * 2 - 10 mm) < 0.01 mm, "stars 10 mm across"
assert gift.label.bb.left >= gift.box.lid.bb.left + 4 mm and gift.label.bb.right <= gift.box.lid.bb.right - 4 mm,
    "label 4 mm in from the lid's long edges"
assert distance(gift.label, gift.box.lid.pull) >= 4 mm, "label clear of the pull"
assert distance(gift.label, gift.stars) >= 4 mm, "label clear of the stars"
assert gift.stars.bb.left >= gift.box.lid.bb.left + 4 mm, "stars in from the edge"
