# Request (garden): a hanging suet-cake feeder for a standard 115 x 100 x 25 mm suet block,
# cut from 4 mm exterior ply. An open-top finger-jointed box with a space inside 125 long,
# 35 deep and 120 high; front and back are each a mesh of 4 rows x 5 columns of 16 mm square
# openings on a 21 mm pitch (birds cling and peck through it), centred on the panel. Three
# 6 mm drain holes 30 mm apart in the bottom. A 6 mm dowel runs across the top between the two
# sides (6.5 mm holes in the sides, 12 mm below the top edge); the hanging cord is tied to it
# and goes up through an 8 mm hole in the middle of a lift-off roof: a 165 x 75 mm plate
# (corners rounded 6 mm) with "SUET CAFE" engraved 9 mm tall, and under it a glued plug
# 1 mm smaller each way than the opening (123 x 33) that keeps the roof from sliding off.

import "std/joints.aidl"

thickness 4 mm

T = 4 mm
IN_L = 125 mm
IN_D = 35 mm
IN_H = 120 mm
PITCH = 21 mm
SQ = 16 mm

def mesh() -> hole {
    sq = Rectangle(center=(0, 0), width=SQ, height=SQ)
    g = GridPattern(sq, 4, 5, PITCH)
}

def dowel_hole() -> hole {
    c = Circle(center=(0, 0), diameter=6.5)
}

assembly suet_feeder {
    box = finger_box(length=IN_L, depth=IN_D, height=IN_H, thickness=T, finger=10 mm,
                     closed=false, outside=false)

    front_mesh = mesh()
    CenterInside(front_mesh, box.front)
    CutInto(front_mesh, box.front)
    back_mesh = mesh()
    CenterInside(back_mesh, box.back)
    CutInto(back_mesh, box.back)

    # the sides lie on their side, top edge outward (left's at -x, right's at +x)
    dl = dowel_hole()
    AlignCenterY(dl, box.left)
    dl.c.center.x == box.left.bb.left + 12 mm
    CutInto(dl, box.left)
    dr = dowel_hole()
    AlignCenterY(dr, box.right)
    dr.c.center.x == box.right.bb.right - 12 mm
    CutInto(dr, box.right)

    hole drain {
        for i in range(3) {
            c = Circle(center=(i * 30 mm, 0), diameter=6)
        }
    }
    CenterInside(drain, box.bottom)
    CutInto(drain, box.bottom)

    solid roof {
        plate = RoundedRectangle(center=(0, 0), width=165, height=75, corner_radius=6)
        hole cord {
            c = Circle(center=(0, 0), diameter=8)
        }
        drawing name {
            t = Text("SUET CAFE", position=(0, -22), size=9, valign="middle")
        }
    }
    solid plug {
        p = Rectangle(center=(0, 0), width=IN_L - 2 mm, height=IN_D - 2 mm)
        hole cord {
            c = Circle(center=(0, 0), diameter=8)
        }
    }

    # on the sheet: roof and plug to the right of the box's net
    RightOf(roof, box, gap=10)
    AlignTop(roof, box)
    Below(plug, roof, gap=10)
    AlignLeft(plug, roof)

    # in 3D (the box stands on z = 0, centred on x = y = 0)
    Place(plug, position=(0, 0, IN_H + T - T))
    Place(roof, position=(0, 0, IN_H + T))

    # the request's numbers
    assert len(front_mesh.g) == 20 and len(back_mesh.g) == 20, "4 x 5 openings each side"
    assert front_mesh.sq.width == 16 mm, "16 mm openings"
    assert front_mesh.g[1].sq.center.x - front_mesh.g[0].sq.center.x == 21 mm, "21 mm pitch"
    assert len(drain.c) == 3, "three drain holes"
    assert roof.plate.width == 165 mm and roof.plate.height == 75 mm, "roof 165 x 75"
    assert plug.p.width == 123 mm and plug.p.height == 33 mm, "plug 123 x 33"
    assert IN_H - 12 mm - 3.25 mm + T >= 100 mm + T, "dowel clears the 100 mm block"
}
