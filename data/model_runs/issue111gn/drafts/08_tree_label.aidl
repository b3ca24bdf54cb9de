# Request (signs): a tree label for a village arboretum, 6 mm exterior ply. A 160 x 100 mm
# plaque (R6) set at 45 degrees on two bracket cheeks that are tenoned through a 60 mm wide,
# 480 mm tall stake (its bottom 80 mm pointed). The plaque reads, centred: "ENGLISH OAK"
# (12 mm serif Bold), "Quercus robur" (9 mm serif Italic), "FAGACEAE - NATIVE" and
# "PLANTED 1998" (5 mm sans); "No 14" at the bottom left; a filled oak-leaf silhouette about
# 27 mm tall at the bottom right. Four 4 mm screw holes, countersunk 8 mm, 20 mm either side of
# the centre line and 42 mm above and below the middle, into the cheeks. Each cheek: a
# 110 mm back edge with one 40 mm through-tenon, a 45-degree top edge 106 mm long for the plaque,
# 75 mm deep; their mid-planes 20 mm either side of the stake's centre line; the tenons' tops
# 55 mm below the stake's top.

units mm
thickness 6 mm
import "std/joints.aidl"

half_leaf = [(0, 15), (3, 13), (5.5, 10.5), (3.5, 8), (7, 5), (4, 2.5), (7.5, -1), (4.5, -4),
             (6.5, -7), (3, -9.5), (1.5, -12), (0, -12)]

def cheek() -> solid {
    body = Polygon([(0, 0), (0, 110), (6, 110), (81, 35), (81, 20), (6, 0)])
    tenon = tab_and_slot(part="tab", length=110 mm, thickness=6 mm, tabs=1, tab=40 mm, screw=0,
                         rotation=90 deg, cx=0 mm, cy=55 mm)
}

assembly tree_label {
    solid stake {
        body = Polygon([(30, 0), (60, 80), (60, 480), (0, 480), (0, 80)])
        left_mortise = tab_and_slot(part="slot", length=110 mm, thickness=6 mm, tabs=1, tab=40 mm,
                                    screw=0, rotation=90 deg, cx=10 mm, cy=405 mm)
        right_mortise = tab_and_slot(part="slot", length=110 mm, thickness=6 mm, tabs=1, tab=40 mm,
                                     screw=0, rotation=90 deg, cx=50 mm, cy=405 mm)
    }
    left = cheek()
    right = cheek()
    solid plaque {
        body = RoundedRectangle(center=(0, 0), width=160, height=100, corner_radius=6)
        for p in [(-20, -42), (-20, 42), (20, -42), (20, 42)] {
            hole screw { c = Circle(center=p, diameter=4) }
        }
        Countersink(screw, diameter=8)
        drawing words {
            name = Text("ENGLISH OAK", position=(0, 24), size=12, font="serif:Bold", valign="middle", fill=true)
            latin = Text("Quercus robur", position=(0, 6), size=9, font="serif:Italic", valign="middle", fill=true)
            family = Text("FAGACEAE - NATIVE", position=(0, -12), size=5, font="sans", valign="middle", fill=true)
            planted = Text("PLANTED 1998", position=(0, -26), size=5, font="sans", valign="middle", fill=true)
            number = Text("No 14", position=(-62, -30), size=5, font="sans", valign="middle", fill=true)
        }
        drawing leaf {
            s = Spline(mirror(half_leaf), closed=true, fill=true)
            stem = Line((0, -12), (0, -17))
        }
        Translate(leaf, (62, -22))
    }
    RightOf(left, stake, gap=10)
    RightOf(right, left, gap=10)
    AlignTop(left, stake)
    AlignTop(right, stake)
    Below(plaque, right, gap=10)
    AlignLeft(plaque, left)

    # the stake's front face at y = 0; the cheeks stand out in front, tenons through it;
    # the plaque's back on the cheeks' 45-degree edges, its middle at the edges' middle
    Place(stake, position=(-30, 6, 0), face="front", up="up")
    Place(left, position=(-17, 6, 350), face="left", up="up")
    Place(right, position=(23, 6, 350), face="left", up="up")
    Place(plaque, position=(0, -37.5, 422.5), face=(0, -1, 1), up="up")

    assert plaque.body.bb.width == 160 mm and plaque.body.bb.height == 100 mm, "plaque 160 x 100"
    assert stake.body.bb.width == 60 mm and stake.body.bb.height == 480 mm, "stake 60 x 480"
    assert stake.body.points[4].y - stake.body.points[0].y == 80 mm, "80 mm point"
    assert left.body.points[1].y - left.body.points[0].y == 110 mm, "110 mm back edge"
    assert abs(distance(left.body.points[2], left.body.points[3]) - 106 mm) < 0.1 mm, "106 mm top edge"
    assert left.body.points[3].x - left.body.points[2].x == left.body.points[2].y - left.body.points[3].y, "45 degrees"
    assert left.body.points[3].x - left.body.points[0].x == 81 mm, "75 mm deep past the 6 mm tenon"
    assert stake.right_mortise.slot[0].bb.center_x - stake.left_mortise.slot[0].bb.center_x == 40 mm, "cheeks 20 mm either side"
    assert stake.body.bb.top - stake.left_mortise.slot[0].bb.top == 55 mm, "tenons' tops 55 mm down"
    assert len(plaque.screw) == 4, "four screws"
    assert abs(plaque.screw[0].c.center.x) == 20 mm and abs(plaque.screw[0].c.center.y) == 42 mm, "screws at 20 / 42"
    assert distance(plaque.words, plaque.screw[0]) >= 2 mm and distance(plaque.words, plaque.screw[3]) >= 2 mm, "words clear of the screws"
    assert plaque.words.bb.left >= plaque.body.bb.left + 5 mm and plaque.words.bb.right <= plaque.body.bb.right - 5 mm, "words on the plaque"
    assert distance(plaque.leaf, plaque.words) >= 2 mm, "leaf clear of the words"
    assert plaque.leaf.bb.right <= plaque.body.bb.right - 5 mm and plaque.leaf.bb.bottom >= plaque.body.bb.bottom + 5 mm, "leaf on the plaque"
}
