# Gift: a coin bank, a closed finger-jointed box 120 mm long, 80 mm deep and 100 mm
# tall outside, 3 mm plywood, 10 mm fingers. A coin slot 40 x 4 mm (rounded ends)
# through the middle of the lid, along the box's length. A 40 mm round hole in the
# middle of the bottom to take the coins out (closed by a cork). "SAVINGS" engraved
# filled on the front in sans Bold, 14 mm high, centred on the front.

import "std/joints.aidl"

units mm
thickness 3 mm

assembly bank {
    box = finger_box(length=120 mm, depth=80 mm, height=100 mm, thickness=3 mm, finger=10 mm)

    hole coin {
        s = Slot(center=(0, 0), length=40, width=4)
    }
    CenterInside(coin, box.lid)
    CutInto(coin, box.lid)

    hole cork {
        c = Circle(center=(0, 0), diameter=40)
    }
    CenterInside(cork, box.bottom)
    CutInto(cork, box.bottom)

    drawing name {
        word = Text("SAVINGS", (0, 0), size=14, font="sans:Bold", fill=true, valign="middle")
    }
    CenterInside(name, box.front)
    CutInto(name, box.front)

    # the request's numbers
    assert box.front.bb.width == 120 mm, "120 long outside"
    assert box.front.bb.height == 100 mm, "100 tall outside"
    assert box.left.bb.height == 80 mm, "80 deep outside"
    assert coin.s.length == 40 mm and coin.s.width == 4 mm, "coin slot 40 x 4"
    assert cork.c.diameter == 40 mm, "40 mm coin hole"
    assert name.word.size == 14 mm, "14 mm letters"
    assert name.bb.width < box.front.bb.width - 20 mm, "the word fits the front"
}
