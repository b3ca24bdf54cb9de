# Request: a rope bridge for the cat between two wall shelves whose ends are 700 mm apart,
# from 9 mm ply. Eleven slats 260 x 50 (R8 corners), each with two 10 mm rope holes 25 mm
# in from its ends (ropes 210 mm apart), spaced evenly so the gaps are 12.5 mm; a filled
# paw print engraved on each slat, alternately 40 mm left and right of the middle. Two
# anchor plates 260 x 100, screwed on top of each shelf's end with three countersunk M4
# screws (9 mm heads) and overhanging it by 30 mm, the rope holes 15 mm from the overhanging
# edge and 210 mm apart. The bridge hangs with about 60 mm of sag in the middle.

units mm
t = 9 mm
thickness t
import "std/plates.aidl"

span = 700 mm
slat_w = 50 mm
slats = 11
gap = (span - slats * slat_w) / (slats + 1)
sag = 60 mm

def slat(px=0 mm) -> solid {
    body = RoundedRectangle(center=(0, 0), width=260 mm, height=slat_w, corner_radius=8 mm)
    hole rope {
        a = Circle(center=(-105 mm, 0), diameter=10 mm)
        b = Circle(center=(105 mm, 0), diameter=10 mm)
    }
    drawing paw {
        pad = Ellipse(center=(px, -6 mm), rx=10 mm, ry=8 mm, fill=true)
        toe1 = Circle(center=(px - 11 mm, 6 mm), radius=3.5 mm, fill=true)
        toe2 = Circle(center=(px - 4 mm, 11 mm), radius=3.5 mm, fill=true)
        toe3 = Circle(center=(px + 4 mm, 11 mm), radius=3.5 mm, fill=true)
        toe4 = Circle(center=(px + 11 mm, 6 mm), radius=3.5 mm, fill=true)
    }
}

def anchor() -> solid {
    body = RoundedRectangle(center=(0, 0), width=260 mm, height=100 mm, corner_radius=8 mm)
    hole rope {
        a = Circle(center=(-105 mm, 50 mm - 15 mm), diameter=10 mm)
        b = Circle(center=(105 mm, 50 mm - 15 mm), diameter=10 mm)
    }
    for k in range(3) {
        hole screw {
            c = Circle(center=((k - 1) * 90 mm, -20 mm), diameter=4.5 mm)
        }
    }
    Countersink(screw, diameter=9 mm)
}

def x_of(i) = -span / 2 + gap + slat_w / 2 + i * (gap + slat_w)
def z_of(x) = -sag * (1 - (2 * x / span) ** 2)

assembly cat_bridge {
    for i in range(slats) {
        s = slat(px=(-40 mm if i % 2 == 0 else 40 mm))
        Place(s, position=(x_of(i), 0, z_of(x_of(i))), face="up", up="right")
    }
    left_anchor = anchor()
    right_anchor = anchor()
    # on the shelves: the overhanging edge (+y as drawn) toward the bridge, rope holes at x = -+350
    Place(left_anchor, position=(-span / 2 - 35 mm, 0, 0), face="up", up="right")
    Place(right_anchor, position=(span / 2 + 35 mm, 0, 0), face="up", up="left")

    # flat on the sheet: two columns of slats, the anchors under them
    for i in range(1, slats) {
        if i % 2 == 1 {
            RightOf(s[i], s[i - 1], gap=5 mm)
            AlignTop(s[i], s[i - 1])
        } else {
            Below(s[i], s[i - 2], gap=5 mm)
            AlignLeft(s[i], s[i - 2])
        }
    }
    Below(left_anchor, s[10], gap=5 mm)
    AlignLeft(left_anchor, s[10])
    RightOf(right_anchor, left_anchor, gap=5 mm)
    AlignTop(right_anchor, left_anchor)

    assert len(s) == 11, "eleven slats"
    assert s[0].body.width == 260 mm and s[0].body.height == 50 mm, "slats 260 x 50"
    assert s[0].body.bb.right - s[0].rope.b.center.x == 25 mm, "rope holes 25 mm from the ends"
    assert s[0].rope.b.center.x - s[0].rope.a.center.x == 210 mm, "ropes 210 apart"
    assert left_anchor.rope.b.center.x - left_anchor.rope.a.center.x == 210 mm, "anchor holes 210 apart"
    assert left_anchor.body.bb.top - left_anchor.rope.a.center.y == 15 mm, "15 mm from the edge"
    assert gap == 12.5 mm, "12.5 mm gaps"
    assert len(left_anchor.screw) == 3, "three screws"
    assert distance(s[0].paw, s[0].rope) >= 10 mm and distance(s[1].paw, s[1].rope) >= 10 mm,
        "paws clear of the rope holes"
    assert left_anchor.rope.a.center.y - left_anchor.screw[0].c.center.y >= 30 mm + 15 mm,
        "screws on the shelf, not in the overhang"
}
