# Request: a lazy-tongs grabber toy for my son Luca, cut from 3 mm birch ply and pinned
# with 4 mm Chicago screws. Four slats 150 x 14 mm with round ends and three 4.2 mm holes
# 68 mm apart (the middle one at the centre). Two handles: a 14 mm bar with pin holes at its
# centre and 68 mm in front of it, and behind, a finger ring 36 mm across with a 24 mm
# hole, its centre 88 mm behind the pivot; "LUCA" engraved 6 mm high on each handle between
# the ring and the pivot. Two jaws: a bar with holes 68 mm apart, reaching 50 mm past the
# front hole, with an 18 mm pad at the tip turned toward the middle (the two jaws mirror
# images). Shown opened to 30 deg, the + slats on the bottom layer, the - slats on top.

thickness 3 mm

t = 3 mm
pitch = 68 mm           # pin to pin along a slat
pin = 4.2 mm
theta = 30 deg          # each slat's angle to the tongs' axis, as shown
span = 2 * pitch * cos(theta)   # from one crossing to the next along the axis

def slat_t() -> solid {
    bar = Slot(center=(0, 0), length=150, width=14)
    hole pins {
        for k in [-1, 0, 1] {
            c = Circle(center=(k * pitch, 0), diameter=pin)
        }
    }
}

def handle_t() -> solid {
    bar = Slot(start=(0, 0), end=(pitch, 0), width=14)
    grip = Slot(start=(-88 mm, 0), end=(0, 0), width=14)
    ring = Circle(center=(-88 mm, 0), diameter=36)
    hole finger { c = Circle(center=(-88 mm, 0), diameter=24) }
    hole pins {
        front = Circle(center=(pitch, 0), diameter=pin)
        pivot = Circle(center=(0, 0), diameter=pin)
    }
    drawing name { t = Text("LUCA", position=(-40 mm, 0), size=6, valign="middle") }
}

def jaw_t(side=1) -> solid {
    bar = Slot(start=(-pitch, 0), end=(50 mm, 0), width=14)
    pad = Rectangle(corner=(40 mm, 0), opposite=(57 mm, -side * 18 mm))
    hole pins {
        rear = Circle(center=(-pitch, 0), diameter=pin)
        pivot = Circle(center=(0, 0), diameter=pin)
    }
    Fillet(2)
}

assembly tongs {
    handle_a = handle_t()
    handle_b = handle_t()
    Place(handle_a, position=(0, 0, 0), rotation=(0, 0, theta))
    Place(handle_b, position=(0, 0, t), rotation=(0, 0, -theta))

    for j in range(4) {
        slat = slat_t()
        # pairs cross at 1 and 2 spans; even j: the + slat (bottom), odd j: the - slat (top)
        Place(slat, position=((1 + j // 2) * span, 0, (j % 2) * t),
              rotation=(0, 0, theta if j % 2 == 0 else -theta))
    }

    jaw_a = jaw_t(side=1)
    jaw_b = jaw_t(side=-1)
    Place(jaw_a, position=(3 * span, 0, 0), rotation=(0, 0, theta))
    Place(jaw_b, position=(3 * span, 0, t), rotation=(0, 0, -theta))

    # flat on the sheet: one column
    Above(handle_b, handle_a, gap=4)
    AlignLeft(handle_b, handle_a)
    Above(slat[0], handle_b, gap=4)
    AlignLeft(slat[0], handle_b)
    for j in range(1, 4) {
        Above(slat[j], slat[j - 1], gap=4)
        AlignLeft(slat[j], slat[j - 1])
    }
    Above(jaw_a, slat[3], gap=4)
    AlignLeft(jaw_a, slat[3])
    Above(jaw_b, jaw_a, gap=4)
    AlignLeft(jaw_b, jaw_a)

    assert len(slat) == 4
    assert slat[0].bar.length == 150 mm and slat[0].bar.width == 14 mm
    assert distance(slat[0].pins.c[0].center, slat[0].pins.c[1].center) == 68 mm
    assert distance(slat[0].pins.c[1].center, slat[0].pins.c[2].center) == 68 mm
    assert slat[0].pins.c[0].diameter == 4.2 mm
    assert handle_a.ring.diameter == 36 mm and handle_a.finger.c.diameter == 24 mm
    assert distance(handle_a.ring.center, handle_a.pins.pivot.center) == 88 mm
    assert distance(handle_a.pins.front.center, handle_a.pins.pivot.center) == 68 mm
    assert distance(jaw_a.pins.rear.center, jaw_a.pins.pivot.center) == 68 mm
    assert jaw_a.bar.bb.right - jaw_a.pins.pivot.center.x == 50 mm + 7 mm
    assert jaw_a.pad.height == 18 mm and jaw_b.pad.height == 18 mm
    assert handle_a.name.t.size == 6 mm
}
