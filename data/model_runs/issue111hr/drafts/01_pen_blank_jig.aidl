# Request (workshop): a drill-press jig that holds square pen blanks upright so they are drilled
# through their centre. A stack of 6 mm birch ply: a base plate 160 x 80 mm and four holder
# layers 120 x 80 mm glued on top of it (24 mm deep pockets). Every holder layer has two square
# pockets side by side, 50 mm apart centre to centre on the long axis: 20.4 mm square for
# 20 mm blanks and 25.8 mm square for 1 in (25.4 mm) blanks. The base has a 12 mm drill-exit
# hole under the centre of each pocket and an 8 mm wide, 30 mm long clamp slot (along the
# short side) 10 mm in from each short end, on the ears left and right of the stack. All five
# layers have 6 mm alignment-dowel holes 10 mm in from the holder's corners (so 100 x 60 mm
# apart). The top layer has "20" and "25.4" engraved filled (6 mm) 20 mm above each pocket's
# centre and "PEN BLANK JIG" (5 mm) engraved along its bottom edge.

units mm
thickness 6 mm

def holder(top=false) -> solid {
    body = Rectangle(center=(0, 0), width=120, height=80)
    hole small { s = Rectangle(center=(-25, 0), width=20.4, height=20.4) }
    hole big { s = Rectangle(center=(25, 0), width=25.8, height=25.8) }
    hole dowel { d = Circle(center=(0, 0), diameter=6) }
    dowels = CornerPattern(dowel, body, inset=10)
    if top {
        drawing marks {
            a = Text("20", position=(-25, 20), size=6, font="sans:Bold", valign="middle", fill=true)
            b = Text("25.4", position=(25, 20), size=6, font="sans:Bold", valign="middle", fill=true)
            n = Text("PEN BLANK JIG", position=(0, -34), size=5, valign="middle")
        }
    }
}

assembly jig {
    solid base {
        body = Rectangle(center=(0, 0), width=160, height=80)
        hole relief {
            a = Circle(center=(-25, 0), diameter=12)
            b = Circle(center=(25, 0), diameter=12)
        }
        hole clamp {
            l = Slot(center=(-66, 0), length=30, width=8, rotation=90)
            r = Slot(center=(66, 0), length=30, width=8, rotation=90)
        }
        hole dowel { d = Circle(center=(0, 0), diameter=6) }
        # base dowels line up with the holders' (10 mm in from a 120 x 80 holder)
        dowels = CornerPattern(dowel, body, inset=(30, 10))
    }
    Place(base, position=(0, 0, 0))

    for i in range(4) {
        layer = holder(top=(i == 3))
        # flat on the sheet: a row above the base
        layer.bb.center == (-195 + 130 * i, 100)
        # in 3D: stacked on the base, one 6 mm layer over the other
        Place(layer, position=(0, 0, 6 + 6 * i))
    }

    # the request's numbers
    assert len(layer) == 4, "four holder layers (24 mm deep pockets)"
    assert layer[0].small.s.width == 20.4 mm and layer[0].big.s.width == 25.8 mm, "pocket sizes"
    assert layer[0].big.s.center.x - layer[0].small.s.center.x == 50 mm, "pockets 50 mm apart"
    assert base.body.width == 160 mm and layer[0].body.width == 120 mm, "plate widths"
    # drill-exit holes under the pockets' centres (each relative to its own plate's centre)
    assert base.relief.a.center.x - base.body.center.x == layer[0].small.s.center.x - layer[0].body.center.x,
        "exit hole under the 20 mm pocket"
    assert base.relief.b.center.x - base.body.center.x == layer[0].big.s.center.x - layer[0].body.center.x,
        "exit hole under the 25.4 mm pocket"
    # dowel holes 100 x 60 apart in both kinds of layer
    assert base.dowels[1].d.center.x - base.dowels[0].d.center.x == 100 mm, "base dowels 100 apart"
    assert base.dowels[3].d.center.y - base.dowels[0].d.center.y == 60 mm, "base dowels 60 apart"
    assert layer[0].dowels[1].d.center.x - layer[0].dowels[0].d.center.x == 100 mm, "holder dowels 100 apart"
    assert layer[0].dowels[3].d.center.y - layer[0].dowels[0].d.center.y == 60 mm, "holder dowels 60 apart"
    # clamp slots 10 mm in from the short ends
    assert base.clamp.l.bb.left - base.body.bb.left == 10 mm, "left clamp slot 10 mm in"
    assert base.body.bb.right - base.clamp.r.bb.right == 10 mm, "right clamp slot 10 mm in"
    # labels 20 mm above the pockets' centres
    assert layer[3].marks.a.position.y - layer[3].small.s.center.y == 20 mm, "20 label placed"
}
