# Request (garden): a blue-tit nest box from 6 mm exterior ply. A finger-jointed open-top box
# 150 x 150 mm outside and 220 mm tall (fingers 20 mm), with a separate flat roof 200 mm wide x
# 190 mm deep that overhangs 25 mm each side and 40 mm at the front, held by four 4 mm
# screws (countersunk for 8 mm heads) into the tops of the side walls (over the walls' middles,
# 30 mm and 120 mm from the back edge), so it lifts off for cleaning. In the front: a 25 mm
# entrance hole centred, its centre 125 mm above the floor (the floor's top face); "BLUE TIT"
# engraved 10 mm high, 70 mm above the bottom edge. Four 6 mm drain holes in the floor, 60 mm
# apart in a square around its centre. Two 5 mm hanging holes in the back, on its centre line,
# 30 mm from its top and bottom edges. "FRONT" engraved 6 mm high on the roof's front edge.

units mm
thickness 6 mm
import "std/joints.aidl"

ply = 6 mm

assembly nest {
    box = finger_box(length=150 mm, depth=150 mm, height=220 mm, thickness=ply, finger=20 mm,
                     closed=false, gap=10 mm)

    # the front: entrance and name
    hole entrance { c = Circle(center=(0, 0), diameter=25) }
    AlignCenterX(entrance, box.front)
    entrance.c.center.y == box.front.bb.bottom + ply + 125 mm
    CutInto(entrance, box.front)

    drawing name { t = Text("BLUE TIT", (0, 0), size=10, valign="middle") }
    AlignCenterX(name, box.front)
    name.t.position.y == box.front.bb.bottom + 70 mm
    CutInto(name, box.front)

    # the floor: four drain holes
    hole drain { c = Circle(center=(0, 0), diameter=6) }
    drains = GridPattern(drain, 2, 2, 60)
    At(drain.c.center, box.bottom.bb.center, dx=-30, dy=-30)
    CutInto(drain, box.bottom)

    # the back: two hanging holes
    hole hang { c = Circle(center=(0, 0), diameter=5) }
    hangs = LinearPattern(hang, 2, (0, -160))
    AlignCenterX(hang, box.back)
    hang.c.center.y == box.back.bb.top - 30 mm
    CutInto(hang, box.back)

    # the lift-off roof: screws over the middle of each 6 mm side wall
    solid roof {
        body = Rectangle(center=(0, 0), width=200, height=190)
        hole screw { c = Circle(center=(-72, 95 - 30), diameter=4) }
        screws = GridPattern(screw, 2, 2, (144, -90))
        Countersink(screws, diameter=8)
        drawing front_mark { t = Text("FRONT", (0, -95 + 10), size=6) }
    }
    RightOf(roof, box, gap=10)
    AlignBottom(roof, box)
    # FIX after the first valid program: W0518 said the roof, having no Place, touches no part
    # in the assembled view. The box stands on z = 0 centred on x = y = 0, 150 deep: its back
    # face at y = +75; the roof (drawn about (0, 0), back edge at +95) sits on the walls' tops
    # (z = 220) with its back edge flush with the back.
    Place(roof, position=(0, 75 - 95, 220))

    assert box.front.bb.width == 150 mm and box.left.bb.width == 220 mm, "150 wide, 220 tall"
    assert entrance.c.diameter == 25 mm, "25 mm entrance (blue tit)"
    assert entrance.c.center.y - (box.front.bb.bottom + ply) == 125 mm,
        "entrance centre 125 mm above the floor"
    assert len(drains) == 4 and drain.c.diameter == 6 mm, "four 6 mm drains"
    assert len(hangs) == 2, "two hanging holes"
    assert hangs[1].c.center.y == box.back.bb.bottom + 30 mm, "lower hanging hole 30 mm up"
    assert roof.body.width - 150 mm == 2 * 25 mm, "roof overhangs 25 mm each side"
    assert roof.body.height - 150 mm == 40 mm, "roof overhangs 40 mm at the front"
    assert roof.screw.c.center.x - roof.body.bb.left == 25 mm + ply / 2,
        "screws over the middle of the side walls"
    assert roof.body.bb.top - roof.screw.c.center.y == 30 mm, "first screws 30 mm from the back"
}
