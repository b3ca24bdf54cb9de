# Request (kitchen): a flat-pack cooling rack for cakes and bread, 4 mm birch ply. The grid is
# 300 x 220 mm and stands 30 mm high. Six long slats, 300 mm long and 18 mm tall, run along the
# rack at 30 mm pitch; five cross slats, 220 mm long and 30 mm tall, cross them at 65 mm pitch.
# Every crossing is a cross-halving so all tops are flush. Each cross slat stands on two 25 mm
# feet at its ends, leaving 12 mm of air under the middle. The outer cross slat on the right
# carries the engraved words "FRESH FROM THE OVEN".

units mm
thickness 4 mm
import "std/joints.aidl"

t = 4 mm
rack_l = 300 mm
rack_w = 220 mm
rack_h = 30 mm
long_h = 18 mm
longs = 6
long_pitch = 30 mm
crosses = 5
cross_pitch = 65 mm
foot = 25 mm
air = 12 mm
half = long_h / 2

def long_y(i) = (i - (longs - 1) / 2) * long_pitch
def cross_x(j) = (j - (crosses - 1) / 2) * cross_pitch

# a long slat, drawn with its length along x and its height along y (bottom edge at y = air)
def long_slat() -> solid {
    body = Rectangle(center=(0, air + long_h / 2), width=rack_l, height=long_h)
    for j in range(crosses) {
        slot = cross_halving(depth=half, thickness=t, cx=cross_x(j), cy=rack_h)
    }
}

# a cross slat: feet at both ends, the halving slots run up from the underside between them
def cross_slat(label="") -> solid {
    body = Polygon([(-rack_w / 2, 0), (-rack_w / 2 + foot, 0), (-rack_w / 2 + foot, air),
                    (rack_w / 2 - foot, air), (rack_w / 2 - foot, 0), (rack_w / 2, 0),
                    (rack_w / 2, rack_h), (-rack_w / 2, rack_h)])
    for i in range(longs) {
        slot = cross_halving(depth=half, thickness=t, cx=long_y(i), cy=air, rotation=180 deg)
    }
    if label != "" {
        drawing words {
            w = Text(label, position=(0, (air + half + rack_h) / 2), size=5, valign="middle")
        }
    }
}

assembly rack {
    for i in range(longs) {
        ls = long_slat()
        ls.bb.center == (0, 40 + i * (long_h + 6))
        # stood on edge, running along x, centred on its line y = long_y(i)
        Place(ls, position=(0, long_y(i) + t / 2, 0), face="front", up="up")
    }
    for j in range(crosses) {
        cs = cross_slat(label="FRESH FROM THE OVEN" if j == crosses - 1 else "")
        cs.bb.center == (0, 40 + longs * (long_h + 6) + 10 + j * (rack_h + 6))
        # stood on edge, running along y, centred on its line x = cross_x(j)
        Place(cs, position=(cross_x(j) - t / 2, 0, 0), face="right", up="up")
    }

    assert len(ls) == 6, "six long slats"
    assert len(cs) == 5, "five cross slats"
    assert ls[0].body.bb.width == 300 mm, "long slats 300 mm"
    assert ls[0].body.bb.height == 18 mm, "long slats 18 mm tall"
    assert cs[0].body.bb.width == 220 mm, "cross slats 220 mm"
    assert cs[0].body.bb.height == 30 mm, "rack 30 mm high"
    assert long_y(1) - long_y(0) == 30 mm, "long slats at 30 mm pitch"
    assert cross_x(1) - cross_x(0) == 65 mm, "cross slats at 65 mm pitch"
    assert ls[0].slot[0].depth + cs[0].slot[0].depth == ls[0].body.bb.height, "halvings meet"
}
