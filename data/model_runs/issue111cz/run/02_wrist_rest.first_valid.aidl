# Request (office): a keyboard wrist rest glued up from six layers of 3 mm birch ply, 18 mm tall.
# Outline 360 x 75 mm with 20 mm corner radii. The bottom layer is whole, with four 10 mm rings
# engraved on its underside where the rubber feet go (centred 25 mm in from each end and 15 mm in
# from the long edges). The four middle layers are hollow to save weight: a 12 mm wall all round
# and four pockets split by three 10 mm ribs (the same pockets in every layer, so the ribs glue
# onto each other). The two top layers step in 1.5 mm and 3 mm all round to soften the edge;
# the top layer is whole and carries the owner's name "N. OKAFOR" engraved filled, 12 mm tall,
# centred.

thickness 3 mm

param L = 360 mm, min = 250 mm, max = 450 mm
param Dp = 75 mm, min = 60 mm, max = 100 mm
R = 20 mm
WALL = 12 mm
RIB = 10 mm
POCKETS = 4
LAYERS = 6
STEP = [0 mm, 0 mm, 0 mm, 0 mm, 1.5 mm, 3 mm]
HOLLOW = [false, true, true, true, true, false]
POCKET_W = (L - 2 * WALL - (POCKETS - 1) * RIB) / POCKETS

def layer(inset=0 mm, hollow=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=L - 2 * inset, height=Dp - 2 * inset,
                            corner_radius=R - inset)
    if hollow {
        for i in range(POCKETS) {
            hole pocket {
                p = RoundedRectangle(center=(-L / 2 + WALL + POCKET_W / 2 + i * (POCKET_W + RIB), 0),
                                     width=POCKET_W, height=Dp - 2 * WALL, corner_radius=R - WALL)
            }
        }
    }
}

assembly wrist_rest {
    for i in range(LAYERS) {
        lay = layer(inset=STEP[i], hollow=HOLLOW[i])
    }
    # on the sheet: one above the other
    for i in range(1, LAYERS) {
        Above(lay[i], lay[i - 1], gap=5 mm)
    }

    # in 3D: stacked; the bottom layer's engraved face looks down
    Place(lay[0], position=(0, 0, 3 mm), face="down")
    for i in range(1, LAYERS) {
        Place(lay[i], position=(0, 0, i * 3 mm), face="up")
    }

    drawing feet {
        for sx in [-1, 1] {
            for sy in [-1, 1] {
                ring = Circle(center=(sx * (L / 2 - 25 mm), sy * (Dp / 2 - 15 mm)), diameter=10 mm)
            }
        }
    }
    CutInto(feet, lay[0])
    Rigid(feet)
    AlignCenterX(feet, lay[0])
    AlignCenterY(feet, lay[0])

    drawing name {
        t = Text("N. OKAFOR", position=(0, 0), size=12 mm, font="serif:Bold", valign="middle",
                 fill=true)
    }
    CutInto(name, lay[5])
    At(name.t.position, lay[5].body.center)

    assert len(lay) == 6, "six layers"
    assert lay[0].body.bb.width == 360 mm and lay[0].body.bb.height == 75 mm, "360 x 75 outline"
    assert LAYERS * 3 mm == 18 mm, "18 mm tall"
    assert lay[0].body.bb.width - lay[4].body.bb.width == 2 * 1.5 mm, "5th layer steps in 1.5"
    assert lay[0].body.bb.width - lay[5].body.bb.width == 2 * 3 mm, "top layer steps in 3"
    assert lay[1].pocket[0].p.bb.left - lay[1].body.bb.left == 12 mm, "12 mm wall"
    assert lay[1].pocket[1].p.bb.left - lay[1].pocket[0].p.bb.right == 10 mm, "10 mm ribs"
    assert feet.ring[0][0].center.x - lay[0].body.bb.left == 25 mm, "feet 25 in from the ends"
    assert name.t.size == 12 mm, "name 12 tall"
}
