# Request: a kitchen placemat and its matching coaster, cut from 3 mm cork sheet. The mat
# is 420 x 300 mm with 30 mm rounded corners. Down each short end runs a vine: an engraved
# stem 240 mm long, 30 mm in from the end, with 7 pointed leaves (24 mm long, 10 mm wide)
# cut out, 36 mm apart, alternating left and right of the stem at 35 degrees to it. The
# family name "HARTLEY" is engraved in serif letters 14 mm high, centred, 22 mm below the
# top edge. The coaster is a 100 mm disc with 8 of the same leaves cut in a ring (their
# centres on a 34 mm radius, pointing outward) around an engraved 12 mm "H".

units mm
thickness 3 mm

param mat_w = 420 mm, min = 360, max = 480
param mat_h = 300 mm, min = 260, max = 340
leaf_len = 24 mm
leaf_w = 10 mm
# a pointed leaf is the overlap of two circles of radius R whose centres are d apart
R = (leaf_len ** 2 / 4 + leaf_w ** 2 / 4) / leaf_w
d = 2 * R - leaf_w

def leaf(x=0 mm, y=0 mm, ang=0 deg) -> hole {
    v = Intersect(Circle(center=(x - d / 2 * sin(ang), y + d / 2 * cos(ang)), radius=R),
                  Circle(center=(x + d / 2 * sin(ang), y - d / 2 * cos(ang)), radius=R))
}

assembly table_set {
    solid mat {
        body = RoundedRectangle(center=(0, 0), width=mat_w, height=mat_h, corner_radius=30)
        # the two vines, left (k = 0) and right (k = 1)
        for k in range(2) {
            for i in range(7) {
                lf = leaf(x=(-1 if k == 0 else 1) * (mat_w / 2 - 30 mm)
                            + (1 if i % 2 == 0 else -1) * 0.5 * leaf_len * sin(35 deg),
                          y=(i - 3) * 36 mm + 0.5 * leaf_len * cos(35 deg),
                          ang=90 deg + (-35 deg if i % 2 == 0 else 35 deg))
            }
        }
        drawing stems {
            for k in range(2) {
                st = Line(((-1 if k == 0 else 1) * (mat_w / 2 - 30 mm), -120),
                          ((-1 if k == 0 else 1) * (mat_w / 2 - 30 mm), 120))
            }
        }
        drawing name {
            word = Text("HARTLEY", position=(0, mat_h / 2 - 22 mm), size=14, font="serif",
                        valign="top", fill=true)
        }
    }

    solid coaster {
        disc = Circle(center=(300, 0), diameter=100)
        for j in range(8) {
            cl = leaf(x=300 mm + 34 mm * cos(j * 45 deg), y=34 mm * sin(j * 45 deg),
                      ang=j * 45 deg)
        }
        drawing mono {
            h = Text("H", position=(300, 0), size=12, font="serif", valign="middle",
                     fill=true)
        }
    }
    RightOf(coaster, mat, gap=20)
    AlignCenterY(coaster, mat)

    assert mat.body.bb.width == 420 mm and mat.body.bb.height == 300 mm, "mat 420 x 300"
    assert coaster.disc.diameter == 100 mm, "coaster 100 mm"
    assert len(mat.lf) == 2 and len(mat.lf[0]) == 7, "7 leaves a vine, two vines"
    assert len(coaster.cl) == 8, "8 leaves on the coaster"
    assert mat.stems.st[0].length == 240 mm, "stem 240 long"
    assert mat.stems.st[0].start.x - mat.body.bb.left == 30 mm, "stem 30 in from the end"
    assert mat.body.bb.top - mat.name.bb.top == 22 mm, "name 22 below the top edge"
    assert mat.lf[0][0].v.bb.height <= 24 mm, "a leaf no longer than 24"
}
