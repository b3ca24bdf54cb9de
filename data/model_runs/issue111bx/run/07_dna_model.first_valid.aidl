# Request: a classroom DNA double-helix model, 3 mm acrylic, on a 6 mm dowel. Ten base-pair
# rungs 90 mm long: a 10 mm bar with a 14 mm disc at each end (the backbones) and a 16 mm boss
# in the middle with a 6.2 mm hole; the pair's letters engraved 5 mm on the bar, 20 mm either
# side of the centre (top strand ATGCGTACGA from the bottom up, its partner the complement:
# A-T, G-C). The rungs stack 9 mm apart (two 14 mm washers with 6.2 mm holes between each
# rung and the next, and under the lowest), each turned 36 deg from the one below: one full
# turn in ten pairs. A 120 mm base disc with a 6.2 mm hole, "DNA DOUBLE HELIX" engraved 6 mm
# round the top and "10 BASE PAIRS PER TURN" 4 mm round the bottom, both on a 48 mm circle.

import "std/shapes.aidl"

thickness 3 mm

t = 3 mm
pairs = 10
turn = 36 deg
pitch = 3 * t      # a rung and two washers
seq = ["A", "T", "G", "C", "G", "T", "A", "C", "G", "A"]

def comp(b) = "T" if b == "A" else ("A" if b == "T" else ("C" if b == "G" else "G"))

def rung_t(left="A", right="T") -> solid {
    bar = Slot(center=(0, 0), length=76, width=10)
    end_l = Circle(center=(-38, 0), radius=7)
    end_r = Circle(center=(38, 0), radius=7)
    boss = Circle(center=(0, 0), radius=8)
    hole dowel { c = Circle(center=(0, 0), diameter=6.2) }
    drawing letters {
        a = Text(left, position=(-20, 0), size=5, valign="middle")
        b = Text(right, position=(20, 0), size=5, valign="middle")
    }
}

assembly dna {
    solid base {
        disc = Circle(center=(0, 0), diameter=120)
        hole dowel { c = Circle(center=(0, 0), diameter=6.2) }
        drawing words {
            ring = Circle(center=(0, 0), radius=48, construction=true)
            title = Text("DNA DOUBLE HELIX", along=ring, size=6)
            note = Text("10 BASE PAIRS PER TURN", along=ring, size=4, flip=true)
        }
    }
    Place(base, position=(0, 0, 0))

    for i in range(pairs) {
        rung = rung_t(left=seq[i], right=comp(seq[i]))
        rung.bb.center == (120, 55 - i * 18 mm)
        Place(rung, rotation=(0, 0, i * turn), position=(0, 0, t + 2 * t + i * pitch))
    }

    for w in range(2 * pairs) {
        spacer = washer(outer=14 mm, inner=6.2 mm, cx=185 mm + (w % 2) * 18 mm,
                        cy=55 mm - (w // 2) * 18 mm)
        Place(spacer, position=(0, 0, t + (w // 2) * pitch + (w % 2) * t))
    }

    assert len(rung) == 10, "ten base pairs"
    assert rung[0].bb.width == 90 mm, "rungs 90 long"
    assert rung[0].bar.width == 10 mm, "10 mm bar"
    assert rung[0].end_l.diameter == 14 mm and rung[0].boss.diameter == 16 mm, "discs 14, boss 16"
    assert rung[0].dowel.c.diameter == 6.2 mm, "6.2 hole"
    assert rung[0].letters.b.position.x - rung[0].boss.center.x == 20 mm, "letters 20 out"
    assert pitch == 9 mm, "9 mm apart"
    assert turn * pairs == 360 deg, "one turn in ten"
    assert len(spacer) == 20, "two washers a rung"
    assert spacer[0].ring.diameter == 14 mm, "14 mm washers"
    assert base.disc.diameter == 120 mm, "120 base"
    assert base.words.ring.radius == 48 mm, "on a 48 mm circle"
    assert comp("G") == "C" and comp("A") == "T", "complements"
}
