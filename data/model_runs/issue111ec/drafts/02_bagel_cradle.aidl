# Request (kitchen): a bagel slicing cradle from 5 mm ply. A base 140 x 140 mm (R10 corners)
# and three identical rings of the same outline glued on it, so the stack stands 15 mm above
# the base: a bread knife laid flat across the top ring splits a 30 mm bagel in half. Each
# ring has a 108 mm round pocket, centred, for a 100 mm bagel, open to the front by a 60 mm
# wide mouth (push the halves out with a thumb), its sharp corners rounded R3. Four 6 mm
# dowel holes, 14 mm in from each edge, line the layers up (same holes in the base). The top
# ring has "BAGELS" engraved filled (serif bold, 8 mm) centred on its back rim.

thickness 5 mm

t = 5 mm
size = 140 mm
pocket_d = 108 mm
mouth_w = 60 mm
dowel_d = 6 mm
dowel_in = 14 mm
corners = [[-1, -1], [1, -1], [1, 1], [-1, 1]]

def dowel_holes() -> hole {
    for k in range(4) {
        c = Circle(center=(corners[k][0] * (size / 2 - dowel_in),
                           corners[k][1] * (size / 2 - dowel_in)), diameter=dowel_d)
    }
}

def layer(label=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=size, height=size, corner_radius=10)
    hole pocket {
        round = Circle(center=(0, 0), diameter=pocket_d)
        mouth = Rectangle(center=(0, -size / 2 + 10 mm), width=mouth_w, height=40, overrun=true)
    }
    dowels = dowel_holes()
    if label {
        drawing name {
            word = Text("BAGELS", position=(0, (pocket_d / 2 + size / 2) / 2), size=8,
                        font="serif:Bold", valign="middle", fill=true)
        }
    }
    Fixed(body)
    Fillet(3 mm)
}

assembly cradle {
    solid base {
        body = RoundedRectangle(center=(0, 0), width=size, height=size, corner_radius=10)
        dowels = dowel_holes()
        Fixed(body)
    }
    ring1 = layer()
    ring2 = layer()
    ring3 = layer(label=true)

    # flat on the sheet: in a row
    RightOf(ring1, base, gap=5)
    RightOf(ring2, ring1, gap=5)
    RightOf(ring3, ring2, gap=5)
    AlignCenterY(ring1, base)
    AlignCenterY(ring2, base)
    AlignCenterY(ring3, base)

    # stacked in 3D
    Place(base, position=(0, 0, 0), face="up")
    Place(ring1, position=(0, 0, t), face="up")
    Place(ring2, position=(0, 0, 2 * t), face="up")
    Place(ring3, position=(0, 0, 3 * t), face="up")

    assert 3 * t == 15 mm, "top ring 15 mm above the base: half a 30 mm bagel"
    assert ring1.body.bb.width == 140 mm and ring1.body.bb.height == 140 mm, "140 square"
    assert ring1.pocket.round.diameter == 108 mm, "108 pocket"
    assert ring1.pocket.round.diameter >= 100 mm + 4 mm, "a 100 mm bagel drops in"
    assert ring1.pocket.mouth.width == 60 mm, "60 mouth"
    assert ring1.pocket.mouth.bb.bottom < ring1.body.bb.bottom, "mouth opens through the front"
    assert ring1.dowels.c[0].center.x - ring1.body.bb.left == 14 mm, "dowels 14 in"
    assert ring1.dowels.c[0].center.y - ring1.body.bb.bottom == 14 mm, "dowels 14 in"
    assert base.dowels.c[2].center.x - base.body.bb.center_x ==
        ring1.dowels.c[2].center.x - ring1.body.bb.center_x, "base holes match the rings"
    assert distance(ring1.dowels, ring1.pocket) >= 5 mm, "dowels clear of the pocket"
    assert ring3.name.word.bb.bottom >= ring3.pocket.round.bb.top + 2 mm, "label on the rim"
    assert ring3.name.word.bb.top <= ring3.body.bb.top - 2 mm, "label on the rim"
    assert distance(ring3.name, ring3.dowels) >= 3 mm, "label clear of the dowels"
}
