# Request: a chunky toy camera for a three-year-old, glued up from three layers of 6 mm
# poplar ply (front, core, back), each 120 x 70 with R8 corners and a viewfinder hump on top
# over the left (44 wide at its base, 32 at the top, 12 high, centred 40 left of the middle),
# a 14 x 8 viewfinder window through all three and a 24 mm peephole through all three behind
# the lens (centred 8 left and 3 below the middle). The core alone has the shutter button
# (16 x 8, R3, standing 6 mm proud of the top, 38 right of the middle) and two strap lugs
# (14 mm round ears, centres 63 out from the middle and 20 up, with 5 mm holes). A lens ring
# 56 across with the 24 mm bore is glued on the front, with two engraved rings (46 and 36)
# and "50mm 1:1.8" round the top, "TOY CAM" round the bottom. On the front: a flash window
# 22 x 10 engraved filled (centred 40 right, 22 up), eight grip lines 3 mm apart below it
# and "SNAP" near the bottom right.

thickness 6 mm

def layer(core=false) -> solid {
    body = RoundedRectangle(center=(0, 0), width=120, height=70, corner_radius=8)
    # FIX after the first valid program: W0519, the hump's base ran over the body's R8 corner
    # (a nick at its left foot): the hump now sits 30 left of the middle, its base ending
    # where the corner's arc begins
    hump = Trapezoid(center=(-30, 41), bottom_width=44, top_width=32, height=12)
    hole finder { w = Rectangle(center=(-30, 40), width=14, height=8) }
    hole peep { c = Circle(center=(-8, -3), diameter=24) }
    if core {
        button = RoundedRectangle(center=(38, 37), width=16, height=8, corner_radius=3)
        for s in [-1, 1] {
            ear = Circle(center=(s * 63, 20), diameter=14)
        }
        hole lugs {
            for s in [-1, 1] {
                h = Circle(center=(s * 63, 20), diameter=5)
            }
        }
    }
}

assembly camera {
    front = layer()
    core = layer(core=true)
    back = layer()

    drawing art {
        flash = Rectangle(center=(40, 22), width=22, height=10, fill=true)
        for i in range(8) {
            g = Line((34 + i * 3, -18), (34 + i * 3, 12))
        }
        t = Text("SNAP", position=(44, -28), size=6, valign="middle")
    }
    At(art.flash.center, front.body.center, dx=40, dy=22)
    CutInto(art, front)

    solid lens {
        ring = Circle(center=(0, 0), diameter=56)
        hole bore { c = Circle(center=(0, 0), diameter=24) }
        drawing marks {
            c1 = Circle(center=(0, 0), diameter=46)
            c2 = Circle(center=(0, 0), diameter=36)
            path = Circle(center=(0, 0), radius=19.5, construction=true)
            top = Text("50mm 1:1.8", along=path, size=3)
            # FIX after the first valid program: W0513, flipped text hangs inside its circle,
            # so on r 19.5 it ran over the 36 ring: its own circle at r 22
            low = Circle(center=(0, 0), radius=22, construction=true)
            bottom = Text("TOY CAM", along=low, size=3, flip=true)
        }
    }

    RightOf(core, front, gap=8)
    AlignBottom(core, front)
    RightOf(back, core, gap=8)
    AlignBottom(back, front)
    Above(lens, front, gap=8)
    AlignLeft(lens, front)

    # in 3D: the camera faces -y, the lens in front of the front layer
    Place(front, position=(0, 6, 35), face="front", up="up")
    Place(core, position=(0, 12, 35), face="front", up="up")
    Place(back, position=(0, 18, 35), face="front", up="up")
    Place(lens, position=(-8, 0, 32), face="front", up="up")

    assert front.body.bb.width == 120 mm and front.body.bb.height == 70 mm, "120 x 70"
    assert front.hump.bb.height == 12 mm, "hump 12 high"
    assert core.button.bb.top - core.body.bb.top == 6 mm, "button 6 proud"
    assert len(core.ear) == 2 and len(core.lugs.h) == 2, "two strap lugs"
    assert lens.ring.diameter == 56 mm and lens.bore.c.diameter == 24 mm, "lens 56, bore 24"
    assert len(art.g) == 8, "eight grip lines"
}
