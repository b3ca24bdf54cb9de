# REQUEST (03, bathroom): a wig stand for the dressing table. 4 mm ply. Two head-and-neck
# silhouettes cross-halved at right angles: the front one 150 mm across the head, 100 mm
# across the foot of the neck; the side one 180 mm deep (face to back of the skull), also
# 100 mm at the foot; both 300 mm tall from the base to the crown. The front one is slotted
# 150 mm down from the crown, the side one 150 mm up from the foot. Each stands in the base
# on two 10 mm tabs (glued into mortises), 50 mm apart. Base: a 200 mm disc, "ROSA"
# engraved filled (serif italic, 14 mm) 70 mm in front of the centre.

import "std/joints.aidl"

thickness 4 mm

ply = 4 mm
tall = 300 mm
half = 150 mm

# right half of each outline from the foot to the crown; the left half mirrors it
front_right = [(50, 0), (42, 40), (40, 80), (50, 108), (68, 140), (75, 190), (66, 245), (42, 284)]
# the side: the back of the skull to +x, the face to -x
side_back = [(50, 0), (44, 50), (48, 95), (72, 130), (88, 185), (80, 240), (52, 282)]
side_face = [(-50, 0), (-42, 50), (-45, 95), (-62, 122), (-84, 160), (-90, 205), (-76, 252), (-46, 285)]

def flipped(pts) = [(-p[0], p[1]) for p in pts]
def reversed(pts) = [pts[len(pts) - 1 - i] for i in range(len(pts))]

def feet(w) -> hole {
    j = tab_and_slot(part="tab", length=w, thickness=ply, tabs=2, tab=10 mm, screw=0,
                     rotation=180 deg, cx=0, cy=0)
}

assembly wig_stand {
    solid front {
        outline = Spline(front_right + [(0, tall)] + reversed(flipped(front_right)), closed=true,
                         corners=[0, 16])
        halving = cross_halving(depth=half, thickness=ply, cx=0, cy=tall)
        foot = feet(w=100 mm)
    }
    solid side {
        outline = Spline(side_back + [(0, tall)] + reversed(side_face), closed=true,
                         corners=[0, 15])
        halving = cross_halving(depth=half, thickness=ply, rotation=180 deg, cx=0, cy=0)
        foot = feet(w=100 mm)
    }
    solid base {
        disc = Circle(center=(0, 0), diameter=200)
        front_mortise = tab_and_slot(part="slot", length=100 mm, thickness=ply, tabs=2, tab=10 mm,
                                     screw=0, cx=0, cy=0)
        side_mortise = tab_and_slot(part="slot", length=100 mm, thickness=ply, tabs=2, tab=10 mm,
                                    screw=0, rotation=90 deg, cx=0, cy=0)
        drawing name {
            t = Text("ROSA", position=(0, -70), size=14, font="serif:Italic", valign="middle",
                     fill=true)
        }
    }

    # 3D: the base on the table, the silhouettes crossing on its centre
    Place(base, position=(0, 0, 0), face="up")
    Place(front, position=(0, ply / 2, 0), face="front", up="up")
    # FIX after the first valid program: face="left" turned the side's +x (the back of the
    # skull) to the front, so the face looked away from the name; "right" turns it round.
    # (The cut parts are the same: the tabs are symmetric.)
    Place(side, position=(-ply / 2, 0, 0), face="right", up="up")

    # flat on the sheet
    RightOf(side, front, gap=8)
    AlignBottom(side, front)
    RightOf(base, side, gap=8)
    AlignBottom(base, side)

    assert front.outline.points[8][1] - front.outline.points[0][1] == 300 mm, "300 tall"
    assert side.outline.points[7][1] - side.outline.points[0][1] == 300 mm, "300 tall"
    assert front.outline.points[0][0] - front.outline.points[16][0] == 100 mm, "foot 100"
    assert side.outline.points[0][0] - side.outline.points[15][0] == 100 mm, "foot 100"
    assert abs(front.outline.bb.width - 150 mm) < 3 mm, "head about 150 across"
    assert abs(side.outline.bb.width - 180 mm) < 3 mm, "head about 180 deep"
    assert front.halving.bb.height == 150 mm and side.halving.bb.height == 150 mm, "halvings 150"
    assert front.halving.bb.height + side.halving.bb.height == 300 mm, "halvings meet"
    assert base.disc.diameter == 200 mm, "base 200"
    assert base.front_mortise.slot[1].bb.center_x - base.front_mortise.slot[0].bb.center_x == 50 mm,
        "tabs 50 apart"
    assert base.bb.center_y - base.name.t.position.y == 70 mm, "name 70 in front"
}
