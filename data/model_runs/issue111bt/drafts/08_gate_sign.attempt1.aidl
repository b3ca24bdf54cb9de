# Request: a garden-gate sign, two layers of 3 mm plywood glued together (the back painted
# red, the front left natural), 300 x 140 mm with 10 mm rounded corners. The front layer has the
# words cut through as bold stencil letters so the red shows: "PLEASE" (16 mm) above
# "KEEP THE GATE" and "CLOSED" (22 mm each), centred, and a dog's paw print cut out at each side
# (a 18 x 14 mm oval pad under four 7 x 9 mm toes), 125 mm either side of the middle. Four 4 mm
# screw holes 10 mm in from the corners through both layers, countersunk 8 mm in the front one.

units mm
thickness 3 mm

W = 300 mm
H = 140 mm
PAW_X = 125 mm

def paw(x=0 mm) -> hole {
    pad = Ellipse(center=(x, -6), rx=9, ry=7)
    t1 = Ellipse(center=(x - 11, 5), rx=3.5, ry=4.5, rotation=30 deg)
    t2 = Ellipse(center=(x - 4, 11), rx=3.5, ry=4.5, rotation=10 deg)
    t3 = Ellipse(center=(x + 4, 11), rx=3.5, ry=4.5, rotation=-10 deg)
    t4 = Ellipse(center=(x + 11, 5), rx=3.5, ry=4.5, rotation=-30 deg)
}

def layer(front=true) -> solid {
    plate = RoundedRectangle(center=(0, 0), width=W, height=H, corner_radius=10)
    hole screw { c = Circle(center=(0, 0), diameter=4) }
    screws = CornerPattern(screw, plate, inset=10)
    if front {
        Countersink(screws, diameter=8 mm)
        hole words {
            please = Text("PLEASE", position=(0, 42), size=16, font="sans:Bold",
                          valign="middle", stencil=true)
            keep = Text("KEEP THE GATE", position=(0, 6), size=22, font="sans:Bold",
                        valign="middle", stencil=true)
            closed = Text("CLOSED", position=(0, -34), size=22, font="sans:Bold",
                          valign="middle", stencil=true)
        }
        paw_l = paw(x=-PAW_X)
        paw_r = paw(x=PAW_X)
    }
}

assembly sign {
    front = layer(front=true)
    back = layer(front=false)
    Below(back, front, gap=10)
    AlignCenterX(back, front)
    Place(back, position=(0, 0, 0))
    Place(front, position=(0, 0, 3))

    assert front.plate.width == 300 mm and front.plate.height == 140 mm, "300 x 140"
    assert front.words.keep.size == 22 mm and front.words.please.size == 16 mm, "letter sizes"
    assert front.screws[1].c.center.x - front.screws[0].c.center.x == 280 mm and
        front.screws[0].c.center.x - front.plate.bb.left == 10 mm, "screws 10 mm in"
    assert front.paw_r.pad.center.x - front.plate.center.x == 125 mm, "paws 125 mm out"
    # the words must stay clear of the paws and the screw holes
    assert front.words.bb.right <= front.paw_r.bb.left - 5 mm, "words clear of the paws"
    assert front.words.bb.top <= front.plate.bb.top - 10 mm and
        front.words.bb.bottom >= front.plate.bb.bottom + 10 mm, "words inside a 10 mm margin"
}
