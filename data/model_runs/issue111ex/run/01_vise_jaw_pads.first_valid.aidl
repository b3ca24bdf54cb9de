# Request: magnetic soft jaws for my 150 mm (6 in) engineer's bench vise, cut from 6 mm MDF.
# Two jaws; each is a FACE and a BACKER, 150 x 45 mm, glued together. The face has its two
# top corners chamfered 3 mm, a 10 mm engraved centre mark running down from the middle of its
# top edge, and a 12 mm bold engraved "L" or "R" whose bottom-right corner is 8 mm in from
# the face's bottom-right corner. The backer has three 13 mm holes for 12.7 x 3 mm disc
# magnets, 25, 75 and 125 mm from its left end, centred in its height (the face closes them;
# the magnets grip the steel jaw). Lay the four parts out for cutting 5 mm apart and place
# them in 3D on an open vise (jaw faces 20 mm apart).

thickness 6 mm

param w = 150 mm
param h = 45 mm
param magnet_d = 13 mm
param gap = 5 mm

def face(side="L") -> solid {
    body = Rectangle(center=(0, 0), width=w, height=h)
    Chamfer([body.top_left, body.top_right], 3 mm)
    drawing marks {
        # starts 0.5 mm below the top edge (W0516: an engraving must stay clear of the cut)
        centre = Line((0, h / 2 - 0.5 mm), (0, h / 2 - 10.5 mm))
        letter = Text(side, position=(w / 2 - 8 mm, -h / 2 + 8 mm), size=12, anchor="end",
                      valign="bottom", font="sans:Bold", fill=true)
    }
}

def backer() -> solid {
    body = Rectangle(center=(0, 0), width=w, height=h)
    hole magnets {
        for i in range(3) {
            m = Circle(center=(-w / 2 + 25 mm + i * 50 mm, 0), diameter=magnet_d)
        }
    }
}

assembly soft_jaws {
    face_l = face(side="L")
    back_l = backer()
    face_r = face(side="R")
    back_r = backer()

    RightOf(back_l, face_l, gap=gap)
    AlignTop(back_l, face_l)
    Below(face_r, face_l, gap=gap)
    AlignLeft(face_r, face_l)
    RightOf(back_r, face_r, gap=gap)
    AlignTop(back_r, face_r)

    # 3D: the rear jaw's face looks to the front, the front jaw's to the back, 20 mm apart
    Place(face_l, position=(0, 16, h / 2), face="front", up="up")
    Place(back_l, position=(0, 22, h / 2), face="front", up="up")
    Place(face_r, position=(0, -16, h / 2), face="back", up="up")
    Place(back_r, position=(0, -22, h / 2), face="back", up="up")

    # the request's numbers
    assert face_l.body.width == 150 mm and face_l.body.height == 45 mm, "face 150 x 45"
    assert back_l.body.width == 150 mm and back_l.body.height == 45 mm, "backer 150 x 45"
    assert len(back_l.magnets.m) == 3, "three magnets per jaw"
    assert back_l.magnets.m[0].diameter == 13 mm, "13 mm magnet holes"
    assert back_l.magnets.m[0].center.x - back_l.body.bb.left == 25 mm, "first magnet 25 mm in"
    assert back_l.magnets.m[1].center.x - back_l.body.bb.left == 75 mm, "second magnet 75 mm in"
    assert back_l.magnets.m[2].center.x - back_l.body.bb.left == 125 mm, "third magnet 125 mm in"
    assert back_l.magnets.m[0].center.y - back_l.body.bb.bottom == 22.5 mm, "magnets centred in height"
    assert face_l.body.bb.right - face_l.marks.letter.bb.right == 8 mm, "letter 8 mm from the right"
    assert face_l.marks.letter.bb.bottom - face_l.body.bb.bottom == 8 mm, "letter 8 mm up"
    assert face_l.marks.centre.length == 10 mm, "10 mm centre mark"
    assert face_l.body.bb.top - face_l.marks.centre.start.y == 0.5 mm, "mark starts at the top edge"
}
